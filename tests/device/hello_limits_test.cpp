// HELLO's motion-limits extension (docs/protocol.md, "HELLO"), both ways of being old:
//  - an older host sends an empty HELLO: the reply is byte for byte protocol 1.0's, which
//    the 1.0 decoder (strict: nothing may trail the axes) reads;
//  - an older device refuses a HELLO with a payload (BadPayload), as 1.0 firmware did, and
//    answers the empty HELLO a host then sends;
//  - the new reply carries the simulator's real planner limits, and a block of an id the
//    host does not know is carried past, not fatal.
#include "device/protocol/frame_codec.h"
#include "device/protocol/messages.h"
#include "device/sim/firmware.h"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>

namespace {

using namespace dev::proto;

/// What the firmware answers to one HELLO with this payload.
struct Answer {
    std::uint8_t type = 0;
    Bytes payload;
};

Answer helloTo(dev::sim::Firmware& fw, const Bytes& payload, std::uint16_t seq)
{
    std::vector<std::uint8_t> wire;
    EXPECT_TRUE(encodeFrame(static_cast<std::uint8_t>(MsgType::Hello), seq, payload.data(), payload.size(), wire));
    fw.receive(wire.data(), wire.size());
    std::vector<std::uint8_t> out;
    fw.drainOutput(out);
    FrameDecoder d;
    std::vector<Frame> frames;
    d.feed(out.data(), out.size(), frames);
    EXPECT_EQ(frames.size(), 1u);
    if (frames.empty())
        return {};
    return {frames[0].type, frames[0].payload};
}

std::uint32_t u32(double v) { return static_cast<std::uint32_t>(std::lround(v)); }

/// Protocol 1.0's HELLO reply layout: 23 fixed bytes around the two strings, 18 per axis.
std::size_t v10Size(const HelloReply& h) { return 23 + h.model.size() + h.firmware.size() + 18 * h.axes.size(); }

TEST(HelloLimits, AnEmptyHelloIsAnsweredExactlyAsProtocol10Did)
{
    dev::sim::Firmware fw(dev::sim::stageConfig(), 115200);
    const Answer a = helloTo(fw, {}, 1);
    ASSERT_EQ(a.type, replyTypeOf(MsgType::Hello));
    const auto h = decodeHelloReply(a.payload);
    ASSERT_TRUE(h);
    // Nothing after the axes: a 1.0 host's decoder, which insists on that, reads it.
    EXPECT_EQ(a.payload.size(), v10Size(*h));
    EXPECT_FALSE(h->motionLimits);
    HelloReply plain = *h;
    EXPECT_EQ(encode(plain), a.payload);
}

TEST(HelloLimits, AHostThatAsksGetsThePlannersLimits)
{
    dev::sim::Firmware fw(dev::sim::stageConfig(), 115200);
    const Answer a = helloTo(fw, encode(HelloRequest{HelloReadsExtensions}), 1);
    ASSERT_EQ(a.type, replyTypeOf(MsgType::Hello));
    const auto h = decodeHelloReply(a.payload);
    ASSERT_TRUE(h);
    ASSERT_TRUE(h->motionLimits);
    // The 1.0 part is unchanged; the block follows it.
    EXPECT_EQ(a.payload.size(), v10Size(*h) + 1 + 3 + 1 + 16 * 2);
    const MotionLimits& l = *h->motionLimits;
    EXPECT_EQ(l.profile, MotionProfile::JerkLimited);
    ASSERT_EQ(l.axes.size(), 2u);
    const auto cfg = dev::sim::stageConfig();
    for (std::size_t i = 0; i < 2; ++i) {
        EXPECT_EQ(l.axes[i].maxAccel, u32(cfg.axes[i].maxAccel * 1e3)) << "µm/s²";
        EXPECT_EQ(l.axes[i].maxJerk, u32(cfg.axes[i].maxJerk * 1e3)) << "µm/s³";
        EXPECT_EQ(l.axes[i].defaultSpeed, u32(cfg.axes[i].defaultSpeed * 1e6)) << "nm/s";
        EXPECT_EQ(l.axes[i].minAccelTimeUs, 0u);
    }
}

TEST(HelloLimits, TheAnalyzerStatesItsSeedSCurve)
{
    dev::sim::Firmware fw(dev::sim::analyzerConfig(), 115200);
    const auto h = decodeHelloReply(helloTo(fw, encode(HelloRequest{HelloReadsExtensions}), 1).payload);
    ASSERT_TRUE(h && h->motionLimits);
    const MotionLimits& l = *h->motionLimits;
    EXPECT_EQ(l.profile, MotionProfile::SeedSCurve);
    ASSERT_EQ(l.axes.size(), 4u);
    // X: 1500 mm/s², seed 000's 0.1 s acceleration phase; the S-curve's largest jerk is
    // 4·a/t2 = 60 000 mm/s³ (reached at 100 mm/s, X's top speed).
    EXPECT_EQ(l.axes[0].maxAccel, 1500000u);
    EXPECT_EQ(l.axes[0].minAccelTimeUs, 100000u);
    EXPECT_EQ(l.axes[0].maxJerk, 60000000u);
    EXPECT_EQ(l.axes[0].defaultSpeed, 50000000u);
    // The pump in nL: 5000 µL/s² and a 100 µL/s default.
    EXPECT_EQ(l.axes[3].maxAccel, 5000000u);
    EXPECT_EQ(l.axes[3].defaultSpeed, 100000u);
}

TEST(HelloLimits, AnOlderDeviceRefusesThePayloadAndAnswersTheEmptyHello)
{
    dev::sim::Firmware fw(dev::sim::stageConfig(), 115200);
    fw.setHelloExtensions(false);  // as protocol 1.0 firmware
    const Answer refused = helloTo(fw, encode(HelloRequest{HelloReadsExtensions}), 1);
    ASSERT_EQ(refused.type, static_cast<std::uint8_t>(MsgType::Error));
    const auto e = decodeErrorReply(refused.payload);
    ASSERT_TRUE(e);
    EXPECT_EQ(e->code, ErrorCode::BadPayload);
    // What the host sends next, with a fresh seq.
    const Answer plain = helloTo(fw, {}, 2);
    ASSERT_EQ(plain.type, replyTypeOf(MsgType::Hello));
    const auto h = decodeHelloReply(plain.payload);
    ASSERT_TRUE(h);
    EXPECT_FALSE(h->motionLimits);
}

TEST(HelloLimits, AHelloPayloadOfMoreThanItsFlagsIsRefused)
{
    dev::sim::Firmware fw(dev::sim::stageConfig(), 115200);
    const Answer a = helloTo(fw, {1, 0}, 1);
    EXPECT_EQ(a.type, static_cast<std::uint8_t>(MsgType::Error));
}

HelloReply stageHello()
{
    HelloReply h;
    h.kind = DeviceKind::Stage;
    h.model = "m";
    h.firmware = "f";
    h.axes = {{'X', AxisUnit::Millimetre, 0, 100000000, 20000000, 500}, {'Y', AxisUnit::Millimetre, 0, 100000000, 20000000, 500}};
    h.motionLimits = MotionLimits{MotionProfile::Trapezoid, {{100000, 0, 5000000, 0}, {200000, 0, 5000000, 0}}};
    return h;
}

TEST(HelloLimits, AnUnknownBlockIsCarriedAndKnownOnesStillRead)
{
    HelloReply h = stageHello();
    h.otherBlocks = {{7, {1, 2, 3}}};
    const Bytes b = encode(h);
    const auto d = decodeHelloReply(b);
    ASSERT_TRUE(d);
    ASSERT_TRUE(d->motionLimits);
    EXPECT_EQ(d->motionLimits->axes[1].maxAccel, 200000u);
    ASSERT_EQ(d->otherBlocks.size(), 1u);
    EXPECT_EQ(d->otherBlocks[0], (HelloBlock{7, {1, 2, 3}}));
    EXPECT_EQ(encode(*d), b);
}

TEST(HelloLimits, TheDecoderRefusesMalformedBlocks)
{
    const Bytes good = encode(stageHello());
    ASSERT_TRUE(decodeHelloReply(good));
    const std::size_t blocksAt = v10Size(stageHello());
    Bytes zeroBlocks(good.begin(), good.begin() + static_cast<std::ptrdiff_t>(blocksAt));
    zeroBlocks.push_back(0);
    EXPECT_FALSE(decodeHelloReply(zeroBlocks)) << "a block count of 0";
    Bytes badProfile = good;
    badProfile[blocksAt + 4] = 4;
    EXPECT_FALSE(decodeHelloReply(badProfile)) << "an unknown profile";
    Bytes shortBlock = good;
    shortBlock[blocksAt + 2] = static_cast<std::uint8_t>(shortBlock[blocksAt + 2] - 16);  // one axis' entry missing
    EXPECT_FALSE(decodeHelloReply(shortBlock)) << "a limits block without an entry per axis";
    HelloReply twice = stageHello();
    twice.otherBlocks = {{1, {0}}};
    EXPECT_FALSE(decodeHelloReply(encode(twice))) << "block ids not strictly increasing";
}

TEST(HelloLimits, TheRequestsFlagsByte)
{
    EXPECT_EQ(decodeHelloRequest({})->flags, 0);
    EXPECT_EQ(decodeHelloRequest({1})->flags, HelloReadsExtensions);
    EXPECT_FALSE(decodeHelloRequest({1, 0}));
    EXPECT_EQ(encode(HelloRequest{HelloReadsExtensions}), (Bytes{1}));
}

} // namespace
