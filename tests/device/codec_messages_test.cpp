// Protocol v1 payloads: every message's encode/decode round trip, its exact byte
// layout, and the decoders' strictness (short, long, unknown enum values).
#include "device/protocol/bytes.h"
#include "device/protocol/messages_arch.h"
#include "device/protocol/messages.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace {

using namespace dev::proto;

/// Decoding `valid` succeeds; every strict prefix and `valid` + one byte fail.
template <typename T>
void expectStrict(const Bytes& valid, std::optional<T> (*decode)(const Bytes&), const char* what)
{
    ASSERT_TRUE(decode(valid).has_value()) << what;
    for (std::size_t n = 0; n < valid.size(); ++n) {
        const Bytes prefix(valid.begin(), valid.begin() + static_cast<std::ptrdiff_t>(n));
        EXPECT_FALSE(decode(prefix).has_value()) << what << ": accepted a prefix of " << n << " of " << valid.size();
    }
    for (std::uint8_t extra : {std::uint8_t{0x00}, std::uint8_t{0xFF}}) {
        Bytes longer = valid;
        longer.push_back(extra);
        EXPECT_FALSE(decode(longer).has_value()) << what << ": accepted a trailing byte";
    }
}

Bytes with(Bytes b, std::size_t at, std::uint8_t v)
{
    b.at(at) = v;
    return b;
}

HelloReply sampleHello()
{
    HelloReply h;
    h.protocolVersion = 1;
    h.kind = DeviceKind::Stage;
    h.capabilities = CapHoming | CapGrating | CapClosedLoopPid | CapTelemetry | CapJogVelocity;
    h.controlPeriodUs = 1000;
    h.maxTelemetryRateHz = 10000;
    h.jogWatchdogMs = 250;
    h.linkBaud = 115200;
    h.model = "Stage µ";
    h.firmware = "fw 1.0";
    h.axes = {{'X', AxisUnit::Millimetre, 0, 100000000, 20000000, 500},
              {'P', AxisUnit::Microlitre, -5, 1000000, 500000, 50}};
    return h;
}

// ---- round trips and layouts ----------------------------------------------------

TEST(CodecMessages, HelloRoundTripAndLayout)
{
    const HelloReply h = sampleHello();
    const Bytes b = encode(h);
    const std::size_t model = h.model.size(), fw = h.firmware.size();
    ASSERT_EQ(b.size(), 23 + model + fw + 18 * 2);
    EXPECT_EQ(b[0], 1);                 // version
    EXPECT_EQ(b[1], 2);                 // stage
    EXPECT_EQ(b[2], 0x6D);              // capabilities LE: 0x0000006D
    EXPECT_EQ(b[3], 0x00);
    EXPECT_EQ(b[6], 0xE8);              // control period 1000 = 0x03E8
    EXPECT_EQ(b[7], 0x03);
    EXPECT_EQ(b[14], 0xFA);             // watchdog 250
    EXPECT_EQ(b[15], 0x00);
    EXPECT_EQ(b[16], 0x00);             // 115200 = 0x0001C200
    EXPECT_EQ(b[17], 0xC2);
    EXPECT_EQ(b[18], 0x01);
    EXPECT_EQ(b[20], model);
    EXPECT_EQ(b[21 + model], fw);
    EXPECT_EQ(b[22 + model + fw], 2);   // axis count
    const std::size_t a1 = 23 + model + fw + 18;
    EXPECT_EQ(b[a1], 'P');
    EXPECT_EQ(b[a1 + 1], 1);            // µL
    EXPECT_EQ(b[a1 + 2], 0xFB);         // travelMin −5
    EXPECT_EQ(b[a1 + 5], 0xFF);

    const auto d = decodeHelloReply(b);
    ASSERT_TRUE(d);
    EXPECT_EQ(d->protocolVersion, 1);
    EXPECT_EQ(d->kind, DeviceKind::Stage);
    EXPECT_EQ(d->capabilities, h.capabilities);
    EXPECT_EQ(d->controlPeriodUs, 1000u);
    EXPECT_EQ(d->maxTelemetryRateHz, 10000u);
    EXPECT_EQ(d->jogWatchdogMs, 250);
    EXPECT_EQ(d->linkBaud, 115200u);
    EXPECT_EQ(d->model, "Stage µ");
    EXPECT_EQ(d->firmware, "fw 1.0");
    ASSERT_EQ(d->axes.size(), 2u);
    EXPECT_EQ(d->axes[0].letter, 'X');
    EXPECT_EQ(d->axes[0].unit, AxisUnit::Millimetre);
    EXPECT_EQ(d->axes[0].travelMax, 100000000);
    EXPECT_EQ(d->axes[0].maxSpeed, 20000000u);
    EXPECT_EQ(d->axes[0].resolution, 500u);
    EXPECT_EQ(d->axes[1].letter, 'P');
    EXPECT_EQ(d->axes[1].unit, AxisUnit::Microlitre);
    EXPECT_EQ(d->axes[1].travelMin, -5);
    EXPECT_EQ(d->axes[1].travelMax, 1000000);
    EXPECT_EQ(encode(*d), b);
}

