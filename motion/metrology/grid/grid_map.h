#pragma once
// A grid plate's map of an XY stage: at every node of a regular grid, the
// nominal stage position and the error vector the camera saw there (where the
// plate's dot truly was against where the stage was sent, µm). The plate lies on
// the stage at some offset and rotation of its own, so those are fitted out first
// (least squares over every node); what remains is decomposed along ISO 230-1's
// least-squares reference lines:
//
//  - scale_x_ppm: the least-squares slope of ex along X in each row, averaged over
//    the rows (µm/mm × 1000); scale_y_ppm likewise of ey along Y in each column;
//  - straightness_x_um: in each row, ey along X less its least-squares line,
//    peak to valley, averaged over the rows; straightness_y_um likewise of ex
//    along Y in each column;
//  - squareness_urad: the slope of ex along Y plus the slope of ey along X. A
//    rotation θ of the plate adds −θ to the first and +θ to the second, so it
//    cancels: squareness is what the plate's placement cannot hide. Positive: Y
//    leans toward +X (as motion/metrology/grid/stage_errors.h);
//  - rms_error_um, max_error_um: the length of the error vector over the nodes once
//    the placement is removed;
//  - rms_residual_um: what is left after an additive model of the decomposition
//    (ex = a + scale_x·x + g(y), ey = b + scale_y·y + k(x), g and k the mean profiles
//    across the grid) is taken off: the part of the map no per-axis line or
//    straightness explains (a pitch error that is not straight, a twist).
//
// Bidirectional passes (the grid visited again in reverse order, every node approached
// from +X and +Y instead of −X and −Y) give a reversal vector per node: forward −
// reverse, ISO 230-2's B_i = x̄↑ − x̄↓ carried to two axes. The map itself, its placement
// and every figure above are then of the mean of the two directions, as ISO 230-2 takes
// the mean bidirectional position: a reversal is split evenly and no longer shifts
// the map. The mean reversal along X and along Y over the nodes is the axes' lost
// motion as the work point sees it (backlash b = −B̄, as the per-axis compensation
// takes it); a 2D table holds one correction per place whatever the direction, so it
// cannot correct that part.
//
// Plain C++ + Eigen; no Qt.
#include "motion/metrology/problem.h"

#include <optional>
#include <vector>

namespace motion::metrology {

struct GridMapInput {
    std::vector<double> xMm;      ///< nominal column positions, increasing
    std::vector<double> yMm;      ///< nominal row positions, increasing
    /// Node (column i, row j) at index j·columns + i: measured − nominal, µm.
    std::vector<double> exUm, eyUm;
    /// The reverse pass, same layout; empty for a one-way map.
    std::vector<double> reverseExUm, reverseEyUm;

    std::size_t columns() const { return xMm.size(); }
    std::size_t rows() const { return yMm.size(); }
};

struct GridPlacement {
    double offsetXUm = 0;
    double offsetYUm = 0;
    double rotationUrad = 0;  ///< counter-clockwise, about the grid's centroid
    double centreXMm = 0;
    double centreYMm = 0;
};

struct GridMapFigures {
    double scaleXPpm = 0;
    double scaleYPpm = 0;
    double straightnessXUm = 0;
    double straightnessYUm = 0;
    double squarenessUrad = 0;
    double rmsErrorUm = 0;
    double maxErrorUm = 0;
    double rmsResidualUm = 0;
    std::optional<double> maxReversalUm;    ///< the longest reversal vector; bidirectional maps only
    std::optional<double> meanReversalXUm;  ///< B̄ along X over the nodes (forward − reverse)
    std::optional<double> meanReversalYUm;
};

struct GridMapNode {
    double xMm = 0, yMm = 0;
    /// After the placement is removed; the mean of both directions in a bidirectional map.
    double exUm = 0, eyUm = 0;
    double residualXUm = 0, residualYUm = 0;    ///< after the decomposition is removed
    /// Bidirectional maps only: forward − reverse.
    std::optional<double> reversalXUm, reversalYUm;
    /// Bidirectional maps only: each direction's error after the placement is removed.
    std::optional<double> forwardExUm, forwardEyUm, reverseExUm, reverseEyUm;

    bool bidirectional() const { return reversalXUm && reversalYUm; }
    /// The reversal vector's length (0 for a one-way map).
    double reversalUm() const;
};

struct GridMapResult {
    GridPlacement placement;
    GridMapFigures figures;
    std::vector<GridMapNode> nodes;  ///< row by row, as the input
};

/// At least 3 × 3 nodes (a straightness needs three points a line), increasing
/// positions, finite errors, the reverse pass complete or absent. Messages:
/// grid.too_few_nodes, grid.positions_not_increasing, grid.node_count_wrong,
/// accuracy.value_not_finite.
motion::msg::Problems validate(const GridMapInput& input);

/// The placement fitted out and the decomposition (of the mean of both directions when
/// the reverse pass is there); nullopt when validate() finds an error.
std::optional<GridMapResult> analyseGridMap(const GridMapInput& input);

/// The least-squares placement (offset and rotation) of a set of error vectors on the
/// grid; exposed for tests and for a caller that only wants the plate's lie.
GridPlacement fitPlacement(const std::vector<double>& xMm, const std::vector<double>& yMm,
                           const std::vector<double>& exUm, const std::vector<double>& eyUm);

} // namespace motion::metrology
