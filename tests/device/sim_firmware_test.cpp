// The reference firmware's protocol side, driven through encoded frames exactly
// as a host would: HELLO, replies and typed errors, retransmissions, corrupted
// frames, realtime-first handling and telemetry batches.
#include "device/protocol/event_reasons.h"
#include "device/protocol/frame_codec.h"
#include "device/protocol/messages.h"
#include "device/sim/firmware.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace {

using dev::proto::ErrorCode;
using dev::proto::MsgType;

constexpr std::uint8_t bit(int i) { return static_cast<std::uint8_t>(1u << i); }
dev::proto::WireUnits nm(double mm) { return static_cast<dev::proto::WireUnits>(std::lround(mm * 1e6)); }

/// A host at the other end of the wire: encodes requests, feeds the firmware,
/// decodes whatever comes back.
struct Host {
    dev::sim::Firmware fw;
    std::uint16_t nextSeq = 1000;  ///< helpers' own requests; tests pick small seqs by hand
    dev::proto::FrameDecoder decoder;
    std::vector<dev::proto::Frame> replies;  ///< replies and error replies, in arrival order
    std::vector<dev::proto::EventMsg> events;
    std::vector<dev::proto::TelemetryBatch> batches;

    explicit Host(const dev::sim::MachineConfig& cfg, std::uint32_t baud = 115200) : fw(cfg, baud) {}

    std::vector<std::uint8_t> frame(MsgType type, const dev::proto::Bytes& payload, std::uint16_t seq)
    {
        std::vector<std::uint8_t> wire;
        EXPECT_TRUE(dev::proto::encodeFrame(static_cast<std::uint8_t>(type), seq, payload.data(), payload.size(), wire));
        return wire;
    }
    std::uint16_t send(MsgType type, const dev::proto::Bytes& payload = {})
    {
        const std::uint16_t seq = nextSeq++;
        const auto wire = frame(type, payload, seq);
        fw.receive(wire.data(), wire.size());
        pump();
        return seq;
    }
    void sendRaw(const std::vector<std::uint8_t>& wire)
    {
        fw.receive(wire.data(), wire.size());
        pump();
    }
    void advance(double seconds)
    {
        // In 10 ms slices, as a host event loop would.
        for (double t = 0; t < seconds - 1e-9; t += 0.01) {
            fw.advance(std::min(0.01, seconds - t));
            pump();
        }
    }
    void pump()
    {
        std::vector<std::uint8_t> out;
        fw.drainOutput(out);
        std::vector<dev::proto::Frame> frames;
        decoder.feed(out.data(), out.size(), frames);
        for (auto& f : frames) {
            if (f.type == static_cast<std::uint8_t>(MsgType::Event)) {
                auto e = dev::proto::decodeEvent(f.payload);
                ASSERT_TRUE(e);
                events.push_back(*e);
            } else if (f.type == static_cast<std::uint8_t>(MsgType::TelemetryBatch)) {
                auto b = dev::proto::decodeTelemetryBatch(f.payload);
                ASSERT_TRUE(b);
                batches.push_back(*b);
            } else {
                replies.push_back(std::move(f));
            }
        }
    }
    /// The latest reply with this seq (tests reuse sequence numbers on purpose).
    const dev::proto::Frame* replyTo(std::uint16_t seq) const
    {
        for (auto it = replies.rbegin(); it != replies.rend(); ++it)
            if (it->seq == seq)
                return &*it;
        return nullptr;
    }
    std::optional<dev::proto::ErrorReply> errorFor(std::uint16_t seq) const
    {
        const auto* f = replyTo(seq);
        if (!f || f->type != static_cast<std::uint8_t>(MsgType::Error))
            return std::nullopt;
        return dev::proto::decodeErrorReply(f->payload);
    }
    bool okFor(std::uint16_t seq, MsgType type) const
    {
        const auto* f = replyTo(seq);
        return f && f->type == dev::proto::replyTypeOf(type);
    }
    dev::proto::StatusReply status()
    {
        const auto seq = send(MsgType::Status);
        const auto* f = replyTo(seq);
        EXPECT_TRUE(f && f->type == dev::proto::replyTypeOf(MsgType::Status));
        auto s = f ? dev::proto::decodeStatusReply(f->payload) : std::nullopt;
        EXPECT_TRUE(s);
        if (!s || s->axes.empty())
            return fw.machine().status();  // keep the test running to report the real failure
        return *s;
    }
};