TEST(CodecMessages, StatusRoundTripAndLayout)
{
    StatusReply s;
    s.deviceFlags = DeviceEStop | DeviceFault;
    s.deviceTimeUs = 0x0102030405060708ull;
    s.axes = {{-1, 2147483647, AxisHomed | AxisMoving}, {INT32_MIN, 0, 0xFFFF}};
    const Bytes b = encode(s);
    ASSERT_EQ(b.size(), 10u + 10 * 2);
    EXPECT_EQ(b[0], 0x03);
    EXPECT_EQ(b[1], 0x08);
    EXPECT_EQ(b[8], 0x01);
    EXPECT_EQ(b[9], 2);
    EXPECT_EQ(b[10], 0xFF);  // commanded −1
    EXPECT_EQ(b[13], 0xFF);
    EXPECT_EQ(b[17], 0x7F);  // measured INT32_MAX, high byte
    EXPECT_EQ(b[18], 0x03);  // flags
    EXPECT_EQ(b[19], 0x00);
    const auto d = decodeStatusReply(b);
    ASSERT_TRUE(d);
    EXPECT_EQ(d->deviceFlags, 3);
    EXPECT_EQ(d->deviceTimeUs, 0x0102030405060708ull);
    ASSERT_EQ(d->axes.size(), 2u);
    EXPECT_EQ(d->axes[0].commanded, -1);
    EXPECT_EQ(d->axes[0].measured, 2147483647);
    EXPECT_EQ(d->axes[0].flags, AxisHomed | AxisMoving);
    EXPECT_EQ(d->axes[1].commanded, INT32_MIN);
    EXPECT_EQ(d->axes[1].flags, 0xFFFF);
    EXPECT_EQ(encode(*d), b);
    // Zero axes is a valid (if odd) status.
    const auto empty = decodeStatusReply(encode(StatusReply{}));
    ASSERT_TRUE(empty);
    EXPECT_TRUE(empty->axes.empty());
}

TEST(CodecMessages, SingleByteMaskRequests)
{
    EXPECT_EQ(encode(HomeRequest{0x05}), (Bytes{0x05}));
    EXPECT_EQ(encode(AxisMaskRequest{0x00}), (Bytes{0x00}));
    EXPECT_EQ(decodeHomeRequest({0xFF})->axisMask, 0xFF);
    EXPECT_EQ(decodeAxisMaskRequest({0x03})->axisMask, 0x03);
    EXPECT_FALSE(decodeHomeRequest({}));
    EXPECT_FALSE(decodeHomeRequest({1, 2}));
    EXPECT_FALSE(decodeAxisMaskRequest({}));
    EXPECT_FALSE(decodeAxisMaskRequest({1, 2}));
}

