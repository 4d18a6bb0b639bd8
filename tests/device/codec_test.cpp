// Protocol v1 framing: CRC-16/CCITT-FALSE, COBS, encodeFrame and the streaming
// FrameDecoder. Every case asserts concrete bytes or counters, so a regression
// in the codec shows up as a value mismatch, not just "something decoded".
#include "device/protocol/cobs.h"
#include "device/protocol/crc16.h"
#include "device/protocol/frame_codec.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace {

using Bytes = std::vector<std::uint8_t>;
using dev::proto::DecoderStats;
using dev::proto::Frame;
using dev::proto::FrameDecoder;

Bytes cobs(const Bytes& in)
{
    Bytes out;
    dev::proto::cobsEncode(in.data(), in.size(), out);
    return out;
}

Bytes frameBytes(std::uint8_t type, std::uint16_t seq, const Bytes& payload)
{
    Bytes out;
    EXPECT_TRUE(dev::proto::encodeFrame(type, seq, payload.data(), payload.size(), out));
    return out;
}

Bytes concat(const std::vector<Bytes>& parts)
{
    Bytes out;
    for (const auto& p : parts)
        out.insert(out.end(), p.begin(), p.end());
    return out;
}

/// A wire frame built by hand, so the CRC can be made wrong or the body too long.
Bytes handFrame(const Bytes& body)
{
    Bytes out{0x00};
    dev::proto::cobsEncode(body.data(), body.size(), out);
    out.push_back(0x00);
    return out;
}

Bytes bodyWithCrc(std::uint8_t type, std::uint16_t seq, const Bytes& payload)
{
    // Sized once and filled in place: growing a small vector here (a braced list
    // then insert(), or push_back after reserve) trips GCC 12's -Warray-bounds and
    // -Wfree-nonheap-object false positives at -O3, which stopped Release builds.
    const std::size_t n = 3 + payload.size();
    Bytes body(n + 2);
    body[0] = type;
    body[1] = static_cast<std::uint8_t>(seq & 0xFF);
    body[2] = static_cast<std::uint8_t>(seq >> 8);
    std::copy(payload.begin(), payload.end(), body.begin() + 3);
    const std::uint16_t crc = dev::proto::crc16Ccitt(body.data(), n);
    body[n] = static_cast<std::uint8_t>(crc & 0xFF);
    body[n + 1] = static_cast<std::uint8_t>(crc >> 8);
    return body;
}

bool sameFrame(const Frame& a, const Frame& b) { return a.type == b.type && a.seq == b.seq && a.payload == b.payload; }

void expectFrames(const std::vector<Frame>& got, const std::vector<Frame>& want)
{
    ASSERT_EQ(got.size(), want.size());
    for (std::size_t i = 0; i < got.size(); ++i) {
        EXPECT_EQ(got[i].type, want[i].type) << "frame " << i;
        EXPECT_EQ(got[i].seq, want[i].seq) << "frame " << i;
        EXPECT_EQ(got[i].payload, want[i].payload) << "frame " << i;
    }
}

void expectStats(const DecoderStats& s, std::uint64_t frames, std::uint64_t crc, std::uint64_t malformed,
                 std::uint64_t oversize, std::uint64_t dropped)
{
    EXPECT_EQ(s.frames, frames);
    EXPECT_EQ(s.crcErrors, crc);
    EXPECT_EQ(s.malformed, malformed);
    EXPECT_EQ(s.oversize, oversize);
    EXPECT_EQ(s.droppedBytes, dropped);
}

Bytes randomBytes(std::mt19937& rng, std::size_t n, bool allowZero)
{
    std::uniform_int_distribution<int> d(allowZero ? 0 : 1, 255);
    Bytes b(n);
    for (auto& x : b)
        x = static_cast<std::uint8_t>(d(rng));
    return b;
}

