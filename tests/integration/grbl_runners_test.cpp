// The runners do not know which backend they drive: the pattern, scan and recipe runners'
// main cases, run over the GRBL backend on the simulator's GRBL personality. The 10 mm circle is
// streamed without ever overflowing GRBL's 127-byte receive buffer (the simulator's own
// accounting), a raster longer than the path window runs with flow control, a scan triggers a
// grblHAL digital output once per tile, and a recipe moves the plunger on GRBL's A axis.
#include "device/client/joystick_driver.h"
#include "device/jobs/pattern_runner.h"
#include "device/jobs/pattern_telemetry.h"
#include "device/jobs/scan_runner.h"
#include "grbl_session.h"
#include "motion/plans/pattern.h"
#include "plates_run_support.h"

#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <algorithm>

#include <cmath>

using itest::GrblSession;
using itest::GrblSessionOptions;
using itest::waitFor;

namespace {

/// The runner fed from the client's own telemetry (status reports), as the CLI does.
struct PatternRig {
    GrblSession s;
    dev::jobs::PatternRunner runner{&s.client};
    std::vector<motion::msg::Message> messages;

    std::string all() const
    {
        std::string out;
        for (const motion::msg::Message& m : messages)
            out += motion::msg::debugString(m) + "\n";
        return out;
    }

    explicit PatternRig(const GrblSessionOptions& o) : s(o)
    {
        QObject::connect(&s.client, &dev::Instrument::telemetryReceived, &runner,
                         [this](const dev::proto::TelemetryBatch& b) { dev::jobs::feedBatch(runner, s.client, b); });
        QObject::connect(&runner, &dev::jobs::PatternRunner::message, &runner, [this](const motion::msg::Message& m, bool) { messages.push_back(m); });
    }
    bool ready()
    {
        if (!s.connect() || !s.homeAll())
            return false;
        bool subscribed = false;
        s.client.subscribe(dev::jobs::patternChannels(), 250, [&](const auto& e, const auto&) { subscribed = !e; });
        return subscribed;
    }
};

std::vector<motion::path::Segment> planOf(const motion::plans::Pattern& p) { return motion::plans::plan(p); }

} // namespace

TEST(GrblRunners, TheTenMillimetreCircleRunsWithoutOverflowingTheReceiveBuffer)
{
    for (const bool hal : {false, true}) {
        GrblSessionOptions o;
        o.grblHal = hal;
        PatternRig r(o);
        ASSERT_TRUE(r.ready()) << r.s.linkErrors.join(QLatin1Char(';')).toStdString();
        EXPECT_EQ(r.s.client.subscribedRateHz(), 10);  // the contour is sampled at the status poll rate
        motion::plans::Pattern p;
        p.shape = motion::plans::PatternShape::Circle;  // 10 mm circle around (50, 50) at 2 mm/s
        const auto path = planOf(p);
        ASSERT_TRUE(r.runner.start(path, {})) << r.all();
        r.s.link.host().setTimeScale(8);
        ASSERT_TRUE(waitFor([&] { return !r.runner.busy(); }, 60000)) << dev::jobs::PatternRunner::stateTerm(r.runner.state());
        r.s.link.host().setTimeScale(1);
        ASSERT_EQ(r.runner.state(), dev::jobs::PatternRunner::State::Done) << r.all();
        const auto sum = r.runner.summary();
        EXPECT_TRUE(sum.complete);
        EXPECT_GE(sum.samples, 5u);
        // GRBL follows the arcs within its $12 chord tolerance (2 µm); reports carry 1 µm.
        EXPECT_LT(sum.maxContourMm, 0.005) << sum.maxContourMm;
        EXPECT_GT(sum.durationS, 1.5);  // host time: 15.7 s of the simulator's at its clock ×8
        // The simulator's buffer accounting: nothing lost, never more than it holds.
        EXPECT_EQ(r.s.firmware().lostRxBytes(), 0u);
        EXPECT_LE(r.s.firmware().maxRxBytesQueued(), r.s.firmware().rxBufferBytes() - 1);
        EXPECT_NEAR(r.s.readout('X').commanded, path.back().end.x, 1e-3);
    }
}

TEST(GrblRunners, ARasterLongerThanThePathWindowIsStreamedWithFlowControl)
{
    PatternRig r({});
    ASSERT_TRUE(r.ready());
    motion::plans::Pattern p;
    p.shape = motion::plans::PatternShape::Raster;
    p.feedMmS = 20;
    p.raster.cornerMm = {40, 40};
    p.raster.widthMm = 4;
    p.raster.heightMm = 10;
    p.raster.spacingMm = 0.2;
    const auto path = planOf(p);
    ASSERT_GT(path.size(), 80u);  // more than the 64 segments the GRBL path window holds
    ASSERT_TRUE(r.runner.start(path, {})) << r.all();
    r.s.link.host().setTimeScale(8);
    ASSERT_TRUE(waitFor([&] { return !r.runner.busy(); }, 90000));
    r.s.link.host().setTimeScale(1);
    ASSERT_EQ(r.runner.state(), dev::jobs::PatternRunner::State::Done) << r.all();
    EXPECT_EQ(r.runner.segmentsDone(), path.size());
    EXPECT_EQ(r.s.firmware().lostRxBytes(), 0u);
}