TEST(CodecMessages, MoveRoundTripAndLayout)
{
    MoveRequest m;
    m.relative = true;
    m.speed = 20000000;  // 20 mm/s
    m.axisMask = 0b1010;
    m.targets = {-1500000, 12345678};
    const Bytes b = encode(m);
    EXPECT_EQ(b, (Bytes{0x01, 0x00, 0x2D, 0x31, 0x01, 0x0A, 0xA0, 0x1C, 0xE9, 0xFF, 0x4E, 0x61, 0xBC, 0x00}));
    const auto d = decodeMoveRequest(b);
    ASSERT_TRUE(d);
    EXPECT_TRUE(d->relative);
    EXPECT_EQ(d->speed, 20000000u);
    EXPECT_EQ(d->axisMask, 0b1010);
    EXPECT_EQ(d->targets, (std::vector<WireUnits>{-1500000, 12345678}));
    EXPECT_EQ(encode(*d), b);

    // All eight axes.
    MoveRequest all;
    all.axisMask = 0xFF;
    all.targets = {1, 2, 3, 4, 5, 6, 7, 8};
    const auto d8 = decodeMoveRequest(encode(all));
    ASSERT_TRUE(d8);
    EXPECT_FALSE(d8->relative);
    EXPECT_EQ(d8->targets, all.targets);
}

TEST(CodecMessages, JogStepRoundTripAndLayout)
{
    const JogStepRequest j{2, -10000, 5000000};
    const Bytes b = encode(j);
    EXPECT_EQ(b, (Bytes{0x02, 0xF0, 0xD8, 0xFF, 0xFF, 0x40, 0x4B, 0x4C, 0x00}));
    const auto d = decodeJogStepRequest(b);
    ASSERT_TRUE(d);
    EXPECT_EQ(d->axis, 2);
    EXPECT_EQ(d->delta, -10000);
    EXPECT_EQ(d->speed, 5000000u);
}

TEST(CodecMessages, LimitsRoundTrip)
{
    LimitsReply l;
    l.axes = {{0, 200000000}, {-5, 5}, {INT32_MIN, INT32_MAX}};
    const Bytes b = encode(l);
    ASSERT_EQ(b.size(), 1u + 8 * 3);
    EXPECT_EQ(b[0], 3);
    const auto d = decodeLimitsReply(b);
    ASSERT_TRUE(d);
    ASSERT_EQ(d->axes.size(), 3u);
    EXPECT_EQ(d->axes[0].max, 200000000);
    EXPECT_EQ(d->axes[1].min, -5);
    EXPECT_EQ(d->axes[2].min, INT32_MIN);
    EXPECT_EQ(d->axes[2].max, INT32_MAX);

    const SetLimitsRequest s{1, {-1000, 99000000}};
    const Bytes sb = encode(s);
    EXPECT_EQ(sb, (Bytes{0x01, 0x18, 0xFC, 0xFF, 0xFF, 0xC0, 0x9E, 0xE6, 0x05}));
    const auto sd = decodeSetLimitsRequest(sb);
    ASSERT_TRUE(sd);
    EXPECT_EQ(sd->axis, 1);
    EXPECT_EQ(sd->limits.min, -1000);
    EXPECT_EQ(sd->limits.max, 99000000);
}

TEST(CodecMessages, JogVelocityRoundTripAndLayout)
{
    const JogVelocityRequest j{0b0101, {-5000000, 0}};
    const Bytes b = encode(j);
    EXPECT_EQ(b, (Bytes{0x05, 0xC0, 0xB4, 0xB3, 0xFF, 0x00, 0x00, 0x00, 0x00}));
    const auto d = decodeJogVelocityRequest(b);
    ASSERT_TRUE(d);
    EXPECT_EQ(d->axisMask, 0b0101);
    EXPECT_EQ(d->velocities, (std::vector<std::int32_t>{-5000000, 0}));
}

TEST(CodecMessages, SubscribeRoundTripAndLayout)
{
    SubscribeRequest s;
    s.rateHz = 200;
    s.channels = {{0, ChannelKind::Commanded}, {1, ChannelKind::Switches}, {kNoAxis, ChannelKind::ContourError}};
    const Bytes b = encode(s);
    EXPECT_EQ(b, (Bytes{0xC8, 0x00, 0x00, 0x00, 0x03, 0x00, 0x00, 0x01, 0x05, 0xFF, 0x06}));
    const auto d = decodeSubscribeRequest(b);
    ASSERT_TRUE(d);
    EXPECT_EQ(d->rateHz, 200u);
    ASSERT_EQ(d->channels.size(), 3u);
    EXPECT_TRUE(d->channels[2] == (ChannelRef{kNoAxis, ChannelKind::ContourError}));
    // Unsubscribe: rate 0, no channels.
    const auto off = decodeSubscribeRequest(encode(SubscribeRequest{}));
    ASSERT_TRUE(off);
    EXPECT_EQ(off->rateHz, 0u);
    EXPECT_TRUE(off->channels.empty());

    const SubscribeReply r{1000, 20};
    const Bytes rb = encode(r);
    EXPECT_EQ(rb, (Bytes{0xE8, 0x03, 0x00, 0x00, 0x14, 0x00}));
    const auto rd = decodeSubscribeReply(rb);
    ASSERT_TRUE(rd);
    EXPECT_EQ(rd->rateHz, 1000u);
    EXPECT_EQ(rd->samplesPerBatch, 20);
}

