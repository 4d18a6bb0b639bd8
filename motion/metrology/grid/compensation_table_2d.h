#pragma once
// An XY stage's 2D compensation: X and Y corrections (µm, added to the command) at
// the nodes of a regular grid, bilinearly interpolated between nodes and held at
// the grid's edge outside it (the nearest point of the grid's rectangle), as a
// controller's cross-compensation table is. Made from a grid map: each node's
// correction k solves "the command n + k lands the work point on n" against the
// map's errors interpolated the same way, so a smooth error is cancelled at every
// node, not only where it was measured.
//
// Plain C++ (no Qt): the device (the simulator) applies it, the host fits and keeps it.
#include "motion/metrology/grid/grid_map.h"
#include "motion/metrology/problem.h"

#include <optional>
#include <vector>

namespace motion::metrology {

struct CompensationTable2D {
    double originXMm = 0;  ///< the node of column 0, row 0 (home coordinates)
    double originYMm = 0;
    double pitchXMm = 1;
    double pitchYMm = 1;
    int columns = 0;
    int rows = 0;
    /// Node (column i, row j) at index j·columns + i.
    std::vector<double> correctionXUm, correctionYUm;

    struct Correction {
        double xUm = 0;
        double yUm = 0;
    };
    Correction correctionAt(double xMm, double yMm) const;
    double endXMm() const { return originXMm + pitchXMm * (columns - 1); }
    double endYMm() const { return originYMm + pitchYMm * (rows - 1); }
};

/// What a device keeps: 2–41 nodes a side, pitches of at least 0.1 mm, corrections
/// within ±10 mm, and every number finite.
constexpr int kMinTable2DNodes = 2;
constexpr int kMaxTable2DNodes = 41;
constexpr double kMinTable2DPitchMm = 0.1;
constexpr double kMaxTable2DCorrectionUm = 10000;

/// Every problem at once, at the file's paths ("grid.columns", "nodes[12].correction_x_um").
/// Messages: compensation2d.nodes_out_of_range, compensation2d.node_count_wrong,
/// accuracy.value_below, accuracy.value_above, accuracy.value_not_finite.
motion::msg::Problems validate(const CompensationTable2D& table);

/// The table that cancels a map's errors (GridMapResult's nodes, placement removed),
/// on the map's own grid. nullopt when the map's grid is not a regular one a device
/// keeps (the map is checked by validate(CompensationTable2D) on the result).
std::optional<CompensationTable2D> compensationFromMap(const GridMapResult& map);

} // namespace motion::metrology