TEST(GrblRunners, APatternOutsideTheTravelIsRefusedBeforeAnythingMoves)
{
    PatternRig r({});
    ASSERT_TRUE(r.ready());
    motion::plans::Pattern p;
    p.shape = motion::plans::PatternShape::Line;
    p.line.startMm = {90, 50};
    p.line.endMm = {120, 50};
    const double x0 = r.s.readout('X').commanded;
    EXPECT_FALSE(r.runner.start(planOf(p), {}));
    // Beyond GRBL's machine travel, which are the instrument's soft limits here.
    const auto beyond = std::find_if(r.messages.begin(), r.messages.end(), [](const motion::msg::Message& m) { return m.id == "pattern.segment_above_limit"; });
    ASSERT_NE(beyond, r.messages.end()) << r.all();
    EXPECT_EQ(beyond->text("axis"), "X") << r.all();
    itest::spin(200);
    EXPECT_DOUBLE_EQ(r.s.readout('X').commanded, x0);
}

TEST(GrblRunners, AScanTriggersTheProfilesOutputOncePerTile)
{
    GrblSessionOptions o;
    o.grblHal = true;
    dev::files::MachineProfile profile = dev::files::defaultProfile(dev::proto::DeviceKind::Stage);
    profile.trigger = dev::files::MachineProfile::Trigger{dev::files::MachineProfile::TriggerOutput::GrblHalDigital, 2};
    o.profile = profile;
    GrblSession s(o);
    ASSERT_TRUE(s.connect());
    ASSERT_TRUE(s.homeAll());
    ASSERT_TRUE(s.client.can(dev::Capability::TriggerOutput));
    motion::scan::ScanPlan plan;
    plan.name = "grbl";
    plan.region.cornerA = {40, 60};
    plan.region.cornerB = {41.8, 61.8};
    plan.camera.source = motion::scan::FieldSource::Direct;
    plan.camera.fieldWidthMm = plan.camera.fieldHeightMm = 1.0;
    plan.overlapX = plan.overlapY = 0.1;
    plan.speedMmS = 10;
    plan.exposureS = 0.02;
    QTemporaryDir dir;
    dev::jobs::ScanRunner runner(&s.client);
    motion::msg::Message error;
    ASSERT_TRUE(runner.prepare(plan, dir.path(), false, &error)) << motion::msg::debugString(error);
    ASSERT_EQ(runner.totalTiles(), 4);
    s.link.host().setTimeScale(4);
    ASSERT_TRUE(runner.start(&error)) << motion::msg::debugString(error);
    ASSERT_TRUE(waitFor([&] { return runner.state() == dev::jobs::ScanRunner::State::Finished || runner.state() == dev::jobs::ScanRunner::State::Stopped; },
                        60000));
    s.link.host().setTimeScale(1);
    ASSERT_EQ(runner.state(), dev::jobs::ScanRunner::State::Finished);
    for (int t = 0; t < 4; ++t) {
        const auto& rec = runner.records()[static_cast<std::size_t>(t)];
        ASSERT_EQ(rec.measuredMm.size(), 2u);
        EXPECT_NEAR(rec.measuredMm[0], rec.commandedMm[0], 1e-3) << "tile " << t;
        EXPECT_NEAR(rec.measuredMm[1], rec.commandedMm[1], 1e-3) << "tile " << t;
    }
    // grblHAL's digital output 2: on and off once per tile, the pulse as long as the exposure.
    ASSERT_TRUE(waitFor([&] { return s.firmware().outputEvents().size() >= 8; }, 5000));
    int pulses = 0;
    const auto& ev = s.firmware().outputEvents();
    for (std::size_t i = 0; i + 1 < ev.size(); ++i)
        if (ev[i].port == 2 && ev[i].on && ev[i + 1].port == 2 && !ev[i + 1].on) {
            ++pulses;
            EXPECT_NEAR(ev[i + 1].timeS - ev[i].timeS, 0.02, 0.002);
        }
    EXPECT_EQ(pulses, 4);
}