/// A mix of frames that stresses COBS: empty, zeros, long non-zero runs, the cap.
std::vector<Frame> sampleFrames()
{
    std::mt19937 rng(20240601);
    std::vector<Frame> f;
    f.push_back({0x01, 0, {}});                              // HELLO, seq 0: zeros in the header
    f.push_back({0x02, 0x0100, {}});                         // seq low byte zero
    f.push_back({0x03, 0xFFFF, {0x00}});                     // single zero payload
    f.push_back({0x04, 7, Bytes(10, 0x00)});                 // all zeros
    f.push_back({0x81, 8, Bytes(253, 0xAA)});                // runs around the 254 COBS block
    f.push_back({0x82, 9, Bytes(254, 0x55)});
    f.push_back({0x83, 10, Bytes(255, 0x11)});
    f.push_back({0x84, 11, Bytes(508, 0x7F)});
    f.push_back({0xE1, 12, Bytes(dev::proto::kMaxPayloadBytes, 0xFF)});  // cap, no zero at all
    f.push_back({0xE0, 13, Bytes(dev::proto::kMaxPayloadBytes, 0x00)});  // cap, all zeros
    for (int i = 0; i < 20; ++i) {
        std::uniform_int_distribution<int> len(0, 300);
        f.push_back({static_cast<std::uint8_t>(rng()), static_cast<std::uint16_t>(rng()),
                     randomBytes(rng, static_cast<std::size_t>(len(rng)), true)});
    }
    return f;
}

Bytes encodeAll(const std::vector<Frame>& frames)
{
    Bytes wire;
    for (const auto& f : frames)
        EXPECT_TRUE(dev::proto::encodeFrame(f, wire));
    return wire;
}

// ---- CRC ------------------------------------------------------------------------

TEST(CodecCrc, CheckValue)
{
    const std::string s = "123456789";
    EXPECT_EQ(dev::proto::crc16Ccitt(reinterpret_cast<const std::uint8_t*>(s.data()), s.size()), 0x29B1);
}

TEST(CodecCrc, EmptyIsInitAndChainingMatchesOneShot)
{
    EXPECT_EQ(dev::proto::crc16Ccitt(nullptr, 0), 0xFFFF);
    const std::string s = "123456789";
    const auto* p = reinterpret_cast<const std::uint8_t*>(s.data());
    const std::uint16_t first = dev::proto::crc16Ccitt(p, 4);
    EXPECT_EQ(dev::proto::crc16Ccitt(p + 4, 5, first), 0x29B1);
    // Known values of CRC-16/CCITT-FALSE for short inputs.
    const std::uint8_t zero = 0x00, a = 'A';
    EXPECT_EQ(dev::proto::crc16Ccitt(&zero, 1), 0xE1F0);
    EXPECT_EQ(dev::proto::crc16Ccitt(&a, 1), 0xB915);
}

// ---- COBS -----------------------------------------------------------------------

TEST(CodecCobs, KnownEncodings)
{
    EXPECT_EQ(cobs({}), (Bytes{0x01}));
    EXPECT_EQ(cobs({0x00}), (Bytes{0x01, 0x01}));
    EXPECT_EQ(cobs({0x00, 0x00}), (Bytes{0x01, 0x01, 0x01}));
    EXPECT_EQ(cobs({0x00, 0x11, 0x00}), (Bytes{0x01, 0x02, 0x11, 0x01}));
    EXPECT_EQ(cobs({0x11, 0x22, 0x00, 0x33}), (Bytes{0x03, 0x11, 0x22, 0x02, 0x33}));
    EXPECT_EQ(cobs({0x11, 0x22, 0x33, 0x44}), (Bytes{0x05, 0x11, 0x22, 0x33, 0x44}));
    EXPECT_EQ(cobs({0x11, 0x00, 0x00, 0x00}), (Bytes{0x02, 0x11, 0x01, 0x01, 0x01}));
}

