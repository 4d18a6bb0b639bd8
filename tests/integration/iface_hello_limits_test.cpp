// The BenchPilot backend and HELLO's motion limits over the loopback, both ways of being
// old: against firmware of protocol 1.0 (which refuses the HELLO payload) the host asks
// again, connects and says the limits are not reported; against the current simulator the
// identity carries the planner's own numbers. A stage that reports other limits gets
// other scan estimates, and an analyzer that reports other limits has its moves timed as
// it runs them, through the real protocol.
#include "device/backends/benchpilot/benchpilot_client.h"
#include "device/files/plates/deck_file.h"
#include "device/jobs/machine_model.h"
#include "device/jobs/scan_runner.h"
#include "device/link/simulated_link.h"
#include "device/sim/sim_machine.h"
#include "motion/plans/recipes/move_time.h"
#include "motion/message_print.h"
#include "wait.h"

#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <cmath>

using itest::waitFor;

namespace {

struct Rig {
    explicit Rig(const dev::sim::MachineConfig& cfg, bool helloExtensions = true) : link(cfg, 0)
    {
        link.host().firmware().setHelloExtensions(helloExtensions);
        client.setTransport(link.hostEnd());
    }
    ~Rig() { client.setTransport(nullptr); }
    bool connect()
    {
        client.connectLink();
        return waitFor([&] { return client.isReady() || client.state() == dev::LinkState::Disconnected; }, 5000)
            && client.isReady();
    }
    dev::SimulatedLink link;
    dev::BenchPilotClient client;
};

} // namespace

TEST(IfaceHelloLimits, TheIdentityCarriesTheSimulatorsPlannerLimits)
{
    Rig r(dev::sim::stageConfig());
    ASSERT_TRUE(r.connect());
    const dev::DeviceIdentity& id = r.client.identity();
    EXPECT_EQ(id.motionProfile, dev::proto::MotionProfile::JerkLimited);
    ASSERT_EQ(id.axes.size(), 2);
    EXPECT_DOUBLE_EQ(id.axes[0].maxAccel, 200);
    EXPECT_DOUBLE_EQ(id.axes[0].maxJerk, 4000);
    EXPECT_DOUBLE_EQ(id.axes[0].defaultSpeed, 10);
    EXPECT_TRUE(r.client.can(dev::Capability::MachineLimits));
}

TEST(IfaceHelloLimits, TheAnalyzersSCurveArrivesWithItsAccelerationPhase)
{
    Rig r(dev::sim::analyzerConfig());
    ASSERT_TRUE(r.connect());
    const dev::DeviceIdentity& id = r.client.identity();
    EXPECT_EQ(id.motionProfile, dev::proto::MotionProfile::SeedSCurve);
    EXPECT_DOUBLE_EQ(id.axes[0].minAccelTimeS, 0.1);
    EXPECT_DOUBLE_EQ(id.axes[1].maxAccel, 2000);
    EXPECT_DOUBLE_EQ(id.axes[3].maxAccel, 5000);  // µL/s² on the pump
}

TEST(IfaceHelloLimits, AProtocol10DeviceStillConnectsWithoutThem)
{
    Rig r(dev::sim::stageConfig(), false);
    ASSERT_TRUE(r.connect());
    const dev::DeviceIdentity& id = r.client.identity();
    EXPECT_FALSE(id.reportsMotionLimits());
    EXPECT_DOUBLE_EQ(id.axes[0].maxAccel, 0);
    EXPECT_DOUBLE_EQ(id.axes[0].maxSpeed, 20);  // what protocol 1.0 did carry
    EXPECT_FALSE(r.client.capabilities().testFlag(dev::Capability::MachineLimits));
    const motion::msg::Message why = r.client.whyNot(dev::Capability::MachineLimits);
    EXPECT_EQ(why.id, "capability.no_machine_limits");
    EXPECT_EQ(why.text("because"), "capability.because.older_firmware");
    // Estimates fall back to the reference stage's planner, as before the limits existed.
    const auto m = dev::jobs::stageModelOf(id, r.client.softLimits());
    EXPECT_DOUBLE_EQ(m.maxAccelMmS2[0], motion::scan::StageModel{}.maxAccelMmS2[0]);
    // The refused HELLO cost nothing else: the link works.
    bool moved = false;
    r.client.home(0, [&](const auto& e) { moved = !e; });
    EXPECT_TRUE(waitFor([&] { return moved; }, 3000));
}

