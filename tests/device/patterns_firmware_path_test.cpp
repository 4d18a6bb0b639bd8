// The path queue through the firmware's wire: replies carry the fill state, realtime hold and
// clear overtake queued requests, a silent host gets a feed hold, a new session ends the path.
#include "device/backends/benchpilot/path_wire.h"
#include "device/protocol/frame_codec.h"
#include "device/protocol/messages_path.h"
#include "device/sim/firmware.h"
#include "device/sim/path_queue.h"

#include <gtest/gtest.h>

namespace {

using dev::proto::MsgType;

struct Wire {
    dev::sim::Firmware fw{dev::sim::stageConfig(), 115200};
    std::uint16_t seq = 1;
    dev::proto::FrameDecoder decoder;
    std::vector<dev::proto::Frame> replies;
    std::vector<dev::proto::EventMsg> events;

    std::uint16_t send(MsgType type, const dev::proto::Bytes& payload = {})
    {
        std::vector<std::uint8_t> wire;
        dev::proto::encodeFrame(static_cast<std::uint8_t>(type), seq, payload.data(), payload.size(), wire);
        fw.receive(wire.data(), wire.size());
        pump();
        return seq++;
    }
    void pump()
    {
        std::vector<std::uint8_t> out;
        fw.drainOutput(out);
        std::vector<dev::proto::Frame> frames;
        decoder.feed(out.data(), out.size(), frames);
        for (auto& f : frames) {
            if (f.type == static_cast<std::uint8_t>(MsgType::Event))
                events.push_back(*dev::proto::decodeEvent(f.payload));
            else if (f.type != static_cast<std::uint8_t>(MsgType::TelemetryBatch))
                replies.push_back(f);
        }
    }
    /// Runs the clock; with `keepTalking` the host polls STATUS every 50 ms as BenchPilot does.
    void advance(double s, bool keepTalking)
    {
        for (double t = 0; t < s; t += 0.01) {
            fw.advance(0.01);
            pump();
            if (keepTalking && static_cast<long>(t * 100) % 5 == 0)
                send(MsgType::Status);
        }
    }
    const dev::proto::Frame& reply(std::uint16_t s) const
    {
        for (auto it = replies.rbegin(); it != replies.rend(); ++it)
            if (it->seq == s)
                return *it;
        static dev::proto::Frame none;
        ADD_FAILURE() << "no reply to seq " << s;
        return none;
    }
    dev::proto::PathStatusReply pathStatus(std::uint16_t s) const
    {
        const auto& f = reply(s);
        auto d = dev::proto::decodePathStatusReply(f.payload);
        EXPECT_TRUE(d) << "type 0x" << std::hex << int(f.type);
        return d ? *d : dev::proto::PathStatusReply{};
    }
    int count(dev::proto::EventKind k) const
    {
        int n = 0;
        for (const auto& e : events)
            n += e.kind == k;
        return n;
    }
    void homeAndBegin()
    {
        send(MsgType::Hello);
        send(MsgType::Home, dev::proto::encode(dev::proto::HomeRequest{0}));
        advance(30, true);
        ASSERT_TRUE(fw.machine().homed(0) && fw.machine().homed(1));
        const auto b = send(MsgType::PathBegin, dev::proto::encode(dev::proto::PathBeginRequest{}));
        ASSERT_EQ(reply(b).type, 0x90);
    }
    std::uint16_t appendLine(std::uint32_t index, double x, double y, std::uint8_t flags, double feed = 10)
    {
        dev::proto::PathAppendRequest a;
        a.firstIndex = index;
        a.flags = flags;
        motion::path::Segment s;
        s.end = {x, y};
        s.feedMmS = feed;
        a.segments = {dev::toWire(s)};
        return send(MsgType::PathAppend, dev::proto::encode(a));
    }
};

}  // namespace

TEST(PatternsFirmwarePath, AppendRepliesWithTheFillState)
{
    Wire w;
    w.homeAndBegin();
    const auto s = w.appendLine(0, 30, 0, 0);
    const auto st = w.pathStatus(s);
    EXPECT_EQ(w.reply(s).type, 0x91);
    EXPECT_EQ(st.state, dev::proto::PathState::Filling);
    EXPECT_EQ(st.capacity, 32);
    EXPECT_EQ(st.freeSlots, 31);
    EXPECT_EQ(st.nextIndex, 1u);
    const auto q = w.send(MsgType::PathStatus);
    EXPECT_EQ(w.reply(q).type, 0x92);
    EXPECT_EQ(w.pathStatus(q).nextIndex, 1u);
    // A retransmitted append (same seq and bytes) is answered from the cache, not queued twice.
    dev::proto::PathAppendRequest a;
    a.firstIndex = 1;
    a.segments = {dev::toWire(motion::path::Segment{motion::path::SegmentKind::Line, {30, 0}, {30, 20}, {}, 10, {}})};
    const auto payload = dev::proto::encode(a);
    std::vector<std::uint8_t> wire;
    dev::proto::encodeFrame(0x11, 500, payload.data(), payload.size(), wire);
    w.fw.receive(wire.data(), wire.size());
    w.fw.receive(wire.data(), wire.size());
    w.pump();
    EXPECT_EQ(w.fw.machine().paths().status().nextIndex, 2u);
    EXPECT_EQ(w.fw.duplicateRequests(), 1u);
}