TEST(CodecCobs, LongRunsSplitEvery254Bytes)
{
    // 254 non-zero bytes fill one block (code 0xFF, no implied zero); like the
    // original Cheshire–Baker encoder this one then closes with an empty block 0x01.
    Bytes run254(254);
    for (std::size_t i = 0; i < run254.size(); ++i)
        run254[i] = static_cast<std::uint8_t>(i + 1);
    Bytes enc = cobs(run254);
    ASSERT_EQ(enc.size(), 256u);
    EXPECT_EQ(enc.front(), 0xFF);
    EXPECT_EQ(enc.back(), 0x01);
    EXPECT_TRUE(std::equal(run254.begin(), run254.end(), enc.begin() + 1));

    Bytes run255 = run254;
    run255.push_back(0xFF);
    enc = cobs(run255);
    ASSERT_EQ(enc.size(), 257u);
    EXPECT_EQ(enc[0], 0xFF);
    EXPECT_EQ(enc[255], 0x02);
    EXPECT_EQ(enc[256], 0xFF);

    // A zero right after a full block: the next code carries it.
    Bytes withZero = run254;
    withZero.push_back(0x00);
    withZero.push_back(0x42);
    enc = cobs(withZero);
    ASSERT_EQ(enc.size(), 258u);
    EXPECT_EQ(enc[255], 0x01);
    EXPECT_EQ(enc[256], 0x02);
    EXPECT_EQ(enc[257], 0x42);
}

TEST(CodecCobs, RoundTripsEdgeCases)
{
    std::vector<Bytes> inputs = {{}, {0x00}, Bytes(1, 0x01), Bytes(253, 0x01), Bytes(254, 0x02), Bytes(255, 0x03),
                                 Bytes(256, 0x04), Bytes(508, 0x05), Bytes(509, 0x06), Bytes(1024, 0x07),
                                 Bytes(1, 0x00), Bytes(254, 0x00), Bytes(255, 0x00), Bytes(1024, 0x00)};
    Bytes alt(600);
    for (std::size_t i = 0; i < alt.size(); ++i)
        alt[i] = (i % 254 == 253) ? 0x00 : 0x5A;
    inputs.push_back(alt);
    std::mt19937 rng(7);
    for (int i = 0; i < 200; ++i)
        inputs.push_back(randomBytes(rng, rng() % 1100, (i % 2) == 0));
    for (const auto& in : inputs) {
        const Bytes enc = cobs(in);
        EXPECT_EQ(std::count(enc.begin(), enc.end(), 0), 0) << "size " << in.size();
        EXPECT_LE(enc.size(), dev::proto::cobsMaxEncodedSize(in.size()));
        const auto dec = dev::proto::cobsDecode(enc.data(), enc.size());
        ASSERT_TRUE(dec.has_value()) << "size " << in.size();
        EXPECT_EQ(*dec, in);
    }
    // All-zero input costs exactly one byte of overhead.
    EXPECT_EQ(cobs(Bytes(1000, 0x00)).size(), 1001u);
    // Worst case is reached by non-zero input.
    EXPECT_EQ(cobs(Bytes(1024, 0x07)).size(), dev::proto::cobsMaxEncodedSize(1024));
}

TEST(CodecCobs, DecodeRejectsMalformedBlocks)
{
    const Bytes zeroInside{0x03, 0x11, 0x00};
    EXPECT_FALSE(dev::proto::cobsDecode(zeroInside.data(), zeroInside.size()).has_value());
    const Bytes codeZero{0x00};
    EXPECT_FALSE(dev::proto::cobsDecode(codeZero.data(), codeZero.size()).has_value());
    const Bytes pastEnd{0x05, 0x11, 0x22};
    EXPECT_FALSE(dev::proto::cobsDecode(pastEnd.data(), pastEnd.size()).has_value());
    const Bytes fullBlockShort{0xFF, 0x01};
    EXPECT_FALSE(dev::proto::cobsDecode(fullBlockShort.data(), fullBlockShort.size()).has_value());
    // A full block without the closing 0x01 still decodes (other encoders omit it).
    Bytes noClose{0xFF};
    noClose.insert(noClose.end(), 254, 0x33);
    const auto dec = dev::proto::cobsDecode(noClose.data(), noClose.size());
    ASSERT_TRUE(dec.has_value());
    EXPECT_EQ(*dec, Bytes(254, 0x33));
}

// ---- encodeFrame ----------------------------------------------------------------