dev::proto::Bytes moveRel(std::uint8_t mask, std::vector<double> mm)
{
    dev::proto::MoveRequest r;
    r.relative = true;
    r.axisMask = mask;
    for (double v : mm)
        r.targets.push_back(nm(v));
    return dev::proto::encode(r);
}

} // namespace

TEST(SimFirmware, HelloDescribesTheAnalyzer)
{
    Host h(dev::sim::analyzerConfig(), 115200);
    const auto seq = h.send(MsgType::Hello);
    ASSERT_TRUE(h.okFor(seq, MsgType::Hello));
    const auto hello = dev::proto::decodeHelloReply(h.replyTo(seq)->payload);
    ASSERT_TRUE(hello);
    EXPECT_EQ(hello->protocolVersion, dev::proto::kProtocolVersion);
    EXPECT_EQ(hello->kind, dev::proto::DeviceKind::Analyzer);
    EXPECT_EQ(hello->linkBaud, 115200u);
    EXPECT_EQ(hello->jogWatchdogMs, 250);
    EXPECT_EQ(hello->controlPeriodUs, 1000u);
    EXPECT_GE(hello->maxTelemetryRateHz, 100u);
    EXPECT_FALSE(hello->model.empty());
    EXPECT_FALSE(hello->firmware.empty());
    for (auto cap : {dev::proto::CapHoming, dev::proto::CapEncoder, dev::proto::CapPump, dev::proto::CapTelemetry, dev::proto::CapJogVelocity,
                     dev::proto::CapCoupledXyThenZ})
        EXPECT_TRUE(hello->capabilities & cap) << cap;
    EXPECT_FALSE(hello->capabilities & dev::proto::CapGrating);
    EXPECT_FALSE(hello->capabilities & dev::proto::CapClosedLoopPid);
    ASSERT_EQ(hello->axes.size(), 4u);
    const char letters[] = {'X', 'Y', 'Z', 'P'};
    const std::int32_t travel[] = {nm(200), nm(200), nm(100), 1000000};
    for (std::size_t i = 0; i < 4; ++i) {
        EXPECT_EQ(hello->axes[i].letter, letters[i]);
        EXPECT_EQ(hello->axes[i].travelMin, 0);
        EXPECT_EQ(hello->axes[i].travelMax, travel[i]);
        EXPECT_GT(hello->axes[i].maxSpeed, 0u);
        EXPECT_GT(hello->axes[i].resolution, 0u);
    }
    EXPECT_EQ(hello->axes[3].unit, dev::proto::AxisUnit::Microlitre);
    EXPECT_EQ(hello->axes[0].unit, dev::proto::AxisUnit::Millimetre);
    EXPECT_EQ(hello->axes[0].resolution, 2000u);  // 8 mm lead / 4000 counts
}

TEST(SimFirmware, HelloDescribesTheStage)
{
    Host h(dev::sim::stageConfig(), 921600);
    const auto seq = h.send(MsgType::Hello);
    const auto hello = dev::proto::decodeHelloReply(h.replyTo(seq)->payload);
    ASSERT_TRUE(hello);
    EXPECT_EQ(hello->kind, dev::proto::DeviceKind::Stage);
    EXPECT_EQ(hello->linkBaud, 921600u);
    EXPECT_TRUE(hello->capabilities & dev::proto::CapGrating);
    EXPECT_TRUE(hello->capabilities & dev::proto::CapClosedLoopPid);
    EXPECT_FALSE(hello->capabilities & dev::proto::CapPump);
    EXPECT_FALSE(hello->capabilities & dev::proto::CapCoupledXyThenZ);
    ASSERT_EQ(hello->axes.size(), 2u);
    EXPECT_EQ(hello->axes[0].resolution, 500u);  // 0.5 µm grating counts
    EXPECT_EQ(hello->axes[1].travelMax, nm(100));
}

TEST(SimFirmware, AbsoluteMoveUnhomedIsRefusedOverTheWire)
{
    Host h(dev::sim::analyzerConfig());
    dev::proto::MoveRequest r;
    r.axisMask = bit(2);
    r.targets = {nm(10)};
    const auto seq = h.send(MsgType::Move, dev::proto::encode(r));
    const auto e = h.errorFor(seq);
    ASSERT_TRUE(e);
    EXPECT_EQ(e->code, ErrorCode::NotHomed);
    EXPECT_EQ(e->axis, 2);
    EXPECT_NE(e->message.find("axis Z"), std::string::npos) << e->message;
}

