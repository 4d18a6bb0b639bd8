// Seed 001 step-period tables (72 MHz clock, 50 µs interrupt).
#include "motion/jerk_limited.h"
#include "motion/step_timing.h"
#include "motion/trapezoid.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace motion;

namespace {

/// Absolute edge times (ticks) the firmware would produce from the table: each entry waits
/// wholePeriods interrupts after the previous edge's interrupt and fires at its match tick.
std::vector<std::int64_t> edgesFromTable(const StepTable& table, std::uint32_t firstMatch = 1800)
{
    std::vector<std::int64_t> edges;
    std::int64_t periodIndex = 0;
    std::int64_t origin = firstMatch;
    for (const auto& e : table.entries) {
        periodIndex += e.wholePeriods;
        edges.push_back(periodIndex * table.interruptTicks + e.matchTicks - origin);
    }
    return edges;
}

StepTable constantRateTable(double rateHz, int steps)
{
    std::vector<double> instants;
    for (int k = 1; k <= steps; ++k)
        instants.push_back(k / rateHz);
    return buildStepTable(instants);
}

}  // namespace

TEST(StepTiming, SeedClockGivesThirtySixHundredTicksAnInterrupt)
{
    const auto table = constantRateTable(1000, 3);
    EXPECT_EQ(table.interruptTicks, 3600u);
    // 1 kHz = 72 000 ticks = 20 whole periods; the edge stays at the seed's initial match 1800.
    for (const auto& e : table.entries) {
        EXPECT_EQ(e.periodTicks, 72000u);
        EXPECT_EQ(e.wholePeriods, 20u);
        EXPECT_EQ(e.matchTicks, 1800);
    }
}

TEST(StepTiming, SeedRateLimitsFitTheFirmwareCounters)
{
    // 20 kHz: exactly one step per 50 µs interrupt period.
    const auto fast = constantRateTable(20000, 4);
    EXPECT_EQ(fast.entries[1].periodTicks, 3600u);
    EXPECT_EQ(fast.entries[1].wholePeriods, 1u);
    EXPECT_EQ(fast.clampedCount, 0);
    // 80 Hz: 900 000 ticks = 250 whole periods, inside the seed's INT8U PWMTimers (≤ 255) …
    const auto slow = constantRateTable(80, 4);
    EXPECT_EQ(slow.entries[1].wholePeriods, 250u);
    EXPECT_EQ(slow.clampedCount, 0);
    EXPECT_LE(slow.maxWholePeriods, 255u);
    // … while anything slower is clamped to 80 Hz (78 Hz would need 256 periods and overflow).
    const auto slower = constantRateTable(78, 4);
    EXPECT_EQ(slower.clampedCount, 4);
    EXPECT_EQ(slower.entries[1].periodTicks, 900000u);
    EXPECT_LE(slower.maxWholePeriods, 255u);
    const auto faster = constantRateTable(25000, 4);
    EXPECT_EQ(faster.clampedCount, 4);
    EXPECT_EQ(faster.entries[2].periodTicks, 3600u);
    EXPECT_GT(faster.timeErrorS, 0);  // clamping slows the move, and the report says by how much
    EXPECT_NEAR(faster.timeErrorS, 4 * (1 / 20000.0 - 1 / 25000.0), 1e-12);
}

TEST(StepTiming, ZeroMatchIsMovedOneTickLateAndTakenBackNextStep)
{
    // 5400 ticks (13 333.3 Hz): 1800 + 5400 = 7200 lands on an interrupt boundary, match 0.
    std::vector<double> instants;
    for (int k = 1; k <= 6; ++k)
        instants.push_back(k * 5400 / 72e6);
    const auto table = buildStepTable(instants);
    ASSERT_EQ(table.entries.size(), 6u);
    EXPECT_TRUE(table.entries[0].zeroCorrected);
    EXPECT_EQ(table.entries[0].matchTicks, 1);
    EXPECT_EQ(table.entries[0].wholePeriods, 2u);
    EXPECT_FALSE(table.entries[1].zeroCorrected);
    EXPECT_EQ(table.entries[1].matchTicks, 1800);  // 5400 + 1 - 1: back on the exact grid
    EXPECT_EQ(table.zeroCorrections, 3);
    const auto edges = edgesFromTable(table);
    for (std::size_t k = 0; k < edges.size(); ++k) {
        const std::int64_t ideal = static_cast<std::int64_t>(k + 1) * 5400;
        EXPECT_EQ(edges[k] - ideal, table.entries[k].zeroCorrected ? 1 : 0) << k;
    }
}

