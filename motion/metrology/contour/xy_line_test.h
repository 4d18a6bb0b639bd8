#pragma once
// Linked XY positioning along a line (seed 000 §4.1, Tables 3–5): X and Y move
// together to targets on a line at angle θ to the X axis, and each stop is judged
// on both axes and on the contour error, the deviation perpendicular to the line:
//
//   ε = −sinθ·e_x + cosθ·e_y          (e = measured − target per axis)
//
// Seed 000 prints ε = cosθ·e_x + sinθ·e_y, which is the component *along* the
// line (a stop that lands further along the line is on the contour); its own
// Table 5 follows the perpendicular formula (tests/motion/accuracy_seed000_test.cpp).
// The seed's stops are approached from the start of the line only, so the test is
// unidirectional: the ISO 230-2 figures reported are the ↑ ones.
#include "motion/metrology/linear/axis_test.h"
#include "motion/metrology/linear/iso230_2.h"
#include "motion/metrology/problem.h"

#include <optional>
#include <string>
#include <vector>

namespace motion::metrology {

struct XyPoint {
    double xMm = 0;
    double yMm = 0;
};

struct XyLineTest {
    std::string name;
    std::vector<XyPoint> pointsMm;   ///< explicit targets on one line, in the order visited
    std::optional<XyPoint> fromMm;   ///< or from…to with `count` evenly spaced targets
    std::optional<XyPoint> toMm;
    int count = 0;
    int cycles = 5;
    double overrunMm = 1.0;          ///< each cycle starts this far before the first target, on the line
    double feedMmS = 5.0;            ///< along the line
    double dwellS = 0.5;
    SettleRule settle;
    AxisTolerances contourTolerances;   ///< judged on the contour error's figures
};

struct XyLimits {
    AxisLimits x;
    AxisLimits y;
    std::optional<double> maxFeedMmS;
};

/// Farther than this from the line through the first and last target, a target is
/// refused: the contour error of a point off the line is not the machine's.
constexpr double kMaxOffLineMm = 0.001;

std::vector<XyPoint> pointsOf(const XyLineTest& t);
/// θ, the angle of the line from the first to the last target to the X axis.
double lineAngleRad(const std::vector<XyPoint>& points);

double contourErrorMm(double thetaRad, double exMm, double eyMm);   ///< −sinθ·e_x + cosθ·e_y
double alongLineErrorMm(double thetaRad, double exMm, double eyMm); ///< cosθ·e_x + sinθ·e_y

motion::msg::Problems validate(const XyLineTest& t, const XyLimits& limits = {});

struct XyStop {
    int cycle = 1;
    std::size_t pointIndex = 0;
    XyPoint targetMm;
    std::optional<XyPoint> overrunMm;   ///< go here first (before the first target, on the line)
};
/// Per cycle: the overrun point, then every target in order. Empty with errors.
std::vector<XyStop> runSequence(const XyLineTest& t);

struct XyReading {
    std::size_t pointIndex = 0;
    int cycle = 1;
    double xMm = 0;   ///< measured
    double yMm = 0;
};

/// Three unidirectional ISO 230-2 evaluations: X at the targets' x, Y at their y,
/// and the contour error with the targets' distance along the line from the first
/// one as its positions (nominal ε = 0). Each target's ε per reading is in
/// `contourMm` (in readings order) for a table like the seed's Table 5.
struct XyEvaluation {
    double thetaRad = 0;
    Evaluation x;
    Evaluation y;
    Evaluation contour;
    std::vector<double> contourMm;
    motion::msg::Problems problems;   ///< about the readings themselves (a point index that does not exist)
};
XyEvaluation evaluate(const std::vector<XyPoint>& targets, const std::vector<XyReading>& readings);

} // namespace motion::metrology