TEST(GrblRunners, ARecipeMovesThePlungerOnTheProfilesAxis)
{
    GrblSessionOptions o;
    o.kind = dev::proto::DeviceKind::Analyzer;
    GrblSession s(o);
    ASSERT_TRUE(s.connect());
    ASSERT_TRUE(s.client.can(dev::Capability::Pump));
    ASSERT_TRUE(s.client.can(dev::Capability::CoupledXyThenZ));
    ASSERT_TRUE(s.homeAll());
    const auto& a = s.client.status().axes;
    motion::plates::StartState start{a[0].commanded, a[1].commanded, a[2].commanded, a[3].commanded};
    const motion::plates::RecipePlan plan = motion::plates::planRecipe(platestest::samplingRecipe("A1:A4", 10), platestest::builtinContext(), start);
    ASSERT_TRUE(plan.ok());
    dev::jobs::RecipeRunner runner(&s.client);
    std::string problems;
    QObject::connect(&runner, &dev::jobs::RecipeRunner::message, &runner, [&](const motion::msg::Message& m, bool problem) {
        if (problem)
            problems += motion::msg::debugString(m) + "\n";
    });
    QTemporaryDir dir;
    motion::msg::Message error;
    ASSERT_TRUE(runner.setPlan(plan, QStringLiteral("sampling"), &error)) << motion::msg::debugString(error);
    const double p0 = s.readout('P').commanded;
    s.link.host().setTimeScale(platestest::kRunTimeScale);
    ASSERT_TRUE(runner.start(dir.filePath(QStringLiteral("run.jsonl")), &error)) << motion::msg::debugString(error);
    ASSERT_TRUE(platestest::waitSettled(runner, 120000));
    s.link.host().setTimeScale(1);
    ASSERT_EQ(runner.state(), dev::jobs::RunState::Finished) << problems;
    const auto counts = platestest::countLog(dir.filePath(QStringLiteral("run.jsonl")));
    ASSERT_EQ(counts.dones.size(), 4u);
    for (const auto& [op, n] : counts.dones)
        EXPECT_EQ(n, 1) << "op " << op;
    ASSERT_TRUE(s.waitStill());
    EXPECT_NEAR(s.readout('P').commanded - p0, 40.0, 1e-3);
    // 1 µL per GRBL "mm" on A in the default wiring: the controller's A moved 40 mm.
    EXPECT_NEAR(s.firmware().machinePositionMm()[3], s.readout('P').commanded, 1e-3);
}

TEST(GrblRunners, TheJoystickDriverMovesXyTogetherAndStopsWithinTheBudgetOfItsRelease)
{
    GrblSession s;
    ASSERT_TRUE(s.connect());
    ASSERT_TRUE(s.homeAll());
    ASSERT_FALSE(s.call([&](auto cb) { s.client.move({{0, 30}, {1, 30}}, false, 20, cb); }));
    ASSERT_TRUE(s.waitStill());
    dev::JoystickDriver stick(&s.client);
    EXPECT_EQ(stick.keepAliveMs(), s.client.jogRefreshMs());
    stick.setVelocities({{0, 8}, {1, 6}});  // a diagonal at 10 mm/s
    ASSERT_TRUE(waitFor([&] { return s.firmware().machinePositionMm()[0] > 33; }, 10000));
    const std::size_t cancels = s.firmware().jogCancelTimesS().size();
    stick.stop();
    ASSERT_TRUE(waitFor([&] { return s.firmware().jogCancelTimesS().size() > cancels; }, 5000));
    const double releasedAt = s.firmware().jogCancelTimesS()[cancels];
    ASSERT_TRUE(s.waitStill());
    itest::spin(300);
    ASSERT_TRUE(s.waitStill());
    const auto& pos = s.firmware().machinePositionMm();
    // Both axes went the stick's way, in its proportion (the ahead queue is one direction).
    EXPECT_NEAR((pos[1] - 30) / (pos[0] - 30), 6.0 / 8.0, 0.02);
    EXPECT_LE(s.firmware().lastMotionEndAtS() - releasedAt + s.client.profile().jog.linkLatencyS, 0.25);
}

TEST(GrblRunners, ABoardResetMidJobInterruptsThePatternAndSaysWhatWasLost)
{
    PatternRig r({});
    ASSERT_TRUE(r.ready());
    motion::plans::Pattern p;
    p.shape = motion::plans::PatternShape::Circle;
    ASSERT_TRUE(r.runner.start(planOf(p), {}));
    ASSERT_TRUE(waitFor([&] { return r.runner.state() == dev::jobs::PatternRunner::State::Running && r.s.firmware().machinePositionMm()[1] > 50.5; },
                        20000));
    // The board resets by itself (a brown-out, a watchdog): nobody here sent the 0x18.
    const std::uint8_t reset = dev::grbl::rt::kSoftReset;
    r.s.firmware().receive(&reset, 1);
    ASSERT_TRUE(waitFor([&] { return !r.runner.busy(); }, 10000)) << dev::jobs::PatternRunner::stateTerm(r.runner.state());
    EXPECT_EQ(r.runner.state(), dev::jobs::PatternRunner::State::Interrupted);
    EXPECT_FALSE(r.runner.summary().complete);
    // Said, and the position is no longer trusted: the controller reports ALARM:3.
    ASSERT_TRUE(waitFor([&] { return r.s.client.status().positionLost; }, 5000));
    EXPECT_FALSE(r.s.readout('X').homed);
    bool alarm = false, reset3 = false;
    for (const auto& e : r.s.events) {
        alarm = alarm || (e.detail.id == "grbl.alarm" && e.detail.integer("code") == 3);
        reset3 = reset3 || e.detail.id == "grbl.controller_reset";
    }
    EXPECT_TRUE(alarm);
    EXPECT_TRUE(reset3);
    EXPECT_TRUE(r.s.client.isReady());  // the link itself is fine
}
