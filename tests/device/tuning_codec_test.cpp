// Tuning messages: layouts, round trips, and decoders that refuse
// anything but exactly one well-formed message.
#include "device/protocol/frame_codec.h"
#include "device/protocol/messages_tuning.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace dev::proto;

namespace {
Bytes with(Bytes b, std::size_t at, std::uint8_t v)
{
    b[at] = v;
    return b;
}
Bytes longer(Bytes b) { b.push_back(0); return b; }
Bytes shorter(Bytes b) { b.pop_back(); return b; }
} // namespace

TEST(TuningCodec, GainsTravelAsFloat32SoNaNAndInfinityReachTheDevice)
{
    SetGainsRequest r;
    r.axis = 1;
    r.flags = kSetGainsSave;
    r.gains = {std::numeric_limits<float>::quiet_NaN(), -0.5f, std::numeric_limits<float>::infinity()};
    const Bytes b = encode(r);
    ASSERT_EQ(b.size(), 14u);
    EXPECT_EQ(b[0], 1);
    EXPECT_EQ(b[1], 1);
    // −0.5f is 0xBF000000, little-endian.
    EXPECT_EQ((Bytes{b[6], b[7], b[8], b[9]}), (Bytes{0x00, 0x00, 0x00, 0xBF}));
    const auto d = decodeSetGainsRequest(b);
    ASSERT_TRUE(d);
    EXPECT_TRUE(std::isnan(d->gains.kp));
    EXPECT_EQ(d->gains.ki, -0.5f);
    EXPECT_TRUE(std::isinf(d->gains.kd));
    EXPECT_EQ(encode(*d), b);
    EXPECT_FALSE(decodeSetGainsRequest(with(b, 1, 2)));  // unknown flag
    EXPECT_FALSE(decodeSetGainsRequest(shorter(b)));
    EXPECT_FALSE(decodeSetGainsRequest(longer(b)));
}

TEST(TuningCodec, GainsReplyRoundTrips)
{
    GainsReply g;
    g.axis = 0;
    g.controlPeriodUs = 1000;
    g.gains = {0.25f, 0.5f, 0.03f};
    g.saved = {0.3f, 0.4f, 0.02f};
    g.flags = kGainsTestRunning;
    g.limits = {100, 100, 100};
    const Bytes b = encode(g);
    EXPECT_EQ(b.size(), 42u);
    const auto d = decodeGainsReply(b);
    ASSERT_TRUE(d);
    EXPECT_EQ(d->gains, g.gains);
    EXPECT_EQ(d->saved, g.saved);
    EXPECT_EQ(d->limits, g.limits);
    EXPECT_EQ(encode(*d), b);
    EXPECT_FALSE(decodeGainsReply(with(b, 29, 2)));
    EXPECT_FALSE(decodeGainsReply(shorter(b)));
}

TEST(TuningCodec, StepTestCarriesTrialGainsOnlyWhenFlagged)
{
    StepTestRequest s;
    s.axis = 0;
    s.step = -10000;
    s.settleBand = 500;
    s.settleHoldMs = 20;
    s.runMs = 0;
    s.envelope = {30000, 20000, 2000};
    const Bytes plain = encode(s);
    EXPECT_EQ(plain.size(), 28u);
    s.trialGains = WireGains{4, 0, 0};
    const Bytes trial = encode(s);
    EXPECT_EQ(trial.size(), 40u);
    EXPECT_EQ(trial[1], 1);
    const auto d = decodeStepTestRequest(trial);
    ASSERT_TRUE(d && d->trialGains);
    EXPECT_EQ(d->step, -10000);
    EXPECT_EQ(*d->trialGains, (WireGains{4, 0, 0}));
    EXPECT_EQ(encode(*d), trial);
    EXPECT_FALSE(decodeStepTestRequest(with(plain, 1, 1)));  // flagged, but no gains follow
    EXPECT_FALSE(decodeStepTestRequest(with(trial, 1, 0)));  // gains follow, unflagged
    EXPECT_FALSE(decodeStepTestRequest(with(plain, 1, 2)));
    const auto p = decodeStepTestRequest(plain);
    ASSERT_TRUE(p);
    EXPECT_FALSE(p->trialGains);
}

TEST(TuningCodec, RelayCaptureAndAbortRoundTrip)
{
    RelayTestRequest r{1, 10000, 1000, 4000, 12, {100000, 100000, 5000}};
    const Bytes rb = encode(r);
    EXPECT_EQ(rb.size(), 27u);
    ASSERT_TRUE(decodeRelayTestRequest(rb));
    EXPECT_EQ(encode(*decodeRelayTestRequest(rb)), rb);
    EXPECT_FALSE(decodeRelayTestRequest(longer(rb)));

    const Bytes cq = encode(CaptureRequest{0, 160, 80});
    EXPECT_EQ(cq.size(), 7u);
    ASSERT_TRUE(decodeCaptureRequest(cq));

    CaptureReply c;
    c.axis = 0;
    c.kind = 1;
    c.reason = 3;
    c.testId = 7;
    c.periodUs = 1000;
    c.total = 2;
    c.startPosition = 50000000;
    c.tripValue = 30500;
    c.tripLimit = 30000;
    c.gains = {4, 0, 0};
    c.first = 0;
    c.samples = {{50010000, 50000500, 40000}, {50010000, 50004000, 24000}};
    const Bytes cb = encode(c);
    EXPECT_EQ(cb.size(), 45u + 24u);
    const auto d = decodeCaptureReply(cb);
    ASSERT_TRUE(d);
    EXPECT_EQ(d->samples.size(), 2u);
    EXPECT_EQ(d->samples[1].output, 24000);
    EXPECT_EQ(encode(*d), cb);
    EXPECT_FALSE(decodeCaptureReply(with(cb, 1, 3)));   // kind
    EXPECT_FALSE(decodeCaptureReply(with(cb, 2, 10)));  // end reason
    EXPECT_FALSE(decodeCaptureReply(shorter(cb)));
    EXPECT_FALSE(decodeCaptureReply(with(cb, 43, 3)));  // sample count disagrees with the bytes
    // A full reply fits the payload cap.
    c.samples.assign(kMaxCaptureSamplesPerReply, CaptureSample{});
    EXPECT_LE(encode(c).size(), kMaxPayloadBytes);

    EXPECT_EQ(encode(AbortRequest{3}), (Bytes{3}));
    EXPECT_FALSE(decodeAbortRequest(Bytes{}));
    EXPECT_FALSE(decodeAxisRequest(Bytes{0, 0}));
    EXPECT_STREQ(tuningTypeName(0x0D), "STEP_TEST");
    EXPECT_EQ(tuningTypeName(0x10), nullptr);
}
