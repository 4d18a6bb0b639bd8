// Recipes run on the simulated analyzer: to the end, paused, aborted, and
// through a pulled cable, each well logged exactly once.
#include "plates_run_support.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace itest;
using namespace platestest;
using dev::jobs::RecipeRunner;
using dev::jobs::RunState;

namespace {

class PlateRun : public ::testing::Test {
protected:
    void SetUp() override
    {
        ASSERT_TRUE(s.connect()) << s.linkErrors.join(QLatin1Char(' ')).toStdString();
        ASSERT_TRUE(s.homeAll());
        s.link.host().setTimeScale(kRunTimeScale);
        logPath = dir.filePath(QStringLiteral("run.jsonl"));
        QObject::connect(&runner, &RecipeRunner::message, &runner, [this](const motion::msg::Message& m, bool problem) {
            (problem ? problems : notes).push_back(m);
        });
    }
    double p() const { return s.readout('P').commanded; }
    double z() const { return s.readout('Z').commanded; }

    SimSession s{dev::proto::DeviceKind::Analyzer, kUnpaced};
    RecipeRunner runner{&s.client};
    QTemporaryDir dir;
    QString logPath;
    std::vector<motion::msg::Message> problems, notes;

    std::string problemText() const
    {
        std::string out;
        for (const motion::msg::Message& m : problems)
            out += motion::msg::debugString(m) + "\n";
        return out;
    }
};

} // namespace

TEST_F(PlateRun, A96WellRecipeRunsToTheEndWithEachWellLoggedOnceAndThePumpAtTheSum)
{
    const motion::plates::RecipePlan plan = planFor(samplingRecipe("A1:H12", 10), s.client);
    ASSERT_TRUE(plan.ok());
    ASSERT_EQ(plan.ops.size(), 96u);
    motion::msg::Message error;
    ASSERT_TRUE(runner.setPlan(plan, QStringLiteral("sampling"), &error)) << error;
    const double p0 = p();
    const quint64 t0 = s.client.status().deviceTimeUs;
    ASSERT_TRUE(runner.start(logPath, &error)) << error;
    int progressSeen = 0;
    double lastEta = 1e9;
    bool etaFell = false;
    QObject::connect(&runner, &RecipeRunner::opFinished, &runner, [&](int) {
        const auto pr = runner.progress();
        ++progressSeen;
        etaFell = etaFell || pr.etaS < lastEta;
        lastEta = pr.etaS;
    });
    ASSERT_TRUE(waitFor([&] { return runner.state() == RunState::Finished || runner.state() == RunState::Stopped; }, 120000));
    ASSERT_EQ(runner.state(), RunState::Finished) << problemText();
    ASSERT_TRUE(s.waitStill());

    // The log has each well exactly once: started once, done once.
    const LogCounts c = countLog(logPath);
    ASSERT_EQ(c.starts.size(), 96u);
    ASSERT_EQ(c.dones.size(), 96u);
    for (int i = 0; i < 96; ++i) {
        EXPECT_EQ(c.starts.at(i), 1) << "op " << i;
        EXPECT_EQ(c.dones.at(i), 1) << "op " << i;
    }
    EXPECT_EQ(c.finished, 1);
    const auto st = readLog(logPath);
    EXPECT_TRUE(st.problems.empty());
    EXPECT_TRUE(st.finished);
    EXPECT_EQ(st.doneCount(), 96);
    std::set<std::string> wells;
    for (const auto& r : st.ops)
        wells.insert(r.well);
    EXPECT_EQ(wells.size(), 96u) << "every well of the plate, each once";

    // Every step moved the plunger the same way: it ends at the sum of the volumes.
    EXPECT_NEAR(p() - p0, 96 * 10.0, 1e-6);
    EXPECT_NEAR(s.readout('P').measured - p0, 960.0, 0.05);
    EXPECT_LE(z(), 55 + 1e-6) << "the tip ends up";

    // Progress and ETA were reported along the way and the ETA came down.
    EXPECT_EQ(progressSeen, 96);
    EXPECT_TRUE(etaFell);
    EXPECT_DOUBLE_EQ(runner.progress().fraction, 1.0);
    // The profiles' time is a floor for the real run; what is above it is the
    // link's turnaround, multiplied here by the sped-up clock.
    const double virtualS = (s.client.status().deviceTimeUs - t0) / 1e6;
    double profileS = 0;
    for (const auto& op : plan.ops)
        for (const auto& m : op.moves)
            profileS += m.durationS > 0 ? m.durationS - dev::files::plates::builtinDeck().moveOverheadS : 0;
    EXPECT_GT(virtualS, profileS * 0.99);
    RecordProperty("planned_s", std::to_string(plan.totalTimeS));
    RecordProperty("virtual_s", std::to_string(virtualS));
    std::printf("96-well run: planned %.1f s (profiles %.1f s), took %.1f s of device time at time scale %g\n", plan.totalTimeS,
                profileS, virtualS, kRunTimeScale);
}

