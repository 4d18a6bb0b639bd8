// ISO 230-4 circular test evaluation on paths with known errors: a two-lobed
// (squareness/scale) error gives G = twice its amplitude whatever the centre
// offset, a reversal step between the directions gives H, and the polar plot
// magnifies the deviation about the least-squares circle.
#include "motion/numbers.h"
#include "motion/metrology/contour/circular_test.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace motion::metrology;

namespace {

using motion::kPi;

/// Samples of r(θ) = R + dr(θ) about (cx, cy); CW runs go the other way round.
CircularRun path(Rotation rot, double cx, double cy, double radius, double lobeMm, double stepMm, int samples = 360)
{
    CircularRun run;
    run.rotation = rot;
    for (int k = 0; k < samples; ++k) {
        const double a = (rot == Rotation::Ccw ? 1 : -1) * 2 * kPi * k / samples;
        const double r = radius + lobeMm * std::cos(2 * a) + stepMm;
        run.samplesMm.push_back({cx + r * std::cos(a), cy + r * std::sin(a)});
    }
    return run;
}

CircularTest tenMm()
{
    CircularTest t;
    t.centreMm = {50, 50};
    t.radiusMm = 10;
    return t;
}

bool has(const motion::msg::Problems& ps, const std::string& id)
{
    return std::any_of(ps.begin(), ps.end(), [&](const motion::msg::Problem& p) { return p.message.id == id; });
}

} // namespace

TEST(CircularTest, LeastSquaresCircleFindsTheCentreAndRadius)
{
    const auto fit = fitCircle(path(Rotation::Ccw, 3, -2, 25, 0, 0).samplesMm);
    ASSERT_TRUE(fit);
    EXPECT_NEAR(fit->centreMm.xMm, 3, 1e-12);
    EXPECT_NEAR(fit->centreMm.yMm, -2, 1e-12);
    EXPECT_NEAR(fit->radiusMm, 25, 1e-12);
    // A quarter arc is enough to pin it down, with noise-free points.
    CircularRun arc = path(Rotation::Ccw, 0, 0, 5, 0, 0, 400);
    arc.samplesMm.resize(100);
    EXPECT_NEAR(fitCircle(arc.samplesMm)->radiusMm, 5, 1e-9);
    EXPECT_FALSE(fitCircle({{0, 0}, {1, 1}, {2, 2}})) << "collinear points have no circle";
}

TEST(CircularTest, CircularDeviationIsTwiceTheLobeWhateverTheCentreOffset)
{
    // The path is centred 20 µm off the set-up centre: the radial deviation about the
    // nominal centre sees that offset, G (about the least-squares centre) does not.
    const CircularTest t = tenMm();
    const CircularEvaluation e = evaluate(t, {path(Rotation::Ccw, 50.02, 50, 10, 0.003, 0)});
    ASSERT_TRUE(e.ok());
    ASSERT_EQ(e.runs.size(), 1u);
    EXPECT_NEAR(e.runs[0].circularDeviationMm, 0.006, 1e-6);
    EXPECT_NEAR(e.runs[0].lsq.centreMm.xMm, 50.02, 1e-6);
    EXPECT_GT(e.runs[0].radialDeviationMaxMm - e.runs[0].radialDeviationMinMm, 0.04) << "about the nominal centre: ±20 µm of offset";
    EXPECT_FALSE(e.hysteresisMm) << "H needs both directions";
}

TEST(CircularTest, HysteresisIsTheRadialStepBetweenDirections)
{
    // CW runs 4 µm outside CCW everywhere (a reversal error that opens the circle).
    const CircularTest t = tenMm();
    const CircularEvaluation e = evaluate(t, {path(Rotation::Cw, 50, 50, 10, 0.002, 0.002), path(Rotation::Ccw, 50, 50, 10, 0.002, -0.002)});
    ASSERT_TRUE(e.ok());
    ASSERT_TRUE(e.hysteresisMm);
    EXPECT_NEAR(*e.hysteresisMm, 0.004, 1e-6);
    EXPECT_NEAR(e.runs[0].circularDeviationMm, 0.004, 1e-6);
    EXPECT_NEAR(e.runs[1].circularDeviationMm, 0.004, 1e-6);
    EXPECT_NEAR(*e.bidirectionalDeviationMm, 0.008, 1e-6) << "both paths between two circles: lobes plus the step";
    EXPECT_NEAR(e.runs[0].radialDeviationMaxMm, 0.004, 1e-9);
    EXPECT_NEAR(e.runs[1].radialDeviationMinMm, -0.004, 1e-9);
}