TEST(CodecMessages, TelemetryBatchRoundTripAndLayout)
{
    TelemetryBatch t;
    t.firstSampleIndex = 40;
    t.firstSampleTimeUs = 1234567;
    t.periodUs = 1000;
    t.channels = {{0, ChannelKind::Measured}, {1, ChannelKind::Velocity}};
    t.sampleCount = 3;
    t.values = {1, -1, 2, -2, 3, -3};
    const Bytes b = encode(t);
    ASSERT_EQ(b.size(), telemetryHeaderBytes(2) + 4 * 6);
    EXPECT_EQ(telemetryHeaderBytes(2), 23u);
    EXPECT_EQ(b[0], 40);
    EXPECT_EQ(b[16], 2);     // channel count
    EXPECT_EQ(b[18], 1);     // first channel: Measured
    EXPECT_EQ(b[21], 3);     // sample count LE
    EXPECT_EQ(b[22], 0);
    EXPECT_EQ(b[23], 1);     // sample 0, channel 0
    EXPECT_EQ(b[27], 0xFF);  // sample 0, channel 1 = −1
    const auto d = decodeTelemetryBatch(b);
    ASSERT_TRUE(d);
    EXPECT_EQ(d->firstSampleIndex, 40u);
    EXPECT_EQ(d->firstSampleTimeUs, 1234567u);
    EXPECT_EQ(d->periodUs, 1000u);
    EXPECT_EQ(d->channels, t.channels);
    EXPECT_EQ(d->sampleCount, 3);
    EXPECT_EQ(d->values, t.values);
    EXPECT_EQ(encode(*d), b);

    // Sample count and value bytes must agree.
    EXPECT_FALSE(decodeTelemetryBatch(with(b, 21, 2)));
    EXPECT_FALSE(decodeTelemetryBatch(with(b, 21, 4)));
    // No channels: only a zero-byte value block is consistent.
    TelemetryBatch none;
    none.sampleCount = 5;
    const auto dn = decodeTelemetryBatch(encode(none));
    ASSERT_TRUE(dn);
    EXPECT_EQ(dn->sampleCount, 5);
    EXPECT_TRUE(dn->values.empty());
}

TEST(CodecMessages, EventAndErrorRoundTripAndLayout)
{
    EventMsg e;
    e.kind = EventKind::LimitHit;
    e.axis = 1;
    e.deviceTimeUs = 2500000;
    e.position = -250000;
    e.text = "hi";
    const Bytes b = encode(e);
    EXPECT_EQ(b, (Bytes{0x03, 0x01, 0xA0, 0x25, 0x26, 0x00, 0x00, 0x00, 0x00, 0x00, 0x70, 0x2F, 0xFC, 0xFF, 0x02, 'h', 'i'}));
    const auto d = decodeEvent(b);
    ASSERT_TRUE(d);
    EXPECT_EQ(d->kind, EventKind::LimitHit);
    EXPECT_EQ(d->axis, 1);
    EXPECT_EQ(d->deviceTimeUs, 2500000u);
    EXPECT_EQ(d->position, -250000);
    EXPECT_EQ(d->text, "hi");

    ErrorReply r;
    r.code = ErrorCode::NotHomed;
    r.axis = kNoAxis;
    r.value = 7;
    r.message = "";
    const Bytes rb = encode(r);
    EXPECT_EQ(rb, (Bytes{0x04, 0xFF, 0x07, 0x00, 0x00, 0x00, 0x00}));
    const auto rd = decodeErrorReply(rb);
    ASSERT_TRUE(rd);
    EXPECT_EQ(rd->code, ErrorCode::NotHomed);
    EXPECT_EQ(rd->axis, kNoAxis);
    EXPECT_EQ(rd->value, 7);
    EXPECT_TRUE(rd->message.empty());

    // Every defined kind and code decodes, and has a name.
    for (int k = 1; k <= 9; ++k) {
        EventMsg ek;
        ek.kind = static_cast<EventKind>(k);
        const auto dk = decodeEvent(encode(ek));
        ASSERT_TRUE(dk) << k;
        EXPECT_EQ(static_cast<int>(dk->kind), k);
        EXPECT_STRNE(eventKindName(ek.kind), "unknown event");
    }
    for (int c = 1; c <= 10; ++c) {
        ErrorReply ec;
        ec.code = static_cast<ErrorCode>(c);
        const auto dc = decodeErrorReply(encode(ec));
        ASSERT_TRUE(dc) << c;
        EXPECT_EQ(static_cast<int>(dc->code), c);
        EXPECT_STRNE(errorCodeName(ec.code), "unknown error");
    }
}

