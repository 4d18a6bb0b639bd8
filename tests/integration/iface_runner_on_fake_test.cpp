// The runners drive dev::Instrument, not a backend: a scan runs to the end on a second,
// test-only backend (FakeInstrument) that speaks no protocol, triggers its camera output
// once per tile, and its estimate follows the limits that backend reports. The joystick
// driver renews held velocities at the pace that backend asks for.
#include "device/client/joystick_driver.h"
#include "device/jobs/scan_runner.h"
#include "iface_fake_instrument.h"
#include "motion/message_print.h"
#include "wait.h"

#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <cmath>

using itest::FakeInstrument;
using itest::waitFor;
using dev::jobs::ScanRunner;

namespace {

/// 2 × 2 fields of 1 mm near the middle of the stage.
motion::scan::ScanPlan fourTiles()
{
    motion::scan::ScanPlan p;
    p.name = "on a fake";
    p.region.cornerA = {40, 60};
    p.region.cornerB = {41.8, 61.8};
    p.camera.source = motion::scan::FieldSource::Direct;
    p.camera.fieldWidthMm = p.camera.fieldHeightMm = 1.0;
    p.overlapX = p.overlapY = 0.1;
    p.speedMmS = 10;
    p.exposureS = 0.005;
    return p;
}

bool connectAndHome(FakeInstrument& f)
{
    f.connectLink();
    bool homed = false;
    f.home(0, [&](const auto& e) { homed = !e; });
    return waitFor([&] { return homed && f.status().axes.size() == 2 && !f.status().anyMoving(); }, 2000);
}

} // namespace

TEST(IfaceRunnerOnFake, AScanRunsToTheEndOnABackendWithoutAProtocol)
{
    FakeInstrument fake;
    ASSERT_TRUE(connectAndHome(fake));
    QTemporaryDir dir;
    ScanRunner runner(&fake);
    motion::msg::Message error;
    ASSERT_TRUE(runner.prepare(fourTiles(), dir.path(), false, &error)) << error;
    ASSERT_EQ(runner.totalTiles(), 4);
    ASSERT_TRUE(runner.start(&error)) << error;
    ASSERT_TRUE(waitFor([&] { return runner.state() == ScanRunner::State::Finished; }, 10000))
        << ScanRunner::stateTerm(runner.state());

    EXPECT_EQ(runner.takenTiles(), 4);
    EXPECT_EQ(fake.moves.size(), 4u);  // one move per tile, no overtravel in this plan
    // Every tile's record is where the fake said the stage stood.
    for (int t = 0; t < 4; ++t) {
        const auto& r = runner.records()[static_cast<std::size_t>(t)];
        ASSERT_EQ(r.measuredMm.size(), 2u) << "tile " << t;
        ASSERT_EQ(r.commandedMm.size(), 2u);
        EXPECT_NEAR(r.measuredMm[0], r.commandedMm[0], 1e-9);
        EXPECT_NEAR(r.measuredMm[1], r.commandedMm[1], 1e-9);
    }
    // The backend has a trigger output: one pulse per tile, held for the exposure.
    ASSERT_EQ(fake.triggerWidthsS.size(), 4u);
    EXPECT_DOUBLE_EQ(fake.triggerWidthsS[0], 0.005);
}

TEST(IfaceRunnerOnFake, WithoutATriggerOutputNoPulseIsAskedFor)
{
    FakeInstrument fake(200, 4000, FakeInstrument::defaultCapabilities() & ~dev::Capabilities(dev::Capability::TriggerOutput));
    ASSERT_TRUE(connectAndHome(fake));
    QTemporaryDir dir;
    ScanRunner runner(&fake);
    motion::msg::Message error;
    ASSERT_TRUE(runner.prepare(fourTiles(), dir.path(), false, &error));
    ASSERT_TRUE(runner.start(&error));
    ASSERT_TRUE(waitFor([&] { return runner.state() == ScanRunner::State::Finished; }, 10000));
    EXPECT_TRUE(fake.triggerWidthsS.empty());
    EXPECT_EQ(runner.takenTiles(), 4);
}

TEST(IfaceRunnerOnFake, TheScanEstimateFollowsTheLimitsTheDeviceReports)
{
    // The same plan on two stages that differ only in the acceleration and jerk they report.
    auto estimateOn = [](double accelMmS2, double jerkMmS3) {
        FakeInstrument fake(accelMmS2, jerkMmS3);
        EXPECT_TRUE(connectAndHome(fake));
        QTemporaryDir dir;
        ScanRunner runner(&fake);
        motion::msg::Message error;
        EXPECT_TRUE(runner.prepare(fourTiles(), dir.path(), false, &error)) << error;
        return runner.estimate().moveS;
    };
    const double brisk = estimateOn(200, 4000);
    const double sluggish = estimateOn(20, 100);
    const double trapezoid = estimateOn(200, 0);  // no jerk limit: a trapezoid planner (GRBL's)
    EXPECT_GT(brisk, 0);
    // Moves of 0.9 mm: a tenth of the acceleration and a fortieth of the jerk take far longer.
    EXPECT_GT(sluggish, 1.5 * brisk);
    // Without a jerk limit the ramps are shorter still.
    EXPECT_LT(trapezoid, brisk);
}

TEST(IfaceRunnerOnFake, TheJoystickRenewsAtTheBackendsPace)
{
    FakeInstrument fake;
    fake.connectLink();
    dev::JoystickDriver stick(&fake);
    EXPECT_EQ(stick.keepAliveMs(), fake.jogRefreshMs());
    stick.setVelocities({{0, 5.0}, {1, -2.0}});
    ASSERT_FALSE(fake.jogs.empty());
    EXPECT_DOUBLE_EQ(fake.jogs.front().at(0), 5.0);
    EXPECT_DOUBLE_EQ(fake.jogs.front().at(1), -2.0);
    // Held still, the same wish goes out again within the backend's refresh.
    const std::size_t first = fake.jogs.size();
    EXPECT_TRUE(waitFor([&] { return fake.jogs.size() > first; }, 20 * fake.jogRefreshMs()));
    stick.stop();
    EXPECT_DOUBLE_EQ(fake.jogs.back().at(0), 0.0);
}
