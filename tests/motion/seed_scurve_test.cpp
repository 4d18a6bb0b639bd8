// Seed 000 simplified S-curve: eq. 1–3 and the Table 2 XY move.
#include "motion/seed_scurve.h"

#include <gtest/gtest.h>

#include <cmath>

using motion::SeedSCurve;

namespace {

// Seed 000 Table 2: both axes accelerate for 0.1 s; x to 37.5 mm/s, y to 50 mm/s.
constexpr double kSeedAccelTimeS = 0.1;
constexpr double kSeedVMaxXMmS = 37.5;
constexpr double kSeedVMaxYMmS = 50.0;

}  // namespace

TEST(SeedSCurve, Table2MovesOfTheXyTestTakeTheSameTimeOnBothAxes)
{
    // Targets (30,40) … (150,200) along tan θ = 4/3 (§4.1). With the Table 2 parameters both axes
    // finish together — that is how the seed keeps the XY move on its straight line.
    const double expectedS[] = {0.9, 1.7, 2.5, 3.3, 4.1};
    for (int k = 1; k <= 5; ++k) {
        const auto x = SeedSCurve::plan(30.0 * k, kSeedVMaxXMmS, kSeedAccelTimeS);
        const auto y = SeedSCurve::plan(40.0 * k, kSeedVMaxYMmS, kSeedAccelTimeS);
        ASSERT_TRUE(x && y);
        EXPECT_NEAR(x->duration(), expectedS[k - 1], 1e-12);
        EXPECT_NEAR(y->duration(), x->duration(), 1e-12);
        for (double t = 0; t <= x->duration(); t += 0.013) {
            const auto sx = x->at(t), sy = y->at(t);
            EXPECT_NEAR(sy.s * 3.0, sx.s * 4.0, 1e-9) << "off the tan θ = 4/3 line at t=" << t;
        }
    }
}

TEST(SeedSCurve, Table2PeakAccelerationStaysUnderTheTablesMaximum)
{
    // Eq. 1 peaks at A·t2²/4 = 1.5·vMax/t2: 562.5 mm/s² (x) and 750 mm/s² (y). Table 2's "maximum
    // acceleration" column (1500, 2000 mm/s²) equals 4·vMax/t2, which eq. 1 never reaches: the
    // table value is a limit of the machine, not the curve's peak. The curve respects it.
    const auto x = SeedSCurve::plan(30, kSeedVMaxXMmS, kSeedAccelTimeS);
    const auto y = SeedSCurve::plan(40, kSeedVMaxYMmS, kSeedAccelTimeS);
    ASSERT_TRUE(x && y);
    EXPECT_NEAR(x->peakAccelerationMmS2(), 562.5, 1e-9);
    EXPECT_NEAR(y->peakAccelerationMmS2(), 750.0, 1e-9);
    EXPECT_NEAR(x->at(0.05).a, 562.5, 1e-9);
    EXPECT_LE(x->peakAccelerationMmS2(), 1500.0);
    EXPECT_LE(y->peakAccelerationMmS2(), 2000.0);
}

TEST(SeedSCurve, SeedParametersGiveABAndT)
{
    // §2.1: acceleration time, cruise time and acceleration distance fix T, A and B.
    // x axis of Table 2, 30 mm: t2 = 0.1 s, s1 = 37.5·0.1/2 = 1.875 mm, cruise 0.7 s.
    const auto p = SeedSCurve::fromSeedParameters(0.1, 0.7, 1.875);
    ASSERT_TRUE(p);
    EXPECT_NEAR(p->peakVelocityMmS(), 37.5, 1e-12);
    EXPECT_NEAR(p->coefficientA(), 12.0 * 1.875 / 1e-4, 1e-6);  // 225000 mm/s⁴
    EXPECT_NEAR(p->coefficientB(), 22500.0, 1e-8);
    EXPECT_NEAR(p->decelStartS(), 0.8, 1e-12);
    EXPECT_NEAR(p->distance(), 30.0, 1e-12);
    const auto planned = SeedSCurve::plan(30.0, 37.5, 0.1);
    ASSERT_TRUE(planned);
    EXPECT_NEAR(planned->coefficientA(), p->coefficientA(), 1e-6);
    EXPECT_NEAR(planned->accelDistanceMm(), 1.875, 1e-12);
}

TEST(SeedSCurve, Eq1AsPrintedMatchesWithTEqualToDecelStart)
{
    // Eq. 1 (decel branch) is correct once T is read as t3: a = A t² - (2TA+B) t + T²A + TB.
    const auto p = SeedSCurve::plan(30.0, 37.5, 0.1);
    ASSERT_TRUE(p);
    const double A = p->coefficientA(), B = p->coefficientB(), T = p->decelStartS();
    for (double t = T; t <= p->duration(); t += 0.001) {
        const double printed = A * t * t - (2 * T * A + B) * t + T * T * A + T * B;
        EXPECT_NEAR(p->at(t).a, printed, 1e-6) << t;
    }
    for (double t = 0; t <= 0.1; t += 0.001)
        EXPECT_NEAR(p->at(t).a, -A * t * t + B * t, 1e-6) << t;
}

