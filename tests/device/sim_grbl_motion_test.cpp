// The simulator's GRBL personality in motion: continuous jog stopped by 0x85 and by a lost
// link, soft and hard limits, reset while moving, feed hold, the receive-buffer limit, and a
// 10 mm circle streamed as G2 arcs with the character-counting streamer.
#include "device/backends/grbl/grbl_gcode.h"
#include "device/backends/grbl/grbl_jog.h"
#include "device/backends/grbl/grbl_streamer.h"
#include "sim_grbl_support.h"

#include <cmath>

namespace {

using grbltest::Host;
using State = dev::sim::GrblFirmware::State;

/// Feeds answers back to the streamer and writes what it lets out. Returns the errors seen.
std::vector<dev::grbl::Streamer::Ack> serviceStreamer(Host& h, dev::grbl::Streamer& s)
{
    std::vector<dev::grbl::Streamer::Ack> errors;
    for (const auto& l : h.fresh()) {
        const dev::grbl::Line c = dev::grbl::classifyLine(l);
        if (c.kind == dev::grbl::LineKind::Ok || c.kind == dev::grbl::LineKind::Error) {
            const auto ack = s.acknowledge(c.kind == dev::grbl::LineKind::Ok, c.code);
            if (ack && !ack->ok)
                errors.push_back(*ack);
        }
    }
    const std::string out = s.takeOutput();
    if (!out.empty())
        h.write(out);
    return errors;
}

dev::grbl::JogPlan analyzerXJogPlan(double refreshS)
{
    dev::grbl::JogPlanInput in;
    in.speedMmS = 100;
    in.maxRateMmS = 100;   // $110 = 6000 mm/min
    in.accelMmS2 = 1500;   // $120
    in.refreshPeriodS = refreshS;
    return dev::grbl::planContinuousJog(in);
}

/// Jogs +X from X = 50 for `holdS`, then either releases (0x85) or goes silent. Returns the
/// time from release / last byte until the axis is at rest, and the distance it went since.
struct JogOutcome {
    double stopS = 0, overrunMm = 0;
    double firstRestS = -1;     ///< release → the first moment at rest (the cancel itself)
    std::size_t inFlightAtRelease = 0;
    double peakSpeedMmS = 0;
};
JogOutcome jogAndLetGo(bool release)
{
    Host h;
    h.home();
    EXPECT_EQ(h.command("G90 G0 X50"), "ok");
    EXPECT_TRUE(h.runUntil([&] { return h.fw.state() == State::Idle; }, 5));
    const dev::grbl::JogPlan plan = analyzerXJogPlan(0.1);
    EXPECT_TRUE(plan.feasible);
    dev::grbl::Streamer s(h.fw.rxBufferBytes());
    dev::grbl::ContinuousJog jog(plan, "X", {1});
    h.fresh();
    for (const auto& l : jog.start(h.now()))
        s.enqueue(l);
    serviceStreamer(h, s);
    JogOutcome o;
    double lastRefresh = h.now();
    const double until = h.now() + 1.0;
    while (h.now() < until) {
        h.run(0.001);
        const bool refresh = h.now() - lastRefresh >= 0.1 - 1e-9;
        if (refresh)
            lastRefresh = h.now();
        const std::size_t acked = s.inFlightLines();
        auto errors = serviceStreamer(h, s);
        EXPECT_TRUE(errors.empty());
        if (refresh || s.inFlightLines() < acked) {  // every refresh period and every ok
            for (const auto& l : jog.tick(h.now()))
                s.enqueue(l);
            serviceStreamer(h, s);
        }
        o.peakSpeedMmS = std::max(o.peakSpeedMmS, h.fw.machine().axis(0).referenceVelocity());
    }
    bool cancelAgain = false;
    if (release) {
        // As a GRBL host must: segments not written yet are dropped, and the jog lines still in
        // GRBL's buffer — read only after the cancel, when they start a new jog — are cancelled
        // once more when the last of them is answered.
        s.clearQueue();
        o.inFlightAtRelease = s.inFlightLines();
        cancelAgain = o.inFlightAtRelease > 0;
        s.enqueueRealtime(jog.stop());
        serviceStreamer(h, s);
    }
    const double t0 = h.now();
    const double x0 = h.fw.machine().axis(0).reference();
    EXPECT_TRUE(h.runUntil(
        [&] {
            serviceStreamer(h, s);
            if (o.firstRestS < 0 && h.fw.machine().axis(0).referenceVelocity() == 0)
                o.firstRestS = h.now() - t0;
            if (cancelAgain && s.inFlightLines() == 0) {
                cancelAgain = false;
                s.enqueueRealtime(dev::grbl::rt::kJogCancel);
                serviceStreamer(h, s);
            }
            return !cancelAgain && h.fw.machine().axis(0).referenceVelocity() == 0 && h.fw.state() == State::Idle;
        },
        2));
    o.stopS = h.now() - t0;
    o.overrunMm = h.fw.machine().axis(0).reference() - x0;
    // …and it stays stopped: nothing queued restarts it.
    const double x1 = h.fw.machine().axis(0).reference();
    h.run(0.5);
    EXPECT_DOUBLE_EQ(h.fw.machine().axis(0).reference(), x1);
    EXPECT_EQ(h.fw.lostRxBytes(), 0u);
    return o;
}

TEST(SimGrblMotion, ContinuousJogReachesFullSpeedAndStopsWithin250msOfRelease)
{
    const JogOutcome o = jogAndLetGo(true);
    EXPECT_NEAR(o.peakSpeedMmS, 100, 1e-6);            // the queue was long enough to reach the jog speed
    EXPECT_NEAR(o.firstRestS, 100.0 / 1500, 0.005);    // the cancel: v/a, no link latency in-process
    EXPECT_LE(o.stopS, 0.25);                          // with the segments read after it, cancelled again
    // v²/2a = 3.3 mm, plus at most the segments that were in GRBL's buffer at the release.
    const dev::grbl::JogPlan plan = analyzerXJogPlan(0.1);
    EXPECT_GE(o.overrunMm, 100.0 * 100 / 3000 - 0.2);
    EXPECT_LE(o.overrunMm, 100.0 * 100 / 3000 + 0.2 + o.inFlightAtRelease * plan.segmentMm);
}

TEST(SimGrblMotion, ALostHostOverrunsNoMoreThanThePlanSays)
{
    const dev::grbl::JogPlan plan = analyzerXJogPlan(0.1);
    const JogOutcome o = jogAndLetGo(false);
    EXPECT_LE(o.stopS, plan.lostLinkOverrunS + 0.002);
    EXPECT_LE(o.stopS, 0.25);
    EXPECT_LE(o.overrunMm, plan.lostLinkOverrunMm + 0.01);
}

TEST(SimGrblMotion, AJogBeyondTheTravelIsRefusedWithoutAnAlarm)
{
    Host h;
    h.home();
    EXPECT_EQ(h.command("$J=G91 G21 X-5 F600"), "error:15");
    EXPECT_EQ(h.command("$J=G53 X250 F600"), "error:15");  // X travel is 200 mm
    EXPECT_EQ(h.status().state, dev::grbl::MachineState::Idle);
    EXPECT_EQ(h.command("$J=G91 G21 X5 F600"), "ok");
}

TEST(SimGrblMotion, AMoveBeyondTheTravelAlarmsAndWaitsForAReset)
{
    Host h;
    h.home();
    h.fresh();
    h.write("G90 G1 X250 F600\n");
    h.run(0.05);
    const auto said = h.fresh();
    ASSERT_EQ(said.size(), 2u);  // and no ok: the line is never answered, the reset follows
    EXPECT_EQ(said[0], "ALARM:2");
    EXPECT_EQ(said[1], "[MSG:Reset to continue]");
    const std::size_t before = h.lines.size();
    h.write("?");
    h.run(0.05);
    EXPECT_EQ(h.lines.size(), before);  // a critical alarm does not even report status
    h.write("\x18");
    h.run(0.01);
    EXPECT_TRUE(h.received("Grbl 1.1h ['$' for help]"));
    EXPECT_EQ(h.status().state, dev::grbl::MachineState::Alarm);
    EXPECT_EQ(h.command("$X"), "ok");  // the position was kept: an unlock is enough
    EXPECT_NEAR(h.status().position[0], 0, 1e-3);
}

TEST(SimGrblMotion, AResetWhileMovingLosesThePositionAndSaysSo)
{
    Host h;
    h.home();
    h.write("G90 G1 X150 F3000\n");
    h.run(0.5);
    h.fresh();
    h.write("\x18");
    h.run(0.01);
    const auto after = h.fresh();
    ASSERT_GE(after.size(), 4u);
    EXPECT_EQ(after[0], "ALARM:3");
    EXPECT_EQ(dev::grbl::classifyLine(after[2]).kind, dev::grbl::LineKind::Banner);
    EXPECT_EQ(after[3], "[MSG:'$H'|'$X' to unlock]");
    const dev::grbl::StatusReport r = h.status();
    EXPECT_EQ(r.state, dev::grbl::MachineState::Alarm);
    EXPECT_GT(r.position[0], 5);
    EXPECT_LT(r.position[0], 150);
    EXPECT_EQ(h.command("G0 X0"), "error:9");
    // A reset at rest keeps the position and needs no unlock.
    EXPECT_EQ(h.command("$X"), "ok");
    h.fresh();
    h.write("\x18");
    h.run(0.01);
    for (const auto& l : h.fresh())
        EXPECT_NE(dev::grbl::classifyLine(l).kind, dev::grbl::LineKind::Alarm) << l;
    EXPECT_EQ(h.status().state, dev::grbl::MachineState::Idle);
}

TEST(SimGrblMotion, ALimitSwitchIsAHardLimitAlarm)
{
    Host h;
    h.home();
    EXPECT_EQ(h.command("$20=0"), "ok");  // soft limits off: the switch is all that is left
    h.write("G91 G1 X-5 F600\n");
    EXPECT_TRUE(h.runUntil([&] { return h.received("ALARM:1"); }, 2));
    EXPECT_TRUE(h.received("[MSG:Reset to continue]"));
    EXPECT_TRUE(h.fw.machine().axis(0).homeSwitch());
    h.write("\x18");
    h.run(0.01);
    EXPECT_EQ(h.command("$X"), "ok");
    EXPECT_TRUE(h.status().pinTriggered('X'));
}

TEST(SimGrblMotion, FeedHoldStopsOnThePathAndResumeFinishesTheMove)
{
    Host h;
    h.home();
    h.write("G90 G1 X100 F3000\n");
    h.run(0.5);
    h.write("!");
    h.run(0.005);
    EXPECT_EQ(h.status().subState, 1);  // Hold:1, slowing down
    EXPECT_TRUE(h.runUntil([&] { return h.fw.machine().axis(0).referenceVelocity() == 0; }, 1));
    const dev::grbl::StatusReport held = h.status();
    EXPECT_EQ(held.state, dev::grbl::MachineState::Hold);
    EXPECT_EQ(held.subState, 0);
    h.run(0.5);
    EXPECT_DOUBLE_EQ(h.status().position[0], held.position[0]);
    h.write("~");
    EXPECT_TRUE(h.runUntil([&] { return h.fw.state() == State::Idle; }, 5));
    EXPECT_NEAR(h.fw.machinePositionMm()[0], 100, 1e-9);
}

TEST(SimGrblMotion, BytesBeyondTheReceiveBufferAreLostUnlessTheHostCounts)
{
    std::vector<std::string> lines;
    for (int i = 0; i < 10; ++i)
        lines.push_back("G91 G0 X0.1 (pad pad pad " + std::to_string(i) + ")");  // 28 bytes with '\n'
    {
        Host h;
        h.command("$X");
        h.fresh();
        std::string all;
        for (const auto& l : lines)
            all += l + "\n";
        h.write(all);
        h.run(0.5);
        EXPECT_EQ(h.fw.lostRxBytes(), all.size() - 127);
        int oks = 0;
        for (const auto& l : h.fresh())
            oks += l == "ok";
        EXPECT_LT(oks, 10);  // lines went missing: the machine did not do what was sent
    }
    {
        Host h;
        h.command("$X");
        h.fresh();
        dev::grbl::Streamer s(h.fw.rxBufferBytes());
        for (const auto& l : lines)
            s.enqueue(l);
        serviceStreamer(h, s);
        EXPECT_TRUE(h.runUntil([&] { serviceStreamer(h, s); return s.idle(); }, 5));
        EXPECT_EQ(h.fw.lostRxBytes(), 0u);
        h.run(0.2);
        EXPECT_NEAR(h.fw.machinePositionMm()[0], 1.0, 1e-9);  // all ten 0.1 mm moves
    }
}

TEST(SimGrblMotion, ATenMillimetreCircleStreamedAsArcsEndsWhereItBegan)
{
    for (const auto dialect : {dev::sim::GrblFirmware::Dialect::Grbl, dev::sim::GrblFirmware::Dialect::GrblHal}) {
        Host h(dev::sim::stageConfig(), dialect);
        h.home();
        // A circle of 10 mm diameter around (45, 50), clockwise from (50, 50), at 10 mm/s.
        EXPECT_EQ(h.command("G90 G0 X50 Y50"), "ok");
        EXPECT_TRUE(h.runUntil([&] { return h.fw.state() == State::Idle; }, 10));
        dev::grbl::Streamer s(h.fw.rxBufferBytes());
        for (const auto& l : dev::grbl::circleLines(45, 50, 5, dev::grbl::ArcDirection::Clockwise, 600))
            ASSERT_EQ(s.enqueue(l.text), dev::grbl::Streamer::Queued::Ok);
        h.fresh();
        double worstRadiusErrMm = 0, t0 = h.now();
        std::size_t maxInFlight = 0;
        bool done = false;
        while (!done && h.now() - t0 < 20) {
            const auto errors = serviceStreamer(h, s);
            EXPECT_TRUE(errors.empty());
            maxInFlight = std::max(maxInFlight, s.inFlightBytes());
            h.run(0.001);
            const auto& p = h.fw.machinePositionMm();
            worstRadiusErrMm = std::max(worstRadiusErrMm, std::fabs(std::hypot(p[0] - 45, p[1] - 50) - 5));
            done = s.idle() && h.fw.state() == State::Idle;
        }
        EXPECT_TRUE(done);
        EXPECT_EQ(h.fw.lostRxBytes(), 0u);
        EXPECT_LE(maxInFlight, h.fw.rxBufferBytes() - 1);
        EXPECT_NEAR(h.fw.machinePositionMm()[0], 50, 1e-9);
        EXPECT_NEAR(h.fw.machinePositionMm()[1], 50, 1e-9);
        // Chords about GRBL's arc tolerance ($12 = 0.002 mm) inside the circle: GRBL's segment
        // count rounds down, so a chord's sagitta slightly exceeds $12 (0.0021 mm here).
        EXPECT_LE(worstRadiusErrMm, 0.0025);
        // About its length at the feed: 31.4 mm at 10 mm/s, plus starting and stopping.
        EXPECT_GT(h.now() - t0, 3.14);
        EXPECT_LT(h.now() - t0, 3.6);
        // The stage's grating agrees: the table is back within a few µm.
        EXPECT_NEAR(h.fw.machine().measuredLogical(0) - h.fw.machine().commandedLogical(0), 0, 0.005);
    }
}

} // namespace