TEST(CodecMessages, AnEventsReasonFollowsItsTextAndIsCheckedLikeTheRest)
{
    EventMsg e{EventKind::LimitHit, 1, 2500000, -250000, "hi", EventReason{2, {0.5, -1.25}}};
    const Bytes b = encode(e);
    const Bytes plain = encode(EventMsg{EventKind::LimitHit, 1, 2500000, -250000, "hi", std::nullopt});
    ASSERT_EQ(b.size(), plain.size() + 2 + 16);
    EXPECT_TRUE(std::equal(plain.begin(), plain.end(), b.begin())) << "the reason is appended: the fields before it keep their places";
    // code, count, then each value as an IEEE 754 double, little-endian: 0.5 = 0x3FE0000000000000.
    EXPECT_EQ(Bytes(b.begin() + static_cast<std::ptrdiff_t>(plain.size()), b.begin() + static_cast<std::ptrdiff_t>(plain.size()) + 10),
              (Bytes{0x02, 0x02, 0, 0, 0, 0, 0, 0, 0xE0, 0x3F}));
    const auto d = decodeEvent(b);
    ASSERT_TRUE(d);
    ASSERT_TRUE(d->reason);
    EXPECT_EQ(*d->reason, (EventReason{2, {0.5, -1.25}}));
    EXPECT_EQ(encode(*d), b);
    EXPECT_FALSE(decodeEvent(plain)->reason) << "an event without one (an older device, or a host that did not ask)";
    EXPECT_TRUE(decodeEvent(encode(EventMsg{EventKind::EStop, kNoAxis, 1, 0, "", EventReason{1, {}}}))->reason);

    // Anything between the text and a whole reason is refused, as is a byte after it.
    for (std::size_t n = plain.size() + 1; n < b.size(); ++n)
        EXPECT_FALSE(decodeEvent(Bytes(b.begin(), b.begin() + static_cast<std::ptrdiff_t>(n)))) << n;
    Bytes longer = b;
    longer.push_back(0);
    EXPECT_FALSE(decodeEvent(longer));
    EXPECT_FALSE(decodeEvent(with(b, plain.size(), 0))) << "code 0 is not a reason";
    EXPECT_FALSE(decodeEvent(encode(EventMsg{EventKind::Fault, 0, 1, 2, "x", EventReason{1, std::vector<double>(9, 1.0)}})))
        << "at most 8 values";
    for (double bad : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()})
        EXPECT_FALSE(decodeEvent(encode(EventMsg{EventKind::Fault, 0, 1, 2, "x", EventReason{1, {bad}}})));
}

TEST(CodecMessages, StringsAreCutAt255BytesOnACharacterBoundary)
{
    ErrorReply r;
    r.message = std::string(300, 'a');
    auto d = decodeErrorReply(encode(r));
    ASSERT_TRUE(d);
    EXPECT_EQ(d->message, std::string(255, 'a'));

    // "µ" is two bytes (C2 B5); cutting between them would leave invalid UTF-8.
    r.message = std::string(254, 'a') + "µµ";
    d = decodeErrorReply(encode(r));
    ASSERT_TRUE(d);
    EXPECT_EQ(d->message, std::string(254, 'a'));
    r.message = std::string(253, 'a') + "µµ";
    d = decodeErrorReply(encode(r));
    ASSERT_TRUE(d);
    EXPECT_EQ(d->message, std::string(253, 'a') + "µ");
    // Exactly 255 bytes is kept whole.
    r.message = std::string(253, 'a') + "µ";
    d = decodeErrorReply(encode(r));
    ASSERT_TRUE(d);
    EXPECT_EQ(d->message, r.message);
}

