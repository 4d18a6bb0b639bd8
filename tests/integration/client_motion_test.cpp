// BenchPilotClient + in-process simulator over a loopback pair at 115200 baud:
// what an operator sees when connecting, homing, moving, jogging, hitting a
// switch or the E-stop, and being refused.
#include "sim_session.h"

#include <QSignalSpy>

#include <gtest/gtest.h>

#include <cmath>

using namespace itest;
using K = dev::proto::EventKind;
using dev::LinkState;
using dev::RequestError;

namespace {

QString letters(const dev::DeviceIdentity& id)
{
    QString s;
    for (const auto& a : id.axes)
        s += a.letter;
    return s;
}

std::string text(const QStringList& l) { return l.join(QStringLiteral(" | ")).toStdString(); }

/// The device's own refusal inside a client's "ACTION refused: CAUSE": the
/// device.refused message with its code's term, the axis letter and the
/// firmware's words ("detail"); empty when the error is not shaped so.
motion::msg::Message deviceRefusal(const RequestError& e)
{
    if (e.message.id != "request.refused")
        return {};
    return motion::msg::nested(e.message, "cause");
}

} // namespace

TEST(ClientOverLoopback, AnalyzerConnectsThroughIdentifiedToReadyWithItsIdentity)
{
    SimSession s(dev::proto::DeviceKind::Analyzer);
    QSignalSpy states(&s.client, &dev::BenchPilotClient::stateChanged);
    QSignalSpy identified(&s.client, &dev::BenchPilotClient::identified);
    ASSERT_TRUE(s.connect()) << text(s.linkErrors);

    std::vector<LinkState> seen;
    for (const auto& args : states)
        seen.push_back(args.at(0).value<LinkState>());
    EXPECT_EQ(seen, (std::vector<LinkState>{LinkState::Connecting, LinkState::Identified, LinkState::Ready}));
    EXPECT_EQ(identified.count(), 1);

    const auto& id = s.client.identity();
    EXPECT_EQ(id.kind, dev::proto::DeviceKind::Analyzer);
    EXPECT_EQ(id.protocolVersion, dev::proto::kProtocolVersion);
    EXPECT_FALSE(id.model.isEmpty());
    EXPECT_EQ(letters(id), QStringLiteral("XYZP"));
    EXPECT_EQ(id.jogWatchdogMs, 250);
    EXPECT_TRUE(id.protocolCapabilities & dev::proto::CapEncoder);
    EXPECT_TRUE(id.protocolCapabilities & dev::proto::CapPump);
    EXPECT_TRUE(s.client.capabilities().testFlag(dev::Capability::MeasuredPosition));
    EXPECT_TRUE(s.client.capabilities().testFlag(dev::Capability::Pump));
    EXPECT_FALSE(s.client.capabilities().testFlag(dev::Capability::PidGains));
    EXPECT_DOUBLE_EQ(id.axes[0].travelMax, 200.0);
    EXPECT_DOUBLE_EQ(id.axes[2].travelMax, 100.0);
    EXPECT_EQ(id.axes[3].unit, dev::proto::AxisUnit::Microlitre);
    EXPECT_DOUBLE_EQ(id.axes[3].travelMax, 1000.0);

    // Ready means limits, a first status and telemetry are in hand. Until homing,
    // positions count from where the axes stood at power-up (X at 57.3 mm).
    ASSERT_EQ(s.client.softLimits().size(), 4);
    EXPECT_NEAR(s.client.softLimits()[0].max - s.client.softLimits()[0].min, 200.0, 1e-6);
    ASSERT_EQ(s.client.status().axes.size(), 4);
    for (const auto& a : s.client.status().axes)
        EXPECT_FALSE(a.homed);
    EXPECT_GT(s.client.subscribedRateHz(), 0);
    EXPECT_TRUE(waitFor([&] { return s.client.stats().telemetrySamples > 10; }, 3000));
    EXPECT_TRUE(s.linkErrors.isEmpty()) << text(s.linkErrors);
}

TEST(ClientOverLoopback, StageIdentifiesWithGratingAxesXY)
{
    SimSession s(dev::proto::DeviceKind::Stage);
    ASSERT_TRUE(s.connect()) << text(s.linkErrors);
    const auto& id = s.client.identity();
    EXPECT_EQ(id.kind, dev::proto::DeviceKind::Stage);
    EXPECT_EQ(letters(id), QStringLiteral("XY"));
    EXPECT_TRUE(id.protocolCapabilities & dev::proto::CapGrating);
    EXPECT_TRUE(s.client.capabilities().testFlag(dev::Capability::PidGains));
    EXPECT_DOUBLE_EQ(id.axes[0].travelMax, 100.0);
    EXPECT_NEAR(id.axes[0].resolution, 0.0005, 1e-9);
}

