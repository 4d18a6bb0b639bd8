// Planning a recipe: the moves per well, the syringe's capacity, and every
// error a recipe can have, found in one pass.
#include "motion/message_print.h"
#include "motion/plans/recipes/move_time.h"
#include "motion/seed_scurve.h"
#include "plates_support.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace motion::plates;
using platestest::context;
using platestest::oneStep;
using platestest::problemAt;

namespace {
int countErrors(const RecipePlan& p)
{
    int n = 0;
    for (const auto& x : p.problems)
        n += x.isError();
    return n;
}
} // namespace

TEST(PlateRecipePlan, AWellIsUpAcrossDownPumpUp)
{
    const RecipePlan plan = planRecipe(oneStep(StepType::Aspirate, {"A1:A2"}, 10), context());
    ASSERT_TRUE(plan.ok()) << plan.problems.front().message;
    ASSERT_EQ(plan.ops.size(), 2u);
    const PlanOp& op = plan.ops[1];
    EXPECT_EQ(op.well, "A2");
    ASSERT_EQ(op.moves.size(), 5u);
    EXPECT_EQ(op.moves[0].kind, MoveKind::Raise);
    EXPECT_EQ(op.moves[1].kind, MoveKind::Travel);
    EXPECT_EQ(op.moves[2].kind, MoveKind::Lower);
    EXPECT_EQ(op.moves[3].kind, MoveKind::Pump);
    EXPECT_EQ(op.moves[4].kind, MoveKind::Raise);
    // Slot 1's plate corner sits at (8, 8): A2 is 8 + 14.38 + 9, 8 + 11.24.
    EXPECT_NEAR(op.moves[1].xMm, 31.38, 1e-9);
    EXPECT_NEAR(op.moves[1].yMm, 19.24, 1e-9);
    EXPECT_DOUBLE_EQ(op.moves[2].zMm, 70);
    EXPECT_DOUBLE_EQ(op.moves[4].zMm, 55);
    EXPECT_DOUBLE_EQ(op.moves[3].pumpDeltaUl, 10);
    // The first op lowers from home to the safe height; the second is already there.
    EXPECT_DOUBLE_EQ(op.moves[0].durationS, 0);
    EXPECT_DOUBLE_EQ(plan.ops[0].moves[0].durationS, 0);  // from Z 0 the tip is above the safe height already
    EXPECT_DOUBLE_EQ(plan.pumpEndUl, 20);
}

TEST(PlateRecipePlan, TimesComeFromTheSeedSCurveTheFirmwarePlans)
{
    const PlanContext c = context();
    const RecipePlan plan = planRecipe(oneStep(StepType::Aspirate, {"A1:A2"}, 10), c);
    const PlanOp& op = plan.ops[1];
    // A 9 mm hop along X at the default 50 mm/s with seed 000's 0.1 s ramps.
    const auto xy = motion::SeedSCurve::plan(9.0, 50.0, 0.1);
    EXPECT_NEAR(op.moves[1].durationS, xy->duration() + c.deck.moveOverheadS, 1e-12);
    // 15 mm down at Z's 30 mm/s.
    const auto z = motion::SeedSCurve::plan(15.0, 30.0, 0.1);
    EXPECT_NEAR(op.moves[2].durationS, z->duration() + c.deck.moveOverheadS, 1e-12);
    // 10 µL at the pump's 100 µL/s with its 0.05 s ramps.
    const auto p = motion::SeedSCurve::plan(10.0, 100.0, 0.05);
    EXPECT_NEAR(op.moves[3].durationS, p->duration() + c.deck.moveOverheadS, 1e-12);
    double sum = 0;
    for (const auto& o : plan.ops)
        sum += o.durationS;
    EXPECT_NEAR(plan.totalTimeS, sum, 1e-9);
    EXPECT_NEAR(remainingTimeS(plan, 1), op.durationS, 1e-12);
}

TEST(PlateRecipePlan, ADiagonalIsCappedByTheSlowerAxisAcceleration)
{
    // The firmware stretches the ramp until each axis stays under its own max
    // acceleration: a fast long diagonal needs more than seed 000's 0.1 s.
    const Deck d = platestest::analyzerDeck();
    const double t = moveTimeS({{&d.x, 120}, {&d.y, 90}}, 100);
    const double u = 120.0 / 150.0;
    const double vPath = 100 / u;  // X at its 100 mm/s
    const double aPath = d.x.maxAccel / u;
    const auto expect = motion::SeedSCurve::plan(150, std::min(vPath, 100.0), std::max(0.1, 1.5 * 100.0 / aPath));
    EXPECT_NEAR(t, expect->duration(), 1e-12);
    EXPECT_DOUBLE_EQ(moveTimeS({{&d.x, 0}}, 0), 0);
}

