// Straight-line multi-axis synchronisation, and seed 000's contour-error formula (Table 5).
#include "motion/message_print.h"
#include "motion/linear_move.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace motion;

TEST(LinearMove, SeedTable2ParametersPutBothAxesAtTheirLimitsTogether)
{
    // Seed 000 Table 2: x 37.5 mm/s, y 50 mm/s, both 0.1 s acceleration. Along (30, 40) each axis's
    // share gives the same path speed (37.5/0.6 = 50/0.8 = 62.5 mm/s), so both reach their own
    // maximum at the same instant.
    const double target[] = {30, 40};
    const double vMax[] = {37.5, 50};
    const auto move = planLinearSeedSCurve(target, vMax, 0.1, 2);
    ASSERT_TRUE(move) << move.error();
    EXPECT_NEAR(move->path().peakVelocityMmS(), 62.5, 1e-12);
    EXPECT_NEAR(move->duration(), 0.9, 1e-12);
    EXPECT_NEAR(move->axisAt(0, 0.5).v, 37.5, 1e-12);
    EXPECT_NEAR(move->axisAt(1, 0.5).v, 50.0, 1e-12);
    EXPECT_EQ(move->axisAt(0, 0.9).s, 30.0);
    EXPECT_EQ(move->axisAt(1, 0.9).s, 40.0);
}

TEST(LinearMove, SeedTable5ContourErrorIsCrossTrackNotThePrintedFormula)
{
    // Seed 000 Tables 3 and 4 (runs 1–5, targets (30,40) … (120,160)) and Table 5's contour error.
    // Table 5 matches ε = -sinθ·e_x + cosθ·e_y (cross-track) in 19 of 20 cells; the printed
    // ε = cosθ·e_x + sinθ·e_y (along-track) matches none. The 20th cell (run 5, (120,160)):
    // e = (+0.03, +0.04) lies exactly along the line, so its contour error is 0, not -0.010 as
    // printed — a typo in the table.
    const double x[5][4] = {{29.98, 59.98, 89.97, 120.04}, {29.96, 60.00, 89.96, 119.98},
                            {29.97, 60.04, 90.03, 120.05}, {30.04, 59.94, 89.96, 120.05},
                            {29.95, 59.97, 90.01, 120.03}};
    const double y[5][4] = {{39.95, 80.04, 119.97, 159.96}, {40.01, 80.03, 120.00, 159.96},
                            {39.97, 80.00, 119.98, 160.05}, {39.95, 79.98, 120.00, 160.00},
                            {39.97, 80.01, 120.03, 160.04}};
    const double table5[5][4] = {{-0.014, 0.040, 0.006, -0.056}, {0.038, 0.018, 0.032, -0.008},
                                 {0.006, -0.032, -0.036, -0.010}, {-0.062, 0.036, 0.032, -0.040},
                                 {0.022, 0.030, 0.010, -0.010}};
    const double theta = std::atan2(4.0, 3.0);
    int printedMatches = 0;
    for (int run = 0; run < 5; ++run) {
        for (int c = 0; c < 4; ++c) {
            const double ex = x[run][c] - 30.0 * (c + 1), ey = y[run][c] - 40.0 * (c + 1);
            const double eps = contourErrorMm(theta, ex, ey);
            if (run == 4 && c == 3) {
                EXPECT_NEAR(eps, 0.0, 1e-9);
            } else {
                EXPECT_NEAR(eps, table5[run][c], 5e-4) << "run " << run + 1 << " col " << c;
            }
            const double printed = std::cos(theta) * ex + std::sin(theta) * ey;
            if (std::fabs(printed - table5[run][c]) < 5e-4)
                ++printedMatches;
        }
    }
    EXPECT_EQ(printedMatches, 0);
}

TEST(LinearMove, JerkLimitedAxesStayOnTheLineAndRespectTheirOwnLimits)
{
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> d(-200, 200), lim(0.5, 2.0);
    for (int trial = 0; trial < 500; ++trial) {
        const double target[3] = {d(rng), d(rng), trial % 10 == 0 ? 0.0 : d(rng)};
        const JerkLimits limits[3] = {{100 * lim(rng), 1000 * lim(rng), 10000 * lim(rng)},
                                      {100 * lim(rng), 1000 * lim(rng), 10000 * lim(rng)},
                                      {50 * lim(rng), 500 * lim(rng), 5000 * lim(rng)}};
        const auto move = planLinearJerkLimited(target, limits, 3);
        ASSERT_TRUE(move) << move.error();
        const double T = move->duration();
        bool someAxisAtVMax = false;
        for (int k = 0; k <= 200; ++k) {
            const double t = T * k / 200;
            for (int i = 0; i < 3; ++i) {
                const auto s = move->axisAt(i, t);
                ASSERT_LE(std::fabs(s.v), limits[i].vMaxMmS * (1 + 1e-9));
                ASSERT_LE(std::fabs(s.a), limits[i].aMaxMmS2 * (1 + 1e-9));
                ASSERT_LE(std::fabs(s.j), limits[i].jMaxMmS3 * (1 + 1e-9));
                if (std::fabs(std::fabs(s.v) - limits[i].vMaxMmS) < 1e-9 * limits[i].vMaxMmS)
                    someAxisAtVMax = true;
                // On the line: s_i / d_i is the same fraction for all moving axes.
                if (target[i] != 0.0 && target[0] != 0.0) {
                    ASSERT_NEAR(s.s / target[i], move->axisAt(0, t).s / target[0], 1e-9);
                }
            }
        }
        if (move->path().cruiseTimeS() > 0) {
            EXPECT_TRUE(someAxisAtVMax) << "a cruising line move must saturate some axis";
        }
        for (int i = 0; i < 3; ++i) {
            EXPECT_EQ(move->axisAt(i, T).s, target[i]);
        }
    }
}

TEST(LinearMove, ErrorsNameAxisFieldAndValue)
{
    const double target[] = {1, 2};
    const JerkLimits limits[] = {{1, 1, 1}, {1, 0, 1}};
    const auto bad = planLinearJerkLimited(target, limits, 2);
    EXPECT_FALSE(bad);
    EXPECT_EQ(motion::msg::debugString(bad.error()), "profile.axis_not_positive{field=\"aMaxMmS2\", value=0, axis=1}");
    const double nanTarget[] = {1, NAN};
    EXPECT_EQ(motion::msg::debugString(planLinearJerkLimited(nanTarget, limits, 2).error()), "profile.axis_not_finite{field=\"distanceMm\", value=nan, axis=1}");
    EXPECT_EQ(motion::msg::debugString(planLinearJerkLimited(target, limits, 0).error()), "profile.axis_count{count=0, max=6}");
    const double zero[] = {0, 0};
    const JerkLimits good[] = {{1, 1, 1}, {1, 1, 1}};
    const auto none = planLinearJerkLimited(zero, good, 2);
    ASSERT_TRUE(none);
    EXPECT_EQ(none->duration(), 0.0);
}