TEST(IfaceHelloLimits, AStageThatReportsOtherLimitsGetsOtherScanEstimates)
{
    auto estimate = [](const dev::sim::MachineConfig& cfg) {
        Rig r(cfg);
        EXPECT_TRUE(r.connect());
        motion::scan::ScanPlan p;
        p.region.cornerA = {40, 60};
        p.region.cornerB = {44, 64};
        p.camera.source = motion::scan::FieldSource::Direct;
        p.camera.fieldWidthMm = p.camera.fieldHeightMm = 1.0;
        QTemporaryDir dir;
        dev::jobs::ScanRunner runner(&r.client);
        motion::msg::Message error;
        EXPECT_TRUE(runner.prepare(p, dir.path(), false, &error)) << error;
        return runner.estimate().moveS;
    };
    dev::sim::MachineConfig slow = dev::sim::stageConfig();
    for (auto& a : slow.axes) {
        a.maxAccel = 50;
        a.maxJerk = 500;
    }
    const double reference = estimate(dev::sim::stageConfig());
    const double slower = estimate(slow);
    EXPECT_GT(reference, 0);
    EXPECT_GT(slower, 1.3 * reference);
}

namespace {

/// Seconds from a MOVE until every axis in it reported MotionDone, on a bare simulated machine.
double simulatedSeconds(dev::sim::SimMachine& m, const dev::proto::MoveRequest& r)
{
    m.takeEvents();
    const double t0 = m.timeS();
    EXPECT_FALSE(m.move(r).has_value());
    int pending = dev::proto::popcount8(r.axisMask);
    for (int tick = 0; tick < 400000 && pending > 0; ++tick) {
        m.tick();
        for (const auto& e : m.takeEvents())
            if (e.kind == dev::proto::EventKind::MotionDone)
                --pending;
    }
    EXPECT_EQ(pending, 0);
    return m.timeS() - t0;
}

void homeAll(dev::sim::SimMachine& m)
{
    ASSERT_FALSE(m.home(0).has_value());
    for (int tick = 0; tick < 3000000; ++tick) {
        m.tick();
        bool all = true;
        for (int i = 0; i < m.axisCount(); ++i)
            all = all && m.homed(i);
        if (all)
            break;
    }
    for (int tick = 0; tick < 1000; ++tick)
        m.tick();
    m.takeEvents();
}

} // namespace

TEST(IfaceHelloLimits, AnAnalyzerWithOtherLimitsIsTimedAsItRuns)
{
    // Not the machine the deck file describes: gentler XY, a longer S-curve phase, a slower default.
    dev::sim::MachineConfig cfg = dev::sim::analyzerConfig();
    cfg.axes[0].maxAccel = 300;
    cfg.axes[1].maxAccel = 400;
    cfg.axes[0].accelTimeS = cfg.axes[1].accelTimeS = 0.15;
    cfg.axes[0].defaultSpeed = cfg.axes[1].defaultSpeed = 40;
    Rig r(cfg);
    ASSERT_TRUE(r.connect());
    const motion::plates::Deck file = dev::files::plates::builtinDeck();
    const motion::plates::Deck device = dev::jobs::deckWithDeviceMotion(file, r.client.identity());

    dev::sim::SimMachine m(cfg);
    homeAll(m);
    const double fromX = m.commandedLogical(0), fromY = m.commandedLogical(1);
    for (const double speed : {0.0, 100.0}) {
        SCOPED_TRACE(speed);
        dev::proto::MoveRequest req;
        req.axisMask = 0b0011;
        req.speed = static_cast<std::uint32_t>(std::lround(speed * 1e6));
        const double toX = speed > 0 ? fromX : 120.0, toY = speed > 0 ? fromY : 150.0;  // there and back
        req.targets = {static_cast<std::int32_t>(std::lround(toX * 1e6)), static_cast<std::int32_t>(std::lround(toY * 1e6))};
        const double dx = toX - m.commandedLogical(0), dy = toY - m.commandedLogical(1);
        const double byDevice = motion::plates::moveTimeS({{&device.x, dx}, {&device.y, dy}}, speed);
        const double byFile = motion::plates::moveTimeS({{&file.x, dx}, {&file.y, dy}}, speed);
        const double simulated = simulatedSeconds(m, req);
        // The firmware ends a segment on the first 100 µs tick at or past its duration.
        EXPECT_NEAR(simulated, byDevice, 2 * dev::sim::SimMachine::kTickS);
        EXPECT_GT(std::abs(simulated - byFile), 0.05) << "the deck file's numbers would have missed it";
    }
}