TEST(ClientOverLoopback, AnalyzerHomesZFirstThenMovesOnTargetWithinEncoderTolerance)
{
    SimSession s(dev::proto::DeviceKind::Analyzer, kUnpaced);
    ASSERT_TRUE(s.connect()) << text(s.linkErrors);
    ASSERT_TRUE(s.homeAll()) << text(s.linkErrors);

    const int x = s.axis('X'), y = s.axis('Y'), z = s.axis('Z'), p = s.axis('P');
    for (int i : {x, y, z, p}) {
        EXPECT_EQ(s.countEvents(K::HomeDone, i), 1) << "axis " << i;
        EXPECT_TRUE(s.client.status().axes[i].homed);
        EXPECT_NEAR(s.client.status().axes[i].commanded, 0.0, 1e-6);
    }
    // Homing moved the origin: the soft limits shown are the travel again.
    ASSERT_EQ(s.client.softLimits().size(), 4);
    EXPECT_NEAR(s.client.softLimits()[x].min, 0.0, 1e-6);
    EXPECT_NEAR(s.client.softLimits()[x].max, 200.0, 1e-6);
    EXPECT_NEAR(s.client.softLimits()[z].max, 100.0, 1e-6);
    EXPECT_NEAR(s.client.softLimits()[p].max, 1000.0, 1e-6);
    // The needle is lifted clear before X and Y sweep: Z reports home first.
    EXPECT_LT(s.findEvent(K::HomeDone, z), s.findEvent(K::HomeDone, x));
    EXPECT_LT(s.findEvent(K::HomeDone, z), s.findEvent(K::HomeDone, y));

    const std::size_t mark = s.events.size();
    s.link.host().setTimeScale(5);
    const auto err = s.call([&](auto cb) { s.client.move({{x, 120.5}, {y, 80.25}, {z, 40.0}, {p, 500.0}}, false, 0, cb); });
    ASSERT_FALSE(err) << motion::msg::debugString(err->message);
    for (int i : {x, y, z, p})
        ASSERT_TRUE(s.waitEvent(K::MotionDone, i, mark)) << "no MotionDone on axis " << i;
    s.link.host().setTimeScale(1);
    ASSERT_TRUE(s.waitStill());

    // Z follows XY: it is done after both of them.
    EXPECT_GT(s.findEvent(K::MotionDone, z, mark), s.findEvent(K::MotionDone, x, mark));
    EXPECT_GT(s.findEvent(K::MotionDone, z, mark), s.findEvent(K::MotionDone, y, mark));

    const auto& st = s.client.status();
    const double target[] = {120.5, 80.25, 40.0, 500.0};
    for (int i : {x, y, z, p}) {
        EXPECT_NEAR(st.axes[i].commanded, target[i], 1e-6) << "axis " << i;
        EXPECT_FALSE(st.axes[i].moving);
    }
    for (int i : {x, y, z})
        EXPECT_NEAR(st.axes[i].measured, target[i], 0.05) << "encoder of axis " << i;
    EXPECT_NEAR(st.axes[p].measured, 500.0, 0.5) << "pump encoder (µL)";
    EXPECT_EQ(s.countEvents(K::LostSteps, SimSession::kAnyAxis), 0);
    EXPECT_TRUE(s.failures.empty());
}

TEST(ClientOverLoopback, StageMovesOnTargetWithinTwoMicronsOfTheGrating)
{
    SimSession s(dev::proto::DeviceKind::Stage, kUnpaced);
    ASSERT_TRUE(s.connect()) << text(s.linkErrors);
    ASSERT_TRUE(s.homeAll()) << text(s.linkErrors);
    const int x = s.axis('X'), y = s.axis('Y');

    struct Target { double x, y; };
    for (const Target t : {Target{12.5, 87.3}, Target{90.0, 30.0}, Target{45.678, 45.679}}) {
        const std::size_t mark = s.events.size();
        s.link.host().setTimeScale(10);
        const auto err = s.call([&](auto cb) { s.client.move({{x, t.x}, {y, t.y}}, false, 20.0, cb); });
        ASSERT_FALSE(err) << motion::msg::debugString(err->message);
        ASSERT_TRUE(s.waitEvent(K::MotionDone, x, mark));
        ASSERT_TRUE(s.waitEvent(K::MotionDone, y, mark));
        s.link.host().setTimeScale(1);
        ASSERT_TRUE(s.waitStill());
        const auto& st = s.client.status();
        EXPECT_NEAR(st.axes[x].measured, t.x, 0.002) << "grating X after moving to " << t.x;
        EXPECT_NEAR(st.axes[y].measured, t.y, 0.002) << "grating Y after moving to " << t.y;
        // Settled inside the window, not merely passing through it.
        for (int i : {x, y})
            EXPECT_TRUE(s.events[std::size_t(s.findEvent(K::MotionDone, i, mark))].text.isEmpty())
                << s.events[std::size_t(s.findEvent(K::MotionDone, i, mark))].text.toStdString();
    }
}