// ---- strictness ----------------------------------------------------------------

TEST(CodecMessages, DecodersRejectShortAndLongPayloads)
{
    expectStrict(encode(sampleHello()), &decodeHelloReply, "HELLO reply");
    StatusReply s;
    s.axes = {{1, 2, 3}, {4, 5, 6}};
    expectStrict(encode(s), &decodeStatusReply, "STATUS reply");
    expectStrict(encode(HomeRequest{1}), &decodeHomeRequest, "HOME");
    expectStrict(encode(MoveRequest{false, 0, 0b101, {1, 2}}), &decodeMoveRequest, "MOVE");
    expectStrict(encode(ArchMoveRequest{1, 2, 3, 4, 5, 6, 7, 8, std::nullopt}), &decodeArchMoveRequest, "ARCH_MOVE");
    {
        // Its first 32 bytes are a plain ARCH_MOVE; anything between that and the whole block is refused.
        const Bytes withPump = encode(ArchMoveRequest{1, 2, 3, 4, 5, 6, 7, 8, ArchPump{-9, 10, 11, 12}});
        ASSERT_EQ(withPump.size(), 48u);
        const auto whole = decodeArchMoveRequest(withPump);
        ASSERT_TRUE(whole && whole->pump);
        EXPECT_EQ(whole->pump->delta, -9);
        EXPECT_EQ(whole->pump->leaveZ, 12);
        for (std::size_t n = 33; n < withPump.size(); ++n)
            EXPECT_FALSE(decodeArchMoveRequest(Bytes(withPump.begin(), withPump.begin() + static_cast<std::ptrdiff_t>(n)))) << n;
        Bytes longer = withPump;
        longer.push_back(0);
        EXPECT_FALSE(decodeArchMoveRequest(longer));
    }
    expectStrict(encode(JogStepRequest{0, 1, 2}), &decodeJogStepRequest, "JOG_STEP");
    expectStrict(encode(AxisMaskRequest{3}), &decodeAxisMaskRequest, "mask");
    expectStrict(encode(LimitsReply{{{0, 1}, {2, 3}}}), &decodeLimitsReply, "GET_LIMITS reply");
    expectStrict(encode(SetLimitsRequest{0, {1, 2}}), &decodeSetLimitsRequest, "SET_LIMITS");
    expectStrict(encode(JogVelocityRequest{0b11, {5, -5}}), &decodeJogVelocityRequest, "JOG_VELOCITY");
    expectStrict(encode(SubscribeRequest{100, {{0, ChannelKind::Measured}}}), &decodeSubscribeRequest, "SUBSCRIBE");
    expectStrict(encode(SubscribeReply{100, 2}), &decodeSubscribeReply, "SUBSCRIBE reply");
    TelemetryBatch t;
    t.channels = {{0, ChannelKind::Measured}};
    t.sampleCount = 2;
    t.values = {10, 20};
    expectStrict(encode(t), &decodeTelemetryBatch, "TELEMETRY");
    expectStrict(encode(EventMsg{EventKind::Fault, 0, 1, 2, "x", std::nullopt}), &decodeEvent, "EVENT");
    expectStrict(encode(ErrorReply{ErrorCode::Busy, 0, 1, "busy"}), &decodeErrorReply, "ERROR");
}

