// The time-optimal bound: its pieces against hand calculations, and that no
// plan is faster than its bound.
#include "motion/plans/recipes/plan_bound.h"
#include "plates_support.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace motion::plates;
using platestest::context;
using platestest::oneStep;

TEST(PlateBound, JerkOfASeedCurveAxisIsItsSteepestRamp)
{
    // Z: 50 mm/s, 800 mm/s², t2 0.1 s: the curve's steepest is 6·50/0.1² (800·0.1/1.5 = 53 is above 50).
    EXPECT_NEAR(axisJerkLimit(context().deck.z), 30000, 1e-9);
    // X: 1500·0.1/1.5 = 100 = its top speed: 6·100/0.01.
    EXPECT_NEAR(axisJerkLimit(context().deck.x), 60000, 1e-9);
}

TEST(PlateBound, ReachingADistanceFromRest)
{
    const AxisMotion& z = context().deck.z;
    // Within the first jerk ramp (up to a/j = 26.7 ms, 0.095 mm): s = j·t³/6.
    EXPECT_NEAR(reachS(z, 0.05), std::cbrt(6 * 0.05 / 30000), 1e-9);
    // Far: a cruise at 50 mm/s after the push; each extra 50 mm costs exactly 1 s.
    EXPECT_NEAR(reachS(z, 150) - reachS(z, 100), 1.0, 1e-9);
    // Free at the end is quicker than stopping there, and no slower than half of a
    // rest-to-rest move twice as long (the same, once the push reaches the top speed:
    // push, cruise, brake are symmetric; shorter, the brake must first undo the push's jerk).
    for (double d : {0.5, 5.0, 14.22, 40.0}) {
        EXPECT_LT(reachS(z, d), restToRestS(z, d)) << d;
        EXPECT_LE(reachS(z, d), restToRestS(z, 2 * d) / 2 + 1e-9) << d;
    }
    EXPECT_NEAR(reachS(z, 40), restToRestS(z, 80) / 2, 1e-6);
}

TEST(PlateBound, AHopBetweenWellsIsRiseCrossDescend)
{
    const PlanContext c = context();
    const RecipePlan plan = planRecipe(oneStep(StepType::Aspirate, {"A1:A2"}, 10), c);
    ASSERT_TRUE(plan.ok());
    const PlanOp& op = plan.ops[1];
    // An sbs-96 plate's top stands at 75 − 14.22; within it the tip clears it by 5 mm.
    EXPECT_NEAR(op.clearZMm, 75 - 14.22 - 5, 1e-9);
    const double rise = 70 - op.clearZMm;
    const double hop = reachS(c.deck.z, rise) + xyRestToRestS(c.deck.x, c.deck.y, 9, 0) + reachS(c.deck.z, rise);
    const RecipePlan one = planRecipe(oneStep(StepType::Aspirate, {"A1"}, 10), c);
    const double pumpS = op.moves[3].durationS - c.deck.moveOverheadS;
    EXPECT_NEAR(plan.boundS - one.boundS, hop + pumpS, 1e-9);
}

TEST(PlateBound, NoPlanIsFasterThanItsBound)
{
    const PlanContext c = context();
    for (const char* wells : {"A1", "A1:H12", "row B", "H12:A1"}) {
        Recipe r = oneStep(StepType::Mix, {wells}, 20);
        r.steps.push_back(oneStep(StepType::Wash, {}, 100).steps[0]);
        r.steps.back().station = "wash";
        const RecipePlan p = planRecipe(r, c);
        ASSERT_TRUE(p.ok()) << wells;
        double profiles = 0;
        for (const PlanOp& op : p.ops)
            for (const MachineMove& m : op.moves)
                profiles += m.durationS > 0 && m.kind != MoveKind::Dwell ? m.durationS - c.deck.moveOverheadS : m.durationS;
        EXPECT_GT(p.boundS, 0) << wells;
        EXPECT_LT(p.boundS, profiles) << wells;
    }
}

TEST(PlateBound, OrdersCompared)
{
    const auto all = compareOrders(oneStep(StepType::Aspirate, {"A1:H12"}, 10), context());
    ASSERT_EQ(all.size(), static_cast<std::size_t>(kWellOrderCount));
    for (const OrderComparison& c : all) {
        EXPECT_TRUE(c.ok) << wellOrderName(c.order);
        EXPECT_LT(c.boundS, c.totalTimeS) << wellOrderName(c.order);
    }
    // A1:H12 runs row by row and comes back 99 mm each row: the snake does not.
    EXPECT_LT(all[static_cast<int>(WellOrder::SnakeRows)].totalTimeS, all[static_cast<int>(WellOrder::AsWritten)].totalTimeS);
}