TEST(SimFirmware, RetransmittedRequestIsExecutedOnceAndAnsweredIdentically)
{
    Host h(dev::sim::analyzerConfig());
    const auto wire = h.frame(MsgType::Move, moveRel(bit(0), {5}), 42);
    h.sendRaw(wire);
    const auto executed = h.fw.executedRequests();
    h.advance(0.05);
    // The reply was lost; the host sends the very same frame again.
    h.sendRaw(wire);
    h.sendRaw(wire);
    EXPECT_EQ(h.fw.executedRequests(), executed);
    EXPECT_EQ(h.fw.duplicateRequests(), 2u);
    ASSERT_EQ(std::count_if(h.replies.begin(), h.replies.end(), [](const dev::proto::Frame& f) { return f.seq == 42; }), 3);
    for (const auto& f : h.replies)
        if (f.seq == 42) {
            EXPECT_EQ(f.type, dev::proto::replyTypeOf(MsgType::Move));
            EXPECT_EQ(f.payload, h.replyTo(42)->payload);
        }
    h.advance(2);
    // A late retransmission, after the move finished, must not move again either.
    h.sendRaw(wire);
    h.advance(2);
    EXPECT_EQ(h.fw.executedRequests(), executed);
    EXPECT_NEAR(h.status().axes[0].commanded / 1e6, 5.0, 1e-6) << "moved once, not twice";
}

TEST(SimFirmware, RetransmittedErrorIsAnsweredWithTheSameError)
{
    Host h(dev::sim::analyzerConfig());
    dev::proto::MoveRequest r;
    r.axisMask = bit(0);
    r.targets = {nm(10)};
    const auto wire = h.frame(MsgType::Move, dev::proto::encode(r), 7);
    h.sendRaw(wire);
    h.sendRaw(wire);
    ASSERT_EQ(h.replies.size(), 2u);
    EXPECT_EQ(h.replies[0].type, static_cast<std::uint8_t>(MsgType::Error));
    EXPECT_EQ(h.replies[0].payload, h.replies[1].payload);
}

TEST(SimFirmware, SameSeqWithDifferentPayloadIsANewRequest)
{
    Host h(dev::sim::analyzerConfig());
    h.sendRaw(h.frame(MsgType::Move, moveRel(bit(0), {1}), 9));
    h.advance(1);
    h.sendRaw(h.frame(MsgType::Move, moveRel(bit(0), {2}), 9));
    h.advance(1);
    EXPECT_EQ(h.fw.duplicateRequests(), 0u);
    EXPECT_NEAR(h.status().axes[0].commanded / 1e6, 3.0, 1e-6);
}

TEST(SimFirmware, ANewSessionIsNotMistakenForRetransmissions)
{
    // Two CLI runs of `move X=+1 --relative` against one benchpilot-sim: each
    // starts its sequence numbers afresh with HELLO, so the second run's move
    // has the same seq and bytes as the first's. It must still move.
    Host h(dev::sim::analyzerConfig());
    for (int run = 0; run < 2; ++run) {
        h.sendRaw(h.frame(MsgType::Hello, {}, 1));
        h.sendRaw(h.frame(MsgType::Move, moveRel(bit(0), {1}), 2));
        h.advance(1);
    }
    EXPECT_NEAR(h.status().axes[0].commanded / 1e6, 2.0, 1e-6);
    // The last session ended on a STATUS with the seq the new HELLO has: still a new session.
    h.sendRaw(h.frame(MsgType::Status, {}, 1));
    h.sendRaw(h.frame(MsgType::Hello, {}, 1));
    h.sendRaw(h.frame(MsgType::Move, moveRel(bit(0), {1}), 2));
    h.advance(1);
    EXPECT_NEAR(h.status().axes[0].commanded / 1e6, 3.0, 1e-6);
    // A retransmitted HELLO is a retransmission like any other: answered from the
    // cache. Retransmissions within the new session are still caught (the move
    // has finished first, so a second execution could not hide behind Busy).
    const auto duplicates = h.fw.duplicateRequests();
    h.sendRaw(h.frame(MsgType::Hello, {}, 4));
    h.sendRaw(h.frame(MsgType::Hello, {}, 4));
    EXPECT_EQ(h.fw.duplicateRequests(), duplicates + 1);
    h.sendRaw(h.frame(MsgType::Move, moveRel(bit(0), {1}), 5));
    h.advance(1);
    h.sendRaw(h.frame(MsgType::Move, moveRel(bit(0), {1}), 5));
    h.advance(1);
    EXPECT_NEAR(h.status().axes[0].commanded / 1e6, 4.0, 1e-6);
}

