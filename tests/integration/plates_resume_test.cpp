// A run that died (the program killed, the runner gone) continues from its log:
// completed wells are never done again, a well interrupted after its plunger
// move was sent is put to the operator, and a log that does not fit is refused.
#include "device/english_words.h"
#include "plates_run_support.h"

#include "device/protocol/frame_codec.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>

using namespace itest;
using namespace platestest;
using dev::jobs::InterruptedChoice;
using dev::jobs::InterruptedOp;
using dev::jobs::RecipeRunner;
using dev::jobs::RunState;

namespace {

/// 10 µL a well at 5 µL/s: each aspirate takes two seconds, time to die in.
motion::plates::Recipe slowRecipe() { return samplingRecipe("A1:A6", 10, 5.0); }

class PlateResume : public ::testing::Test {
protected:
    void SetUp() override
    {
        ASSERT_TRUE(s.connect());
        ASSERT_TRUE(s.homeAll());
        s.link.host().setTimeScale(5);
        logPath = dir.filePath(QStringLiteral("run.jsonl"));
    }

    /// Starts the slow recipe and kills its runner while the third well's plunger moves.
    void dieMidAspirate()
    {
        auto first = std::make_unique<RecipeRunner>(&s.client);
        motion::msg::Message error;
        ASSERT_TRUE(first->setPlan(planFor(slowRecipe(), s.client), QStringLiteral("slow"), &error));
        ASSERT_TRUE(first->start(logPath, &error)) << error;
        ASSERT_TRUE(waitFor(
            [&] {
                const LogCounts c = countLog(logPath);
                return c.pumps.count(2) && !c.dones.count(2);
            },
            30000));
        first.reset();  // as if the program died: no stop line, the analyzer finishes its move
        ASSERT_TRUE(s.waitStill());
        const auto st = readLog(logPath);
        ASSERT_EQ(st.ops[2].state, dev::files::plates::OpState::Interrupted);
        ASSERT_EQ(st.doneCount(), 2);
    }

    double p() const { return s.readout('P').commanded; }

    SimSession s{dev::proto::DeviceKind::Analyzer, kUnpaced};
    QTemporaryDir dir;
    QString logPath;
};

} // namespace

TEST_F(PlateResume, TheOperatorSkipsAWellInterruptedMidAspirateAndNoWellIsDoneTwice)
{
    dieMidAspirate();
    RecipeRunner second(&s.client);
    motion::msg::Message error;
    ASSERT_TRUE(second.setPlan(planForResume(slowRecipe(), s.client, logPath), QStringLiteral("slow"), &error));
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
    EXPECT_EQ(asked[0].op, 2);
    EXPECT_EQ(i18ntest::english(asked[0].label), "aspirate 10.0 µL from samples A3") << asked[0].label;
    ASSERT_TRUE(asked[0].pumpStartUl);
    EXPECT_DOUBLE_EQ(*asked[0].pumpStartUl, 20);
    // The device finished the move the dead program had sent: the evidence says so.
    EXPECT_EQ(asked[0].evidence.id, "recipe.evidence.moved_in_full") << asked[0].evidence;
    ASSERT_TRUE(waitFor([&] { return second.state() == RunState::Finished; }, 60000));
    ASSERT_TRUE(s.waitStill());
    const LogCounts c = countLog(logPath);
    for (int i = 0; i < 6; ++i) {
        EXPECT_EQ(c.starts.at(i), 1) << "op " << i << " was never begun twice";
        EXPECT_EQ(c.dones.count(i) + c.skips.count(i), 1u) << "op " << i;
    }
    EXPECT_EQ(c.skips.count(2), 1u);
    EXPECT_NEAR(p(), 60, 1e-6) << "six wells of 10 µL, none twice";
}

TEST_F(PlateResume, RedoDoesTheInterruptedWellAgain)
{
    dieMidAspirate();
    RecipeRunner second(&s.client);
    motion::msg::Message error;
    ASSERT_TRUE(second.setPlan(planForResume(slowRecipe(), s.client, logPath), QStringLiteral("slow"), &error));
    ASSERT_TRUE(second.resumeFromLog(logPath, [](const InterruptedOp&) { return InterruptedChoice::Redo; }, &error))
        << error;
    ASSERT_TRUE(waitFor([&] { return second.state() == RunState::Finished; }, 60000));
    ASSERT_TRUE(s.waitStill());
    const LogCounts c = countLog(logPath);
    EXPECT_EQ(c.starts.at(2), 2);
    EXPECT_EQ(c.dones.at(2), 1);
    EXPECT_NEAR(p(), 70, 1e-6) << "the operator chose to draw from A3 again";
}

