// Time-optimal jerk-limited rest-to-rest profile.
#include "motion/jerk_limited.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <type_traits>

using motion::JerkLimitedProfile;
using motion::JerkLimits;

namespace {

/// Checks limits, continuity and end conditions by dense sampling; returns the largest |v| seen.
void expectFeasible(const JerkLimitedProfile& p, const JerkLimits& lim, double distanceMm)
{
    const double tol = 1e-9;
    const int n = 400;
    const double T = p.duration();
    motion::ProfileSample prev = p.at(0);
    for (int i = 1; i <= n; ++i) {
        const auto s = p.at(T * i / n);
        ASSERT_LE(std::fabs(s.v), lim.vMaxMmS * (1 + tol)) << "t=" << s.t;
        ASSERT_LE(std::fabs(s.a), lim.aMaxMmS2 * (1 + tol)) << "t=" << s.t;
        ASSERT_LE(std::fabs(s.j), lim.jMaxMmS3 * (1 + tol)) << "t=" << s.t;
        // Velocity and acceleration never jump: a step change over T/n is bounded by the limits.
        const double dt = s.t - prev.t;
        ASSERT_LE(std::fabs(s.v - prev.v), lim.aMaxMmS2 * dt * (1 + 1e-6) + 1e-9);
        ASSERT_LE(std::fabs(s.a - prev.a), lim.jMaxMmS3 * dt * (1 + 1e-6) + 1e-9);
        // Never goes backwards.
        ASSERT_GE((s.s - prev.s) * (distanceMm < 0 ? -1 : 1), -1e-12 * std::max(1.0, std::fabs(distanceMm)));
        prev = s;
    }
    EXPECT_EQ(p.at(T).s, distanceMm);
    EXPECT_EQ(p.at(T).v, 0.0);
    EXPECT_EQ(p.at(T + 1).s, distanceMm);
}

}  // namespace

TEST(JerkLimited, ReachesAllLimitsOnALongMove)
{
    // v 100, a 1000, j 10000: Tj = 0.1 s, Ta = 0, ramp distance 100·0.2 = 20 mm.
    const JerkLimits lim{100, 1000, 10000};
    const auto p = JerkLimitedProfile::plan(120, lim);
    ASSERT_TRUE(p);
    EXPECT_NEAR(p->jerkTimeS(), 0.1, 1e-12);
    EXPECT_NEAR(p->constAccelTimeS(), 0.0, 1e-12);
    EXPECT_NEAR(p->cruiseTimeS(), 1.0, 1e-12);
    EXPECT_NEAR(p->duration(), 1.4, 1e-12);
    EXPECT_NEAR(p->at(0.7).v, 100, 1e-9);
    expectFeasible(*p, lim, 120);

    const JerkLimits lim2{200, 1000, 10000};  // Tj = 0.1, Ta = 0.1, ramps 200·0.3 = 60 mm
    const auto q = JerkLimitedProfile::plan(-100, lim2);
    ASSERT_TRUE(q);
    EXPECT_NEAR(q->constAccelTimeS(), 0.1, 1e-12);
    EXPECT_NEAR(q->cruiseTimeS(), 0.2, 1e-12);
    EXPECT_NEAR(q->duration(), 0.8, 1e-12);
    EXPECT_NEAR(q->at(0.4).v, -200, 1e-9);
    EXPECT_NEAR(q->at(0.15).a, -1000, 1e-9);
    expectFeasible(*q, lim2, -100);
}

TEST(JerkLimited, AccelerationLimitedShortMove)
{
    // vMax not reached, aMax reached: D = A(Ta+Tj)(Ta+2Tj) with Tj = 0.1; pick Ta = 0.05:
    // D = 1000·0.15·0.25 = 37.5 mm.
    const JerkLimits lim{1000, 1000, 10000};
    const auto p = JerkLimitedProfile::plan(37.5, lim);
    ASSERT_TRUE(p);
    EXPECT_NEAR(p->jerkTimeS(), 0.1, 1e-12);
    EXPECT_NEAR(p->constAccelTimeS(), 0.05, 1e-12);
    EXPECT_EQ(p->cruiseTimeS(), 0.0);
    EXPECT_NEAR(p->peakVelocityMmS(), 150, 1e-9);
    expectFeasible(*p, lim, 37.5);
}