TEST(SimFirmware, CorruptedRequestIsNeverExecuted)
{
    Host h(dev::sim::analyzerConfig());
    auto wire = h.frame(MsgType::Move, moveRel(bit(0), {5}), 3);
    // Flip one bit in every position in turn: no variant may move the machine.
    for (std::size_t i = 1; i + 1 < wire.size(); ++i) {
        auto bad = wire;
        bad[i] ^= 0x10;
        if (bad[i] == 0)
            continue;  // that would be a delimiter: a truncated frame, tested below
        h.sendRaw(bad);
    }
    auto truncated = wire;
    truncated.erase(truncated.end() - 3, truncated.end() - 1);
    h.sendRaw(truncated);
    EXPECT_EQ(h.fw.executedRequests(), 0u);
    EXPECT_TRUE(h.replies.empty());
    EXPECT_GT(h.fw.decoderStats().crcErrors + h.fw.decoderStats().malformed, wire.size() / 2);
    h.advance(0.5);
    EXPECT_EQ(h.fw.machine().status().axes[0].commanded, 0);
    // The link recovers: the good frame after the garbage works.
    const auto seq = h.send(MsgType::Move, moveRel(bit(0), {5}));
    EXPECT_TRUE(h.okFor(seq, MsgType::Move));
}

TEST(SimFirmware, UnknownTypeGetsUnknownCommand)
{
    Host h(dev::sim::analyzerConfig());
    for (std::uint8_t type : {std::uint8_t{0x1E}, std::uint8_t{0x3F}, std::uint8_t{0x00}, std::uint8_t{0x55}}) {
        std::vector<std::uint8_t> wire;
        ASSERT_TRUE(dev::proto::encodeFrame(type, 77, nullptr, 0, wire));
        h.replies.clear();
        h.sendRaw(wire);
        ASSERT_EQ(h.replies.size(), 1u) << "type " << int(type);
        const auto e = dev::proto::decodeErrorReply(h.replies[0].payload);
        ASSERT_TRUE(e);
        EXPECT_EQ(h.replies[0].seq, 77);
        EXPECT_EQ(e->code, ErrorCode::UnknownCommand);
        EXPECT_EQ(e->value, type);
    }
    // A device never answers what only a device sends.
    std::vector<std::uint8_t> wire;
    ASSERT_TRUE(dev::proto::encodeFrame(dev::proto::replyTypeOf(MsgType::Hello), 78, nullptr, 0, wire));
    h.replies.clear();
    h.sendRaw(wire);
    EXPECT_TRUE(h.replies.empty());
}

TEST(SimFirmware, MalformedPayloadGetsBadPayload)
{
    Host h(dev::sim::analyzerConfig());
    const auto seq = h.send(MsgType::Move, dev::proto::Bytes{1, 2, 3});
    const auto e = h.errorFor(seq);
    ASSERT_TRUE(e);
    EXPECT_EQ(e->code, ErrorCode::BadPayload);
    EXPECT_NE(e->message.find("MOVE"), std::string::npos);
}

TEST(SimFirmware, SubscriptionAboveLinkCapacityIsRefusedWithTheCapacity)
{
    Host h(dev::sim::analyzerConfig(), 9600);
    dev::proto::SubscribeRequest r;
    r.rateHz = 1000;
    for (std::uint8_t a = 0; a < 4; ++a) {
        r.channels.push_back({a, dev::proto::ChannelKind::Commanded});
        r.channels.push_back({a, dev::proto::ChannelKind::Measured});
    }
    const auto seq = h.send(MsgType::Subscribe, dev::proto::encode(r));
    const auto e = h.errorFor(seq);
    ASSERT_TRUE(e);
    EXPECT_EQ(e->code, ErrorCode::OverCapacity);
    // 9600 baud 8N1 carries 960 B/s; telemetry may use 90 % of it.
    EXPECT_NE(e->message.find("864 B/s"), std::string::npos) << e->message;
    EXPECT_NE(e->message.find("9600 baud"), std::string::npos) << e->message;
    EXPECT_GT(e->value, 0);
    EXPECT_LT(e->value, 1000);
    // The rate the error offers is accepted.
    r.rateHz = static_cast<std::uint32_t>(e->value);
    const auto ok = h.send(MsgType::Subscribe, dev::proto::encode(r));
    EXPECT_TRUE(h.okFor(ok, MsgType::Subscribe)) << (h.errorFor(ok) ? h.errorFor(ok)->message : "");
}

