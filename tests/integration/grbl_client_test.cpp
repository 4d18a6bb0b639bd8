// The GRBL backend against the simulator's GRBL personality, in-process: identification from $I
// and $$, homing and moves with MotionDone, the host's travel check and GRBL's own refusals
// with their meanings, homing disabled and "Set home here", continuous jog stopped within the
// budget on the simulator's clock, E-stop and recovery.
#include "device/backends/grbl/grbl_codes.h"
#include "grbl_session.h"

#include <gtest/gtest.h>

#include <cmath>

using itest::GrblSession;
using itest::GrblSessionOptions;
using itest::waitFor;

namespace {

void feedFirmware(GrblSession& s, const std::string& text)
{
    s.firmware().receive(reinterpret_cast<const std::uint8_t*>(text.data()), text.size());
    s.firmware().advance(0.05);
}

} // namespace

TEST(GrblClient, IdentifiesTheFirmwareAndReadsItsLimitsFromSettings)
{
    for (const bool hal : {false, true}) {
        GrblSessionOptions o;
        o.grblHal = hal;
        GrblSession s(o);
        ASSERT_TRUE(s.connect()) << s.linkErrors.join(QStringLiteral("; ")).toStdString();
        const auto& id = s.client.identity();
        EXPECT_EQ(id.family, hal ? QStringLiteral("grblHAL 1.1f") : QStringLiteral("Grbl 1.1h"));
        EXPECT_TRUE(id.firmware.startsWith(hal ? QStringLiteral("1.1f") : QStringLiteral("1.1h"))) << id.firmware.toStdString();
        EXPECT_EQ(id.kind, dev::proto::DeviceKind::Stage);
        ASSERT_EQ(id.axes.size(), 2);
        // $110 = 20 mm/s × 60, $120 = 200 mm/s², $130 = 100 mm: the stage's own limits.
        EXPECT_NEAR(id.axes[0].maxSpeed, 20, 1e-9);
        EXPECT_NEAR(id.axes[0].maxAccel, 200, 1e-9);
        EXPECT_EQ(id.axes[0].maxJerk, 0);
        EXPECT_EQ(id.motionProfile, dev::proto::MotionProfile::Trapezoid);
        EXPECT_NEAR(s.client.softLimits()[0].max - s.client.softLimits()[0].min, 100, 1e-9);
        EXPECT_EQ(s.client.buildInfo().rxBufferBytes, hal ? 1024 : 128);
        // What GRBL cannot do, said with a reason.
        EXPECT_FALSE(s.client.can(dev::Capability::PidGains));
        EXPECT_EQ(s.client.whyNot(dev::Capability::PidGains).text("because"), "capability.because.grbl_open_loop");
        EXPECT_EQ(s.client.whyNot(dev::Capability::StopsOnHostLoss).text("because"), "capability.because.grbl_no_watchdog");
        EXPECT_TRUE(s.client.can(dev::Capability::Homing));
        EXPECT_TRUE(s.client.can(dev::Capability::PathQueue));
        EXPECT_EQ(s.client.paths() != nullptr, true);
        EXPECT_EQ(s.client.tuning(), nullptr);
        // Power-up with homing enabled: in alarm, position not trusted.
        EXPECT_TRUE(s.client.status().positionLost);
        EXPECT_FALSE(s.readout('X').homed);
    }
}

TEST(GrblClient, HomesThenMovesAndReportsMotionDoneForEachAxis)
{
    GrblSession s;
    ASSERT_TRUE(s.connect());
    // Not homed: an absolute move is refused by the host before anything is sent.
    const auto before = s.call([&](auto cb) { s.client.move({{0, 10}}, false, 10, cb); });
    ASSERT_TRUE(before);
    EXPECT_EQ(before->code, dev::proto::ErrorCode::NotHomed);
    ASSERT_TRUE(s.homeAll());
    EXPECT_TRUE(s.readout('X').homed);
    EXPECT_FALSE(s.client.status().positionLost);
    const std::size_t from = s.events.size();
    ASSERT_FALSE(s.call([&](auto cb) { s.client.move({{0, 12}, {1, 7.5}}, false, 20, cb); }));
    ASSERT_TRUE(s.waitEvent(dev::proto::EventKind::MotionDone, 0, from));
    ASSERT_TRUE(s.waitEvent(dev::proto::EventKind::MotionDone, 1, from));
    EXPECT_NEAR(s.readout('X').commanded, 12, 1e-3);
    EXPECT_NEAR(s.readout('Y').commanded, 7.5, 1e-3);
    EXPECT_NEAR(s.firmware().machinePositionMm()[0], 12, 1e-6);
    EXPECT_EQ(s.firmware().lostRxBytes(), 0u);
}

