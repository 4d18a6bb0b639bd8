// Well orders: each visits the same wells with the same volumes in another
// sequence, deterministically; "shortest" is no slower than any of the others.
#include "motion/plans/recipes/plan_bound.h"
#include "plates_support.h"

#include <gtest/gtest.h>

#include <algorithm>

using namespace motion::plates;
using platestest::context;
using platestest::oneStep;
using platestest::problemAt;

namespace {

std::vector<std::string> wellsOf(const RecipePlan& p)
{
    std::vector<std::string> out;
    for (const PlanOp& op : p.ops)
        if (!op.well.empty())
            out.push_back(op.well);
    return out;
}

RecipePlan planOrdered(std::vector<std::string> wells, WellOrder order, StepType type = StepType::Aspirate)
{
    Recipe r = oneStep(type, std::move(wells), 10);
    r.steps[0].order = order;
    return planRecipe(r, context());
}

/// Every well's totals, sorted: what each well gets, whatever the order.
std::vector<std::tuple<std::string, double, double, int>> totals(const RecipePlan& p)
{
    std::vector<std::tuple<std::string, double, double, int>> out;
    for (const WellTotal& w : p.wells)
        out.emplace_back(w.plate + " " + w.well, w.dispensedUl, w.aspiratedUl, w.visits);
    std::sort(out.begin(), out.end());
    return out;
}

} // namespace

TEST(PlateWellOrder, AsWrittenIsTheDefaultAndKeepsTheWrittenSequence)
{
    const RecipePlan plan = planRecipe(oneStep(StepType::Aspirate, {"B2", "A1", "C3"}, 10), context());
    ASSERT_TRUE(plan.ok());
    EXPECT_EQ(wellsOf(plan), (std::vector<std::string>{"B2", "A1", "C3"}));
    ASSERT_EQ(plan.orders.size(), 1u);
    EXPECT_EQ(plan.orders[0], WellOrder::AsWritten);
}

TEST(PlateWellOrder, ColumnMajorAndTheSnakes)
{
    EXPECT_EQ(wellsOf(planOrdered({"A1:B3"}, WellOrder::ColumnMajor)), (std::vector<std::string>{"A1", "B1", "A2", "B2", "A3", "B3"}));
    EXPECT_EQ(wellsOf(planOrdered({"A1:C3"}, WellOrder::SnakeRows)),
              (std::vector<std::string>{"A1", "A2", "A3", "B3", "B2", "B1", "C1", "C2", "C3"}));
    EXPECT_EQ(wellsOf(planOrdered({"A1:C2"}, WellOrder::SnakeColumns)), (std::vector<std::string>{"A1", "B1", "C1", "C2", "B2", "A2"}));
    // The snake turns on the lines the step uses: rows B and D, D runs backwards.
    EXPECT_EQ(wellsOf(planOrdered({"D1:D2", "B1:B2"}, WellOrder::SnakeRows)), (std::vector<std::string>{"B1", "B2", "D2", "D1"}));
}

TEST(PlateWellOrder, TheRecipesDefaultAppliesToStepsThatNameNone)
{
    Recipe r = oneStep(StepType::Aspirate, {"A1:B2"}, 10);
    r.order = WellOrder::ColumnMajor;
    r.steps.push_back(r.steps[0]);
    r.steps[1].order = WellOrder::AsWritten;
    const RecipePlan plan = planRecipe(r, context());
    ASSERT_TRUE(plan.ok());
    EXPECT_EQ(wellsOf(plan), (std::vector<std::string>{"A1", "B1", "A2", "B2", "A1", "A2", "B1", "B2"}));
    EXPECT_EQ(plan.orders, (std::vector<WellOrder>{WellOrder::ColumnMajor, WellOrder::AsWritten}));
}

TEST(PlateWellOrder, EveryOrderGivesEveryWellTheSameAndShortestIsTheQuickest)
{
    // Written scattered on purpose: as-written zigzags across the plate. Every order
    // starts at A1 here, so the first move from home is the same for all.
    const std::vector<std::string> wells = {"A1", "H12", "D6", "B11", "G2", "A12:A2", "E1:E12", "C3", "F7:F9"};
    const RecipePlan written = planOrdered(wells, WellOrder::AsWritten, StepType::Mix);
    ASSERT_TRUE(written.ok());
    double quickestOther = written.totalTimeS;
    for (WellOrder o : {WellOrder::ColumnMajor, WellOrder::SnakeRows, WellOrder::SnakeColumns, WellOrder::Shortest}) {
        const RecipePlan p = planOrdered(wells, o, StepType::Mix);
        ASSERT_TRUE(p.ok()) << wellOrderName(o);
        EXPECT_EQ(totals(p), totals(written)) << wellOrderName(o) << ": the same wells, the same volumes";
        EXPECT_EQ(p.ops.size(), written.ops.size());
        if (o != WellOrder::Shortest)
            quickestOther = std::min(quickestOther, p.totalTimeS);
    }
    const RecipePlan a = planOrdered(wells, WellOrder::Shortest, StepType::Mix);
    const RecipePlan b = planOrdered(wells, WellOrder::Shortest, StepType::Mix);
    EXPECT_EQ(wellsOf(a), wellsOf(b)) << "deterministic";
    EXPECT_EQ(a.fingerprint, b.fingerprint);
    EXPECT_LE(a.totalTimeS, quickestOther + 1e-9);
    EXPECT_LT(a.totalTimeS, written.totalTimeS * 0.9);
}

TEST(PlateWellOrder, ATransferKeepsItsRoundsAndVolumes)
{
    Recipe r = oneStep(StepType::Dispense, {"A1:H12"}, 150);
    r.steps[0].source.station = "wash";
    const RecipePlan written = planRecipe(r, context());
    r.steps[0].order = WellOrder::Shortest;
    const RecipePlan shortest = planRecipe(r, context());
    ASSERT_TRUE(written.ok());
    ASSERT_TRUE(shortest.ok());
    EXPECT_EQ(totals(shortest), totals(written));
    EXPECT_EQ(shortest.ops.size(), written.ops.size()) << "as many rounds";
    EXPECT_NE(shortest.fingerprint, written.fingerprint) << "a log of one order cannot resume the other";
}

TEST(PlateWellOrder, AStationStepCannotTakeAnOrder)
{
    Recipe r = oneStep(StepType::Aspirate, {}, 10);
    r.steps[0].station = "wash";
    r.steps[0].order = WellOrder::Shortest;
    const RecipePlan plan = planRecipe(r, context());
    EXPECT_FALSE(plan.ok());
    const motion::msg::Problem p = problemAt(plan, "steps[0].order");
    EXPECT_EQ(p.message.id, "recipe.order_without_wells");
    EXPECT_EQ(p.message.text("order"), "shortest");
}

TEST(PlateWellOrder, NamesReadBack)
{
    for (int k = 0; k < kWellOrderCount; ++k)
        EXPECT_EQ(wellOrderFromName(wellOrderName(static_cast<WellOrder>(k))), static_cast<WellOrder>(k));
    EXPECT_FALSE(wellOrderFromName("row-major"));
}