TEST(SimFirmware, TheRateOfferedInACapacityRefusalIsAlwaysAccepted)
{
    // A host that retries at the offered rate must not be refused again, whatever
    // the baud rate and channel count.
    for (std::uint32_t baud : {1200u, 9600u, 19200u, 38400u, 57600u, 115200u, 230400u, 921600u}) {
        for (std::size_t channels = 1; channels <= 8; ++channels) {
            Host h(dev::sim::analyzerConfig(), baud);
            dev::proto::SubscribeRequest r;
            r.rateHz = 10000;
            for (std::size_t c = 0; c < channels; ++c)
                r.channels.push_back({static_cast<std::uint8_t>(c % 4), static_cast<dev::proto::ChannelKind>(c / 4)});
            const auto e = h.errorFor(h.send(MsgType::Subscribe, dev::proto::encode(r)));
            if (!e)
                continue;  // the link carries the full rate
            ASSERT_EQ(e->code, ErrorCode::OverCapacity);
            if (e->value <= 0)
                continue;  // not even 1 Hz fits: nothing to retry
            r.rateHz = static_cast<std::uint32_t>(e->value);
            const auto seq = h.send(MsgType::Subscribe, dev::proto::encode(r));
            EXPECT_TRUE(h.okFor(seq, MsgType::Subscribe))
                << baud << " baud, " << channels << " channels, offered " << e->value << " Hz: "
                << (h.errorFor(seq) ? h.errorFor(seq)->message : "");
        }
    }
}

TEST(SimFirmware, ASubscriptionNeverRunsFasterThanAsked)
{
    // The sample clock divides 10 kHz; a rate in between is served by the next
    // slower one, never the next faster (which the link might not carry).
    for (std::uint32_t asked : {6000u, 3001u, 300u, 7u}) {
        Host h(dev::sim::stageConfig(), 4000000);
        dev::proto::SubscribeRequest r;
        r.rateHz = asked;
        r.channels = {{0, dev::proto::ChannelKind::Measured}};
        const auto seq = h.send(MsgType::Subscribe, dev::proto::encode(r));
        ASSERT_TRUE(h.okFor(seq, MsgType::Subscribe)) << asked;
        const auto reply = dev::proto::decodeSubscribeReply(h.replyTo(seq)->payload);
        ASSERT_TRUE(reply);
        EXPECT_LE(reply->rateHz, asked);
        EXPECT_GE(reply->rateHz, asked * 0.5);
    }
}

TEST(SimFirmware, SubscriptionBatchesAreConsecutive)
{
    Host h(dev::sim::stageConfig(), 921600);
    dev::proto::SubscribeRequest r;
    r.rateHz = 500;
    r.channels = {{0, dev::proto::ChannelKind::Measured}, {1, dev::proto::ChannelKind::Measured},
                  {dev::proto::kNoAxis, dev::proto::ChannelKind::ContourError}};
    const auto seq = h.send(MsgType::Subscribe, dev::proto::encode(r));
    ASSERT_TRUE(h.okFor(seq, MsgType::Subscribe));
    const auto reply = dev::proto::decodeSubscribeReply(h.replyTo(seq)->payload);
    ASSERT_TRUE(reply);
    EXPECT_EQ(reply->rateHz, 500u);
    ASSERT_GE(reply->samplesPerBatch, 1);
    h.advance(1.0);
    ASSERT_GE(h.batches.size(), 10u);
    std::uint32_t expectIndex = 0;
    std::uint64_t expectTimeUs = h.batches[0].firstSampleTimeUs;
    std::size_t samples = 0;
    for (const auto& b : h.batches) {
        EXPECT_EQ(b.firstSampleIndex, expectIndex);
        EXPECT_EQ(b.firstSampleTimeUs, expectTimeUs);
        EXPECT_EQ(b.periodUs, 2000u);
        EXPECT_EQ(b.channels, r.channels);
        EXPECT_EQ(b.sampleCount, reply->samplesPerBatch);
        EXPECT_EQ(b.values.size(), b.sampleCount * r.channels.size());
        expectIndex += b.sampleCount;
        expectTimeUs += std::uint64_t{b.sampleCount} * b.periodUs;
        samples += b.sampleCount;
    }
    EXPECT_NEAR(static_cast<double>(samples), 500.0, reply->samplesPerBatch + 1.0);
}

