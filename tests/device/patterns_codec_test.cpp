// Path queue messages (messages_path.h): layouts, round trips, strict decoding.
#include "device/backends/benchpilot/path_wire.h"
#include "device/protocol/messages_path.h"

#include <gtest/gtest.h>

using namespace dev::proto;

namespace {
Bytes with(Bytes b, std::size_t at, std::uint8_t v)
{
    b[at] = v;
    return b;
}
}  // namespace

TEST(PatternsCodec, BeginLayoutAndRoundTrip)
{
    const Bytes b = encode(PathBeginRequest{7, 10000, 100000000});
    ASSERT_EQ(b.size(), 12u);
    EXPECT_EQ(b[0], 7);
    EXPECT_EQ(b[4], 0x10);  // 10 000 nm = 0x2710
    EXPECT_EQ(b[5], 0x27);
    const auto d = decodePathBeginRequest(b);
    ASSERT_TRUE(d);
    EXPECT_EQ(d->firstIndex, 7u);
    EXPECT_EQ(d->junctionDeviation, 10000u);
    EXPECT_EQ(d->accel, 100000000u);
    EXPECT_FALSE(decodePathBeginRequest(Bytes(11)));
    EXPECT_FALSE(decodePathBeginRequest(Bytes(13)));
}

TEST(PatternsCodec, AppendCarriesLinesArcsAndZ)
{
    PathAppendRequest a;
    a.firstIndex = 3;
    a.flags = PathAppendStart | PathAppendLast;
    PathSegmentWire l;
    l.kind = PathSegmentKind::Line;
    l.feed = 2000000;
    l.x = 55000000;
    l.y = -1;
    PathSegmentWire c;
    c.kind = PathSegmentKind::ArcCcw;
    c.feed = 2000000;
    c.x = 50000000;
    c.y = 55000000;
    c.cx = 50000000;
    c.cy = 50000000;
    c.hasZ = true;
    c.z = 12000000;
    a.segments = {l, c};
    const Bytes b = encode(a);
    EXPECT_EQ(b.size(), 6 + pathSegmentBytes(l) + pathSegmentBytes(c));
    EXPECT_EQ(pathSegmentBytes(l), 13u);
    EXPECT_EQ(pathSegmentBytes(c), 25u);
    EXPECT_EQ(b[4], 3);                 // flags
    EXPECT_EQ(b[5], 2);                 // count
    EXPECT_EQ(b[6], 1);                 // LINE
    EXPECT_EQ(b[19], 0x83);             // ARC CCW with Z
    const auto d = decodePathAppendRequest(b);
    ASSERT_TRUE(d);
    ASSERT_EQ(d->segments.size(), 2u);
    EXPECT_EQ(d->segments[0].y, -1);
    EXPECT_EQ(d->segments[1].kind, PathSegmentKind::ArcCcw);
    EXPECT_TRUE(d->segments[1].hasZ);
    EXPECT_EQ(d->segments[1].z, 12000000);
    EXPECT_EQ(encode(*d), b);
}

TEST(PatternsCodec, AppendDecoderIsStrict)
{
    PathAppendRequest a;
    a.segments.resize(1);
    const Bytes b = encode(a);
    EXPECT_TRUE(decodePathAppendRequest(b));
    EXPECT_FALSE(decodePathAppendRequest(with(b, 4, 4)));     // unknown flag
    EXPECT_FALSE(decodePathAppendRequest(with(b, 5, 0)));     // no segments
    EXPECT_FALSE(decodePathAppendRequest(with(b, 6, 0)));     // kind 0
    EXPECT_FALSE(decodePathAppendRequest(with(b, 6, 4)));     // kind 4
    EXPECT_FALSE(decodePathAppendRequest(with(b, 6, 0x41)));  // a reserved kind bit
    EXPECT_FALSE(decodePathAppendRequest(with(b, 6, 0x81)));  // says Z follows, but it does not
    Bytes longer = b;
    longer.push_back(0);
    EXPECT_FALSE(decodePathAppendRequest(longer));
    a.segments.resize(kMaxPathSegmentsPerAppend + 1);
    EXPECT_FALSE(decodePathAppendRequest(encode(a)));
    a.segments.resize(kMaxPathSegmentsPerAppend);
    EXPECT_TRUE(decodePathAppendRequest(encode(a)));
}

TEST(PatternsCodec, StatusReplyRoundTripAndLimits)
{
    PathStatusReply s{PathState::Held, 32, 5, 40, 12, 2000000, 3, PathReason::HostSilent, 100000000, 10000};
    const Bytes b = encode(s);
    ASSERT_EQ(b.size(), 26u);
    const auto d = decodePathStatusReply(b);
    ASSERT_TRUE(d);
    EXPECT_EQ(d->state, PathState::Held);
    EXPECT_EQ(d->reason, PathReason::HostSilent);
    EXPECT_EQ(d->executingIndex, 12u);
    EXPECT_EQ(d->accel, 100000000u);
    EXPECT_EQ(d->junctionDeviation, 10000u);
    EXPECT_EQ(encode(*d), b);
    EXPECT_FALSE(decodePathStatusReply(with(b, 0, 8)));    // state
    EXPECT_FALSE(decodePathStatusReply(with(b, 17, 8)));   // reason
    EXPECT_FALSE(decodePathStatusReply(with(b, 2, 33)));   // more free than the capacity
}

TEST(PatternsCodec, NamesForEveryNewCodeAndKind)
{
    for (int k = 20; k <= 25; ++k)
        EXPECT_STRNE(eventKindName(static_cast<EventKind>(k)), "unknown event") << k;
    for (int c = 15; c <= 18; ++c)
        EXPECT_STRNE(errorCodeName(static_cast<ErrorCode>(c)), "unknown error") << c;
    for (int s = 0; s <= 7; ++s)
        EXPECT_STRNE(pathStateName(static_cast<PathState>(s)), "unknown");
    for (int r = 0; r <= 7; ++r)
        EXPECT_STRNE(pathReasonName(static_cast<PathReason>(r)), "unknown");
}

TEST(PatternsCodec, SegmentsGoToNanometresAndBack)
{
    motion::path::Segment s;
    s.kind = motion::path::SegmentKind::ArcCw;
    s.start = {55, 50};
    s.end = {45, 50};
    s.center = {50, 50};
    s.feedMmS = 2.5;
    s.zMm = -1.25;
    const PathSegmentWire w = dev::toWire(s);
    EXPECT_EQ(w.kind, PathSegmentKind::ArcCw);
    EXPECT_EQ(w.feed, 2500000u);
    EXPECT_EQ(w.x, 45000000);
    EXPECT_EQ(w.cx, 50000000);
    EXPECT_TRUE(w.hasZ);
    EXPECT_EQ(w.z, -1250000);
    const auto back = dev::fromWire(w, s.start);
    EXPECT_EQ(back.kind, s.kind);
    EXPECT_DOUBLE_EQ(back.end.x, 45);
    EXPECT_DOUBLE_EQ(*back.zMm, -1.25);
}