TEST(CodecMessages, DecodersRejectUnknownEnumValuesAndCounts)
{
    const Bytes hello = encode(sampleHello());
    EXPECT_TRUE(decodeHelloReply(with(hello, 1, 1)));
    EXPECT_FALSE(decodeHelloReply(with(hello, 1, 0)));  // device kind
    EXPECT_FALSE(decodeHelloReply(with(hello, 1, 3)));
    const std::size_t axesAt = 22 + sampleHello().model.size() + sampleHello().firmware.size();
    EXPECT_FALSE(decodeHelloReply(with(hello, axesAt + 2, 2)));  // axis unit
    HelloReply nine = sampleHello();
    nine.axes.assign(9, AxisInfo{});
    EXPECT_FALSE(decodeHelloReply(encode(nine)));  // more than kMaxAxes
    nine.axes.resize(8);
    EXPECT_TRUE(decodeHelloReply(encode(nine)));

    StatusReply s;
    s.axes.assign(9, AxisStatus{});
    EXPECT_FALSE(decodeStatusReply(encode(s)));
    LimitsReply l;
    l.axes.assign(9, AxisLimits{});
    EXPECT_FALSE(decodeLimitsReply(encode(l)));

    const Bytes move = encode(MoveRequest{false, 0, 0b1, {5}});
    EXPECT_FALSE(decodeMoveRequest(with(move, 0, 2)));  // flags other than bit 0
    EXPECT_FALSE(decodeMoveRequest(Bytes{0, 0, 0, 0, 0, 0}));  // empty axis mask
    EXPECT_FALSE(decodeJogVelocityRequest(Bytes{0}));           // empty axis mask

    const Bytes sub = encode(SubscribeRequest{100, {{0, ChannelKind::ContourError}}});
    EXPECT_TRUE(decodeSubscribeRequest(sub));
    EXPECT_FALSE(decodeSubscribeRequest(with(sub, 6, 0xEE)));  // channel kind
    TelemetryBatch t;
    t.channels = {{0, ChannelKind::Measured}};
    const Bytes tb = encode(t);
    EXPECT_TRUE(decodeTelemetryBatch(tb));
    EXPECT_FALSE(decodeTelemetryBatch(with(tb, 18, 0xEE)));

    // Event kinds and error codes a host does not know yet still decode (an older
    // host logs a newer device's events and shows its refusals); 0 and 0x80+ do not.
    const Bytes ev = encode(EventMsg{});
    EXPECT_FALSE(decodeEvent(with(ev, 0, 0)));
    EXPECT_TRUE(decodeEvent(with(ev, 0, 0x7F)));
    EXPECT_FALSE(decodeEvent(with(ev, 0, 0x80)));
    EXPECT_FALSE(decodeEvent(with(ev, 0, 0xFF)));
    const Bytes er = encode(ErrorReply{});
    EXPECT_FALSE(decodeErrorReply(with(er, 0, 0)));
    EXPECT_TRUE(decodeErrorReply(with(er, 0, 0x7F)));
    EXPECT_FALSE(decodeErrorReply(with(er, 0, 0x80)));

    // A string length that points past the end.
    Bytes badStr = encode(ErrorReply{ErrorCode::Busy, 0, 0, "abc"});
    badStr[6] = 4;
    EXPECT_FALSE(decodeErrorReply(badStr));
    badStr[6] = 2;
    EXPECT_FALSE(decodeErrorReply(badStr));  // now one byte trails
}

TEST(CodecMessages, MessageTypeRanges)
{
    EXPECT_TRUE(isRequestType(0x01));
    EXPECT_TRUE(isRequestType(0x3F));
    EXPECT_FALSE(isRequestType(0x00));
    EXPECT_FALSE(isRequestType(0x40));
    EXPECT_FALSE(isRealtimeType(static_cast<std::uint8_t>(MsgType::Subscribe)));
    EXPECT_TRUE(isRealtimeType(static_cast<std::uint8_t>(MsgType::JogVelocity)));
    EXPECT_TRUE(isRealtimeType(static_cast<std::uint8_t>(MsgType::Stop)));
    EXPECT_TRUE(isRealtimeType(static_cast<std::uint8_t>(MsgType::EStop)));
    EXPECT_EQ(replyTypeOf(MsgType::Hello), 0x81);
    EXPECT_EQ(replyTypeOf(MsgType::EStop), 0xA2);
    EXPECT_TRUE(isReplyType(0xA2));
    EXPECT_FALSE(isReplyType(static_cast<std::uint8_t>(MsgType::Event)));
    EXPECT_FALSE(isReplyType(static_cast<std::uint8_t>(MsgType::Error)));
    EXPECT_EQ(popcount8(0), 0);
    EXPECT_EQ(popcount8(0xFF), 8);
    EXPECT_EQ(popcount8(0b1010), 2);
}

} // namespace