TEST(SimFirmware, TelemetryFollowsAMove)
{
    Host h(dev::sim::analyzerConfig());
    dev::proto::SubscribeRequest r;
    r.rateHz = 100;
    r.channels = {{0, dev::proto::ChannelKind::Commanded}, {0, dev::proto::ChannelKind::Switches}};
    ASSERT_TRUE(h.okFor(h.send(MsgType::Subscribe, dev::proto::encode(r)), MsgType::Subscribe));
    h.send(MsgType::Move, moveRel(bit(0), {10}));
    h.advance(1.5);
    ASSERT_FALSE(h.batches.empty());
    const auto& last = h.batches.back();
    EXPECT_EQ(last.values[last.values.size() - 2], nm(10));
    EXPECT_EQ(last.values.back(), 0);  // no switch
}

TEST(SimFirmware, UnsubscribeStopsTheBatches)
{
    Host h(dev::sim::analyzerConfig());
    dev::proto::SubscribeRequest r;
    r.rateHz = 200;
    r.channels = {{0, dev::proto::ChannelKind::Measured}};
    h.send(MsgType::Subscribe, dev::proto::encode(r));
    h.advance(0.5);
    ASSERT_FALSE(h.batches.empty());
    h.send(MsgType::Subscribe, dev::proto::encode(dev::proto::SubscribeRequest{}));
    h.batches.clear();
    h.advance(0.5);
    EXPECT_TRUE(h.batches.empty());
}

TEST(SimFirmware, BadTelemetryChannelIsRefused)
{
    Host h(dev::sim::analyzerConfig());
    dev::proto::SubscribeRequest r;
    r.rateHz = 100;
    r.channels = {{5, dev::proto::ChannelKind::Measured}};
    auto e = h.errorFor(h.send(MsgType::Subscribe, dev::proto::encode(r)));
    ASSERT_TRUE(e);
    EXPECT_EQ(e->code, ErrorCode::BadAxis);
    // The analyzer has no contour channel (it is the stage's stitching drift).
    r.channels = {{dev::proto::kNoAxis, dev::proto::ChannelKind::ContourError}};
    e = h.errorFor(h.send(MsgType::Subscribe, dev::proto::encode(r)));
    ASSERT_TRUE(e);
    r.rateHz = 20000;
    r.channels = {{0, dev::proto::ChannelKind::Measured}};
    e = h.errorFor(h.send(MsgType::Subscribe, dev::proto::encode(r)));
    ASSERT_TRUE(e);
    EXPECT_EQ(e->code, ErrorCode::OutOfRange);
}

TEST(SimFirmware, RealtimeRequestsInTheSameChunkActFirst)
{
    Host h(dev::sim::analyzerConfig());
    // One read from the serial port holds a queued move and, behind it, an E-stop.
    auto chunk = h.frame(MsgType::Move, moveRel(bit(0), {5}), 20);
    const auto estop = h.frame(MsgType::EStop, {}, 21);
    chunk.insert(chunk.end(), estop.begin(), estop.end());
    h.sendRaw(chunk);
    ASSERT_EQ(h.replies.size(), 2u);
    EXPECT_EQ(h.replies[0].seq, 21) << "the E-stop is answered first";
    EXPECT_EQ(h.replies[0].type, dev::proto::replyTypeOf(MsgType::EStop));
    const auto e = h.errorFor(20);
    ASSERT_TRUE(e) << "the move came after the E-stop";
    EXPECT_EQ(e->code, ErrorCode::EStopActive);
    h.advance(0.5);
    EXPECT_EQ(h.fw.machine().status().axes[0].commanded, 0);
}

TEST(SimFirmware, StopOvertakesAQueuedMoveInTheSameChunk)
{
    Host h(dev::sim::analyzerConfig());
    h.send(MsgType::Move, moveRel(bit(1), {50}));
    h.advance(0.3);
    // A stop for Y and a new queued move for X arrive together; the stop acts first.
    auto chunk = h.frame(MsgType::Move, moveRel(bit(0), {5}), 30);
    const auto stop = h.frame(MsgType::Stop, dev::proto::encode(dev::proto::AxisMaskRequest{bit(1)}), 31);
    chunk.insert(chunk.end(), stop.begin(), stop.end());
    h.replies.clear();
    h.sendRaw(chunk);
    ASSERT_EQ(h.replies.size(), 2u);
    EXPECT_EQ(h.replies[0].seq, 31);
    EXPECT_EQ(h.replies[1].seq, 30);
    h.advance(2);
    EXPECT_LT(h.fw.machine().status().axes[1].commanded, nm(50));
    EXPECT_EQ(h.fw.machine().status().axes[0].commanded, nm(5));
}

