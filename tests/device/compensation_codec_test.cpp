// The compensation messages (docs/protocol.md, "Compensation"): every field round-trips,
// float64 coefficients keep their bits, and the decoders refuse what does not fit.
#include "device/protocol/messages_compensation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace {

using namespace dev::proto;

TEST(CompensationCodec, APolynomialRoundTripsBitForBit)
{
    CompUploadRequest r;
    r.axis = 1;
    r.kind = CompKind::Polynomial;
    r.backlash = -4000;
    r.total = 6;
    r.validFrom = -5000000;
    r.validTo = 100000000;
    r.coefficients = {1.021, 0.6397, 0.0168, -1e-7, 3e-10, std::numeric_limits<double>::quiet_NaN()};
    const Bytes b = encode(r);
    EXPECT_EQ(b.size(), 11u + 8 + 6 * 8);
    const auto d = decodeCompUploadRequest(b);
    ASSERT_TRUE(d);
    EXPECT_EQ(d->axis, 1);
    EXPECT_EQ(d->backlash, -4000);
    EXPECT_EQ(d->validFrom, -5000000);
    ASSERT_EQ(d->coefficients.size(), 6u);
    for (int k = 0; k < 5; ++k)
        EXPECT_EQ(d->coefficients[static_cast<std::size_t>(k)], r.coefficients[static_cast<std::size_t>(k)]);
    EXPECT_TRUE(std::isnan(d->coefficients[5])) << "a NaN reaches the device, which refuses it with a reason";
}

TEST(CompensationCodec, ATablePartRoundTrips)
{
    CompUploadRequest r;
    r.axis = 0;
    r.kind = CompKind::TablePerDirection;
    r.total = 200;
    r.first = 80;
    for (int k = 0; k < 80; ++k)
        r.points.push_back({k * 500000, -k, k + 7});
    const Bytes b = encode(r);
    EXPECT_EQ(b.size(), 11u + 80 * 12);
    EXPECT_LE(b.size(), 1019u) << "a full part fits one frame";
    const auto d = decodeCompUploadRequest(b);
    ASSERT_TRUE(d);
    EXPECT_EQ(d->first, 80);
    EXPECT_EQ(d->points, r.points);
}

TEST(CompensationCodec, DecodersRefuseWhatDoesNotFit)
{
    CompUploadRequest poly;
    poly.kind = CompKind::Polynomial;
    poly.total = 2;
    poly.coefficients = {1, 2};
    Bytes b = encode(poly);
    b.pop_back();
    EXPECT_FALSE(decodeCompUploadRequest(b)) << "short";
    b = encode(poly);
    b.push_back(0);
    EXPECT_FALSE(decodeCompUploadRequest(b)) << "long";
    b = encode(poly);
    b[1] = 7;
    EXPECT_FALSE(decodeCompUploadRequest(b)) << "unknown kind";
    poly.total = 3;  // count 2 ≠ total 3: a polynomial comes whole
    EXPECT_FALSE(decodeCompUploadRequest(encode(poly)));
    CompUploadRequest table;
    table.kind = CompKind::Table;
    table.total = 100;
    table.points.resize(81);
    EXPECT_FALSE(decodeCompUploadRequest(encode(table))) << "more than 80 points a frame";
    EXPECT_FALSE(decodeCompEnableRequest(Bytes{1})) << "a mask without flags";
    EXPECT_FALSE(decodeCompGetReply(Bytes{0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1})) << "kind none with a count";
}

TEST(CompensationCodec, RepliesRoundTrip)
{
    const auto u = decodeCompUploadReply(encode(CompUploadReply{2, 160, 1}));
    ASSERT_TRUE(u);
    EXPECT_EQ(u->received, 160);
    EXPECT_EQ(u->installed, 1);
    CompGetReply g;
    g.axis = 1;
    g.kind = CompKind::Table;
    g.flags = CompEnabled | CompSaved;
    g.backlash = 2500;
    g.total = 101;
    g.first = 80;
    g.points = {{80000000, -49000, -49000}, {81000000, -49600, -49600}};
    const auto d = decodeCompGetReply(encode(g));
    ASSERT_TRUE(d);
    EXPECT_EQ(d->flags, g.flags);
    EXPECT_EQ(d->total, 101);
    EXPECT_EQ(d->points, g.points);
    CompGetReply none;
    none.axis = 3;
    const auto n = decodeCompGetReply(encode(none));
    ASSERT_TRUE(n);
    EXPECT_EQ(n->kind, CompKind::None);
    EXPECT_STREQ(compensationTypeName(0x1C), "COMP_GET");
    EXPECT_EQ(compensationTypeName(0x1E), nullptr);
}

} // namespace