TEST(CodecFrame, LayoutIsDelimitedCobsOfHeaderPayloadCrc)
{
    const Bytes payload{0x10, 0x00, 0x20};
    const Bytes wire = frameBytes(0x04, 0x1234, payload);
    ASSERT_GE(wire.size(), 2u);
    EXPECT_EQ(wire.front(), 0x00);
    EXPECT_EQ(wire.back(), 0x00);
    EXPECT_EQ(std::count(wire.begin() + 1, wire.end() - 1, 0), 0);
    const auto body = dev::proto::cobsDecode(wire.data() + 1, wire.size() - 2);
    ASSERT_TRUE(body.has_value());
    // type, seq LE, payload, CRC LE over everything before it
    const Bytes want{0x04, 0x34, 0x12, 0x10, 0x00, 0x20};
    ASSERT_EQ(body->size(), want.size() + 2);
    EXPECT_TRUE(std::equal(want.begin(), want.end(), body->begin()));
    const std::uint16_t crc = dev::proto::crc16Ccitt(want.data(), want.size());
    EXPECT_EQ((*body)[6], crc & 0xFF);
    EXPECT_EQ((*body)[7], crc >> 8);
    // Exact bytes: body 04 34 12 10 00 20 + CRC.
    EXPECT_EQ(wire, handFrame(bodyWithCrc(0x04, 0x1234, payload)));
}

TEST(CodecFrame, PayloadCapIsEnforced)
{
    Bytes out{0xAB};  // existing content must survive a refusal untouched
    const Bytes atCap(dev::proto::kMaxPayloadBytes, 0x01);
    const Bytes overCap(dev::proto::kMaxPayloadBytes + 1, 0x01);
    EXPECT_EQ(dev::proto::kMaxPayloadBytes, 1019u);
    EXPECT_FALSE(dev::proto::encodeFrame(0x01, 1, overCap.data(), overCap.size(), out));
    EXPECT_EQ(out, Bytes{0xAB});
    EXPECT_FALSE(dev::proto::encodeFrame(0x01, 1, overCap.data(), 60000, out));
    EXPECT_EQ(out, Bytes{0xAB});
    EXPECT_TRUE(dev::proto::encodeFrame(0x01, 1, atCap.data(), atCap.size(), out));
    // Worst case: no zero anywhere in type, seq, payload or CRC.
    EXPECT_LE(out.size() - 1, dev::proto::wireBytesForPayload(atCap.size()));
}

TEST(CodecFrame, WireBytesForPayloadIsAnUpperBound)
{
    std::mt19937 rng(99);
    for (std::size_t n : {std::size_t{0}, std::size_t{1}, std::size_t{249}, std::size_t{250}, std::size_t{251},
                          std::size_t{500}, std::size_t{1019}}) {
        for (int k = 0; k < 20; ++k) {
            const Bytes p = randomBytes(rng, n, k % 2 == 0);
            const Bytes wire = frameBytes(static_cast<std::uint8_t>(0x81 + k), static_cast<std::uint16_t>(0x0101 * (k + 1)), p);
            EXPECT_LE(wire.size(), dev::proto::wireBytesForPayload(n)) << n;
            EXPECT_GE(wire.size(), n + 2 + 5 + 1) << n;
        }
    }
    EXPECT_EQ(dev::proto::wireBytesForPayload(0), 2u + 5 + 1);
    EXPECT_EQ(dev::proto::wireBytesForPayload(1019), 2u + 1024 + 4 + 1);
}

// ---- FrameDecoder: chunking --------------------------------------------------

TEST(CodecDecoder, WholeByteByByteAndRandomChunksAgree)
{
    const auto frames = sampleFrames();
    const Bytes wire = encodeAll(frames);

    {
        FrameDecoder d;
        std::vector<Frame> got;
        d.feed(wire.data(), wire.size(), got);
        expectFrames(got, frames);
        expectStats(d.stats(), frames.size(), 0, 0, 0, 0);
    }
    {
        FrameDecoder d;
        std::vector<Frame> got;
        for (std::uint8_t b : wire)
            d.feed(&b, 1, got);
        expectFrames(got, frames);
        expectStats(d.stats(), frames.size(), 0, 0, 0, 0);
    }
    std::mt19937 rng(4242);
    for (int round = 0; round < 50; ++round) {
        FrameDecoder d;
        std::vector<Frame> got;
        std::uniform_int_distribution<std::size_t> chunk(0, round < 25 ? 7 : 700);
        for (std::size_t at = 0; at < wire.size();) {
            const std::size_t n = std::min(chunk(rng), wire.size() - at);
            d.feed(wire.data() + at, n, got);  // zero-length feeds included
            at += n;
        }
        expectFrames(got, frames);
        expectStats(d.stats(), frames.size(), 0, 0, 0, 0);
    }
}

