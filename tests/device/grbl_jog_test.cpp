// Continuous jog on GRBL: the figures that keep both promises (stop within 250 ms of release,
// and within 250 ms of a lost link), and the lines the jog sends.
#include "device/backends/grbl/grbl_gcode.h"
#include "device/backends/grbl/grbl_jog.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using namespace dev::grbl;

TEST(GrblJog, AFastStiffAxisJogsAtFullSpeedWithinBothBudgets)
{
    // The simulated analyzer's X: 100 mm/s, 1500 mm/s²; 15 planner blocks; 10 Hz poll.
    JogPlanInput in;
    in.speedMmS = 100;
    in.maxRateMmS = 100;
    in.accelMmS2 = 1500;
    const JogPlan p = planContinuousJog(in);
    ASSERT_TRUE(p.feasible);
    EXPECT_FALSE(p.speedLimited);
    EXPECT_DOUBLE_EQ(p.speedMmS, 100);
    EXPECT_DOUBLE_EQ(p.feedMmMin, 6000);
    // aheadMin = v/2a + L + C = 0.0333 + 0.02 + 0.1; dt = aheadMin/13 = 11.8 ms.
    EXPECT_NEAR(p.aheadMinS, 0.15333, 1e-4);
    EXPECT_NEAR(p.segmentS, 0.15333 / 13, 1e-6);
    EXPECT_NEAR(p.segmentMm, 100 * 0.15333 / 13, 1e-4);
    EXPECT_LE(p.segmentsAhead, in.plannerBlocks - 1);
    EXPECT_NEAR(p.releaseStopS, 0.02 + 100.0 / 1500, 1e-9);  // 87 ms
    EXPECT_LE(p.releaseStopS, 0.25);
    EXPECT_NEAR(p.lostLinkOverrunS, 0.15333 + p.segmentS + 100.0 / 3000, 1e-4);  // 0.198 s
    EXPECT_LE(p.lostLinkOverrunS, 0.25);
    EXPECT_NEAR(p.lostLinkOverrunMm, 100 * p.aheadMaxS, 1e-9);  // 16.5 mm
}

TEST(GrblJog, ALowAccelerationMachineJogsSlowerToKeepThePromise)
{
    // GRBL's default settings: 10 mm/s² and 500 mm/min. At 8.3 mm/s it would need 0.83 s to stop.
    JogPlanInput in;
    in.speedMmS = 500.0 / 60;
    in.accelMmS2 = 10;
    const JogPlan p = planContinuousJog(in);
    ASSERT_TRUE(p.feasible);
    EXPECT_TRUE(p.speedLimited);
    // v/a + L + C + dt = 0.25, with dt = (v/2a + L + C)/13 (the queue's share of 13 blocks):
    // 0.1·v + 0.12 + (0.05·v + 0.12)/13 = 0.25 → v = 1.163 mm/s.
    const double v = (0.25 - 0.12 - 0.12 / 13) / (0.1 + 0.05 / 13);
    EXPECT_NEAR(p.speedMmS, v, 1e-6);
    EXPECT_NEAR(p.lostLinkOverrunS, 0.25, 1e-6);
    EXPECT_LE(p.releaseStopS, 0.25);
    EXPECT_NEAR(p.segmentS, (v / 20 + 0.12) / 13, 1e-9);
}

TEST(GrblJog, AHostThatRefreshesTooRarelyCannotPromiseTheBudget)
{
    JogPlanInput in;
    in.refreshPeriodS = 0.25;  // 4 Hz poll
    const JogPlan p = planContinuousJog(in);
    EXPECT_FALSE(p.feasible);
    EXPECT_EQ(p.problem.id, "grbl.jog.budget_too_small");
    EXPECT_DOUBLE_EQ(p.problem.number("refresh"), 0.25);
}

TEST(GrblJog, ASmallPlannerStretchesTheSegments)
{
    JogPlanInput in;
    in.speedMmS = 50;
    in.accelMmS2 = 1000;
    in.plannerBlocks = 5;
    const JogPlan p = planContinuousJog(in);
    ASSERT_TRUE(p.feasible);
    EXPECT_LE(p.segmentsAhead, 4);
    EXPECT_GT(p.segmentS, 0.04);
    EXPECT_LE(p.lostLinkOverrunS, 0.25 + 1e-12);
}

TEST(GrblJog, DiagonalLimitsComeFromTheSlowerAxis)
{
    const auto [v, a] = jogLimitsAlong({1, 1}, {100, 50}, {1500, 2000});
    EXPECT_NEAR(v, 50 * std::sqrt(2.0), 1e-9);  // Y's 50 mm/s is its share 1/√2 of the path speed
    EXPECT_NEAR(a, 1500 * std::sqrt(2.0), 1e-9);
    const auto [vx, ax] = jogLimitsAlong({-1, 0}, {100, 50}, {1500, 2000});
    EXPECT_DOUBLE_EQ(vx, 100);
    EXPECT_DOUBLE_EQ(ax, 1500);
}

TEST(GrblJog, TheJogKeepsItsQueueBetweenTheBoundsAndStopsWithJogCancel)
{
    JogPlanInput in;
    in.speedMmS = 100;
    in.maxRateMmS = 100;
    in.accelMmS2 = 1500;
    const JogPlan p = planContinuousJog(in);
    ContinuousJog jog(p, "XY", {0, -2});
    EXPECT_EQ(jog.segmentLine(), "$J=G91 G21 Y-" + formatNumber(p.segmentMm) + " F6000");
    const auto first = jog.start(10.0);
    EXPECT_FALSE(first.empty());
    EXPECT_LE(static_cast<int>(first.size()), p.segmentsAhead);
    // The host ticks at its refresh period; after each tick the queue covers the next period.
    for (double t = 10.0; t < 12.0; t += in.refreshPeriodS) {
        jog.tick(t);
        EXPECT_GE(jog.aheadS(t), p.aheadMinS - 1e-9);
        EXPECT_LE(jog.aheadS(t), p.aheadMaxS + p.speedMmS / (2 * p.accelMmS2) + p.linkLatencyS + 1e-9);
    }
    // Two seconds at 100 mm/s: about 200 mm of segments were sent, not more than the queue's worth beyond.
    EXPECT_NEAR(static_cast<double>(jog.segmentsSent()) * p.segmentMm, 200.0, 100 * p.aheadMaxS);
    EXPECT_EQ(jog.stop(), rt::kJogCancel);
    EXPECT_TRUE(jog.tick(12.1).empty());
    EXPECT_FALSE(jog.active());
}

} // namespace