TEST(StepTiming, TrapezoidTableReproducesTheProfileToATick)
{
    TrapezoidParams p;
    p.startSpeedMmS = 500;
    p.topSpeedMmS = 15000;
    p.accelMmS2 = 200000;
    p.decelMmS2 = 150000;
    p.plateauMm = 10;
    const auto profile = TrapezoidProfile::plan(5000, p);  // 1 mm = 1 step
    ASSERT_TRUE(profile);
    const auto table = stepTableForProfile(*profile, 1.0);
    ASSERT_EQ(table.entries.size(), 5000u);
    EXPECT_EQ(table.clampedCount, 0);
    EXPECT_LE(std::fabs(table.timeErrorS), 0.5 / 72e6 + 1e-12);  // ticks rounded from absolute times
    const auto edges = edgesFromTable(table);
    const auto instants = stepInstantsS(*profile, 1.0);
    for (std::size_t k = 0; k < edges.size(); ++k)
        ASSERT_LE(std::fabs(edges[k] - instants[k] * 72e6), 1.5) << k;  // rounding + zero-match tick
    // Periods match the ideal step intervals: 1/500 s on the plateau, 1/15000 s at the top.
    EXPECT_EQ(table.entries[3].periodTicks, 144000u);
    EXPECT_EQ(table.entries[2500].periodTicks, 4800u);
}

TEST(StepTiming, RestToRestProfileReportsTheTimeLostToTheMinimumRate)
{
    // A jerk-limited move starts from zero speed: the first steps are slower than 80 Hz and get
    // clamped, which the table reports as a (negative: the table runs them faster) time error.
    const auto profile = JerkLimitedProfile::plan(2.0, {50, 500, 5000});
    ASSERT_TRUE(profile);
    const auto table = stepTableForProfile(*profile, 0.005);  // 400 steps
    ASSERT_EQ(table.entries.size(), 400u);
    EXPECT_GT(table.clampedCount, 0);
    EXPECT_LT(table.timeErrorS, 0);
    EXPECT_NEAR(table.idealDurationS, profile->duration(), 1e-12);
}

TEST(StepTiming, Seed001IterationReachesTopSpeedEarlyAndCostsLittleTime)
{
    // The seed replaces the new period by the previous one in v += a·t and says this makes the
    // speed reach vH early (acceleration) and v0 late (deceleration). Check both claims and the
    // total-time error against the exact profile.
    Seed001Move move;
    move.startRateHz = 400;
    move.topRateHz = 8000;
    move.accelHzS = 40000;
    move.decelHzS = 40000;
    move.plateauSteps = 10;
    move.totalSteps = 4000;
    const auto seed = seed001StepInstantsS(move);
    const auto profile = seed001Profile(move);
    ASSERT_TRUE(profile);
    const auto exact = stepInstantsS(*profile, 1.0);
    ASSERT_EQ(seed.size(), 4000u);
    ASSERT_EQ(exact.size(), 4000u);
    const auto firstAtTop = [](const std::vector<double>& t) {
        for (std::size_t k = 1; k < t.size(); ++k)
            if (t[k] - t[k - 1] <= 1.0 / 8000 + 1e-12)
                return k;
        return t.size();
    };
    EXPECT_LT(firstAtTop(seed), firstAtTop(exact));
    const double relError = (seed.back() - exact.back()) / exact.back();
    EXPECT_LT(std::fabs(relError), 0.05);
    // Late in reaching v0: when the stop plateau starts the seed's speed is still further above v0
    // than the exact profile's (the plateau then snaps it down), i.e. its last deceleration
    // period is shorter than the exact one.
    const std::size_t last = seed.size() - 11;
    EXPECT_LT(seed[last] - seed[last - 1], exact[last] - exact[last - 1]);
    const auto table = buildStepTable(seed);
    EXPECT_EQ(table.entries.size(), 4000u);
    EXPECT_EQ(table.clampedCount, 0);
}
