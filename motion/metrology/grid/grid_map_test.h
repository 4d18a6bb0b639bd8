#pragma once
// A grid map as a test to run: the camera looks at a grid plate (dots at the plate's
// certified pitch) and the stage visits a regular grid of its dots. The test starts at
// the dot nearest the image centre where the stage stands (or at `start` when the test
// gives one), and goes `columns` × `rows` nodes every `pitch` towards +X and +Y from
// there. Every node is approached from below on both axes (a lead-in of `approachMm`
// before each row and before the first node of a session), so the axes' lost motion is
// one constant offset of the whole map, which the plate's placement takes out.
//
// A bidirectional test then visits the nodes again in reverse order, every node
// approached from above on both axes (the lead-in overshoots by `approachMm` in +X and
// +Y before each row and comes back), so each node is read once from −X −Y and once
// from +X +Y: the difference is the reversal at that node (motion/metrology/grid/grid_map.h).
//
// Plain C++; no Qt.
#include "motion/metrology/problem.h"

#include <optional>
#include <string>
#include <vector>

namespace motion::metrology {

struct GridMapTest {
    std::string name = "grid-map";
    double pitchXMm = 5;
    double pitchYMm = 5;
    int columns = 19;
    int rows = 19;
    /// The first node (stage mm); empty: the dot nearest the image centre where the stage stands.
    std::optional<double> startXMm, startYMm;
    double platePitchMm = 1;       ///< the plate's certified dot pitch
    double feedMmS = 10;
    double dwellS = 0.2;           ///< wait after arriving, on the device's clock
    double approachMm = 0.05;      ///< the lead-in from below before a row
    bool stopOnFailure = false;    ///< a dot not found stops the run (else it is that node's failure and the run goes on)
    bool bidirectional = false;    ///< a reverse pass after the forward one, every node approached from +X +Y
};

/// The test alone: 3–101 nodes a side, pitches that are whole multiples of the plate's
/// pitch (a node between the plate's dots would read the nearest dot, another node's),
/// positive feed, dwell and lead-in. Paths are the test file's ("pitch_mm.x", "nodes.columns").
/// Messages: grid.too_few_nodes, grid.too_many_nodes, grid.pitch_not_on_plate,
/// accuracy.value_below, accuracy.value_above, accuracy.value_not_finite.
motion::msg::Problems validate(const GridMapTest& test);

/// The test against the travel, from its first node (startXMm, startYMm): every node and
/// lead-in (below the first node; above the last too when bidirectional) within [min, max] per axis. Message grid.leaves_travel {axis, end, limit}
/// at "nodes.columns" (X) or "nodes.rows" (Y).
motion::msg::Problems validateTravel(const GridMapTest& test, double startXMm, double startYMm, double minXMm, double maxXMm,
                                     double minYMm, double maxYMm);

/// One node as the runner visits it: row by row, +X within a row; in the reverse pass
/// the same nodes the other way round, −X within a row from the last row down.
struct GridMapStop {
    int column = 0, row = 0;
    double xMm = 0, yMm = 0;
    bool leadIn = false;   ///< the first of its row: approached from (x − a, y − a), reverse (x + a, y + a)
    bool reverse = false;  ///< read in the reverse pass, approached from +X +Y

    int node(int columns) const { return row * columns + column; }
    /// The side each axis is approached from: −1 below, +1 above.
    double approachSide() const { return reverse ? 1.0 : -1.0; }
};
/// Every reading of the test in the order taken: columns × rows stops, twice when bidirectional
/// (the reverse pass's stop k is node columns·rows − 1 − k).
std::vector<GridMapStop> planGridMap(const GridMapTest& test, double startXMm, double startYMm);

} // namespace motion::metrology
