// One judgement for a step test and the Z–N verification (judgeStep), and the
// residual oscillation at rest it finds (findLimitCycle), on synthetic records
// quantised like the stage's grating (0.5 µm a count, 1 kHz loop).
#include "motion/control/tuning/step_verdict.h"
#include "motion/numbers.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

using namespace motion::control;

namespace {
using motion::kPi;
constexpr double kCountMm = 0.0005;  // the stage's grating: 2 µm pitch counted ×4

double quantised(double mm) { return std::round(mm / kCountMm) * kCountMm; }

/// `seconds` of a 1 kHz loop stepping from 0 to `step` mm, its reading quantised to grating counts.
Record stageRecord(double step, double seconds, EndReason reason, const std::function<double(double)>& y)
{
    Record r;
    r.periodS = 1e-3;
    r.startPosition = 0;
    r.reason = reason;
    const int n = static_cast<int>(std::lround(seconds / r.periodS));
    for (int k = 0; k < n; ++k)
        r.append(step, quantised(y(k * r.periodS)), 0);
    return r;
}

StepJudging stage()
{
    StepJudging j;
    j.resolution = kCountMm;
    j.targetBand = 0.005;
    return j;
}

/// A quick rise to the target by 20 ms, then a swing of ±`amplitude` mm with `periodS` to the end.
std::function<double(double)> hunting(double step, double amplitude, double periodS)
{
    return [=](double t) {
        const double rise = step * std::min(1.0, t / 0.02);
        return rise + (t > 0.02 ? amplitude * std::sin(2 * kPi * (t - 0.02) / periodS) : 0.0);
    };
}
} // namespace

// What the Z–N verification summary hid: "completed, inside ±5 µm of the target from 25 ms"
// while the trace swung ±2.5 µm for the whole second and the step test said "did not settle".
TEST(StepVerdict, AResponseThatSwingsInsideTheBandIsALimitCycleNotASettledStep)
{
    const Record r = stageRecord(0.01, 1.0, EndReason::Completed, hunting(0.01, 0.0025, 0.04));
    const StepVerdict v = judgeStep(r, stage());
    EXPECT_EQ(v.metrics.outcome, StepOutcome::LimitCycle);
    ASSERT_TRUE(v.limitCycle.found);
    EXPECT_NEAR(v.limitCycle.amplitude, 0.0025, kCountMm);
    EXPECT_NEAR(v.limitCycle.periodS, 0.04, 0.002);
    EXPECT_GE(v.limitCycle.cycles, 2);
    EXPECT_TRUE(std::isfinite(v.insideTargetBandS)) << "inside ±5 µm is true, and is no verdict on its own";
    // The figures that a centre gives are kept.
    EXPECT_TRUE(std::isfinite(v.metrics.riseTimeS));
}

// After "Use these": the axis at rest dithers ±1 µm (four counts peak to peak).
TEST(StepVerdict, ADitherOfOneMicrometreAtRestIsFound)
{
    const Record r = stageRecord(0.02, 1.0, EndReason::Completed, hunting(0.02, 0.001, 0.012));
    const StepVerdict v = judgeStep(r, stage());
    ASSERT_TRUE(v.limitCycle.found);
    EXPECT_EQ(v.metrics.outcome, StepOutcome::LimitCycle);
    EXPECT_NEAR(v.limitCycle.amplitude, 0.001, kCountMm);
    EXPECT_NEAR(v.limitCycle.periodS, 0.012, 0.001);
    EXPECT_DOUBLE_EQ(v.limitCycle.threshold, 2 * kCountMm);
}

// A still axis whose reading toggles between neighbouring counts, or wanders inside the
// loop's one-count deadband, is at rest: no limit cycle.
TEST(StepVerdict, QuantisationAndTheDeadbandAreNoLimitCycle)
{
    // Sits on a count boundary: the reading flips between two counts every few periods.
    const Record toggles = stageRecord(0.01, 1.0, EndReason::Completed, [](double t) {
        const double rise = 0.01 * std::min(1.0, t / 0.02);
        return rise + (t > 0.02 ? 0.26 * kCountMm * std::sin(2 * kPi * t / 0.01) : 0.0);
    });
    const StepVerdict a = judgeStep(toggles, stage());
    EXPECT_FALSE(a.limitCycle.found) << "±" << a.limitCycle.amplitude * 1000 << " µm";
    EXPECT_EQ(a.metrics.outcome, StepOutcome::Settled);

    // ±1 count (two counts peak to peak): what the deadband allows, still not motion.
    const Record deadband = stageRecord(0.01, 1.0, EndReason::Completed, hunting(0.01, kCountMm, 0.02));
    EXPECT_FALSE(judgeStep(deadband, stage()).limitCycle.found);
}

