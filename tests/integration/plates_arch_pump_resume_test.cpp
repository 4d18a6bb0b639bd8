// A distribute whose dispenses ride their arched moves (the plunger below the rim inside
// the ARCH_MOVE), its runner killed while one well's move is under way and resumed from
// the log: the well is put to the operator as interrupted mid-dispense, with the plunger
// as evidence, and every well is dosed once.
#include "device/english_words.h"
#include "plates_run_support.h"

#include <gtest/gtest.h>

#include <memory>

using namespace itest;
using namespace platestest;
using dev::jobs::InterruptedChoice;
using dev::jobs::InterruptedOp;
using dev::jobs::RecipeRunner;
using dev::jobs::RunState;

namespace {

/// Eight wells of 50 µL at 10 µL/s from a trough, distributed, arched: each dispense
/// takes five seconds inside its arch, time to die in.
motion::plates::Recipe archPumpRecipe()
{
    motion::plates::Recipe r = samplingRecipe("A1:A8", 50, 10.0);
    r.plates.push_back({"reagents", "2", "sbs-12", 50, 70});
    r.steps[0].type = motion::plates::StepType::Dispense;
    r.steps[0].plate = "samples";
    r.steps[0].source = {"reagents", "A1", ""};
    r.steps[0].distribute = true;
    r.steps[0].disposalUl = 10;
    r.travel.mode = motion::plates::TravelMode::Arched;
    return r;
}

} // namespace

TEST(PlateArchPumpResume, KilledMidDispenseInsideTheArchTheOperatorDecidesAndEveryWellIsDosedOnce)
{
    SimSession s{dev::proto::DeviceKind::Analyzer, kUnpaced};
    ASSERT_TRUE(s.connect());
    ASSERT_TRUE(s.homeAll());
    s.link.host().setTimeScale(10);
    QTemporaryDir dir;
    const QString logPath = dir.filePath(QStringLiteral("run.jsonl"));
    const motion::plates::RecipePlan plan = planFor(archPumpRecipe(), s.client);
    ASSERT_TRUE(plan.ok());
    ASSERT_EQ(plan.ops.size(), 10u);  // the aspiration, eight wells, the disposal volume back
    ASSERT_TRUE(plan.ops[3].moves.front().archPump) << "the third well's dispense rides its arch";
    ASSERT_EQ(plan.ops[3].moves.size(), 1u);

    auto first = std::make_unique<RecipeRunner>(&s.client);
    motion::msg::Message error;
    ASSERT_TRUE(first->setPlan(plan, QStringLiteral("arch-pump"), &error));
    ASSERT_TRUE(first->start(logPath, &error)) << error;
    ASSERT_TRUE(waitFor(
        [&] {
            const LogCounts c = countLog(logPath);
            return c.pumps.count(3) && !c.dones.count(3);
        },
        60000));
    first.reset();  // as if the program died: the analyzer finishes the move it had
    ASSERT_TRUE(s.waitStill());
    ASSERT_EQ(readLog(logPath).ops[3].state, dev::files::plates::OpState::Interrupted)
        << "the pump line was written before the arch that runs the plunger was sent";

    RecipeRunner second(&s.client);
    ASSERT_TRUE(second.setPlan(planForResume(archPumpRecipe(), s.client, logPath), QStringLiteral("arch-pump"), &error));
    std::vector<InterruptedOp> asked;
    ASSERT_TRUE(second.resumeFromLog(
                    logPath,
                    [&](const InterruptedOp& op) {
                        asked.push_back(op);
                        return InterruptedChoice::Skip;
                    },
                    &error))
        << error;
    ASSERT_EQ(asked.size(), 1u);
    EXPECT_EQ(asked[0].op, 3);
    EXPECT_EQ(asked[0].evidence.id, "recipe.evidence.moved_in_full") << asked[0].evidence;
    ASSERT_TRUE(waitFor([&] { return second.state() == RunState::Finished; }, 120000));
    ASSERT_TRUE(s.waitStill());
    const LogCounts c = countLog(logPath);
    for (int i = 0; i < 10; ++i)
        EXPECT_EQ(c.dones.count(i) + c.skips.count(i), 1u) << "op " << i;
    EXPECT_NEAR(s.readout('P').commanded, 0, 1e-6) << "410 µL drawn, 8 × 50 µL dosed and 10 µL returned: none twice";
}