TEST_F(PlateRun, NothingMovesUntilTheRecipeValidatesAndTheMachineIsReady)
{
    motion::plates::Recipe bad = samplingRecipe("I13", 10);
    motion::msg::Message error;
    EXPECT_FALSE(runner.setPlan(planFor(bad, s.client), QStringLiteral("bad"), &error));
    EXPECT_EQ(error.id, "recipe.run.does_not_validate") << error;
    const motion::msg::Message cause = motion::msg::nested(error, "cause");
    EXPECT_EQ(cause.id, "plate.unknown_well") << error;
    EXPECT_EQ(cause.text("well"), "\"I13\"") << error;
    EXPECT_EQ(cause.integer("wells"), 96) << error;
    EXPECT_FALSE(runner.start(logPath, &error));
    // An E-stop latched: refused before anything moves, and no log is made.
    ASSERT_TRUE(runner.setPlan(planFor(samplingRecipe("A1:A3"), s.client), QStringLiteral("ok"), &error));
    ASSERT_FALSE(s.call([&](auto cb) { s.client.estop(cb); }));
    ASSERT_TRUE(waitFor([&] { return s.client.status().estop; }, 2000));
    EXPECT_FALSE(runner.start(logPath, &error));
    EXPECT_EQ(error.id, "recipe.run.estop_latched") << error;
    EXPECT_FALSE(QFileInfo::exists(logPath));
    // A plunger that would pass its end: refused before moving.
    ASSERT_FALSE(s.call([&](auto cb) { s.client.reset(cb); }));
    ASSERT_FALSE(s.call([&](auto cb) { s.client.move({{3, 990}}, false, 0, cb); }));
    ASSERT_TRUE(s.waitStill());
    EXPECT_FALSE(runner.start(logPath, &error));
    EXPECT_EQ(error.id, "recipe.run.plunger_beyond_limits_full") << error;
    EXPECT_FALSE(QFileInfo::exists(logPath));
}

TEST_F(PlateRun, TheTipIsNeverLoweredBeforeItIsOverItsWell)
{
    // The tip starts high (Z 10, above any plate's safe height) over the front
    // slot. The first "raise" of the run must not bring it down to the recipe's
    // safe height there: only the lowering into A1 may go below Z 10.
    ASSERT_FALSE(s.call([&](auto cb) { s.client.move({{0, 60}, {1, 150}, {2, 10}}, false, 0, cb); }));
    ASSERT_TRUE(s.waitStill());
    struct Sent {
        quint8 mask;
        std::vector<double> targets;
    };
    std::vector<Sent> sent;
    s.tap.beforeWrite = [&](const QByteArray& bytes) {
        for (const auto& f : framesIn(bytes))
            if (f.type == static_cast<std::uint8_t>(dev::proto::MsgType::Move))
                if (const auto m = dev::proto::decodeMoveRequest(f.payload)) {
                    Sent x{m->axisMask, {}};
                    for (auto t : m->targets)
                        x.targets.push_back(t / 1e6);
                    sent.push_back(x);
                }
    };
    motion::msg::Message error;
    ASSERT_TRUE(runner.setPlan(planFor(samplingRecipe("A1"), s.client), QStringLiteral("one"), &error));
    ASSERT_TRUE(runner.start(logPath, &error)) << error;
    ASSERT_TRUE(waitFor([&] { return runner.state() == RunState::Finished; }, 20000));
    s.tap.beforeWrite = nullptr;
    const quint8 z = 1u << 2, xy = 0b11;
    bool overWell = false;
    for (const Sent& m : sent) {
        if (m.mask == xy && std::abs(m.targets[0] - 22.38) < 1e-3 && std::abs(m.targets[1] - 19.24) < 1e-3)
            overWell = true;
        if (m.mask == z && m.targets[0] > 10 + 1e-6) {
            EXPECT_TRUE(overWell) << "Z sent to " << m.targets[0] << " before the tip was over A1";
        }
    }
    EXPECT_TRUE(overWell);
}