TEST(PatternsFirmwarePath, ASilentHostGetsAFeedHoldOnThePath)
{
    Wire w;
    w.homeAndBegin();
    w.appendLine(0, 90, 0, dev::proto::PathAppendStart | dev::proto::PathAppendLast);
    w.advance(0.5, true);
    ASSERT_TRUE(w.fw.machine().paths().moving());
    w.advance(0.9, false);  // quiet, but not for long enough
    EXPECT_EQ(w.fw.machine().paths().state(), dev::proto::PathState::Running);
    w.advance(1.0, false);
    EXPECT_EQ(w.fw.machine().paths().state(), dev::proto::PathState::Held);
    EXPECT_EQ(w.fw.machine().paths().status().reason, dev::proto::PathReason::HostSilent);
    EXPECT_EQ(w.count(dev::proto::EventKind::PathHeld), 1);
    const double x = w.fw.machine().commandedLogical(0);
    EXPECT_LT(x, 90);
    w.advance(1.0, false);
    EXPECT_EQ(w.fw.machine().commandedLogical(0), x);  // at rest, waiting
    w.send(MsgType::PathResume);                       // the host is back (same session)
    w.advance(12, true);
    EXPECT_EQ(w.fw.machine().paths().state(), dev::proto::PathState::Done);
    EXPECT_NEAR(w.fw.machine().commandedLogical(0), 90, 1e-3);
}

TEST(PatternsFirmwarePath, ANewSessionEndsThePathItDidNotQueue)
{
    Wire w;
    w.homeAndBegin();
    w.appendLine(0, 90, 0, dev::proto::PathAppendStart | dev::proto::PathAppendLast);
    w.advance(0.5, true);
    w.seq = 1;  // a restarted host numbers afresh and opens with HELLO
    w.send(MsgType::Hello);
    w.advance(2.0, true);
    const auto st = w.fw.machine().paths().status();
    EXPECT_EQ(st.state, dev::proto::PathState::Aborted);
    EXPECT_EQ(st.reason, dev::proto::PathReason::NewSession);
    EXPECT_EQ(st.executingIndex, 0u);  // segment 0 was not completed: a restart begins there
    EXPECT_EQ(w.count(dev::proto::EventKind::PathAborted), 1);
    EXPECT_LT(w.fw.machine().commandedLogical(0), 90);
}

TEST(PatternsFirmwarePath, ClearOvertakesQueuedRequestsAndStopsOnThePath)
{
    Wire w;
    w.homeAndBegin();
    w.appendLine(0, 60, 60, dev::proto::PathAppendStart | dev::proto::PathAppendLast);
    w.advance(1.0, true);
    // CLEAR and a STATUS in one read: the realtime request is acted on first.
    std::vector<std::uint8_t> wire;
    dev::proto::encodeFrame(0x12, 900, nullptr, 0, wire);
    dev::proto::encodeFrame(0x26, 901, nullptr, 0, wire);
    w.fw.receive(wire.data(), wire.size());
    w.pump();
    ASSERT_GE(w.replies.size(), 2u);
    EXPECT_EQ(w.replies[w.replies.size() - 2].seq, 901);
    EXPECT_EQ(w.pathStatus(900).state, dev::proto::PathState::Holding);
    w.advance(1.0, true);
    EXPECT_EQ(w.fw.machine().paths().status().reason, dev::proto::PathReason::Cleared);
    const double x = w.fw.machine().commandedLogical(0), y = w.fw.machine().commandedLogical(1);
    EXPECT_NEAR(x, y, 1e-3);  // stopped on the diagonal it was running along
    const auto again = w.appendLine(1, 10, 10, 0);
    EXPECT_EQ(w.reply(again).type, 0xFF);
}

TEST(PatternsFirmwarePath, ASpedUpSimulatorJudgesHostSilenceOnTheHostsClock)
{
    // At ten times real time the host's 50 ms polls are 0.5 s of device time, and one second of
    // the host's silence is ten of the device's: a path must not be held for the clock's speed.
    Wire w;
    w.fw.setHostSilenceLimitS(10.0);
    w.homeAndBegin();
    w.appendLine(0, 90, 0, dev::proto::PathAppendStart | dev::proto::PathAppendLast, 5);
    w.advance(0.5, true);
    w.advance(5.0, false);
    EXPECT_EQ(w.fw.machine().paths().state(), dev::proto::PathState::Running);
    w.advance(6.0, false);
    EXPECT_EQ(w.fw.machine().paths().state(), dev::proto::PathState::Held);
}
