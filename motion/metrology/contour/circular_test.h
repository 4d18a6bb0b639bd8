#pragma once
// The circular test of ISO 230-4 (what a ballbar measures): two axes contour a
// circle of radius R at feed F, clockwise and counter-clockwise, while the
// position is sampled. Definitions as the standard gives them:
//
//  - radial deviation: r − R of each sample about the nominal centre (the set-up);
//  - circular deviation G, per direction: the radial separation of the two circles
//    about the least-squares circle's centre that just enclose the path, i.e. the
//    largest minus the smallest distance from that centre;
//  - bidirectional circular deviation G(b): the same over both paths about one
//    least-squares centre of both;
//  - circular hysteresis H: the largest radial difference between the clockwise and
//    the counter-clockwise path at the same angle, both measured from that common
//    centre (each path interpolated linearly in angle at the other's samples).
//
// The evaluated revolution is 360°; the runner adds a lead arc before and after
// (feed-in/feed-out, not evaluated) so the axes are at feed when it starts.
#include "motion/metrology/problem.h"
#include "motion/metrology/contour/xy_line_test.h"

#include <optional>
#include <string>
#include <vector>

namespace motion::metrology {

enum class Rotation { Cw, Ccw };
const char* rotationName(Rotation r);    ///< "cw" / "ccw"
const char* rotationTermId(Rotation r);  ///< "rotation.cw" / "rotation.ccw"

struct CircularTest {
    std::string name;
    std::string axes = "XY";          ///< the plane: two different capital letters
    XyPoint centreMm;
    double radiusMm = 10;
    double feedMmS = 5;
    bool clockwise = true;
    bool counterClockwise = true;
    double leadArcDeg = 45;           ///< before and after the evaluated 360°
    int samplesPerRevolution = 360;
    std::optional<double> maxGMm;     ///< pass/fail limits; empty: not judged
    std::optional<double> maxHMm;
};

/// Radius above 0, the circle inside the soft limits, a feed above 0 and within the
/// instrument's, at least one direction, a lead arc of 0–180°, 8 samples or more.
motion::msg::Problems validate(const CircularTest& t, const XyLimits& limits = {});

struct CircleFit {
    XyPoint centreMm;
    double radiusMm = 0;
};
/// The least-squares circle: Σ(distance to centre − radius)² smallest (algebraic fit
/// as the start, then Gauss–Newton on the geometric residuals).
std::optional<CircleFit> fitCircle(const std::vector<XyPoint>& points);

struct CircularRun {
    Rotation rotation = Rotation::Ccw;
    std::vector<XyPoint> samplesMm;   ///< the evaluated revolution, in the order sampled
};

struct RadialSample {
    double angleRad = 0;              ///< about the nominal centre, [0, 2π)
    double radialDeviationMm = 0;     ///< r − R about the nominal centre
    double lsqAngleRad = 0;           ///< about the run's least-squares centre
    double lsqDeviationMm = 0;        ///< distance to that centre − its radius
};

struct RunResult {
    Rotation rotation = Rotation::Ccw;
    std::vector<RadialSample> samples;
    CircleFit lsq;
    double circularDeviationMm = 0;   ///< G of this direction
    double radialDeviationMinMm = 0;
    double radialDeviationMaxMm = 0;
};

struct CircularEvaluation {
    std::vector<RunResult> runs;
    std::optional<double> bidirectionalDeviationMm;  ///< G(b), with both directions
    std::optional<double> hysteresisMm;              ///< H, with both directions
    motion::msg::Problems problems;
    bool ok() const { return !hasErrors(problems); }
};

/// Largest angular gap between samples of a run that still counts as a whole revolution.
constexpr double kMaxSampleGapDeg = 30;

/// Refused: a run with fewer than 8 samples, a sample that is not finite, a run that
/// leaves a gap above 30° of the revolution, two runs of the same direction.
CircularEvaluation evaluate(const CircularTest& t, const std::vector<CircularRun>& runs);

struct PolarPoint {
    double angleRad = 0;
    double plotRadiusMm = 0;          ///< R + magnification × deviation from the least-squares circle
};
/// What a polar plot draws for one run: the path with its deviation magnified.
std::vector<PolarPoint> polarPlot(const RunResult& run, double nominalRadiusMm, double magnification);
/// A 1-2-5 magnification that shows the largest deviation as about a quarter of R.
double autoMagnification(const CircularEvaluation& e, double nominalRadiusMm);

} // namespace motion::metrology