TEST(PlateRecipePlan, UnknownWellOnA96Plate)
{
    Recipe r = oneStep(StepType::Dispense, {"I13"}, 10);
    const RecipePlan plan = planRecipe(r, context());
    EXPECT_FALSE(plan.ok());
    EXPECT_EQ(motion::msg::debugString(problemAt(plan, "steps[0].wells").message), "plate.unknown_well{well=\"\"I13\"\", wells=96}");
}

TEST(PlateRecipePlan, VolumeOverCapacityIsRefused)
{
    const RecipePlan plan = planRecipe(oneStep(StepType::Aspirate, {"A1"}, 1200), context());
    EXPECT_EQ(motion::msg::debugString(problemAt(plan, "steps[0].volume_ul").message),
              "recipe.volume_over_capacity{volume=1200 µL, capacity=1000 µL}");
    // Well by well, the syringe fills: the eleventh 100 µL would not fit.
    Recipe r = oneStep(StepType::Aspirate, {"A1:A11"}, 100);
    r.plates[0].labware = "sbs-48";
    r.plates[0].depthZMm = 60;
    r.steps[0].wells = {"A1:B3"};
    r.steps[0].volumeUl = 200;
    const RecipePlan fill = planRecipe(r, context());
    EXPECT_NE(motion::msg::debugString(problemAt(fill, "steps[0].volume_ul").message).find("volume=1200 µL, capacity=1000 µL"),
              std::string::npos)
        << motion::msg::debugString(problemAt(fill, "steps[0].volume_ul").message);
}

TEST(PlateRecipePlan, NegativeAndZeroVolumesAreRefused)
{
    for (double v : {-5.0, 0.0, std::nan("")}) {
        const RecipePlan plan = planRecipe(oneStep(StepType::Aspirate, {"A1"}, v), context());
        EXPECT_FALSE(plan.ok());
        EXPECT_NE(motion::msg::debugString(problemAt(plan, "steps[0].volume_ul").message).find("plate.not_positive"), std::string::npos) << v;
        EXPECT_TRUE(plan.ops.empty()) << "nothing is planned for a step that cannot run";
    }
}

TEST(PlateRecipePlan, MissingAndUnknownPlates)
{
    Recipe r = oneStep(StepType::Aspirate, {"A1"}, 10);
    r.plates.push_back({"reservoir", "2", "sbs-12", 50, 70});
    RecipePlan plan = planRecipe(r, context());
    EXPECT_EQ(motion::msg::debugString(problemAt(plan, "steps[0].plate").message), "recipe.plate_ambiguous{count=2, plates=\"samples, reservoir\"}");
    r.steps[0].plate = "reagents";
    plan = planRecipe(r, context());
    EXPECT_EQ(motion::msg::debugString(problemAt(plan, "steps[0].plate").message),
              "recipe.unknown_plate{plate=\"reagents\", plates=\"\"samples\", \"reservoir\"\"}");
    r.plates.clear();
    r.steps[0].plate.clear();
    plan = planRecipe(r, context());
    EXPECT_EQ(problemAt(plan, "steps[0].plate").message.id, "recipe.no_plates");
}

TEST(PlateRecipePlan, EveryErrorAtOnce)
{
    Recipe r = oneStep(StepType::Aspirate, {"A1"}, 10);
    r.plates[0].slot = "7";
    r.plates.push_back({"dest", "2", "sbs-97", 50, 70});
    Step s;
    s.type = StepType::Dispense;
    s.plate = "dest";
    s.wells = {"A1"};
    s.volumeUl = -1;
    r.steps.push_back(s);
    Step m;
    m.type = StepType::Mix;
    m.plate = "samples";
    m.wells = {"Z9"};
    m.volumeUl = 20;
    m.cycles = 0;
    r.steps.push_back(m);
    const RecipePlan plan = planRecipe(r, context());
    EXPECT_EQ(motion::msg::debugString(problemAt(plan, "plates[0].slot").message), "recipe.unknown_slot{slot=\"7\", slots=\"1, 2\"}");
    EXPECT_NE(motion::msg::debugString(problemAt(plan, "plates[1].labware").message).find("recipe.unknown_labware{labware=\"sbs-97\""), std::string::npos);
    EXPECT_NE(problemAt(plan, "steps[1].volume_ul").message.id.find("plate.not_positive"), std::string::npos);
    EXPECT_NE(motion::msg::debugString(problemAt(plan, "steps[2].cycles").message).find("min=1, max=100"), std::string::npos);
    EXPECT_GE(countErrors(plan), 4);
}