TEST_F(PlateResume, WithoutADecisionNothingResumesAndTheLogIsUntouched)
{
    dieMidAspirate();
    const LogCounts before = countLog(logPath);
    RecipeRunner second(&s.client);
    motion::msg::Message error;
    ASSERT_TRUE(second.setPlan(planForResume(slowRecipe(), s.client, logPath), QStringLiteral("slow"), &error));
    EXPECT_FALSE(second.resumeFromLog(logPath, {}, &error));
    EXPECT_EQ(error.id, "recipe.run.interrupted_needs_decision") << error;
    EXPECT_EQ(i18ntest::english(motion::msg::nested(error, "op")), "aspirate 10.0 µL from samples A3") << error;
    EXPECT_FALSE(second.resumeFromLog(logPath, [](const InterruptedOp&) { return InterruptedChoice::Cancel; }, &error));
    EXPECT_EQ(second.state(), RunState::Idle);
    const LogCounts after = countLog(logPath);
    EXPECT_EQ(after.resumes, before.resumes);
    EXPECT_EQ(after.starts, before.starts);
}

TEST_F(PlateResume, ALogThatDoesNotFitIsRefused)
{
    motion::msg::Message error;
    {
        RecipeRunner first(&s.client);
        ASSERT_TRUE(first.setPlan(planFor(samplingRecipe("A1:A3"), s.client), QStringLiteral("short"), &error));
        ASSERT_TRUE(first.start(logPath, &error));
        ASSERT_TRUE(waitFor([&] { return first.progress().opsDone >= 1; }, 20000));
        first.abort();
        ASSERT_TRUE(waitFor([&] { return first.state() == RunState::Stopped; }, 10000));
    }
    ASSERT_TRUE(s.waitStill());
    // Another recipe.
    RecipeRunner other(&s.client);
    ASSERT_TRUE(other.setPlan(planFor(samplingRecipe("A1:A3", 12), s.client), QStringLiteral("other"), &error));
    EXPECT_FALSE(other.resumeFromLog(logPath, {}, &error));
    EXPECT_EQ(error.id, "recipe.run.log_of_other_recipe") << error;
    // The right recipe, but someone moved the plunger since.
    RecipeRunner same(&s.client);
    ASSERT_TRUE(same.setPlan(planForResume(samplingRecipe("A1:A3"), s.client, logPath), QStringLiteral("short"), &error));
    ASSERT_FALSE(s.call([&](auto cb) { s.client.move({{3, 5}}, true, 0, cb); }));
    ASSERT_TRUE(s.waitStill());
    EXPECT_FALSE(same.resumeFromLog(logPath, {}, &error));
    EXPECT_EQ(error.id, "recipe.run.plunger_moved") << error;
    // Put back: it resumes.
    ASSERT_FALSE(s.call([&](auto cb) { s.client.move({{3, -5}}, true, 0, cb); }));
    ASSERT_TRUE(s.waitStill());
    ASSERT_TRUE(same.resumeFromLog(logPath, {}, &error)) << error;
    ASSERT_TRUE(waitFor([&] { return same.state() == RunState::Finished; }, 30000));
    // A finished log has nothing left.
    RecipeRunner third(&s.client);
    ASSERT_TRUE(third.setPlan(planForResume(samplingRecipe("A1:A3"), s.client, logPath), QStringLiteral("short"), &error));
    EXPECT_FALSE(third.resumeFromLog(logPath, {}, &error));
    EXPECT_EQ(error.id, "recipe.run.log_finished") << error;
}

/// The analyzer's simulator behind a tap that can drop frames on their way in, homed,
/// its clock at the runs' time scale.
struct TappedAnalyzer {
    dev::LoopbackPair pair{0};
    dev::SimulatorHost host{dev::sim::analyzerConfig(), 0, pair.end(dev::LoopbackPair::B)};
    TapTransport hostEnd{pair.end(dev::LoopbackPair::A)};
    dev::BenchPilotClient client;
    ~TappedAnalyzer() { client.setTransport(nullptr); }
    bool connectAndHome()
    {
        host.start();
        client.setTransport(&hostEnd);
        client.connectLink();
        if (!waitFor([&] { return client.isReady(); }, 5000))
            return false;
        host.setTimeScale(kRunTimeScale);
        client.home(0, [](const auto&) {});
        return waitFor(
            [&] {
                for (const auto& a : client.status().axes)
                    if (!a.homed || a.moving)
                        return false;
                return client.status().axes.size() == 4;
            },
            20000);
    }
};

