#pragma once
// The errors of an XY stage between what its gratings read and where its work
// point truly is: what a grid plate under the microscope's camera measures, and
// what the simulator's stage does (benchpilot-sim --stage-errors FILE).
//
//   true x = x + pitch_x(x) + straightness_y(y) + squareness · y
//   true y = y + pitch_y(y) + straightness_x(x)
//
// (positions in mm, errors in µm, polynomials in mm with coefficient 0 first;
// squareness in µrad, so squareness · y in mm is nm: divided by 1000 into µm), plus
// half the axis's backlash against the direction it was approached from: an axis
// that arrives from below stops short by b/2. straightness_x is how far the X
// axis' travel strays in Y; straightness_y how far Y's strays in X. A positive
// squareness leans the Y axis toward +X (the angle between +X and +Y is below 90°).
//
// Plain C++ (no Qt): the simulator applies it, and the grid map's tests build their
// maps from it without telling the fitting code what it holds.
#include "motion/metrology/problem.h"
#include "motion/metrology/readings.h"

#include <optional>
#include <vector>

namespace motion::metrology {

struct StageAxisErrors {
    std::vector<double> pitchPolyUm;         ///< along the axis' own travel, µm over mm, c0 first
    std::vector<double> straightnessPolyUm;  ///< across it (X: in Y; Y: in X), µm over this axis' mm
};

struct StageErrors {
    StageAxisErrors x, y;
    double squarenessUrad = 0;  ///< + : Y leans toward +X
    double backlashXUm = 0;     ///< lost motion at the work point on a reversal of X
    double backlashYUm = 0;
};

/// The simulated stage's errors when no file says otherwise: seed 002's fitted
/// curves (work point against the carriage) as the pitch polynomials, a straight
/// and square stage without lost motion at the work point (the grating loop takes
/// the screw's play out).
StageErrors builtInStageErrors();

/// p(mm) = c0 + c1·mm + …, µm.
double polynomialUm(const std::vector<double>& coefficientsUm, double mm);

struct ErrorVectorUm {
    double xUm = 0;
    double yUm = 0;
};

/// true − read at grating reading (xMm, yMm), µm. An approach side left empty
/// leaves that axis' backlash out (a stage standing where it was put by hand).
ErrorVectorUm stageErrorUm(const StageErrors& errors, double xMm, double yMm,
                           std::optional<Direction> approachX = std::nullopt,
                           std::optional<Direction> approachY = std::nullopt);

/// The most coefficients a polynomial may have (order 5), the largest coefficient 0
/// and value within a 1 m travel taken for an error rather than a typo.
constexpr std::size_t kMaxStageErrorCoefficients = 6;
constexpr double kMaxStageErrorUm = 10000;
constexpr double kMaxSquarenessUrad = 100000;

/// Every problem at once, at the file's field paths ("x.pitch_poly_um[2]",
/// "squareness_urad", "backlash_um.y"); `travelMm` is where the polynomials are
/// checked to stay within ±kMaxStageErrorUm. Messages: stage_errors.too_many_coefficients,
/// accuracy.value_not_finite, accuracy.value_above, accuracy.value_below,
/// stage_errors.curve_too_large.
motion::msg::Problems validate(const StageErrors& errors, double travelMm = 100);

} // namespace motion::metrology