TEST(CircularTest, HysteresisComparesTheSameAngleWhenSamplesDoNotLineUp)
{
    // 359 CW samples against 360 CCW: no two at the same angle, the same circle.
    const CircularTest t = tenMm();
    const CircularEvaluation e = evaluate(t, {path(Rotation::Cw, 50, 50, 10, 0.001, 0, 359), path(Rotation::Ccw, 50, 50, 10, 0.001, 0, 360)});
    ASSERT_TRUE(e.ok());
    EXPECT_LT(*e.hysteresisMm, 0.0001) << "interpolation in angle, not sample by sample";
}

TEST(CircularTest, PolarPlotMagnifiesTheDeviation)
{
    const CircularTest t = tenMm();
    const CircularEvaluation e = evaluate(t, {path(Rotation::Ccw, 50, 50, 10, 0.003, 0)});
    const double m = autoMagnification(e, 10);
    EXPECT_EQ(m, 500) << "3 µm shown as a quarter of 10 mm wants 833×: the 1-2-5 step below is 500";
    const auto plot = polarPlot(e.runs[0], 10, m);
    ASSERT_EQ(plot.size(), 360u);
    EXPECT_NEAR(plot[0].angleRad, 0, 1e-9);
    EXPECT_NEAR(plot[0].plotRadiusMm, 10 + 500 * 0.003, 1e-6);
    EXPECT_NEAR(plot[45].plotRadiusMm, 10, 1e-6) << "the lobe crosses zero at 45°";
}

TEST(CircularTest, RefusesShortRunsGapsAndBadDefinitions)
{
    const CircularTest t = tenMm();
    CircularRun half = path(Rotation::Ccw, 50, 50, 10, 0, 0);
    half.samplesMm.resize(180);
    EXPECT_TRUE(has(evaluate(t, {half}).problems, "accuracy.circle.incomplete_revolution"));
    CircularRun few = path(Rotation::Ccw, 50, 50, 10, 0, 0, 6);
    EXPECT_TRUE(has(evaluate(t, {few}).problems, "accuracy.circle.too_few_samples"));
    EXPECT_TRUE(has(evaluate(t, {path(Rotation::Cw, 50, 50, 10, 0, 0), path(Rotation::Cw, 50, 50, 10, 0, 0)}).problems,
                    "accuracy.circle.direction_twice"));
    CircularRun nan = path(Rotation::Ccw, 50, 50, 10, 0, 0);
    nan.samplesMm[3].xMm = std::nan("");
    EXPECT_TRUE(has(evaluate(t, {nan}).problems, "accuracy.value_not_finite"));
    EXPECT_TRUE(has(evaluate(t, {}).problems, "accuracy.circle.no_runs"));

    CircularTest bad = tenMm();
    bad.radiusMm = -1;
    bad.clockwise = bad.counterClockwise = false;
    bad.axes = "XX";
    bad.feedMmS = 2000;
    const motion::msg::Problems ps = validate(bad);
    for (const char* id : {"accuracy.value_not_positive", "accuracy.circle.no_direction", "accuracy.circle.axes_invalid", "accuracy.value_above"})
        EXPECT_TRUE(has(ps, id)) << id;
    XyLimits limits;
    limits.x.maxMm = 55;
    const motion::msg::Problems out = validate(tenMm(), limits);
    ASSERT_TRUE(has(out, "accuracy.circle.above_limit"));
    EXPECT_EQ(out[0].message.number("value"), 60);
    EXPECT_FALSE(hasErrors(validate(tenMm())));
}