TEST(SimFirmware, EventsCarryKindAxisAndDeviceTime)
{
    Host h(dev::sim::analyzerConfig());
    h.send(MsgType::Move, moveRel(bit(0), {3}));
    h.advance(1);
    ASSERT_EQ(h.events.size(), 1u);
    EXPECT_EQ(h.events[0].kind, dev::proto::EventKind::MotionDone);
    EXPECT_EQ(h.events[0].axis, 0);
    EXPECT_GT(h.events[0].deviceTimeUs, 0u);
    EXPECT_LT(h.events[0].deviceTimeUs, 1000000u);
    EXPECT_NEAR(h.events[0].position, nm(3), 12000);  // encoder: the first move takes up half the 20 µm play
    h.send(MsgType::EStop);
    ASSERT_EQ(h.events.size(), 2u);
    EXPECT_EQ(h.events[1].kind, dev::proto::EventKind::EStop);
    EXPECT_TRUE(h.status().deviceFlags & dev::proto::DeviceEStop);
    const auto reset = h.send(MsgType::Reset);
    EXPECT_TRUE(h.okFor(reset, MsgType::Reset));
    EXPECT_FALSE(h.status().deviceFlags & dev::proto::DeviceEStop);
}

TEST(SimFirmware, EventsCarryTheirReasonOnlyToAHostThatAskedForIt)
{
    Host h(dev::sim::stageConfig());
    auto session = [&](std::uint8_t flags) {
        const auto seq = h.send(MsgType::Hello, dev::proto::encode(dev::proto::HelloRequest{flags}));
        ASSERT_TRUE(h.okFor(seq, MsgType::Hello));
        h.events.clear();
        h.send(MsgType::EStop);
        h.send(MsgType::Reset);
        ASSERT_EQ(h.events.size(), 2u);
    };
    session(dev::proto::HelloReadsExtensions);
    EXPECT_FALSE(h.events[0].reason) << "a host that did not ask reads the text alone";
    EXPECT_EQ(h.events[0].text, "emergency stop: all motion halted");

    session(dev::proto::HelloReadsExtensions | dev::proto::HelloReadsEventReasons);
    ASSERT_TRUE(h.events[0].reason);
    EXPECT_EQ(h.events[0].reason->code, dev::proto::reason::kAllHalted);
    ASSERT_TRUE(h.events[1].reason);
    EXPECT_EQ(h.events[1].reason->code, dev::proto::reason::kCleared);
    EXPECT_FALSE(h.events[0].text.empty()) << "and still the text, for a person reading the wire";

    session(0);
    EXPECT_FALSE(h.events[0].reason) << "the choice is the session's: a new HELLO makes it again";
}

TEST(SimFirmware, JogOverTheWireStopsWhenRefreshesStop)
{
    Host h(dev::sim::stageConfig());
    dev::proto::JogVelocityRequest j;
    j.axisMask = bit(0);
    j.velocities = {nm(10)};
    for (int n = 0; n < 10; ++n) {  // refreshed at 20 Hz for 0.5 s
        h.send(MsgType::JogVelocity, dev::proto::encode(j));
        h.advance(0.05);
    }
    // Silence. Within 250 ms of the last refresh the axis is at rest and said so.
    h.advance(0.25);
    EXPECT_FALSE(h.status().axes[0].flags & dev::proto::AxisMoving);
    const bool expired = std::any_of(h.events.begin(), h.events.end(),
                                     [](const dev::proto::EventMsg& e) { return e.kind == dev::proto::EventKind::JogExpired; });
    EXPECT_TRUE(expired);
}

TEST(SimFirmware, AHostThatStopsReadingLosesTelemetryNotMemory)
{
    Host h(dev::sim::stageConfig(), 921600);
    dev::proto::SubscribeRequest r;
    r.rateHz = 1000;
    r.channels = {{0, dev::proto::ChannelKind::Measured}, {1, dev::proto::ChannelKind::Measured}};
    ASSERT_TRUE(h.okFor(h.send(MsgType::Subscribe, dev::proto::encode(r)), MsgType::Subscribe));
    h.fw.advance(60.0);  // a minute without draining
    std::vector<std::uint8_t> out;
    h.fw.drainOutput(out);
    EXPECT_LE(out.size(), dev::sim::Firmware::kMaxPendingOutputBytes + 2048);
    EXPECT_GT(h.fw.droppedTelemetryBatches(), 0u);
    // Replies still get through, and the next batches show the gap.
    const auto seq = h.send(MsgType::Status);
    EXPECT_TRUE(h.okFor(seq, MsgType::Status));
    h.batches.clear();
    h.advance(0.1);
    ASSERT_FALSE(h.batches.empty());
    EXPECT_GT(h.batches.front().firstSampleIndex, 50000u);
}