TEST(JerkLimited, JerkLimitedTinyMove)
{
    // Neither limit reached: D = 2 J Tj³ → Tj = ∛(0.002/20000) = 0.0464 s.
    const JerkLimits lim{100, 1000, 10000};
    const auto p = JerkLimitedProfile::plan(0.002 * 1000, lim);
    ASSERT_TRUE(p);
    EXPECT_NEAR(p->jerkTimeS(), std::cbrt(2.0 / 20000.0), 1e-15);
    EXPECT_EQ(p->constAccelTimeS(), 0.0);
    EXPECT_LT(p->peakAccelerationMmS2(), 1000);
    expectFeasible(*p, lim, 2.0);
}

TEST(JerkLimited, VelocityLimitBeforeAccelerationLimit)
{
    // v·J < a²: aMax can never be reached; ramp is a jerk triangle of Tj = √(v/J) = 0.01 s.
    const JerkLimits lim{1, 1000, 10000};
    const auto p = JerkLimitedProfile::plan(5, lim);
    ASSERT_TRUE(p);
    EXPECT_NEAR(p->jerkTimeS(), 0.01, 1e-12);
    EXPECT_NEAR(p->peakAccelerationMmS2(), 100, 1e-9);
    EXPECT_NEAR(p->cruiseTimeS(), (5 - 0.02) / 1.0, 1e-12);
    expectFeasible(*p, lim, 5);
}

TEST(JerkLimited, ZeroDistanceTakesNoTimeAndBadLimitsAreRejected)
{
    const auto p = JerkLimitedProfile::plan(0, {1, 1, 1});
    ASSERT_TRUE(p);
    EXPECT_EQ(p->duration(), 0.0);
    EXPECT_EQ(p->at(0.5).s, 0.0);
    EXPECT_FALSE(JerkLimitedProfile::plan(1, {0, 1, 1}));
    EXPECT_FALSE(JerkLimitedProfile::plan(1, {1, -1, 1}));
    EXPECT_FALSE(JerkLimitedProfile::plan(1, {1, 1, NAN}));
    EXPECT_FALSE(JerkLimitedProfile::plan(INFINITY, {1, 1, 1}));
    const auto problem = motion::validateJerkLimits({1, -3, 1}, 1);
    ASSERT_TRUE(problem);
    EXPECT_EQ(motion::msg::debugString(*problem), "profile.axis_not_positive{field=\"aMaxMmS2\", value=-3, axis=1}");
    EXPECT_FALSE(motion::validateJerkLimits({1, 2, 3}));
}

TEST(JerkLimited, PropertyRandomMovesAreFeasibleAndTimeOptimal)
{
    std::mt19937_64 rng(20240603);
    std::uniform_real_distribution<double> logU(-3, 3);
    for (int i = 0; i < 3000; ++i) {
        const JerkLimits lim{std::pow(10, logU(rng)), std::pow(10, logU(rng) + 1), std::pow(10, logU(rng) + 3)};
        const double d = std::pow(10, logU(rng)) * (rng() % 2 ? 1 : -1);
        const auto p = JerkLimitedProfile::plan(d, lim);
        ASSERT_TRUE(p);
        expectFeasible(*p, lim, d);
        // Bang-bang optimality: a segment only exists when the limit it rides on is reached.
        if (p->cruiseTimeS() > 0) {
            EXPECT_NEAR(p->peakVelocityMmS(), lim.vMaxMmS, 1e-9 * lim.vMaxMmS);
        }
        if (p->constAccelTimeS() > 0) {
            EXPECT_NEAR(p->peakAccelerationMmS2(), lim.aMaxMmS2, 1e-9 * lim.aMaxMmS2);
        }
        EXPECT_EQ(p->jerkMmS3(), lim.jMaxMmS3);
        // Time-optimality: no shorter move covers d. The jerk-limited profile's reach in time T is
        // increasing in T, so planning a little further must take longer, and looser limits never slower.
        const auto longer = JerkLimitedProfile::plan(d * (1 + 1e-6), lim);
        EXPECT_GE(longer->duration(), p->duration());
        const auto looser = JerkLimitedProfile::plan(d, {lim.vMaxMmS * 1.1, lim.aMaxMmS2 * 1.1, lim.jMaxMmS3 * 1.1});
        EXPECT_LE(looser->duration(), p->duration() * (1 + 1e-12));
    }
}

TEST(JerkLimited, CheapToCopy)
{
    // Profiles are passed by value in the simulator's realtime loop: no heap, a few doubles.
    static_assert(std::is_nothrow_copy_constructible_v<JerkLimitedProfile>);
    static_assert(sizeof(JerkLimitedProfile) <= 64);
    const auto p = JerkLimitedProfile::plan(10, {10, 100, 1000});
    const JerkLimitedProfile copy = *p;
    EXPECT_EQ(copy.at(0.3).s, p->at(0.3).s);
}