TEST(CodecDecoder, IdleDelimitersAreNotErrors)
{
    Bytes wire(10, 0x00);
    const Bytes f = frameBytes(0x02, 5, {});
    wire.insert(wire.end(), f.begin(), f.end());
    wire.insert(wire.end(), 5, 0x00);
    FrameDecoder d;
    std::vector<Frame> got;
    d.feed(wire.data(), wire.size(), got);
    ASSERT_EQ(got.size(), 1u);
    EXPECT_EQ(got[0].seq, 5);
    expectStats(d.stats(), 1, 0, 0, 0, 0);
}

TEST(CodecDecoder, FrameWithoutLeadingDelimiterAtStartOfStream)
{
    // A peer that only sends trailing delimiters still interoperates.
    Bytes wire = frameBytes(0x21, 3, {0x00});
    wire.erase(wire.begin());
    FrameDecoder d;
    std::vector<Frame> got;
    d.feed(wire.data(), wire.size(), got);
    ASSERT_EQ(got.size(), 1u);
    EXPECT_TRUE(sameFrame(got[0], Frame{0x21, 3, {0x00}}));
}

// ---- FrameDecoder: damage ------------------------------------------------------

TEST(CodecDecoder, BadCrcIsCountedDroppedAndNextFrameStillDecodes)
{
    Bytes body = bodyWithCrc(0x04, 77, {1, 2, 3, 4});
    body.back() ^= 0x01;  // CRC off by one bit
    const Bytes bad = handFrame(body);
    const Bytes good = frameBytes(0x05, 78, {9, 9});
    const Bytes wire = concat({bad, good});

    for (int mode = 0; mode < 2; ++mode) {
        FrameDecoder d;
        std::vector<Frame> got;
        if (mode == 0)
            d.feed(wire.data(), wire.size(), got);
        else
            for (std::uint8_t b : wire)
                d.feed(&b, 1, got);
        ASSERT_EQ(got.size(), 1u);
        EXPECT_TRUE(sameFrame(got[0], Frame{0x05, 78, {9, 9}}));
        // Dropped: the bad block's bytes, delimiters not included.
        expectStats(d.stats(), 1, 1, 0, 0, bad.size() - 2);
    }
}

TEST(CodecDecoder, SingleBitFlipInAnyByteNeverDeliversAWrongFrame)
{
    const Frame original{0x04, 0x0203, {0x00, 0x10, 0x00, 0x00, 0x00, 0xA0, 0x86, 0x01, 0x00}};
    const Bytes wire = encodeAll({original});
    const Frame next{0x02, 0x0204, {}};
    const Bytes tail = encodeAll({next});
    for (std::size_t i = 0; i < wire.size(); ++i) {
        for (int bit = 0; bit < 8; ++bit) {
            Bytes w = wire;
            w[i] = static_cast<std::uint8_t>(w[i] ^ (1u << bit));
            w.insert(w.end(), tail.begin(), tail.end());
            FrameDecoder d;
            std::vector<Frame> got;
            d.feed(w.data(), w.size(), got);
            // CRC-16 detects every single-bit error; COBS damage is caught as malformed or CRC.
            // Flipping a delimiter merges the frame with its neighbour, which is caught too.
            ASSERT_EQ(got.size(), 1u) << "byte " << i << " bit " << bit;
            EXPECT_TRUE(sameFrame(got[0], next)) << "byte " << i << " bit " << bit;
            const auto& s = d.stats();
            EXPECT_GE(s.crcErrors + s.malformed, 1u) << "byte " << i << " bit " << bit;
            EXPECT_EQ(s.oversize, 0u);
            const auto nonZero = static_cast<std::uint64_t>(
                std::count_if(w.begin(), w.end() - static_cast<std::ptrdiff_t>(tail.size()), [](std::uint8_t b) { return b != 0; }));
            EXPECT_EQ(s.droppedBytes, nonZero) << "byte " << i << " bit " << bit;
        }
    }
}

