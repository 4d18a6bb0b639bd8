#pragma once
// Teaching a slot: the operator jogs the tip over three wells (A1, the last well
// of row A, the first well of the last row) and records where the machine is.
// The fit maps the labware's nominal well centres onto those taught points.
//
// Why not a full affine: six parameters through exactly three points always fit
// with zero residual, so the residual would never reveal a mis-taught point. We
// fit a restricted model by least squares instead:
//   * Similarity (default): offset, rotation and one scale: 4 parameters,
//     6 equations, 2 degrees of freedom left to show a bad teach. A molded plate
//     is rigid and its pitch is exact; screw lead errors on this machine are
//     1–2·10⁻⁴, so one scale covers them.
//   * ScaledAxes: offset, rotation, a scale per plate axis: 5 parameters, one
//     degree of freedom left. For machines whose X and Y leads differ; but a
//     teach point off along its own row or column is then absorbed by that
//     axis' scale and shows no residual (see the calibration tests), which is
//     why it is not the default.
// The residual per point is the distance from the fitted well to the taught one.
// Past kResidualWarnMm (seed 000 Table 1: the XY repeatability the analyzer must
// hold, 0.2 mm) a point was probably taught off centre or on the wrong well;
// least squares spreads that error over all three points, so the warning lists
// them all instead of blaming one.
#include "motion/plans/plates/labware.h"
#include "motion/plans/plates/transform.h"

#include <optional>
#include <string>
#include <vector>

namespace motion::plates {

constexpr double kResidualWarnMm = 0.2;
/// A scale further than this from 1 means the wrong labware or wrong wells.
constexpr double kScaleWarn = 0.005;
/// A plate turned more than this is not seated in its slot.
constexpr double kRotationWarnDeg = 3.0;

enum class FitModel { Similarity, ScaledAxes };
const char* fitModelName(FitModel m);  ///< "similarity", "scaled-axes"

struct TeachPoint {
    std::string well;          ///< "A1"
    PointMm plateMm;           ///< nominal centre in the plate frame
    PointMm machineMm;         ///< where the operator put the tip
};

/// The three wells to teach on `labware`: A1, the last well of row A, the first
/// well of the last row, with their nominal plate-frame centres. Fewer when the
/// plate has a single row or column (then only the wells that differ).
std::vector<TeachPoint> teachWells(const Labware& labware);

struct CalibrationFit {
    FitModel model = FitModel::Similarity;
    PlateTransform transform;
    double rotationDeg = 0;
    double scaleX = 1, scaleY = 1;     ///< equal for Similarity
    std::vector<double> residualMm;    ///< per teach point, in their order
    double maxResidualMm = 0;
    double rmsResidualMm = 0;
    std::vector<motion::msg::Message> warnings; ///< plate.calibration.* for the operator
};

/// One slot's calibration as it is kept between runs.
struct SlotCalibration {
    std::string slot;          ///< deck slot id
    std::string labware;       ///< what was taught on (its wells gave the nominal points)
    FitModel model = FitModel::Similarity;
    std::vector<TeachPoint> points;
    std::string taughtAt;      ///< ISO 8601, for the person reading the file
    CalibrationFit fit;        ///< from the points (recomputed on reading)
};

/// Least-squares fit; nullopt with `error` when the points cannot fix the model
/// (fewer than 2, taught wells on top of each other, non-finite numbers).
/// `slotRotationDeg` is the slot's nominal turn: the warning is about departing from it.
std::optional<CalibrationFit> fitCalibration(const std::vector<TeachPoint>& points, FitModel model, motion::msg::Message* error,
                                             double slotRotationDeg = 0);

} // namespace motion::plates