TEST_F(PlateRun, PauseWaitsForTheWellUnderWayThenResumeFinishes)
{
    motion::msg::Message error;
    ASSERT_TRUE(runner.setPlan(planFor(samplingRecipe("A1:A8"), s.client), QStringLiteral("row"), &error));
    ASSERT_TRUE(runner.start(logPath, &error)) << error;
    ASSERT_TRUE(waitFor([&] { return runner.progress().opsDone >= 2 && runner.state() == RunState::Running; }, 20000));
    runner.pause();
    EXPECT_EQ(runner.state(), RunState::Pausing);
    ASSERT_TRUE(waitSettled(runner, 20000));
    ASSERT_EQ(runner.state(), RunState::Paused) << problemText();
    const int doneAtPause = runner.progress().opsDone;
    ASSERT_TRUE(s.waitStill());
    EXPECT_LE(z(), 55 + 1e-6) << "paused with the tip up";
    spin(300);
    EXPECT_EQ(runner.progress().opsDone, doneAtPause) << "nothing runs while paused";
    ASSERT_TRUE(runner.resume({}, &error)) << error;
    ASSERT_TRUE(waitFor([&] { return runner.state() == RunState::Finished; }, 30000)) << problemText();
    ASSERT_TRUE(s.waitStill());
    const LogCounts c = countLog(logPath);
    for (int i = 0; i < 8; ++i) {
        EXPECT_EQ(c.starts.at(i), 1);
        EXPECT_EQ(c.dones.at(i), 1);
    }
    EXPECT_NEAR(p(), 80, 1e-6);
}

// Paused after a well, nothing is under way: the well done is done, the next is "next",
// not "current". And the pause is not running time: the ETA on Resume is the ETA paused
// (it jumped from 2:42 to 4:28 when the pace was judged afresh from nothing).
TEST_F(PlateRun, PausedNothingIsCurrentAndResumeKeepsTheEta)
{
    motion::msg::Message error;
    ASSERT_TRUE(runner.setPlan(planFor(samplingRecipe("A1:A12"), s.client), QStringLiteral("row"), &error));
    ASSERT_TRUE(runner.start(logPath, &error)) << error;
    // Enough done for the pace to count (the runner judges it after 2 s of planned time).
    const double total = runner.plan().totalTimeS;
    ASSERT_TRUE(waitFor([&] { return runner.progress().fraction * total > 3 && runner.state() == RunState::Running; }, 20000));
    runner.pause();
    ASSERT_TRUE(waitSettled(runner, 20000));
    ASSERT_EQ(runner.state(), RunState::Paused) << problemText();
    const dev::jobs::RunProgress paused = runner.progress();
    ASSERT_LT(paused.opsDone, paused.opsTotal);
    EXPECT_EQ(paused.currentOp, -1) << "paused between wells, op " << paused.currentOp << " is shown as under way";
    EXPECT_EQ(paused.nextOp, paused.opsDone) << "the op Resume begins with";
    EXPECT_EQ(motion::msg::debugString(paused.nextLabel), motion::msg::debugString(runner.plan().ops[static_cast<std::size_t>(paused.opsDone)].label()));
    double remainingPlannedS = 0;
    for (int i = paused.opsDone; i < paused.opsTotal; ++i)
        remainingPlannedS += runner.plan().ops[static_cast<std::size_t>(i)].durationS;
    // The simulator runs faster than planned (its clock is sped up): the ETA says so.
    ASSERT_LT(paused.etaS, 0.9 * remainingPlannedS) << "the run's pace is not what this test is about";
    spin(300);  // a pause of any length
    EXPECT_DOUBLE_EQ(runner.progress().etaS, paused.etaS) << "the ETA moves while nothing runs";
    ASSERT_TRUE(runner.resume({}, &error)) << error;
    const dev::jobs::RunProgress resumed = runner.progress();
    EXPECT_NEAR(resumed.etaS, paused.etaS, 0.05 * paused.etaS) << "the ETA jumped on Resume";
    EXPECT_EQ(resumed.nextOp, -1);
    ASSERT_TRUE(waitFor([&] { return runner.state() == RunState::Finished; }, 30000)) << problemText();
}