TEST(CodecDecoder, OversizeIsCountedAndDecoderRecoversAtNextDelimiter)
{
    std::mt19937 rng(5);
    const Bytes junk = randomBytes(rng, 3000, false);
    const Bytes good = frameBytes(0x02, 300, {0x42});
    Bytes wire{0x00};
    wire.insert(wire.end(), junk.begin(), junk.end());
    wire.insert(wire.end(), good.begin(), good.end());

    std::vector<std::size_t> chunkings = {wire.size(), 1, 13, 1029, 1030};
    for (std::size_t c : chunkings) {
        FrameDecoder d;
        std::vector<Frame> got;
        for (std::size_t at = 0; at < wire.size(); at += c)
            d.feed(wire.data() + at, std::min(c, wire.size() - at), got);
        ASSERT_EQ(got.size(), 1u) << "chunk " << c;
        EXPECT_TRUE(sameFrame(got[0], Frame{0x02, 300, {0x42}}));
        expectStats(d.stats(), 1, 0, 0, 1, junk.size());
    }
}

TEST(CodecDecoder, LargestBodyIsAcceptedOneMoreIsOversize)
{
    // 1024-byte body without zeros: the worst-case encoded block of 1029 bytes.
    const Bytes maxPayload(dev::proto::kMaxPayloadBytes, 0xEE);
    const Bytes wire = frameBytes(0xE1, 0xEEEE, maxPayload);
    ASSERT_EQ(wire.size(), dev::proto::cobsMaxEncodedSize(dev::proto::kMaxBodyBytes) + 2);
    FrameDecoder d;
    std::vector<Frame> got;
    d.feed(wire.data(), wire.size(), got);
    ASSERT_EQ(got.size(), 1u);
    EXPECT_EQ(got[0].payload, maxPayload);
    expectStats(d.stats(), 1, 0, 0, 0, 0);
}

TEST(CodecDecoder, BodyOverTheCapIsRejectedEvenWhenItsBlockFits)
{
    // A body with zeros in it encodes to size + 1, so a 1028-byte body fits in
    // the 1029-byte block limit. The decoder must still refuse it: the cap is on
    // the body, and encodeFrame could never have produced it.
    for (std::size_t bodySize : {dev::proto::kMaxBodyBytes + 1, dev::proto::kMaxBodyBytes + 4}) {
        Bytes payload(bodySize - 5, 0x00);
        for (std::size_t i = 0; i < payload.size(); i += 2)
            payload[i] = 0x5A;
        const Bytes body = bodyWithCrc(0x81, 1, payload);
        ASSERT_EQ(body.size(), bodySize);
        const Bytes bad = handFrame(body);
        ASSERT_LE(bad.size() - 2, dev::proto::cobsMaxEncodedSize(dev::proto::kMaxBodyBytes));
        const Bytes good = frameBytes(0x82, 2, {});
        const Bytes wire = concat({bad, good});
        FrameDecoder d;
        std::vector<Frame> got;
        d.feed(wire.data(), wire.size(), got);
        ASSERT_EQ(got.size(), 1u) << "body " << bodySize;
        EXPECT_EQ(got[0].seq, 2);
        expectStats(d.stats(), 1, 0, 0, 1, bad.size() - 2);
    }
}