TEST(PlateRecipePlan, ATransferBiggerThanTheSyringeSplitsIntoRounds)
{
    // 12 wells × 200 µL = 2.4 mL through a 1 mL syringe: rounds of 5, 5 and 2.
    Recipe r = oneStep(StepType::Dispense, {"A1:A12"}, 200);
    r.plates[0].labware = "sbs-96";
    r.steps[0].wells = {"row A"};
    r.steps[0].volumeUl = 200;
    r.plates.push_back({"reservoir", "2", "sbs-12", 50, 70});
    r.steps[0].plate = "samples";
    r.steps[0].source = {"reservoir", "A1", ""};
    const RecipePlan plan = planRecipe(r, context());
    ASSERT_TRUE(plan.ok()) << plan.problems.front().path << ": " << plan.problems.front().message;
    ASSERT_EQ(plan.ops.size(), 15u);  // 3 aspirates + 12 dispenses
    std::vector<double> rounds;
    for (const auto& op : plan.ops)
        if (op.type == StepType::Aspirate)
            rounds.push_back(op.volumeUl);
    EXPECT_EQ(rounds, (std::vector<double>{1000, 1000, 400}));
    EXPECT_EQ(plan.ops[0].well, "A1");
    EXPECT_EQ(plan.ops[0].plate, "reservoir");
    EXPECT_EQ(plan.ops[6].type, StepType::Aspirate);
    EXPECT_EQ(plan.ops[6].round, 2);
    EXPECT_DOUBLE_EQ(plan.pumpEndUl, 0);
    EXPECT_DOUBLE_EQ(plan.totalDispensedUl, 2400);
    ASSERT_TRUE(plan.total("samples", "A7"));
    EXPECT_DOUBLE_EQ(plan.total("samples", "A7")->dispensedUl, 200);
    EXPECT_DOUBLE_EQ(plan.total("reservoir", "A1")->aspiratedUl, 2400);
    // One well more than the syringe: refused, however it is split.
    r.steps[0].volumeUl = 1001;
    EXPECT_EQ(problemAt(planRecipe(r, context()), "steps[0].volume_ul").message.id, "recipe.volume_over_capacity");
}

TEST(PlateRecipePlan, DispensingNeedsLiquidInTheSyringe)
{
    const RecipePlan plan = planRecipe(oneStep(StepType::Dispense, {"A1:A3"}, 10), context());
    EXPECT_NE(motion::msg::debugString(problemAt(plan, "steps[0]").message).find("recipe.dispense_without_liquid{"), std::string::npos);
}

TEST(PlateRecipePlan, AnAirGapLeavesWithTheNextDispense)
{
    Recipe r = oneStep(StepType::Aspirate, {"A1"}, 50);
    Step gap;
    gap.type = StepType::AirGap;
    gap.volumeUl = 5;
    Step d;
    d.type = StepType::Dispense;
    d.wells = {"B1:B2"};
    d.volumeUl = 25;
    r.steps = {r.steps[0], gap, d};
    const RecipePlan plan = planRecipe(r, context());
    ASSERT_TRUE(plan.ok()) << plan.problems.front().message;
    ASSERT_EQ(plan.ops.size(), 4u);
    EXPECT_DOUBLE_EQ(plan.ops[1].pumpNetUl, 5);
    EXPECT_DOUBLE_EQ(plan.ops[2].pumpNetUl, -30);
    EXPECT_DOUBLE_EQ(plan.ops[3].pumpNetUl, -25);
    EXPECT_DOUBLE_EQ(plan.pumpEndUl, 0);
}