TEST(GrblClient, ASoftLimitIsRefusedClearlyByTheHostAndByGrbl)
{
    GrblSession s;
    ASSERT_TRUE(s.connect());
    ASSERT_TRUE(s.homeAll());
    // A G-code move beyond the travel: refused before sending (GRBL would stop with ALARM:2).
    const auto far = s.call([&](auto cb) { s.client.move({{0, 150}}, false, 10, cb); });
    ASSERT_TRUE(far);
    EXPECT_EQ(far->code, dev::proto::ErrorCode::SoftLimit);
    EXPECT_EQ(far->message.id, "grbl.beyond_travel") << far->message;
    EXPECT_EQ(far->message.text("axis"), "X");
    EXPECT_DOUBLE_EQ(far->message.number("target"), 150);
    EXPECT_LT(far->message.number("max"), 150);
    EXPECT_EQ(far->message.integer("setting"), 130);
    ASSERT_NE(far->message.arg("target"), nullptr);
    EXPECT_EQ(far->message.arg("target")->unit, motion::msg::Unit::Mm);
    EXPECT_FALSE(s.client.status().positionLost);
    // A jog step beyond it goes to GRBL, which answers error:15: shown with its meaning and line.
    const auto jog = s.call([&](auto cb) { s.client.jogStep(0, 500, 10, cb); });
    ASSERT_TRUE(jog);
    EXPECT_EQ(jog->message.id, "grbl.error") << jog->message;
    EXPECT_EQ(jog->message.integer("code"), 15);
    EXPECT_EQ(jog->message.text("line"), "$J=G91 G21 X500 F600");
    EXPECT_EQ(jog->message.text("request"), "request.jog_step");
    EXPECT_FALSE(s.client.status().positionLost);  // a jog refusal is not an alarm
}

TEST(GrblClient, WithHomingDisabledSetHomeHereAllowsAbsoluteMoves)
{
    GrblSession s;
    // A machine without homing switches, set up before we connect — its answers ("ok", "ok",
    // "[MSG:Caution: Unlocked]") are still waiting: the client's sync must not take them for its own.
    feedFirmware(s, "$22=0\n$X\n");
    ASSERT_TRUE(s.connect());
    EXPECT_FALSE(s.client.can(dev::Capability::Homing));
    EXPECT_EQ(s.client.whyNot(dev::Capability::Homing).text("because"), "capability.because.grbl_homing_disabled");
    EXPECT_FALSE(s.client.status().positionLost);
    // $H: GRBL's error:5, with its meaning.
    const auto home = s.call([&](auto cb) { s.client.home(0, cb); });
    ASSERT_TRUE(home);
    EXPECT_EQ(home->message.id, "grbl.error") << home->message;
    EXPECT_EQ(home->message.integer("code"), 5);
    EXPECT_EQ(home->message.text("request"), "request.home");
    // Relative moves work; absolute ones wait for the operator's word.
    ASSERT_FALSE(s.call([&](auto cb) { s.client.move({{0, 2}}, true, 10, cb); }));
    ASSERT_TRUE(s.waitStill());
    const auto abs = s.call([&](auto cb) { s.client.move({{0, 1}}, false, 10, cb); });
    ASSERT_TRUE(abs);
    EXPECT_EQ(abs->code, dev::proto::ErrorCode::NotHomed);
    ASSERT_FALSE(s.call([&](auto cb) { s.client.setZero(0, cb); }));
    ASSERT_TRUE(waitFor([&] { return s.readout('X').homed && std::fabs(s.readout('X').commanded) < 1e-6; }, 5000));
    const std::size_t from = s.events.size();
    ASSERT_FALSE(s.call([&](auto cb) { s.client.move({{0, 3}}, false, 10, cb); }));
    ASSERT_TRUE(s.waitEvent(dev::proto::EventKind::MotionDone, 0, from));
    EXPECT_NEAR(s.readout('X').commanded, 3, 1e-3);
    // GRBL's work offset (G54) carries the home: machine position = work + offset.
    EXPECT_NEAR(s.firmware().machinePositionMm()[0] - s.firmware().workOffsetMm()[0], 3, 1e-6);
}

