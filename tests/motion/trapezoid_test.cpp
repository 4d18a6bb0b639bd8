// Seed 001 trapezoid with plateau steps.
#include "motion/trapezoid.h"

#include <gtest/gtest.h>

#include <cmath>

using motion::TrapezoidParams;
using motion::TrapezoidProfile;

namespace {
// In steps and steps/s (1 mm = 1 step): start 500 Hz, top 5000 Hz, a = d = 50000 steps/s², plateau 20.
TrapezoidParams seedLikeParams()
{
    TrapezoidParams p;
    p.startSpeedMmS = 500;
    p.topSpeedMmS = 5000;
    p.accelMmS2 = 50000;
    p.decelMmS2 = 50000;
    p.plateauMm = 20;
    return p;
}
}  // namespace

TEST(Trapezoid, LongMoveRunsPlateauRampCruiseRampPlateau)
{
    const auto p = TrapezoidProfile::plan(2000, seedLikeParams());
    ASSERT_TRUE(p);
    // nA = nD = (5000² - 500²) / (2·50000) = 247.5 steps.
    EXPECT_NEAR(p->accelLengthMm(), 247.5, 1e-9);
    EXPECT_NEAR(p->decelLengthMm(), 247.5, 1e-9);
    EXPECT_NEAR(p->cruiseLengthMm(), 2000 - 40 - 495, 1e-9);
    EXPECT_EQ(p->reachedTopSpeedMmS(), 5000);
    const double plateauS = 20.0 / 500.0, rampS = 4500.0 / 50000.0;
    EXPECT_NEAR(p->duration(), 2 * plateauS + 2 * rampS + 1465.0 / 5000.0, 1e-12);
    EXPECT_EQ(p->at(0.01).v, 500);                   // start plateau at the start speed
    EXPECT_NEAR(p->at(plateauS + rampS / 2).a, 50000, 1e-9);
    EXPECT_EQ(p->at(p->duration() - 0.01).v, 500);   // stop plateau
    EXPECT_EQ(p->at(p->duration()).s, 2000);
}

TEST(Trapezoid, SeedShortMoveRuleLowersTopSpeedAndKeepsOnePlateauAtTheTop)
{
    // 300 steps: nA + nD + 3P = 495 + 60 > 300 → ramps get 300 - 60 = 240 steps, cruise P = 20.
    TrapezoidParams params = seedLikeParams();
    params.decelMmS2 = 100000;  // unequal ramps: split d:a = 2:1
    const auto p = TrapezoidProfile::plan(300, params);
    ASSERT_TRUE(p);
    EXPECT_NEAR(p->accelLengthMm(), 160, 1e-9);
    EXPECT_NEAR(p->decelLengthMm(), 80, 1e-9);
    EXPECT_NEAR(p->cruiseLengthMm(), 20, 1e-9);
    EXPECT_NEAR(p->reachedTopSpeedMmS(), std::sqrt(500.0 * 500 + 2 * 50000 * 160), 1e-9);
    EXPECT_LT(p->reachedTopSpeedMmS(), 5000);
    EXPECT_NEAR(p->at(p->duration()).s, 300, 0);
    // Both ramps reach the same speed: the cruise joins them without a jump.
    const double cruiseStartS = 20.0 / 500 + (p->reachedTopSpeedMmS() - 500) / 50000;
    const double cruiseS = 20.0 / p->reachedTopSpeedMmS();
    EXPECT_NEAR(p->at(cruiseStartS - 1e-9).v, p->at(cruiseStartS + cruiseS + 1e-9).v, 1e-3);
}

TEST(Trapezoid, SeedRuleThreePlateausCoverTheMoveMeansConstantSpeed)
{
    const auto p = TrapezoidProfile::plan(-60, seedLikeParams());  // 3·20 ≥ 60
    ASSERT_TRUE(p);
    EXPECT_TRUE(p->constantSpeed());
    EXPECT_NEAR(p->duration(), 60.0 / 500.0, 1e-15);
    EXPECT_EQ(p->at(0.05).v, -500);
    EXPECT_EQ(p->at(0.05).a, 0);
    EXPECT_EQ(p->at(1).s, -60);
    const auto q = TrapezoidProfile::plan(61, seedLikeParams());
    ASSERT_TRUE(q);
    EXPECT_FALSE(q->constantSpeed());
}

TEST(Trapezoid, PositionIsContinuousAndVelocityMatchesItsDerivative)
{
    for (double d : {2000.0, 300.0, 100.0, -1234.5}) {
        const auto p = TrapezoidProfile::plan(d, seedLikeParams());
        ASSERT_TRUE(p);
        const double T = p->duration();
        for (int k = 1; k < 1000; ++k) {
            const double t = T * k / 1000, h = 1e-7;
            const double numeric = (p->at(t + h).s - p->at(t - h).s) / (2 * h);
            ASSERT_NEAR(numeric, p->at(t).v, 1e-3 * std::fabs(p->reachedTopSpeedMmS()) + 1e-2) << d << " t=" << t;
        }
    }
}

TEST(Trapezoid, RejectsImpossibleParameters)
{
    TrapezoidParams p = seedLikeParams();
    p.startSpeedMmS = 0;  // a plateau at zero speed would never end
    EXPECT_FALSE(TrapezoidProfile::plan(100, p));
    p.plateauMm = 0;
    EXPECT_TRUE(TrapezoidProfile::plan(100, p));  // plain rest-to-rest trapezoid
    p = seedLikeParams();
    p.startSpeedMmS = 6000;  // above the top speed
    EXPECT_FALSE(TrapezoidProfile::plan(100, p));
    p = seedLikeParams();
    p.accelMmS2 = -1;
    EXPECT_FALSE(TrapezoidProfile::plan(100, p));
}