TEST(CodecDecoder, TruncatedFrameIsDroppedAtTheNextFramesDelimiter)
{
    const Bytes first = frameBytes(0x04, 10, Bytes(40, 0x31));
    const Bytes second = frameBytes(0x02, 11, {});
    for (std::size_t cut = 2; cut + 1 < first.size(); ++cut) {
        Bytes wire(first.begin(), first.begin() + static_cast<std::ptrdiff_t>(cut));
        wire.insert(wire.end(), second.begin(), second.end());
        FrameDecoder d;
        std::vector<Frame> got;
        d.feed(wire.data(), wire.size(), got);
        ASSERT_EQ(got.size(), 1u) << "cut " << cut;
        EXPECT_TRUE(sameFrame(got[0], Frame{0x02, 11, {}}));
        const auto& s = d.stats();
        EXPECT_EQ(s.crcErrors + s.malformed, 1u) << "cut " << cut;
        EXPECT_EQ(s.droppedBytes, cut - 1) << "cut " << cut;
    }
    // Header-only remains: too short to hold type, seq and CRC.
    const Bytes tiny{0x00, 0x03, 0x02, 0x01, 0x00};
    FrameDecoder d;
    std::vector<Frame> got;
    d.feed(tiny.data(), tiny.size(), got);
    EXPECT_TRUE(got.empty());
    expectStats(d.stats(), 0, 0, 1, 0, 3);
}

TEST(CodecDecoder, UnfinishedFrameWaitsAndResetForgetsIt)
{
    const Bytes f = frameBytes(0x02, 1, {});
    FrameDecoder d;
    std::vector<Frame> got;
    d.feed(f.data(), f.size() - 1, got);
    EXPECT_TRUE(got.empty());
    expectStats(d.stats(), 0, 0, 0, 0, 0);
    d.reset();
    const std::uint8_t delim = 0;
    d.feed(&delim, 1, got);  // the half frame is gone: nothing decodes, nothing is counted
    EXPECT_TRUE(got.empty());
    expectStats(d.stats(), 0, 0, 0, 0, 0);
    d.feed(f.data(), f.size(), got);
    ASSERT_EQ(got.size(), 1u);
}

TEST(CodecDecoder, GarbageBetweenFramesIsCountedAndFramesStayIntact)
{
    const auto frames = sampleFrames();
    std::mt19937 rng(31337);
    Bytes wire;
    std::uint64_t garbageNonZero = 0;
    for (const auto& f : frames) {
        // Garbage with zeros in it: several short bad blocks per gap.
        const Bytes g = randomBytes(rng, rng() % 200, true);
        garbageNonZero += static_cast<std::uint64_t>(std::count_if(g.begin(), g.end(), [](std::uint8_t b) { return b != 0; }));
        wire.insert(wire.end(), g.begin(), g.end());
        ASSERT_TRUE(dev::proto::encodeFrame(f, wire));
    }
    for (int mode = 0; mode < 3; ++mode) {
        FrameDecoder d;
        std::vector<Frame> got;
        std::mt19937 chunkRng(1);
        for (std::size_t at = 0; at < wire.size();) {
            const std::size_t n = mode == 0 ? wire.size() : mode == 1 ? 1 : std::min<std::size_t>(chunkRng() % 97, wire.size() - at);
            d.feed(wire.data() + at, n, got);
            at += n;
        }
        expectFrames(got, frames);
        const auto& s = d.stats();
        EXPECT_EQ(s.frames, frames.size());
        EXPECT_EQ(s.droppedBytes, garbageNonZero);
        EXPECT_GT(s.crcErrors + s.malformed, 0u);
        EXPECT_EQ(s.oversize, 0u);
    }
}

TEST(CodecDecoder, NonZeroGarbageRunIsCountedExactly)
{
    const Bytes a = frameBytes(0x02, 1, {});
    const Bytes b = frameBytes(0x02, 2, {});
    const Bytes junk{0x13, 0x37, 0xC0, 0xFF, 0xEE};
    const Bytes wire = concat({a, junk, b});
    FrameDecoder d;
    std::vector<Frame> got;
    d.feed(wire.data(), wire.size(), got);
    ASSERT_EQ(got.size(), 2u);
    EXPECT_EQ(got[0].seq, 1);
    EXPECT_EQ(got[1].seq, 2);
    // 13 37 C0 FF EE: code 0x13 points past the end of the block → malformed.
    expectStats(d.stats(), 2, 0, 1, 0, junk.size());
}

} // namespace