TEST(SimFirmware, NonFiniteOrNegativeTimeIsIgnored)
{
    Host h(dev::sim::analyzerConfig());
    h.fw.advance(std::nan(""));
    h.fw.advance(-1.0);
    h.fw.advance(std::numeric_limits<double>::infinity());
    h.fw.advance(0.01);
    EXPECT_EQ(h.fw.machine().timeUs(), 10000u);
}

TEST(SimFirmware, AdvanceRunsWholeTicksAndCarriesTheRemainder)
{
    Host h(dev::sim::analyzerConfig());
    for (int i = 0; i < 1000; ++i)
        h.fw.advance(0.00025);  // 2.5 ticks each
    EXPECT_EQ(h.fw.machine().timeUs(), 250000u);
}

TEST(SimFirmware, ALateVelocityCommandNeverRestartsAStoppedAxis)
{
    // A host retries a velocity command whose reply the line lost; meanwhile it
    // stopped the jog. The retry (same seq, answered from the cache) and a copy
    // numbered before the stop (a retry whose first attempt never arrived) must
    // leave the axis at rest.
    Host h(dev::sim::stageConfig());
    dev::proto::JogVelocityRequest j;
    j.axisMask = bit(0);
    j.velocities = {nm(10)};
    const auto jog = h.frame(MsgType::JogVelocity, dev::proto::encode(j), 10);
    const auto neverArrived = h.frame(MsgType::JogVelocity, dev::proto::encode(j), 11);
    h.sendRaw(jog);
    h.advance(0.1);
    ASSERT_TRUE(h.status().axes[0].flags & dev::proto::AxisMoving);
    h.nextSeq = 12;
    ASSERT_TRUE(h.okFor(h.send(MsgType::Stop, dev::proto::encode(dev::proto::AxisMaskRequest{bit(0)})), MsgType::Stop));
    ASSERT_TRUE(h.okFor(12, MsgType::Stop));
    h.advance(0.5);
    ASSERT_FALSE(h.status().axes[0].flags & dev::proto::AxisMoving);
    const double stoppedAt = h.status().axes[0].commanded / 1e6;

    const auto executed = h.fw.executedRequests();
    h.sendRaw(jog);           // a retry of the first: answered from the cache
    h.sendRaw(neverArrived);  // sent before the stop, arrives after it
    EXPECT_TRUE(h.okFor(10, MsgType::JogVelocity));
    EXPECT_TRUE(h.okFor(11, MsgType::JogVelocity)) << "a late copy is answered, so the host stops retrying it";
    h.advance(0.3);
    EXPECT_FALSE(h.status().axes[0].flags & dev::proto::AxisMoving);
    EXPECT_NEAR(h.status().axes[0].commanded / 1e6, stoppedAt, 1e-9) << "the stopped axis moved again";
    EXPECT_EQ(h.fw.staleVelocityRequests(), 1u);
    EXPECT_EQ(h.fw.executedRequests(), executed + 2) << "only the two status requests ran";

    // A fresh command after the stop still works.
    h.send(MsgType::JogVelocity, dev::proto::encode(j));
    h.advance(0.1);
    EXPECT_TRUE(h.status().axes[0].flags & dev::proto::AxisMoving);
}

TEST(SimFirmware, ARetryAfterTwoHundredOtherRequestsIsStillAnsweredFromTheCache)
{
    // A host that retries one request for seconds while status polls go on.
    Host h(dev::sim::analyzerConfig());
    const auto wire = h.frame(MsgType::Move, moveRel(bit(0), {2}), 500);
    h.sendRaw(wire);
    h.nextSeq = 501;
    for (int i = 0; i < 200; ++i)
        h.send(MsgType::Status);
    const auto executed = h.fw.executedRequests();
    h.sendRaw(wire);
    EXPECT_EQ(h.fw.executedRequests(), executed);
    h.advance(3);
    EXPECT_NEAR(h.status().axes[0].commanded / 1e6, 2.0, 1e-6) << "moved once, not twice";
}