TEST(ClientOverLoopback, AbsoluteMoveOnUnhomedAxisIsRefusedNamingTheAxis)
{
    SimSession s(dev::proto::DeviceKind::Analyzer);
    ASSERT_TRUE(s.connect()) << text(s.linkErrors);
    const int y = s.axis('Y');
    const double before = s.readout('Y').commanded;

    const auto err = s.call([&](auto cb) { s.client.move({{y, 50.0}}, false, 0, cb); });
    ASSERT_TRUE(err);
    EXPECT_EQ(err->kind, RequestError::Kind::Device);
    EXPECT_EQ(err->code, dev::proto::ErrorCode::NotHomed);
    EXPECT_EQ(err->axis, y);
    const motion::msg::Message why = deviceRefusal(*err);
    EXPECT_EQ(why.id, "device.refused") << err->message;
    EXPECT_EQ(why.text("code"), "device.error.not_homed") << err->message;
    EXPECT_EQ(why.text("axis"), "Y") << err->message;
    EXPECT_NE(why.text("detail").find("axis Y"), std::string::npos) << err->message;
    EXPECT_NE(why.text("detail").find("not homed"), std::string::npos) << err->message;
    // A status bar listening to requestFailed hears the same reason.
    ASSERT_FALSE(s.failures.empty());
    EXPECT_EQ(s.failures.back().code, dev::proto::ErrorCode::NotHomed);

    spin(200);
    ASSERT_TRUE(s.waitStill());
    EXPECT_DOUBLE_EQ(s.readout('Y').commanded, before);
    EXPECT_DOUBLE_EQ(s.link.machine().commandedLogical(y), before);

    // A relative move is what an unhomed axis may do.
    const auto rel = s.call([&](auto cb) { s.client.move({{y, 2.0}}, true, 0, cb); });
    EXPECT_FALSE(rel) << rel->message;
    EXPECT_TRUE(s.waitEvent(K::MotionDone, y));
}