TEST_F(PlateRun, AbortStopsAtOnceThenLiftsTheTipAndTheLogResumes)
{
    motion::msg::Message error;
    const motion::plates::RecipePlan plan = planFor(samplingRecipe("A1:A6"), s.client);
    ASSERT_TRUE(runner.setPlan(plan, QStringLiteral("row"), &error));
    s.link.host().setTimeScale(1);  // so the status shows the tip going down
    ASSERT_TRUE(runner.start(logPath, &error));
    // Abort while the tip goes down into the third well.
    ASSERT_TRUE(waitFor([&] { return runner.progress().opsDone == 2 && s.readout('Z').moving && z() > 60; }, 20000));
    runner.abort();
    EXPECT_EQ(runner.state(), RunState::Aborting);
    ASSERT_TRUE(waitFor([&] { return runner.state() == RunState::Stopped; }, 10000));
    ASSERT_TRUE(s.waitStill());
    EXPECT_LE(z(), 55 + 1e-6) << "Z went up to the safe height once everything was still";
    EXPECT_GE(s.countEvents(dev::proto::EventKind::Stopped, s.axis('Z')), 1) << "the move was stopped, not finished";
    const auto st = readLog(logPath);
    EXPECT_EQ(st.lastStop, "recipe.run.aborted");
    EXPECT_EQ(st.doneCount(), 2);
    EXPECT_EQ(st.ops[2].state, dev::files::plates::OpState::Started) << "no liquid had moved in the third well";
    s.link.host().setTimeScale(kRunTimeScale);

    // A later run continues from the log: the third well begins again, the first two are not touched.
    RecipeRunner again(&s.client);
    ASSERT_TRUE(again.setPlan(planForResume(samplingRecipe("A1:A6"), s.client, logPath), QStringLiteral("row"), &error));
    bool asked = false;
    ASSERT_TRUE(again.resumeFromLog(logPath, [&](const dev::jobs::InterruptedOp&) { asked = true; return dev::jobs::InterruptedChoice::Skip; }, &error))
        << error;
    EXPECT_FALSE(asked) << "nothing to ask: no liquid had moved";
    ASSERT_TRUE(waitFor([&] { return again.state() == RunState::Finished; }, 30000));
    ASSERT_TRUE(s.waitStill());
    const LogCounts c = countLog(logPath);
    EXPECT_EQ(c.starts.at(0), 1);
    EXPECT_EQ(c.starts.at(1), 1);
    EXPECT_EQ(c.starts.at(2), 2) << "begun again";
    for (int i = 0; i < 6; ++i)
        EXPECT_EQ(c.dones.at(i), 1) << "op " << i;
    EXPECT_NEAR(p(), 60, 1e-6);
}

TEST_F(PlateRun, APulledCableStopsTheRunWhichResumesAfterReconnecting)
{
    motion::msg::Message error;
    ASSERT_TRUE(runner.setPlan(planFor(samplingRecipe("A1:A8"), s.client), QStringLiteral("row"), &error));
    ASSERT_TRUE(runner.start(logPath, &error));
    ASSERT_TRUE(waitFor([&] { return runner.progress().opsDone >= 3; }, 20000));
    s.link.pair().unplug();
    ASSERT_TRUE(waitFor([&] { return runner.state() == RunState::Stopped; }, 5000));
    ASSERT_FALSE(problems.empty());
    EXPECT_EQ(problems.back().id, "recipe.run.link_lost") << problemText();
    EXPECT_FALSE(runner.resume({}, &error)) << "not while the link is down";
    spin(500);  // the analyzer finishes the move it had
    s.link.pair().replug();
    ASSERT_TRUE(s.connect());
    ASSERT_TRUE(s.waitStill());
    dev::jobs::InterruptedOp seen;
    bool asked = false;
    ASSERT_TRUE(runner.resume(
                    [&](const dev::jobs::InterruptedOp& op) {
                        // As an operator would: the evidence says whether the
                        // plunger move left before the cable went.
                        asked = true;
                        seen = op;
                        return op.evidence.id == "recipe.evidence.nothing_moved" ? dev::jobs::InterruptedChoice::Redo
                                                                                        : dev::jobs::InterruptedChoice::Skip;
                    },
                    &error))
        << error;
    ASSERT_TRUE(waitFor([&] { return runner.state() == RunState::Finished; }, 30000)) << problemText();
    ASSERT_TRUE(s.waitStill());
    const LogCounts c = countLog(logPath);
    for (int i = 0; i < 8; ++i)
        EXPECT_EQ(c.dones.count(i) + c.skips.count(i), 1u) << "op " << i << " closed exactly once";
    EXPECT_EQ(c.stops, 1);
    EXPECT_EQ(c.resumes, 1);
    // Whether the cable went mid-aspirate or not, the plunger holds 10 µL per well.
    EXPECT_NEAR(p(), 80, 1e-6) << (asked ? motion::msg::debugString(seen.evidence) : std::string("no op was mid-aspirate"));
}