TEST(GrblClient, AContinuousJogStopsWithinTheBudgetOfItsReleaseOnTheSimulatorsClock)
{
    GrblSession s;
    ASSERT_TRUE(s.connect());
    ASSERT_TRUE(s.homeAll());
    ASSERT_FALSE(s.call([&](auto cb) { s.client.move({{0, 20}}, false, 20, cb); }));
    ASSERT_TRUE(s.waitStill());
    const dev::grbl::JogPlan plan = s.client.jogPlan(0, 20);
    ASSERT_TRUE(plan.feasible);
    s.client.startJog(0, 20);
    ASSERT_TRUE(waitFor([&] { return s.firmware().machinePositionMm()[0] > 25; }, 10000));
    const std::size_t cancelsBefore = s.firmware().jogCancelTimesS().size();
    s.client.stopJog(0);
    ASSERT_TRUE(waitFor([&] { return s.firmware().jogCancelTimesS().size() > cancelsBefore; }, 5000));
    const double releasedAt = s.firmware().jogCancelTimesS()[cancelsBefore];
    // At rest, and staying there (a jog line still in GRBL's buffer would have started again).
    ASSERT_TRUE(s.waitStill());
    itest::spin(300);
    ASSERT_TRUE(s.waitStill());
    const double stoppedAt = s.firmware().lastMotionEndAtS();
    EXPECT_GT(stoppedAt, releasedAt);
    // Release → rest on the simulator's clock, plus the link latency the plan allows for.
    EXPECT_LE(stoppedAt - releasedAt + plan.linkLatencyS, 0.25) << "released at " << releasedAt << ", at rest at " << stoppedAt;
    EXPECT_FALSE(s.client.isJogging(0));
    EXPECT_EQ(s.firmware().state(), dev::sim::GrblFirmware::State::Idle);
}

TEST(GrblClient, EStopLosesThePositionOfAMovingMachineAndRecoveryNeedsItBack)
{
    GrblSession s;
    ASSERT_TRUE(s.connect());
    ASSERT_TRUE(s.homeAll());
    ASSERT_FALSE(s.call([&](auto cb) { s.client.move({{0, 80}}, false, 20, cb); }));
    ASSERT_TRUE(waitFor([&] { return s.firmware().machinePositionMm()[0] > 30; }, 10000));
    const std::size_t from = s.events.size();
    ASSERT_FALSE(s.call([&](auto cb) { s.client.estop(cb); }));
    const int estop = s.findEvent(dev::proto::EventKind::EStop, -1, from);
    ASSERT_GE(estop, 0);
    EXPECT_EQ(s.events[static_cast<std::size_t>(estop)].detail.id, "grbl.event.estop");
    // ALARM:3: reset while moving; the position is lost.
    ASSERT_TRUE(waitFor([&] { return s.client.status().positionLost && s.client.alarmCode() == dev::grbl::alarm::kAbortCycle; }, 5000));
    EXPECT_TRUE(s.client.status().estop);
    EXPECT_FALSE(s.readout('X').homed);
    const int alarm = s.findEvent(dev::proto::EventKind::Fault, -1, from);
    ASSERT_GE(alarm, 0);
    EXPECT_EQ(s.events[static_cast<std::size_t>(alarm)].detail.id, "grbl.alarm");
    EXPECT_EQ(s.events[static_cast<std::size_t>(alarm)].detail.integer("code"), 3);
    EXPECT_EQ(s.events[static_cast<std::size_t>(alarm)].text, QStringLiteral("ALARM:3"));  // what the controller said
    // Reset clears the latch; moves still wait for the position.
    ASSERT_FALSE(s.call([&](auto cb) { s.client.reset(cb); }));
    EXPECT_FALSE(s.client.status().estop);
    const auto refused = s.call([&](auto cb) { s.client.move({{0, 10}}, false, 10, cb); });
    ASSERT_TRUE(refused);
    EXPECT_EQ(refused->code, dev::proto::ErrorCode::NotHomed);
    EXPECT_EQ(refused->message.id, "grbl.move_in_alarm") << refused->message;
    // Recovery: unlock on the operator's word (or home).
    ASSERT_FALSE(s.call([&](auto cb) { s.client.unlock(cb); }));
    ASSERT_TRUE(waitFor([&] { return !s.client.status().positionLost && s.readout('X').homed; }, 5000));
    const std::size_t later = s.events.size();
    ASSERT_FALSE(s.call([&](auto cb) { s.client.move({{0, 10}}, false, 20, cb); }));
    ASSERT_TRUE(s.waitEvent(dev::proto::EventKind::MotionDone, 0, later));
    EXPECT_NEAR(s.readout('X').commanded, 10, 1e-3);
}

TEST(GrblClient, AStopHoldsThenFlushesAndKeepsThePosition)
{
    GrblSession s;
    ASSERT_TRUE(s.connect());
    ASSERT_TRUE(s.homeAll());
    ASSERT_FALSE(s.call([&](auto cb) { s.client.move({{0, 80}}, false, 20, cb); }));
    ASSERT_TRUE(waitFor([&] { return s.firmware().machinePositionMm()[0] > 20; }, 10000));
    const std::size_t from = s.events.size();
    ASSERT_FALSE(s.call([&](auto cb) { s.client.stop(0, cb); }));
    EXPECT_GE(s.findEvent(dev::proto::EventKind::Stopped, 0, from), 0);
    ASSERT_TRUE(s.waitStill());
    EXPECT_FALSE(s.client.status().positionLost);
    EXPECT_TRUE(s.readout('X').homed);
    EXPECT_LT(s.readout('X').commanded, 79);
    EXPECT_EQ(s.firmware().alarmCode(), 0);
}
