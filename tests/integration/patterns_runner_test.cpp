// The pattern runner against the in-process simulator over a real client: approach, streaming
// with flow control, contour from telemetry, pause/resume, abort, refusals before anything
// moves, and a run that survives a pulled cable.
#include "device/client/path_client.h"
#include "device/files/pattern_run_csv.h"
#include "device/jobs/pattern_runner.h"
#include "device/jobs/pattern_telemetry.h"
#include "device/sim/path_queue.h"
#include "motion/plans/pattern.h"
#include "sim_session.h"

#include <QSignalSpy>

#include <gtest/gtest.h>

using itest::SimSession;
using itest::waitFor;
using dev::jobs::PatternRunner;
using motion::plans::Pattern;
using motion::plans::PatternShape;

namespace {

/// A session with the clock sped up over an unpaced link, homed, with the runner fed from the
/// client's own telemetry (the default subscription carries commanded and measured X, Y).
struct RunnerRig {
    SimSession s;
    dev::PathClient& paths = *s.client.paths();
    PatternRunner runner{&s.client};
    std::vector<motion::msg::Message> messages;

    std::string all() const
    {
        std::string out;
        for (const motion::msg::Message& m : messages)
            out += motion::msg::debugString(m) + "\n";
        return out;
    }

    explicit RunnerRig(dev::proto::DeviceKind kind, double timeScale = 8) : s(kind, itest::kUnpaced)
    {
        QObject::connect(&s.client, &dev::BenchPilotClient::telemetryReceived, &runner,
                         [this](const dev::proto::TelemetryBatch& b) { dev::jobs::feedBatch(runner, s.client, b); });
        QObject::connect(&runner, &PatternRunner::message, &runner, [this](const motion::msg::Message& m, bool) { messages.push_back(m); });
        EXPECT_TRUE(s.connect());
        EXPECT_TRUE(s.homeAll());
        s.link.host().setTimeScale(timeScale);
        bool limits = false;
        paths.refreshLimits([&](const auto&) { limits = true; });
        EXPECT_TRUE(waitFor([&] { return limits; }, 3000));
    }
    bool runToEnd(int timeoutMs)
    {
        return waitFor([&] { return !runner.busy(); }, timeoutMs);
    }
};

std::vector<motion::path::Segment> planOf(PatternShape shape, double feed)
{
    Pattern p;
    p.shape = shape;
    p.feedMmS = feed;
    return motion::plans::plan(p);
}

}  // namespace

TEST(PatternsRunner, StageCircleRunsToTheEndWithItsContourMeasured)
{
    RunnerRig rig(dev::proto::DeviceKind::Stage);
    const auto path = planOf(PatternShape::Circle, 2.0);
    for (const motion::msg::Message& problem : rig.runner.preflight(path, {}))
        ADD_FAILURE() << "preflight: " << problem;
    EXPECT_NEAR(rig.runner.estimatedS(path), 31.416 / 2 + 0.02, 0.01);
    QSignalSpy finished(&rig.runner, &PatternRunner::finished);
    ASSERT_TRUE(rig.runner.start(path, {}));
    ASSERT_TRUE(rig.runToEnd(30000)) << rig.all();
    ASSERT_EQ(rig.runner.state(), PatternRunner::State::Done) << rig.all();
    ASSERT_EQ(finished.size(), 1);
    const auto sum = rig.runner.summary();
    EXPECT_TRUE(sum.complete);
    EXPECT_GT(sum.samples, 1000u);           // 100 Hz telemetry over ~16 s of device time
    EXPECT_LT(sum.maxContourMm, 0.002);      // the stage's acceptance figure, from telemetry
    EXPECT_NEAR(sum.durationS, 31.416 / 2, 0.2);
    EXPECT_EQ(sum.underruns, 0);
    EXPECT_EQ(rig.runner.segmentsDone(), 4u);
    // The run exports as CSV, one row per judged sample.
    const std::string csv = dev::files::patternRunCsv(rig.runner.samples());
    EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), static_cast<long>(rig.runner.samples().size()) + 1);
    EXPECT_EQ(csv.rfind("time_s,commanded_x_mm", 0), 0u);
}

TEST(PatternsRunner, ARasterLongerThanTheQueueIsStreamedWithFlowControl)
{
    // Time scale 10: the client's 50 ms status polls are then 0.5 s of device time, inside the
    // device's 1 s host-silence hold.
    RunnerRig rig(dev::proto::DeviceKind::Stage, 10);
    Pattern p;
    p.shape = PatternShape::Raster;
    p.feedMmS = 20;
    p.raster.spacingMm = 1;  // 21 passes, 41 segments: more than the 32 the queue holds
    const auto path = motion::plans::plan(p);
    ASSERT_EQ(path.size(), 41u);
    std::vector<std::size_t> progress;
    QObject::connect(&rig.runner, &PatternRunner::progress, &rig.runner, [&](std::size_t d, std::size_t) { progress.push_back(d); });
    ASSERT_TRUE(rig.runner.start(path, {}));
    ASSERT_TRUE(rig.runToEnd(60000)) << rig.all();
    ASSERT_EQ(rig.runner.state(), PatternRunner::State::Done) << rig.all();
    // Never overrun: no append was refused (the run would have failed), every segment ran once, in
    // order. (Whether the queue also never ran dry depends on how fast this machine runs the
    // sped-up simulator; the device-level test and bench_patterns check that deterministically.)
    EXPECT_EQ(progress.back(), 41u);
    EXPECT_TRUE(std::is_sorted(progress.begin(), progress.end()));
    EXPECT_LT(rig.runner.summary().maxContourMm, 0.005);
}