TEST(PlateRunLink, AMotionDoneLostOnTheLinkIsMadeGoodByTheStatus)
{
    TappedAnalyzer rig;
    ASSERT_TRUE(rig.connectAndHome());
    dev::BenchPilotClient& client = rig.client;
    TapTransport& hostEnd = rig.hostEnd;
    // From now on the first MotionDone of Z never arrives.
    int dropped = 0;
    hostEnd.dropReceived = [&](const dev::proto::Frame& f) {
        if (f.type != static_cast<std::uint8_t>(dev::proto::MsgType::Event) || dropped > 0)
            return false;
        const auto e = dev::proto::decodeEvent(f.payload);
        if (e && e->kind == dev::proto::EventKind::MotionDone && e->axis == 2) {
            ++dropped;
            return true;
        }
        return false;
    };
    RecipeRunner runner(&client);
    std::vector<motion::msg::Message> notes;
    QObject::connect(&runner, &RecipeRunner::message, &runner, [&](const motion::msg::Message& m, bool) { notes.push_back(m); });
    auto allNotes = [&] {
        std::string out;
        for (const motion::msg::Message& m : notes)
            out += motion::msg::debugString(m) + "\n";
        return out;
    };
    QTemporaryDir dir;
    motion::msg::Message error;
    ASSERT_TRUE(runner.setPlan(planFor(samplingRecipe("A1:A2"), client), QStringLiteral("two"), &error));
    ASSERT_TRUE(runner.start(dir.filePath(QStringLiteral("run.jsonl")), &error)) << error;
    ASSERT_TRUE(waitFor([&] { return runner.state() == RunState::Finished || runner.state() == RunState::Stopped; },
                        RecipeRunner::kMoveGraceMs + 20000));
    EXPECT_EQ(dropped, 1);
    EXPECT_EQ(runner.state(), RunState::Finished) << allNotes();
    EXPECT_TRUE(std::any_of(notes.begin(), notes.end(), [](const motion::msg::Message& m) { return m.id == "recipe.run.motion_done_lost"; }))
        << allNotes();
}

// A move that never arrives (here the device stopped it, its Stopped and MotionDone lost on
// the line) stops the run when its budget is spent, and the log says what the device last
// reported: the evidence for a timeout nobody scripted.
TEST(PlateRunLink, AMoveThatNeverArrivesStopsWithTheDevicesLastWordsInTheLog)
{
    TappedAnalyzer rig;
    ASSERT_TRUE(rig.connectAndHome());
    dev::BenchPilotClient& client = rig.client;
    TapTransport& hostEnd = rig.hostEnd;
    bool stopped = false;
    hostEnd.dropReceived = [&](const dev::proto::Frame& f) {
        if (!stopped || f.type != static_cast<std::uint8_t>(dev::proto::MsgType::Event))
            return false;
        const auto e = dev::proto::decodeEvent(f.payload);
        return e && (e->kind == dev::proto::EventKind::MotionDone || e->kind == dev::proto::EventKind::Stopped);
    };
    RecipeRunner runner(&client);
    QObject::connect(&client, &dev::Instrument::statusChanged, &runner, [&](const dev::InstrumentStatus& st) {
        if (!stopped && runner.state() == RunState::Running && st.anyMoving()) {
            stopped = true;
            client.stop(0);
        }
    });
    std::vector<motion::msg::Message> problems;
    QObject::connect(&runner, &RecipeRunner::message, &runner, [&](const motion::msg::Message& m, bool problem) {
        if (problem)
            problems.push_back(m);
    });
    QTemporaryDir dir;
    const QString logPath = dir.filePath(QStringLiteral("run.jsonl"));
    motion::msg::Message error;
    ASSERT_TRUE(runner.setPlan(planFor(samplingRecipe("A1:A2"), client), QStringLiteral("two"), &error));
    ASSERT_TRUE(runner.start(logPath, &error)) << error;
    ASSERT_TRUE(waitFor([&] { return runner.state() == RunState::Finished || runner.state() == RunState::Stopped; },
                        RecipeRunner::kMoveGraceMs + 20000));
    ASSERT_TRUE(stopped);
    EXPECT_EQ(runner.state(), RunState::Stopped);
    ASSERT_EQ(problems.size(), 1u);
    EXPECT_EQ(problems.front().id, "recipe.run.move_timeout");

    QFile f(logPath);
    ASSERT_TRUE(f.open(QIODevice::ReadOnly));
    const QByteArray text = f.readAll();
    const auto state = dev::files::plates::readRunLog(text.toStdString());
    EXPECT_TRUE(state.problems.empty()) << text.toStdString();
    EXPECT_EQ(state.lastStop, "recipe.run.move_timeout");
    const QList<QByteArray> lines = text.trimmed().split('\n');
    const auto last = dev::files::json::parse(lines.back().toStdString());
    ASSERT_TRUE(last);
    const dev::files::json::Value* device = last.value->find("device");
    ASSERT_TRUE(device && device->isObject()) << lines.back().toStdString();
    EXPECT_TRUE(device->find("replied")->asBool());
    EXPECT_GE(device->find("device_s_since_answer")->asNumber(), device->find("budget_s")->asNumber());
    // The device's word against the plan's: the stopped axis short of its target.
    const dev::files::json::Value* expected = device->find("expected");
    const dev::files::json::Value* axes = device->find("axes");
    ASSERT_TRUE(expected && axes && !expected->members().empty());
    bool short_ = false;
    for (const auto& m : expected->members()) {
        const dev::files::json::Value* a = axes->find(m.key);
        ASSERT_TRUE(a) << m.key;
        EXPECT_FALSE(a->find("moving")->asBool());
        short_ = short_ || std::abs(a->find("commanded")->asNumber() - m.value.asNumber()) > 1e-3;
    }
    EXPECT_TRUE(short_) << lines.back().toStdString();
}