TEST(SeedSCurve, PrintedDecelVelocityIsDiscontinuousCorrectedIsNot)
{
    // Seed 000 eq. 2, t3 ≤ t ≤ t5, as printed:
    //   v = -A/3 t³ - (2TA+B)/2 t² + (T²A - TB) t + v(t2) + c1,
    //   c1 = -(T²A+TB) t2 + (2TA+B)/2 t2² - A/3 t2³.
    // It does not even meet the cruise speed at t3; the derived form does (and integrates eq. 1).
    const auto p = SeedSCurve::plan(30.0, 37.5, 0.1);
    ASSERT_TRUE(p);
    const double A = p->coefficientA(), B = p->coefficientB(), T = p->decelStartS(), t2 = p->accelTimeS();
    const double vt2 = p->peakVelocityMmS();
    const auto printedV = [&](double t) {
        const double c1 = -(T * T * A + T * B) * t2 + (2 * T * A + B) / 2 * t2 * t2 - A / 3 * t2 * t2 * t2;
        return -A / 3 * t * t * t - (2 * T * A + B) / 2 * t * t + (T * T * A - T * B) * t + vt2 + c1;
    };
    EXPECT_GT(std::fabs(printedV(T) - vt2), 1.0) << "printed eq. 2 should jump at t3";
    const auto derivedV = [&](double t) {
        const double c1 = -A * T * T * T / 3 - B * T * T / 2;
        return A / 3 * t * t * t - (2 * T * A + B) / 2 * t * t + (T * T * A + T * B) * t + vt2 + c1;
    };
    for (double t = T; t <= p->duration() + 1e-12; t += 0.001)
        EXPECT_NEAR(p->at(t).v, derivedV(t), 1e-6) << t;
    EXPECT_NEAR(derivedV(T), vt2, 1e-6);
    EXPECT_NEAR(derivedV(p->duration()), 0.0, 1e-6);
}

TEST(SeedSCurve, JoinsAreContinuousAndTheMoveEndsExactlyAtDistance)
{
    for (double d : {30.0, -30.0, 3.75, 1.0, -0.2, 250.0}) {
        const auto p = SeedSCurve::plan(d, 37.5, 0.1);
        ASSERT_TRUE(p);
        const double t2 = p->accelTimeS(), t3 = p->decelStartS();
        for (double join : {t2, t3}) {
            const auto before = p->at(join - 1e-9), after = p->at(join + 1e-9);
            EXPECT_NEAR(before.s, after.s, 1e-7) << d;
            EXPECT_NEAR(before.v, after.v, 1e-5) << d;
            EXPECT_NEAR(before.a, after.a, 1e-3) << d;
        }
        EXPECT_EQ(p->at(p->duration()).s, d);
        EXPECT_EQ(p->at(p->duration() + 5).s, d);
        EXPECT_EQ(p->at(p->duration()).v, 0.0);
        EXPECT_EQ(p->at(-1).s, 0.0);
        // Integrating v numerically reproduces s: the three phases are one consistent move.
        double sIntegrated = 0;
        const int n = 20000;
        const double dt = p->duration() / n;
        for (int i = 0; i < n; ++i)
            sIntegrated += p->at((i + 0.5) * dt).v * dt;
        EXPECT_NEAR(sIntegrated, d, 1e-6 * std::max(1.0, std::fabs(d)));
    }
}

TEST(SeedSCurve, ShortMoveLowersPeakSpeedAndKeepsAccelTime)
{
    const auto p = SeedSCurve::plan(-2.0, 37.5, 0.1);  // ramps at full speed would need 3.75 mm
    ASSERT_TRUE(p);
    EXPECT_NEAR(p->peakVelocityMmS(), 20.0, 1e-12);
    EXPECT_EQ(p->cruiseTimeS(), 0.0);
    EXPECT_NEAR(p->duration(), 0.2, 1e-15);
    EXPECT_NEAR(p->at(0.1).v, -20.0, 1e-9);
    EXPECT_LE(p->at(0.1).s, 0.0);
}

TEST(SeedSCurve, RejectsBadLimits)
{
    EXPECT_FALSE(SeedSCurve::plan(10, 0, 0.1));
    EXPECT_FALSE(SeedSCurve::plan(10, 10, -0.1));
    EXPECT_FALSE(SeedSCurve::plan(NAN, 10, 0.1));
    EXPECT_FALSE(SeedSCurve::plan(10, INFINITY, 0.1));
    const auto zero = SeedSCurve::plan(0, 10, 0.1);
    ASSERT_TRUE(zero);
    EXPECT_EQ(zero->duration(), 0.0);
}