TEST(PatternsRunner, ARunnerGoneWithItsApproachMoveInFlightIsNeverCalledBack)
{
    // A screen closed right after Run: the device's answer to the move towards the
    // pattern's start must not reach the runner that sent it.
    RunnerRig rig(dev::proto::DeviceKind::Stage);
    {
        PatternRunner gone(&rig.s.client);
        ASSERT_TRUE(gone.start(planOf(PatternShape::Circle, 2.0), {}));
    }
    ASSERT_TRUE(rig.s.waitStill());
    EXPECT_TRUE(rig.s.client.isReady());
}

TEST(PatternsRunner, APatternOutsideTheSoftLimitsIsRefusedBeforeAnythingMoves)
{
    RunnerRig rig(dev::proto::DeviceKind::Stage);
    Pattern p;
    p.shape = PatternShape::Circle;
    p.circle.centerMm = {97, 50};  // radius 5: its second quarter… no, its first reaches x = 102
    const auto path = motion::plans::plan(p);
    const double x0 = rig.s.link.machine().commandedLogical(0);
    EXPECT_FALSE(rig.runner.start(path, {}));
    EXPECT_EQ(rig.runner.state(), PatternRunner::State::Failed);
    ASSERT_FALSE(rig.messages.empty());
    const motion::msg::Message& why = rig.messages.back();
    EXPECT_EQ(why.id, "pattern.segment_above_limit") << rig.all();
    EXPECT_EQ(why.integer("segment", -1), 0) << why;
    EXPECT_EQ(why.text("kind"), "segment.arc_ccw") << why;
    EXPECT_EQ(why.text("axis"), "X") << why;
    EXPECT_NEAR(why.number("value"), 102.0, 1e-6) << why;
    itest::spin(200);
    EXPECT_EQ(rig.s.link.machine().commandedLogical(0), x0);
}

TEST(PatternsRunner, PauseHoldsOnThePathAndResumeFinishes)
{
    RunnerRig rig(dev::proto::DeviceKind::Stage, 4);
    const auto path = planOf(PatternShape::Rectangle, 10);
    ASSERT_TRUE(rig.runner.start(path, {}));
    ASSERT_TRUE(waitFor([&] { return rig.runner.segmentsDone() >= 1; }, 20000));
    rig.runner.pause();
    ASSERT_TRUE(waitFor([&] { return rig.runner.state() == PatternRunner::State::Paused; }, 5000));
    ASSERT_TRUE(waitFor([&] { return !rig.s.link.machine().paths().moving(); }, 5000));
    const double x = rig.s.link.machine().commandedLogical(0);
    itest::spin(300);
    EXPECT_EQ(rig.s.link.machine().commandedLogical(0), x);
    rig.runner.resume();
    ASSERT_TRUE(rig.runToEnd(30000));
    EXPECT_EQ(rig.runner.state(), PatternRunner::State::Done) << rig.all();
    EXPECT_LT(rig.runner.summary().maxContourMm, 0.005);
}

TEST(PatternsRunner, AbortStopsAndForgetsThePath)
{
    RunnerRig rig(dev::proto::DeviceKind::Stage, 4);
    ASSERT_TRUE(rig.runner.start(planOf(PatternShape::Spiral, 4), {}));
    ASSERT_TRUE(waitFor([&] { return rig.runner.state() == PatternRunner::State::Running && rig.runner.segmentsDone() >= 2; }, 20000));
    rig.runner.abort();
    ASSERT_TRUE(rig.runToEnd(5000));
    EXPECT_EQ(rig.runner.state(), PatternRunner::State::Aborted);
    EXPECT_EQ(rig.s.link.machine().paths().state(), dev::proto::PathState::Aborted);
    EXPECT_FALSE(rig.s.link.machine().paths().active());  // the axes are free again
}

TEST(PatternsRunner, APulledCableInterruptsAndResumeContinuesFromTheSegmentReached)
{
    RunnerRig rig(dev::proto::DeviceKind::Stage, 2);
    Pattern p;
    p.shape = PatternShape::Sine;
    p.feedMmS = 4;
    p.wave.toleranceMm = 0.01;
    const auto path = motion::plans::plan(p);
    ASSERT_TRUE(rig.runner.start(path, {}));
    ASSERT_TRUE(waitFor([&] { return rig.runner.segmentsDone() >= 20; }, 30000));
    rig.s.link.pair().unplug();
    ASSERT_TRUE(waitFor([&] { return rig.runner.state() == PatternRunner::State::Interrupted; }, 5000));
    ASSERT_FALSE(rig.messages.empty());
    EXPECT_EQ(rig.messages.back().id, "pattern.run.link_lost") << rig.all();
    // The machine holds the path by itself once it hears nothing for a second.
    ASSERT_TRUE(waitFor([&] { return !rig.s.link.machine().paths().moving(); }, 5000));
    const std::size_t reached = rig.runner.segmentsDone();
    EXPECT_LT(reached, path.size());
    rig.s.link.pair().replug();
    ASSERT_TRUE(rig.s.connect());
    rig.runner.resume();
    ASSERT_TRUE(waitFor([&] { return rig.runner.state() != PatternRunner::State::Interrupted; }, 5000)) << rig.all();
    ASSERT_TRUE(rig.runToEnd(60000)) << rig.all();
    EXPECT_EQ(rig.runner.state(), PatternRunner::State::Done) << rig.all();
    EXPECT_EQ(rig.runner.segmentsDone(), path.size());
    EXPECT_NEAR(rig.s.link.machine().commandedLogical(0), path.back().end.x, 1e-3);
    EXPECT_LT(rig.runner.summary().maxContourMm, 0.005);  // the restart went on along the path
}
