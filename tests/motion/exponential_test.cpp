// Seed 003 exponential acceleration: the ideal curve and its timer-reload staircase.
#include "motion/exponential.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace motion;

TEST(ExponentialProfile, FollowsTheSeedCurveAndEndsAtDistance)
{
    // f(t) = fm(1 - e^(-t/τ)): fm = 100 mm/s, τ = 0.1 s, ramp 0.3 s reaches 95.02 %.
    const auto p = ExponentialProfile::plan(100, 100, 0.1, 0.3);
    ASSERT_TRUE(p);
    EXPECT_NEAR(p->cruiseSpeedMmS(), 100 * (1 - std::exp(-3.0)), 1e-12);
    EXPECT_NEAR(p->at(0.1).v, 100 * (1 - std::exp(-1.0)), 1e-12);  // 63.2 % after one τ
    EXPECT_NEAR(p->at(0.1).a, 1000 * std::exp(-1.0), 1e-9);
    const double T = p->duration();
    EXPECT_NEAR(p->at(T - 0.1).v, p->at(0.1).v, 1e-9);  // deceleration mirrors acceleration
    EXPECT_NEAR(p->at(T - 0.1).a, -p->at(0.1).a, 1e-9);
    EXPECT_EQ(p->at(T).s, 100);
    double integrated = 0;
    const int n = 20000;
    for (int i = 0; i < n; ++i)
        integrated += p->at((i + 0.5) * T / n).v * T / n;
    EXPECT_NEAR(integrated, 100, 1e-4);
}

TEST(ExponentialProfile, ShortMoveShortensTheRampAndStillLandsExactly)
{
    const auto p = ExponentialProfile::plan(-2, 100, 0.1, 0.3);
    ASSERT_TRUE(p);
    EXPECT_LT(p->accelTimeS(), 0.3);
    EXPECT_EQ(p->cruiseTimeS(), 0);
    const double ta = p->accelTimeS();
    EXPECT_NEAR(100 * (ta - 0.1 * (1 - std::exp(-ta / 0.1))), 1.0, 1e-12);  // each ramp covers half
    EXPECT_NEAR(p->at(ta).s, -1.0, 1e-12);
    EXPECT_EQ(p->at(p->duration()).s, -2);
    EXPECT_FALSE(ExponentialProfile::plan(1, 100, 0, 0.3));
}

TEST(ExponentialStair, TableHasTheSeedsShapeAndLatencyCorrectedReloads)
{
    ExponentialStairConfig c;  // fm 4 kHz, τ 50 ms, 10 stairs, 1 MHz timer, 12 µs latency
    const auto stair = buildExponentialStair(c);
    ASSERT_TRUE(stair);
    ASSERT_EQ(stair->stages.size(), 10u);
    EXPECT_TRUE(stair->stages.back().last);
    EXPECT_EQ(stair->stages.back().steps, 0u);  // seed: 0x00 steps marks the end of acceleration
    EXPECT_GE(stair->stages.front().rateHz, c.startRateHz);
    for (std::size_t i = 0; i < stair->stages.size(); ++i) {
        const auto& st = stair->stages[i];
        if (i > 0) {
            EXPECT_GT(st.rateHz, stair->stages[i - 1].rateHz);
        }
        if (!st.last) {
            EXPECT_GE(st.steps, 1u);
        }
        // Corrected reload + latency gives the intended period; the uncorrected one runs slow.
        EXPECT_NEAR((st.reloadTicks + 12.0) / 1e6, 1.0 / st.rateHz, 0.5e-6);
        EXPECT_EQ(st.reloadValue, 65536u - st.reloadTicks);
        EXPECT_LT(1e6 / (st.periodTicks + 12.0), st.rateHz);
    }
    // Top stair: fm(1 - e^-3) = 3800.9 Hz.
    EXPECT_NEAR(stair->stages.back().rateHz, 4000 * (1 - std::exp(-3.0)), 1e-9);
    // Stairs cover the curve's step count (each rounded to whole steps).
    EXPECT_NEAR(stair->accelSteps, stair->idealAccelSteps, 0.5 * 9 + 1);
    EXPECT_NEAR(stair->timeErrorS, 0, 0.01);
}

TEST(ExponentialStair, MoreStairsFollowTheCurveCloser)
{
    ExponentialStairConfig c;
    double previous = 1e300;
    for (int n : {4, 8, 16, 32}) {
        c.stages = n;
        const auto stair = buildExponentialStair(c);
        ASSERT_TRUE(stair);
        // A stair can be off by at most the curve's rise across one slot (steepest at t = 0).
        const double slotS = c.accelTimeS / (n - 1);
        EXPECT_LE(stair->maxRateErrorHz, c.maxRateHz * slotS / c.timeConstantS + 1.0) << n;
        EXPECT_LT(stair->maxRateErrorHz, previous) << n;
        previous = stair->maxRateErrorHz;
    }
}

TEST(ExponentialStair, DecelerationWalksTheTableBackwards)
{
    ExponentialStairConfig c;
    const auto stair = buildExponentialStair(c);
    ASSERT_TRUE(stair);
    for (std::int64_t total : {5000LL, 101LL, 2LL, 1LL}) {
        const auto periods = stairStepPeriodsS(*stair, c, total);
        ASSERT_EQ(static_cast<std::int64_t>(periods.size()), total);
        for (std::size_t k = 0; k < periods.size(); ++k)
            ASSERT_DOUBLE_EQ(periods[k], periods[periods.size() - 1 - k]) << total << " step " << k;
        for (std::size_t k = 1; k < periods.size() / 2; ++k)
            ASSERT_LE(periods[k], periods[k - 1]);  // never slows down while accelerating
    }
    const auto longMove = stairStepPeriodsS(*stair, c, 5000);
    EXPECT_NEAR(longMove[2500], 1.0 / stair->stages.back().rateHz, 1e-6);
}

TEST(ExponentialStair, RejectsReloadsThatDoNotFitTheTimer)
{
    ExponentialStairConfig c;
    c.maxRateHz = 20;  // the first stair runs at the 10 Hz jump rate: 100 000 ticks at 1 MHz,
    c.startRateHz = 10;  // too long for a 16-bit timer
    EXPECT_FALSE(buildExponentialStair(c));
    c = {};
    c.maxRateHz = 200000;  // 5 ticks, less than the 12-tick latency
    c.startRateHz = 100000;
    EXPECT_FALSE(buildExponentialStair(c));
    c = {};
    c.stages = 1;
    EXPECT_FALSE(buildExponentialStair(c));
}
