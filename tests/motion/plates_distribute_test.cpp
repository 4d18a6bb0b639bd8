// Distributing: one aspiration for as many wells as the syringe holds with the
// disposal volume and an air gap, the wells dosed in order, the disposal volume
// back; every well gets its volume and the validator follows the plunger.
#include "motion/message_print.h"
#include "plates_support.h"

#include <gtest/gtest.h>

using namespace motion::plates;
using platestest::context;
using platestest::oneStep;
using platestest::problemAt;

namespace {

Recipe fill96(bool distribute)
{
    Recipe r = oneStep(StepType::Dispense, {"all"}, 50);
    r.plates.push_back({"reagents", "2", "sbs-12", 50, 70});
    r.steps[0].plate = "samples";
    r.steps[0].source = {"reagents", "A1", ""};
    r.steps[0].distribute = distribute;
    if (distribute) {
        r.steps[0].disposalUl = 20;
        r.steps[0].airGapUl = 5;
    }
    return r;
}

} // namespace

TEST(PlateDistribute, OneAspirationPerRoundEveryWellItsVolumeAndTheDisposalBack)
{
    const RecipePlan p = planRecipe(fill96(true), context());
    ASSERT_TRUE(p.ok()) << p.problems.front().message;
    // (1000 − 20 − 5) / 50: 19 wells a round, so 96 wells are 6 rounds (5 × 19 + 1).
    int aspirates = 0, gaps = 0, returns = 0;
    for (const PlanOp& op : p.ops) {
        if (op.type == StepType::Aspirate) {
            ++aspirates;
            EXPECT_EQ(op.plate, "reagents");
            EXPECT_DOUBLE_EQ(op.volumeUl, op.round < 6 ? 19 * 50 + 20 : 50 + 20) << "round " << op.round;
        }
        gaps += op.type == StepType::AirGap;
        returns += op.type == StepType::Dispense && op.plate == "reagents";
    }
    EXPECT_EQ(aspirates, 6);
    EXPECT_EQ(gaps, 6);
    EXPECT_EQ(returns, 6) << "each round's disposal volume goes back to the source";
    for (const WellTotal& w : p.wells) {
        if (w.plate == "samples") {
            EXPECT_DOUBLE_EQ(w.dispensedUl, 50) << w.well;
        }
    }
    EXPECT_NEAR(p.pumpEndUl, 0, 1e-9) << "the syringe ends empty: every microlitre drawn went out";
    const WellTotal* src = p.total("reagents", "A1");
    ASSERT_NE(src, nullptr);
    EXPECT_DOUBLE_EQ(src->aspiratedUl - src->dispensedUl, 96 * 50.0);
}

TEST(PlateDistribute, TheSameVolumesAsOneAspirationPerRoundToday)
{
    const RecipePlan today = planRecipe(fill96(false), context());
    const RecipePlan dist = planRecipe(fill96(true), context());
    ASSERT_TRUE(today.ok());
    ASSERT_TRUE(dist.ok());
    for (const WellTotal& w : today.wells)
        if (w.plate == "samples") {
            const WellTotal* d = dist.total(w.plate, w.well);
            ASSERT_NE(d, nullptr) << w.well;
            EXPECT_DOUBLE_EQ(d->dispensedUl, w.dispensedUl) << w.well;
        }
}

TEST(PlateDistribute, WhatCannotFitIsRefusedWhereItIsWritten)
{
    Recipe r = fill96(true);
    r.steps[0].volumeUl = 300;
    r.steps[0].wells = {"A1"};
    r.steps[0].disposalUl = 710;
    RecipePlan p = planRecipe(r, context());
    EXPECT_FALSE(p.ok());
    EXPECT_EQ(problemAt(p, "steps[0].volume_ul").message.id, "recipe.distribute_no_room");

    r = fill96(true);
    r.steps[0].source = {};
    p = planRecipe(r, context());
    EXPECT_EQ(problemAt(p, "steps[0].distribute").message.id, "recipe.distribute_needs_source");

    r = fill96(false);
    r.steps[0].disposalUl = 10;
    p = planRecipe(r, context());
    EXPECT_EQ(problemAt(p, "steps[0].disposal_ul").message.id, "recipe.needs_distribute");

    r = fill96(true);
    r.steps[0].restTo = "sink";
    p = planRecipe(r, context());
    EXPECT_EQ(problemAt(p, "steps[0].rest_to").message.id, "recipe.unknown_station");
}

TEST(PlateDistribute, TheRestMayGoToTheWaste)
{
    Recipe r = fill96(true);
    r.steps[0].restTo = "waste";
    const RecipePlan p = planRecipe(r, context());
    ASSERT_TRUE(p.ok());
    int toWaste = 0;
    for (const PlanOp& op : p.ops)
        toWaste += op.type == StepType::Dispense && op.station == "waste";
    EXPECT_EQ(toWaste, 6);
}