// An underdamped step whose ringing has died out by the second half is a settled step.
TEST(StepVerdict, ADecayingTransientIsNoLimitCycle)
{
    const double zeta = 0.2, wn = 200, wd = wn * std::sqrt(1 - zeta * zeta);
    const Record r = stageRecord(0.02, 0.4, EndReason::Completed, [&](double t) {
        return 0.02 * (1 - std::exp(-zeta * wn * t) * (std::cos(wd * t) + zeta / std::sqrt(1 - zeta * zeta) * std::sin(wd * t)));
    });
    const StepVerdict v = judgeStep(r, stage());
    EXPECT_FALSE(v.limitCycle.found);
    EXPECT_EQ(v.metrics.outcome, StepOutcome::Settled);
    EXPECT_GT(v.metrics.overshootPct, 30);

    // The same ringing, slower, still decaying in the window read: its amplitude falls too fast to be a cycle.
    const double slow = 40;
    const Record ringing = stageRecord(0.02, 0.4, EndReason::Completed, [&](double t) {
        return 0.02 * (1 - std::exp(-zeta * slow * t) * std::cos(slow * std::sqrt(1 - zeta * zeta) * t));
    });
    EXPECT_FALSE(judgeStep(ringing, stage()).limitCycle.found);
}

// The judgement keeps the step test's own rules: a tripped envelope is unstable, whatever swings.
TEST(StepVerdict, ATrippedEnvelopeIsUnstableWithoutALimitCycleReading)
{
    Record r = stageRecord(0.01, 0.5, EndReason::Excursion, hunting(0.01, 0.003, 0.02));
    const StepVerdict v = judgeStep(r, stage());
    EXPECT_EQ(v.metrics.outcome, StepOutcome::Unstable);
    EXPECT_FALSE(v.limitCycle.found);
    EXPECT_EQ(v.metrics.outcome, stepMetrics(r).outcome);
}

// A response that creeps (no oscillation, never inside its 2 % band) did not settle, as the step test says.
TEST(StepVerdict, ACreepIsDidNotSettleAsTheStepTestSays)
{
    const Record r = stageRecord(0.02, 1.0, EndReason::Completed, [](double t) { return 0.02 * (1 - std::exp(-t / 0.5)); });
    const StepVerdict v = judgeStep(r, stage());
    EXPECT_FALSE(v.limitCycle.found);
    EXPECT_EQ(v.metrics.outcome, StepOutcome::DidNotSettle);
    EXPECT_EQ(v.metrics.outcome, stepMetrics(r).outcome);
}

// A model plant has no quantum: a sustained oscillation of a few per cent of the step is a
// cycle, a well-damped response is not.
TEST(StepVerdict, OnAModelTheThresholdIsAShareOfTheStep)
{
    Record sustained;
    sustained.periodS = 1e-3;
    sustained.reason = EndReason::Completed;
    for (int k = 0; k < 4000; ++k) {
        const double t = k * 1e-3;
        sustained.append(1, std::min(1.0, t / 0.1) + 0.02 * std::sin(2 * kPi * t / 0.25), 0);
    }
    const StepVerdict v = judgeStep(sustained, StepJudging{});
    ASSERT_TRUE(v.limitCycle.found);
    EXPECT_NEAR(v.limitCycle.amplitude, 0.02, 0.002);
    EXPECT_NEAR(v.limitCycle.periodS, 0.25, 0.01);
    EXPECT_TRUE(std::isnan(v.insideTargetBandS)) << "no band asked for";

    Record damped = sustained;
    for (std::size_t k = 0; k < damped.size(); ++k)
        damped.measured[k] = 1 - std::exp(-static_cast<double>(k) * 1e-3 / 0.05);
    EXPECT_FALSE(judgeStep(damped, StepJudging{}).limitCycle.found);
}

TEST(StepVerdict, OutcomeNamesGoBothWays)
{
    for (StepOutcome o : {StepOutcome::Settled, StepOutcome::DidNotSettle, StepOutcome::Unstable, StepOutcome::LimitCycle}) {
        StepOutcome back = StepOutcome::Settled;
        ASSERT_TRUE(stepOutcomeFromName(stepOutcomeName(o), &back)) << stepOutcomeName(o);
        EXPECT_EQ(back, o);
    }
    StepOutcome none = StepOutcome::Unstable;
    EXPECT_FALSE(stepOutcomeFromName("calm", &none));
    EXPECT_EQ(none, StepOutcome::Unstable);
}
