#pragma once
// The tile grid of a plan and the order the stage visits it in.
//
// Tile count per axis: a region W wide, field F, overlap o gets
//     n = max(1, ceil((W − F) / (F·(1 − o))) + 1)
// fields at the exact step s = F·(1 − o), the grid centred on the region. So
// neighbouring fields overlap by exactly the share asked for, and the grid, which
// is (n − 1)·s + F ≥ W wide, overhangs the region by less than s/2 on each side.
// Every field centre lies inside the region's bounding box, because (n − 1)·s ≤ W.
// (Spreading the same n fields over W instead would make the overlap larger than
// asked, up to nearly 100 % when W is just over F: not what a person typed.)
//
// A polygon region keeps the fields whose rectangle overlaps the polygon with a
// positive area (an exact clip, so a field holding the whole polygon is kept too).
#include "motion/plans/scan/scan_plan.h"

#include <cstdint>
#include <vector>

namespace motion::scan {

struct Tile {
    int index = 0;    ///< place in the visiting order, from 0
    int row = 0;      ///< grid row from 0 at the top (stage +Y side)
    int col = 0;      ///< grid column from 0 at the left (stage −X side)
    Point2 centre;    ///< planned stage position: the field's centre, before compensation
};

/// One move of the run. Overtravel points (unidirectional approach) carry no tile.
struct Waypoint {
    Point2 target;    ///< planned position (compensation is applied when commanding)
    int tile = -1;    ///< index into ScanLayout::tiles, or −1 for an overtravel point
};

struct GridSize {
    int columns = 0, rows = 0;
    double stepXMm = 0, stepYMm = 0;
    double fieldWidthMm = 0, fieldHeightMm = 0;
};

/// n = max(1, ceil((W − F) / (F·(1 − o))) + 1); nullopt-free: W ≤ F gives 1. A tiny
/// rounding slack keeps an exact fit (W − F a whole number of steps) from gaining a column.
long tilesAlong(double regionMm, double fieldMm, double overlap);
GridSize gridSize(const ScanPlan& plan);

struct ScanLayout {
    GridSize grid;
    Rect gridBounds;                 ///< union of all the grid's fields (kept or not)
    std::vector<Tile> tiles;         ///< in visiting order
    std::vector<Waypoint> path;      ///< every move in order, overtravel points included
    int approachSignX = 1, approachSignY = -1;  ///< direction of the last move onto a tile, per axis
};

/// The grid, ordered. Call validate() first: an invalid plan gives an empty layout.
ScanLayout layoutScan(const ScanPlan& plan);

/// Where to come from so a tile is approached the plan's way (the overtravel point).
Point2 overtravelPoint(const ScanLayout& layout, const ScanPlan& plan, Point2 tileCentre);

/// Field rectangle of a tile at its planned centre.
Rect tileField(const ScanLayout& layout, const Tile& tile);

/// Identifies the tiles a run visits: their order, grid places and commanded
/// positions (to the nanometre). A run log made under one fingerprint is only
/// resumed under the same one, so a changed plan never mixes into an old run.
std::uint64_t layoutFingerprint(const ScanPlan& plan, const ScanLayout& layout);

/// Sum of straight-line distances between consecutive waypoints, mm.
double pathLengthMm(const ScanLayout& layout);

} // namespace motion::scan