TEST(PlateRecipePlan, MixWashWaitAndTouchOff)
{
    Recipe r = oneStep(StepType::Mix, {"C3"}, 100);
    r.steps[0].cycles = 3;
    Step wash;
    wash.type = StepType::Wash;
    wash.station = "wash";
    wash.volumeUl = 200;
    wash.cycles = 2;
    Step wait;
    wait.type = StepType::Wait;
    wait.seconds = 2.5;
    Step touch;
    touch.type = StepType::TouchOff;
    touch.wells = {"C3"};
    touch.offsetMm = 2.5;
    r.steps = {r.steps[0], wash, wait, touch};
    const RecipePlan plan = planRecipe(r, context());
    ASSERT_TRUE(plan.ok()) << plan.problems.front().message;
    ASSERT_EQ(plan.ops.size(), 4u);
    int pumps = 0;
    for (const auto& m : plan.ops[0].moves)
        pumps += m.kind == MoveKind::Pump;
    EXPECT_EQ(pumps, 6);
    EXPECT_DOUBLE_EQ(plan.ops[0].pumpNetUl, 0);
    EXPECT_EQ(plan.ops[1].station, "wash");
    EXPECT_DOUBLE_EQ(plan.ops[1].depthZMm, 65);
    EXPECT_DOUBLE_EQ(plan.ops[2].durationS, 2.5);
    // The touch goes 2.5 mm toward +x and back, at the well's depth.
    const auto& t = plan.ops[3].moves;
    ASSERT_GE(t.size(), 5u);
    EXPECT_EQ(t[3].kind, MoveKind::Touch);
    EXPECT_NEAR(t[3].xMm - t[4].xMm, 2.5, 1e-9);
    // A touch past the wall (a 96 well is 6.86 mm wide) is refused.
    r.steps[3].offsetMm = 4;
    EXPECT_NE(problemAt(planRecipe(r, context()), "steps[3].offset_mm").message.id.find("recipe.offset_past_wall"), std::string::npos);
    // An unknown station.
    r.steps[1].station = "sink";
    EXPECT_EQ(motion::msg::debugString(problemAt(planRecipe(r, context()), "steps[1].station").message),
              "recipe.unknown_station{station=\"sink\", stations=\"wash, waste\"}");
}

TEST(PlateRecipePlan, HeightsAreCheckedAgainstThePlate)
{
    Recipe r = oneStep(StepType::Aspirate, {"A1"}, 10);
    r.plates[0].safeZMm = 62;  // the 96 plate's top is at 75 − 14.22 = 60.78
    EXPECT_NE(problemAt(planRecipe(r, context()), "plates[0].safe_z_mm").message.id.find("recipe.safe_not_above_plate"), std::string::npos);
    r.plates[0].safeZMm = 55;
    r.plates[0].depthZMm = 72;  // the wells' bottoms are at 75 − 3.55 = 71.45
    EXPECT_NE(problemAt(planRecipe(r, context()), "plates[0].depth_z_mm").message.id.find("recipe.depth_below_bottom"),
              std::string::npos);
    r.plates[0].depthZMm = 50;
    EXPECT_NE(problemAt(planRecipe(r, context()), "plates[0].depth_z_mm").message.id.find("recipe.depth_not_below_safe"),
              std::string::npos);
}

TEST(PlateRecipePlan, CalibrationMovesTheWellsButNotTheFingerprint)
{
    const Recipe r = oneStep(StepType::Aspirate, {"A1:H12"}, 5);
    PlanContext c = context();
    const RecipePlan nominal = planRecipe(r, c);
    c.calibration["1"] = PlateTransform::make(9.1, 7.6, 0.4, 1.0002, 1.0002);
    const RecipePlan taught = planRecipe(r, c);
    ASSERT_TRUE(taught.ok());
    EXPECT_EQ(nominal.fingerprint, taught.fingerprint);
    EXPECT_NE(nominal.ops[95].at.x, taught.ops[95].at.x);
    const PointMm want = c.calibration["1"].apply({14.38 + 99, 11.24 + 63});
    EXPECT_NEAR(taught.ops[95].at.x, want.x, 1e-9);
    EXPECT_NEAR(taught.ops[95].at.y, want.y, 1e-9);
    // A different volume is a different run.
    EXPECT_NE(planRecipe(oneStep(StepType::Aspirate, {"A1:H12"}, 6), c).fingerprint, taught.fingerprint);
}

TEST(PlateRecipePlan, AWellOutsideTheTravelIsRefused)
{
    PlanContext c = context();
    c.calibration["1"] = PlateTransform::make(110, 8, 0);  // taught far right: column 12 at X 223
    const RecipePlan plan = planRecipe(oneStep(StepType::Aspirate, {"A1:A12"}, 5), c);
    EXPECT_NE(problemAt(plan, "steps[0].wells").message.id.find("recipe.well_outside_travel"), std::string::npos);
}

TEST(PlateRecipePlan, The96WellSamplingRecipeEndsWithTheSumOfItsVolumes)
{
    const RecipePlan plan = planRecipe(oneStep(StepType::Aspirate, {"A1:H12"}, 10), context());
    ASSERT_TRUE(plan.ok());
    EXPECT_EQ(plan.ops.size(), 96u);
    EXPECT_DOUBLE_EQ(plan.pumpEndUl - plan.pumpStartUl, 960);
    EXPECT_EQ(plan.wells.size(), 96u);
    // About 1.6 s a well on this machine.
    EXPECT_GT(plan.totalTimeS, 96 * 1.2);
    EXPECT_LT(plan.totalTimeS, 96 * 2.2);
}