TEST(ClientOverLoopback, MoveBeyondSoftLimitIsRefusedWithReasonAndLimit)
{
    SimSession s(dev::proto::DeviceKind::Stage, kUnpaced);
    ASSERT_TRUE(s.connect()) << text(s.linkErrors);
    ASSERT_TRUE(s.homeAll()) << text(s.linkErrors);
    const int x = s.axis('X'), y = s.axis('Y');

    ASSERT_FALSE(s.call([&](auto cb) { s.client.setSoftLimits(x, 5.0, 60.0, cb); }));
    EXPECT_DOUBLE_EQ(s.client.softLimits()[x].min, 5.0);
    EXPECT_DOUBLE_EQ(s.client.softLimits()[x].max, 60.0);

    auto err = s.call([&](auto cb) { s.client.move({{x, 75.0}}, false, 0, cb); });
    ASSERT_TRUE(err);
    EXPECT_EQ(err->code, dev::proto::ErrorCode::SoftLimit);
    EXPECT_EQ(err->axis, x);
    EXPECT_NEAR(err->value, 60.0, 1e-6);
    EXPECT_EQ(deviceRefusal(*err).text("code"), "device.error.soft_limit") << err->message;
    EXPECT_EQ(deviceRefusal(*err).text("axis"), "X") << err->message;
    EXPECT_NE(deviceRefusal(*err).text("detail").find("upper soft limit"), std::string::npos) << err->message;
    EXPECT_NE(deviceRefusal(*err).text("detail").find("60.000"), std::string::npos) << err->message;

    err = s.call([&](auto cb) { s.client.move({{x, 2.0}}, false, 0, cb); });
    ASSERT_TRUE(err);
    EXPECT_EQ(err->code, dev::proto::ErrorCode::SoftLimit);
    EXPECT_NEAR(err->value, 5.0, 1e-6);
    EXPECT_NE(deviceRefusal(*err).text("detail").find("lower soft limit"), std::string::npos) << err->message;

    // Relative moves are checked against the same limits.
    err = s.call([&](auto cb) { s.client.move({{x, 61.0}}, true, 0, cb); });
    ASSERT_TRUE(err);
    EXPECT_EQ(err->code, dev::proto::ErrorCode::SoftLimit);

    // The default limits are the travel.
    err = s.call([&](auto cb) { s.client.move({{y, 100.5}}, false, 0, cb); });
    ASSERT_TRUE(err);
    EXPECT_EQ(err->code, dev::proto::ErrorCode::SoftLimit);
    EXPECT_EQ(err->axis, y);
    EXPECT_NEAR(err->value, 100.0, 1e-6);

    ASSERT_TRUE(s.waitStill());
    EXPECT_NEAR(s.readout('X').commanded, 0.0, 1e-6) << "a refused move must not move";
    EXPECT_NEAR(s.readout('Y').commanded, 0.0, 1e-6);

    // Inside the limits the move goes.
    s.link.host().setTimeScale(10);
    const std::size_t mark = s.events.size();
    EXPECT_FALSE(s.call([&](auto cb) { s.client.move({{x, 59.5}}, false, 20.0, cb); }));
    EXPECT_TRUE(s.waitEvent(K::MotionDone, x, mark));
    s.link.host().setTimeScale(1);
    ASSERT_TRUE(s.waitStill());

    // Zeroing here moves the origin: the limits read 59.5 mm lower, and are enforced so.
    ASSERT_FALSE(s.call([&](auto cb) { s.client.setZero(quint8(1u << x), cb); }));
    ASSERT_TRUE(waitFor([&] { return std::abs(s.client.softLimits()[x].max - 0.5) < 1e-6; }, 3000))
        << "limits shown after zeroing: " << s.client.softLimits()[x].min << " … " << s.client.softLimits()[x].max;
    EXPECT_NEAR(s.client.softLimits()[x].min, -54.5, 1e-6);
    err = s.call([&](auto cb) { s.client.move({{x, 1.0}}, false, 0, cb); });
    ASSERT_TRUE(err);
    EXPECT_EQ(err->code, dev::proto::ErrorCode::SoftLimit);
    EXPECT_NEAR(err->value, 0.5, 1e-6);
}

TEST(ClientOverLoopback, HoldToJogMovesWhileHeldAndStopsOnRelease)
{
    SimSession s(dev::proto::DeviceKind::Analyzer);
    ASSERT_TRUE(s.connect()) << text(s.linkErrors);
    const int x = s.axis('X');
    const double start = s.readout('X').commanded;

    s.client.startJog(x, 20.0);
    EXPECT_TRUE(s.client.isJogging(x));
    ASSERT_TRUE(waitFor([&] { return s.readout('X').jogging && s.readout('X').moving; }, 3000));
    // Held for a second: four times the device's watchdog, so only the client's
    // refreshes keep it going (without them it would stop after ~4 mm).
    spin(1000);
    EXPECT_TRUE(s.readout('X').jogging);
    const std::size_t mark = s.events.size();
    s.client.stopJog(x);
    EXPECT_FALSE(s.client.isJogging(x));
    ASSERT_TRUE(s.waitEvent(K::MotionDone, x, mark));
    ASSERT_TRUE(s.waitStill());

    const double travelled = s.readout('X').commanded - start;
    EXPECT_GT(travelled, 8.0) << "a 1 s hold at 20 mm/s went only " << travelled << " mm";
    EXPECT_LT(travelled, 60.0);
    EXPECT_FALSE(s.readout('X').jogging);

    // Released means released: the axis stays put.
    const double parked = s.link.machine().commandedLogical(x);
    spin(400);
    EXPECT_DOUBLE_EQ(s.link.machine().commandedLogical(x), parked);

    // And the other way.
    s.client.startJog(x, -10.0);
    ASSERT_TRUE(waitFor([&] { return s.readout('X').commanded < parked - 1.0; }, 3000));
    const std::size_t mark2 = s.events.size();
    s.client.stopJog(x);
    ASSERT_TRUE(s.waitEvent(K::MotionDone, x, mark2));
    EXPECT_LT(s.link.machine().commandedLogical(x), parked - 1.0);
}

TEST(ClientOverLoopback, UnhomedRelativeMoveIntoTheLimitSwitchStopsWithLimitHit)
{
    SimSession s(dev::proto::DeviceKind::Analyzer, kUnpaced);
    ASSERT_TRUE(s.connect()) << text(s.linkErrors);
    const int x = s.axis('X');
    const double start = s.readout('X').commanded;

    s.link.host().setTimeScale(10);
    const auto err = s.call([&](auto cb) { s.client.move({{x, 250.0}}, true, 0, cb); });
    ASSERT_FALSE(err) << motion::msg::debugString(err->message);
    ASSERT_TRUE(s.waitEvent(K::LimitHit, x)) << "no LimitHit on X";
    s.link.host().setTimeScale(1);
    const auto& hit = s.events[std::size_t(s.findEvent(K::LimitHit, x))];
    EXPECT_TRUE(hit.text.contains(QStringLiteral("limit switch"))) << hit.text.toStdString();
    // X started 57.3 mm from its home switch; its limit switch closes 0.5 mm past 200 mm.
    EXPECT_NEAR(hit.position - start, 200.5 - 57.3, 1.0);

    ASSERT_TRUE(s.waitStill());
    EXPECT_TRUE(s.readout('X').limitSwitch);
    EXPECT_FALSE(s.readout('X').moving);
    EXPECT_LT(s.readout('X').commanded, start + 200.0) << "the switch, not the target, ended the move";

    // Backing off the switch is allowed.
    const std::size_t mark = s.events.size();
    EXPECT_FALSE(s.call([&](auto cb) { s.client.move({{x, -5.0}}, true, 0, cb); }));
    ASSERT_TRUE(s.waitEvent(K::MotionDone, x, mark));
    ASSERT_TRUE(s.waitStill());
    EXPECT_FALSE(s.readout('X').limitSwitch);
}

TEST(ClientOverLoopback, EStopDuringMoveHaltsAndRefusesMovesUntilReset)
{
    SimSession s(dev::proto::DeviceKind::Analyzer);
    ASSERT_TRUE(s.connect()) << text(s.linkErrors);
    const int x = s.axis('X');
    const double start = s.readout('X').commanded;

    ASSERT_FALSE(s.call([&](auto cb) { s.client.move({{x, 60.0}}, true, 0, cb); }));
    ASSERT_TRUE(waitFor([&] { return s.link.machine().commandedLogical(x) > start + 5.0; }, 5000));
    const std::size_t mark = s.events.size();
    const auto err = s.call([&](auto cb) { s.client.estop(cb); });
    ASSERT_FALSE(err) << motion::msg::debugString(err->message);
    ASSERT_TRUE(s.waitEvent(K::EStop, -1, mark));
    ASSERT_TRUE(waitFor([&] { return s.client.status().estop && !s.readout('X').moving; }, 3000));

    // Halted where it was, short of the target, and it stays there.
    const double halted = s.link.machine().commandedLogical(x);
    EXPECT_LT(halted, start + 59.0);
    spin(300);
    EXPECT_DOUBLE_EQ(s.link.machine().commandedLogical(x), halted);
    EXPECT_EQ(s.countEvents(K::MotionDone, x, mark), 0);

    auto refused = s.call([&](auto cb) { s.client.move({{x, 1.0}}, true, 0, cb); });
    ASSERT_TRUE(refused);
    EXPECT_EQ(refused->code, dev::proto::ErrorCode::EStopActive);
    EXPECT_EQ(deviceRefusal(*refused).text("code"), "device.error.estop_active") << refused->message;
    refused = s.call([&](auto cb) { s.client.home(0, cb); });
    ASSERT_TRUE(refused);
    EXPECT_EQ(refused->code, dev::proto::ErrorCode::EStopActive);
    // A jog press is refused too, and the client stops refreshing it.
    const std::size_t failuresBefore = s.failures.size();
    s.client.startJog(x, 10.0);
    ASSERT_TRUE(waitFor([&] { return s.failures.size() > failuresBefore; }, 3000));
    EXPECT_EQ(s.failures.back().code, dev::proto::ErrorCode::EStopActive);
    EXPECT_FALSE(s.client.isJogging(x));
    EXPECT_DOUBLE_EQ(s.link.machine().commandedLogical(x), halted);

    const std::size_t markReset = s.events.size();
    ASSERT_FALSE(s.call([&](auto cb) { s.client.reset(cb); }));
    ASSERT_TRUE(s.waitEvent(K::Reset, -1, markReset));
    ASSERT_TRUE(waitFor([&] { return !s.client.status().estop; }, 3000));
    ASSERT_FALSE(s.call([&](auto cb) { s.client.move({{x, 1.0}}, true, 0, cb); }));
    ASSERT_TRUE(s.waitEvent(K::MotionDone, x, markReset));
    EXPECT_NEAR(s.link.machine().commandedLogical(x), halted + 1.0, 1e-6);
}
