// Fuzz driver for protocol v1: the streaming FrameDecoder, every payload decoder
// and the simulator firmware's receive path.
//
// Standalone (the default): `fuzz_codec [--iterations N] [--seed S] [FILE...]`
// generates N deterministic inputs (mutations of valid frame streams: bit flips,
// truncation, splicing, garbage, oversize runs, retransmissions) or replays FILEs,
// and exits 1 on the first violated invariant, after writing the input to
// fuzz_codec-failure.bin. With -DBP_LIBFUZZER and clang -fsanitize=fuzzer the same
// checks run as LLVMFuzzerTestOneInput; codec, simulator and motion are plain C++,
// so from the repository root:
//   clang++ -std=c++17 -g -O1 -fsanitize=fuzzer,address,undefined -DBP_LIBFUZZER -I.
//     -isystem /usr/include/eigen3 tests/fuzz/fuzz_codec.cpp device/protocol/*.cpp
//     device/sim/*.cpp motion/*.cpp -o fuzz_codec_lf          (one command line)
//   ./fuzz_codec_lf -max_len=4096 CORPUS_DIR
//
// Invariants checked on every input:
//  - the streaming decoder gives the same frames and the same stats whether fed
//    whole, byte by byte or in random chunks, and agrees with an independent
//    whole-buffer reference decoder (frames, crc/malformed/oversize counts and
//    dropped bytes, exactly); its counters never decrease;
//  - every decoded frame is within the cap and re-encodes to a frame that decodes
//    back to itself with no error;
//  - every payload decoder either rejects a payload or accepts one that re-encodes
//    to exactly the same bytes;
//  - the firmware answers every request frame with exactly one reply (its type|0x80
//    or ERROR, same seq), realtime requests of a chunk first; a request equal in
//    type, seq and payload to one of the last 32 executed is not executed again and
//    is answered with the identical reply; every byte it sends decodes cleanly;
//    replies, events and telemetry batches decode with their decoders; events and
//    batches carry consecutive sequence numbers.
#include "device/protocol/cobs.h"
#include "device/protocol/crc16.h"
#include "device/protocol/frame_codec.h"
#include "device/protocol/messages.h"
#include "device/sim/firmware.h"
#include "device/sim/machine_config.h"

#include <algorithm>
#include <array>
#include <cinttypes>
#include <cstdarg>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>
#include <vector>

namespace {

using Bytes = std::vector<std::uint8_t>;
using proto::DecoderStats;
using proto::Frame;
using proto::FrameDecoder;
using proto::MsgType;

const Bytes* g_input = nullptr;  // the input under test, saved when an invariant fails
std::uint64_t g_iteration = 0;

/// What the inputs reached, printed at the end so a generator that stops
/// producing interesting inputs is noticed.
struct Coverage {
    std::uint64_t frames = 0, crcErrors = 0, malformed = 0, oversize = 0;
    std::uint64_t payloadsAccepted = 0, executed = 0, duplicates = 0, errorReplies = 0, events = 0, batches = 0;
    std::array<std::uint64_t, 16> errorByCode{}, eventByKind{};
} g_cov;

[[noreturn]] void fail(const char* fmt, ...)
{
    std::fprintf(stderr, "fuzz_codec: invariant violated (iteration %" PRIu64 "): ", g_iteration);
    va_list ap;
    va_start(ap, fmt);
    std::vfprintf(stderr, fmt, ap);
    va_end(ap);
    std::fputc('\n', stderr);
#ifdef BP_LIBFUZZER
    std::abort();  // libFuzzer saves the input itself
#else
    if (g_input) {
        if (std::FILE* f = std::fopen("fuzz_codec-failure.bin", "wb")) {
            std::fwrite(g_input->data(), 1, g_input->size(), f);
            std::fclose(f);
            std::fprintf(stderr, "fuzz_codec: input (%zu bytes) written to fuzz_codec-failure.bin; replay with "
                                 "`fuzz_codec fuzz_codec-failure.bin`\n",
                         g_input->size());
        }
    }
    std::exit(1);
#endif
}

#define CHECK(cond, ...)         \
    do {                         \
        if (!(cond))             \
            fail(__VA_ARGS__);   \
    } while (0)

/// SplitMix64: the same sequence with every compiler and standard library.
class Rng {
public:
    explicit Rng(std::uint64_t seed) : m_s(seed) {}
    std::uint64_t next()
    {
        std::uint64_t z = (m_s += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
    /// Uniform in [0, n); n > 0.
    std::size_t below(std::size_t n) { return static_cast<std::size_t>(next() % n); }
    std::int64_t range(std::int64_t lo, std::int64_t hi) { return lo + static_cast<std::int64_t>(next() % static_cast<std::uint64_t>(hi - lo + 1)); }
    bool chance(unsigned percent) { return below(100) < percent; }
    std::uint8_t byte() { return static_cast<std::uint8_t>(next()); }

private:
    std::uint64_t m_s;
};

std::uint64_t hashBytes(const std::uint8_t* p, std::size_t n)
{
    std::uint64_t h = 0xCBF29CE484222325ull;
    for (std::size_t i = 0; i < n; ++i)
        h = (h ^ p[i]) * 0x100000001B3ull;
    return h;
}

bool sameFrame(const Frame& a, const Frame& b) { return a.type == b.type && a.seq == b.seq && a.payload == b.payload; }
bool sameStats(const DecoderStats& a, const DecoderStats& b)
{
    return a.frames == b.frames && a.crcErrors == b.crcErrors && a.malformed == b.malformed && a.oversize == b.oversize
        && a.droppedBytes == b.droppedBytes;
}
std::string statsText(const DecoderStats& s)
{
    char buf[160];
    std::snprintf(buf, sizeof buf, "frames %" PRIu64 " crc %" PRIu64 " malformed %" PRIu64 " oversize %" PRIu64 " dropped %" PRIu64,
                  s.frames, s.crcErrors, s.malformed, s.oversize, s.droppedBytes);
    return buf;
}

// ---- reference decoder ---------------------------------------------------------
// Written independently of FrameDecoder, on the whole buffer at once: split at
// every 0x00, classify each block. Its results define what the streaming decoder
// must report, whatever the chunking.

std::optional<Bytes> refCobsDecode(const std::uint8_t* p, std::size_t n)
{
    Bytes out;
    std::size_t i = 0;
    while (i < n) {
        const std::size_t code = p[i++];
        if (code == 0 || i + (code - 1) > n)
            return std::nullopt;
        for (std::size_t k = 0; k + 1 < code; ++k) {
            if (p[i + k] == 0)
                return std::nullopt;
            out.push_back(p[i + k]);
        }
        i += code - 1;
        if (code < 0xFF && i < n)
            out.push_back(0);
    }
    return out;
}

struct RefResult {
    std::vector<Frame> frames;
    DecoderStats stats;
};

RefResult referenceDecode(const Bytes& s)
{
    constexpr std::size_t kMaxBlock = proto::kMaxBodyBytes + proto::kMaxBodyBytes / 254 + 1;
    RefResult r;
    auto classify = [&](std::size_t from, std::size_t to, bool terminated) {
        const std::size_t len = to - from;
        if (len == 0)
            return;
        if (len > kMaxBlock) {
            ++r.stats.oversize;
            r.stats.droppedBytes += len;
            return;
        }
        if (!terminated)
            return;  // still waiting for its delimiter
        const auto body = refCobsDecode(s.data() + from, len);
        if (body && body->size() > proto::kMaxBodyBytes) {
            ++r.stats.oversize;
        } else if (!body || body->size() < 5) {
            ++r.stats.malformed;
        } else {
            const std::size_t n = body->size();
            const unsigned want = (*body)[n - 2] | ((*body)[n - 1] << 8);
            if (proto::crc16Ccitt(body->data(), n - 2) != want) {
                ++r.stats.crcErrors;
            } else {
                Frame f;
                f.type = (*body)[0];
                f.seq = static_cast<std::uint16_t>((*body)[1] | ((*body)[2] << 8));
                f.payload.assign(body->begin() + 3, body->end() - 2);
                r.frames.push_back(std::move(f));
                ++r.stats.frames;
                return;
            }
        }
        r.stats.droppedBytes += len;
    };
    std::size_t start = 0;
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (s[i] == 0) {
            classify(start, i, true);
            start = i + 1;
        }
    }
    classify(start, s.size(), false);
    return r;
}

// ---- payload decoders ------------------------------------------------------------

template <typename T>
void checkDecoder(const Bytes& p, std::optional<T> (*decode)(const Bytes&), const char* name)
{
    const auto d = decode(p);
    if (!d)
        return;
    ++g_cov.payloadsAccepted;
    const Bytes again = proto::encode(*d);
    CHECK(again == p, "%s accepted a %zu-byte payload that re-encodes to %zu different bytes", name, p.size(), again.size());
}

void checkAllDecoders(const Bytes& p)
{
    checkDecoder(p, &proto::decodeHelloReply, "decodeHelloReply");
    checkDecoder(p, &proto::decodeStatusReply, "decodeStatusReply");
    checkDecoder(p, &proto::decodeHomeRequest, "decodeHomeRequest");
    checkDecoder(p, &proto::decodeMoveRequest, "decodeMoveRequest");
    checkDecoder(p, &proto::decodeJogStepRequest, "decodeJogStepRequest");
    checkDecoder(p, &proto::decodeAxisMaskRequest, "decodeAxisMaskRequest");
    checkDecoder(p, &proto::decodeLimitsReply, "decodeLimitsReply");
    checkDecoder(p, &proto::decodeSetLimitsRequest, "decodeSetLimitsRequest");
    checkDecoder(p, &proto::decodeJogVelocityRequest, "decodeJogVelocityRequest");
    checkDecoder(p, &proto::decodeSubscribeRequest, "decodeSubscribeRequest");
    checkDecoder(p, &proto::decodeSubscribeReply, "decodeSubscribeReply");
    checkDecoder(p, &proto::decodeTelemetryBatch, "decodeTelemetryBatch");
    checkDecoder(p, &proto::decodeEvent, "decodeEvent");
    checkDecoder(p, &proto::decodeErrorReply, "decodeErrorReply");
    const auto move = proto::decodeMoveRequest(p);
    if (move)
        CHECK(static_cast<int>(move->targets.size()) == proto::popcount8(move->axisMask), "MOVE target count != axes");
    const auto jog = proto::decodeJogVelocityRequest(p);
    if (jog)
        CHECK(static_cast<int>(jog->velocities.size()) == proto::popcount8(jog->axisMask), "JOG_VELOCITY count != axes");
    const auto batch = proto::decodeTelemetryBatch(p);
    if (batch)
        CHECK(batch->values.size() == std::size_t{batch->sampleCount} * batch->channels.size(), "batch value count");
}

// ---- frame decoder ---------------------------------------------------------------

/// Feeds `input` split at `cuts` (ascending offsets) and checks counters never decrease.
std::vector<Frame> feedChunked(FrameDecoder& d, const Bytes& input, const std::vector<std::size_t>& cuts)
{
    std::vector<Frame> out;
    std::size_t at = 0;
    DecoderStats prev;
    for (std::size_t k = 0; k <= cuts.size(); ++k) {
        const std::size_t end = k < cuts.size() ? cuts[k] : input.size();
        d.feed(input.data() + at, end - at, out);
        at = end;
        const DecoderStats& s = d.stats();
        CHECK(s.frames >= prev.frames && s.crcErrors >= prev.crcErrors && s.malformed >= prev.malformed
                  && s.oversize >= prev.oversize && s.droppedBytes >= prev.droppedBytes,
              "decoder counters went down");
        CHECK(s.frames == out.size(), "stats.frames %" PRIu64 " but %zu frames delivered", s.frames, out.size());
        prev = s;
    }
    return out;
}

std::vector<std::size_t> randomCuts(Rng& rng, std::size_t size, std::size_t maxChunk)
{
    std::vector<std::size_t> cuts;
    for (std::size_t at = 0;;) {
        at += rng.below(maxChunk + 1);  // zero-length chunks included
        if (at >= size)
            return cuts;
        cuts.push_back(at);
    }
}

void expectSame(const std::vector<Frame>& got, const DecoderStats& gotStats, const RefResult& want, const char* how)
{
    CHECK(sameStats(gotStats, want.stats), "%s: decoder stats {%s}, reference {%s}", how, statsText(gotStats).c_str(),
          statsText(want.stats).c_str());
    CHECK(got.size() == want.frames.size(), "%s: %zu frames, reference %zu", how, got.size(), want.frames.size());
    for (std::size_t i = 0; i < got.size(); ++i)
        CHECK(sameFrame(got[i], want.frames[i]), "%s: frame %zu differs from the reference", how, i);
}

void checkFrameDecoder(const Bytes& input, Rng& rng)
{
    const RefResult ref = referenceDecode(input);
    {
        FrameDecoder d;
        expectSame(feedChunked(d, input, {}), d.stats(), ref, "whole");
    }
    if (input.size() <= 8192) {
        FrameDecoder d;
        std::vector<std::size_t> cuts(input.empty() ? 0 : input.size() - 1);
        for (std::size_t i = 0; i < cuts.size(); ++i)
            cuts[i] = i + 1;
        expectSame(feedChunked(d, input, cuts), d.stats(), ref, "byte by byte");
    }
    for (std::size_t maxChunk : {std::size_t{16}, std::size_t{1100}}) {
        FrameDecoder d;
        expectSame(feedChunked(d, input, randomCuts(rng, input.size(), maxChunk)), d.stats(), ref, "random chunks");
    }
    // A final delimiter settles any unfinished block.
    Bytes flushed = input;
    flushed.push_back(0);
    const RefResult refFlushed = referenceDecode(flushed);
    FrameDecoder d;
    const auto frames = feedChunked(d, flushed, randomCuts(rng, flushed.size(), 300));
    expectSame(frames, d.stats(), refFlushed, "flushed");
    const DecoderStats& s = d.stats();
    g_cov.frames += s.frames;
    g_cov.crcErrors += s.crcErrors;
    g_cov.malformed += s.malformed;
    g_cov.oversize += s.oversize;
    std::uint64_t nonZero = 0;
    for (std::uint8_t b : flushed)
        nonZero += b != 0;
    // Every non-zero byte is either inside a good frame's block or dropped.
    CHECK(s.droppedBytes <= nonZero, "dropped %" PRIu64 " of %" PRIu64 " non-zero bytes", s.droppedBytes, nonZero);
    CHECK(s.droppedBytes + 6 * s.frames <= nonZero, "good frames and dropped bytes exceed the input");
    CHECK(s.droppedBytes >= s.malformed + 6 * s.crcErrors + 1026 * s.oversize, "error counted without its bytes");

    for (const auto& f : frames) {
        CHECK(f.payload.size() <= proto::kMaxPayloadBytes, "decoded payload of %zu bytes is over the cap", f.payload.size());
        Bytes wire;
        CHECK(proto::encodeFrame(f, wire), "a decoded frame does not re-encode");
        CHECK(wire.size() >= 2 && wire.front() == 0 && wire.back() == 0, "re-encoded frame is not delimited");
        CHECK(std::count(wire.begin() + 1, wire.end() - 1, 0) == 0, "re-encoded frame has a zero inside");
        CHECK(wire.size() <= proto::wireBytesForPayload(f.payload.size()), "re-encoded frame longer than wireBytesForPayload");
        FrameDecoder again;
        std::vector<Frame> back;
        again.feed(wire.data(), wire.size(), back);
        CHECK(back.size() == 1 && sameFrame(back[0], f), "re-encoded frame does not decode to itself");
        CHECK(sameStats(again.stats(), DecoderStats{1, 0, 0, 0, 0}), "re-encoded frame decodes with errors");
        checkAllDecoders(f.payload);
    }
}

// ---- firmware ----------------------------------------------------------------------

struct CachedModel {
    std::uint8_t type = 0;
    std::uint16_t seq = 0;
    Bytes payload;
    Frame reply;
};

/// The duplicate-request cache as docs/protocol.md specifies it: the last 32
/// executed requests, keyed by type, seq and payload; a HELLO that is not a
/// repeat of the last queued request starts a new session and empties it.
class ReplyCacheModel {
public:
    CachedModel* find(const Frame& f)
    {
        for (auto& c : m_entries)
            if (c.type == f.type && c.seq == f.seq && c.payload == f.payload)
                return &c;
        return nullptr;
    }
    CachedModel& insert(const Frame& f)
    {
        if (m_entries.size() == 32)
            m_entries.pop_front();
        m_entries.push_back({f.type, f.seq, f.payload, {}});
        return m_entries.back();
    }
    const CachedModel* newest() const { return m_entries.empty() ? nullptr : &m_entries.back(); }
    void clear() { m_entries.clear(); }

private:
    std::deque<CachedModel> m_entries;
};

bool knownRequest(std::uint8_t t)
{
    return (t >= 0x01 && t <= 0x0A) || (t >= 0x20 && t <= 0x22);
}

struct FirmwareChecker {
    sim::Firmware& fw;
    int axes;
    proto::DeviceKind kind;
    FrameDecoder outDecoder;
    std::uint16_t nextDeviceSeq = 0;
    std::uint64_t executed = 0, duplicates = 0;
    ReplyCacheModel cache;
    std::optional<Frame> lastQueued;  ///< type, seq and payload of the last executed queued request

    /// Checks a device-initiated frame (event or telemetry batch).
    void deviceFrame(const Frame& f)
    {
        CHECK(f.seq == nextDeviceSeq, "device frame seq %u, expected %u", unsigned{f.seq}, unsigned{nextDeviceSeq});
        ++nextDeviceSeq;
        if (f.type == static_cast<std::uint8_t>(MsgType::Event)) {
            ++g_cov.events;
            const auto e = proto::decodeEvent(f.payload);
            CHECK(e.has_value(), "EVENT payload does not decode");
            CHECK(e->axis == proto::kNoAxis || e->axis < axes, "event on axis %u", unsigned{e->axis});
            ++g_cov.eventByKind[static_cast<std::size_t>(e->kind) & 15];
        } else {
            ++g_cov.batches;
            const auto b = proto::decodeTelemetryBatch(f.payload);
            CHECK(b.has_value(), "TELEMETRY payload does not decode");
            CHECK(b->sampleCount >= 1 && !b->channels.empty(), "empty telemetry batch");
        }
    }

    std::vector<Frame> drain()
    {
        Bytes out;
        fw.drainOutput(out);
        std::vector<Frame> frames;
        outDecoder.feed(out.data(), out.size(), frames);
        const DecoderStats& s = outDecoder.stats();
        CHECK(s.crcErrors == 0 && s.malformed == 0 && s.oversize == 0 && s.droppedBytes == 0,
              "firmware output does not decode cleanly: %s", statsText(s).c_str());
        CHECK(out.empty() || out.back() == 0, "firmware output ends inside a frame");
        return frames;
    }

    void checkReplyPayload(const Frame& req, const Frame& rep)
    {
        if (rep.type == static_cast<std::uint8_t>(MsgType::Error)) {
            const auto e = proto::decodeErrorReply(rep.payload);
            CHECK(e.has_value(), "ERROR reply to 0x%02X does not decode", unsigned{req.type});
            ++g_cov.errorByCode[static_cast<std::size_t>(e->code) & 15];
            if (!knownRequest(req.type))
                CHECK(e->code == proto::ErrorCode::UnknownCommand && e->value == req.type,
                      "unknown request 0x%02X answered with error %d", unsigned{req.type}, int(e->code));
            return;
        }
        CHECK(knownRequest(req.type), "unknown request 0x%02X got a success reply", unsigned{req.type});
        CHECK(rep.type == (req.type | proto::kReplyFlag), "reply type 0x%02X to request 0x%02X", unsigned{rep.type},
              unsigned{req.type});
        switch (static_cast<MsgType>(req.type)) {
        case MsgType::Hello: {
            const auto h = proto::decodeHelloReply(rep.payload);
            CHECK(h && h->kind == kind && static_cast<int>(h->axes.size()) == axes
                      && h->protocolVersion == proto::kProtocolVersion,
                  "HELLO reply wrong");
            CHECK(req.payload.empty(), "HELLO with a payload was accepted");
            break;
        }
        case MsgType::Status: {
            const auto st = proto::decodeStatusReply(rep.payload);
            CHECK(st && static_cast<int>(st->axes.size()) == axes, "STATUS reply wrong");
            break;
        }
        case MsgType::GetLimits: {
            const auto l = proto::decodeLimitsReply(rep.payload);
            CHECK(l && static_cast<int>(l->axes.size()) == axes, "GET_LIMITS reply wrong");
            for (const auto& a : l->axes)
                CHECK(a.min < a.max, "soft limits out of order");
            break;
        }
        case MsgType::Subscribe: {
            const auto r = proto::decodeSubscribeReply(rep.payload);
            CHECK(r.has_value(), "SUBSCRIBE reply does not decode");
            CHECK((r->rateHz == 0) == (r->samplesPerBatch == 0), "SUBSCRIBE reply rate/batch inconsistent");
            break;
        }
        default:
            CHECK(rep.payload.empty(), "reply to 0x%02X has a %zu-byte payload", unsigned{req.type}, rep.payload.size());
            break;
        }
    }

    /// Feeds one chunk; `chunkFrames` are the frames a mirror decoder completed in it.
    /// Every type below 0x80 is a request (unknown ones get an UnknownCommand
    /// error); realtime ones (0x20–0x3F) of a chunk are handled first.
    void receive(const std::uint8_t* data, std::size_t size, const std::vector<Frame>& chunkFrames)
    {
        std::vector<const Frame*> order;
        for (const auto& f : chunkFrames)
            if (proto::isRealtimeType(f.type))
                order.push_back(&f);
        for (const auto& f : chunkFrames)
            if (f.type < 0x80 && !proto::isRealtimeType(f.type))
                order.push_back(&f);

        fw.receive(data, size);
        const auto out = drain();
        std::size_t next = 0;
        for (const auto& rep : out) {
            if (rep.type == static_cast<std::uint8_t>(MsgType::Event) || rep.type == static_cast<std::uint8_t>(MsgType::TelemetryBatch)) {
                deviceFrame(rep);
                continue;
            }
            CHECK(next < order.size(), "firmware sent a reply (0x%02X seq %u) nobody asked for", unsigned{rep.type},
                  unsigned{rep.seq});
            const Frame& req = *order[next++];
            CHECK(rep.seq == req.seq, "reply seq %u to request seq %u", unsigned{rep.seq}, unsigned{req.seq});
            if (req.type == static_cast<std::uint8_t>(MsgType::Hello)
                && !(lastQueued && lastQueued->type == req.type && lastQueued->seq == req.seq
                     && lastQueued->payload == req.payload))
                cache.clear();
            if (CachedModel* c = cache.find(req)) {
                ++duplicates;
                ++g_cov.duplicates;
                CHECK(sameFrame(rep, c->reply), "retransmitted request 0x%02X seq %u got a different reply",
                      unsigned{req.type}, unsigned{req.seq});
            } else {
                ++executed;
                ++g_cov.executed;
                g_cov.errorReplies += rep.type == static_cast<std::uint8_t>(MsgType::Error);
                cache.insert(req).reply = rep;
                if (!proto::isRealtimeType(req.type))
                    lastQueued = req;
                checkReplyPayload(req, rep);
            }
        }
        CHECK(next == order.size(), "%zu requests, %zu replies", order.size(), next);
        CHECK(fw.executedRequests() == executed, "firmware executed %" PRIu64 " requests, expected %" PRIu64,
              fw.executedRequests(), executed);
        CHECK(fw.duplicateRequests() == duplicates, "firmware counted %" PRIu64 " duplicates, expected %" PRIu64,
              fw.duplicateRequests(), duplicates);
    }

    void advance(double dtS)
    {
        fw.advance(dtS);
        for (const auto& f : drain()) {
            CHECK(f.type == static_cast<std::uint8_t>(MsgType::Event) || f.type == static_cast<std::uint8_t>(MsgType::TelemetryBatch),
                  "firmware sent 0x%02X unprompted", unsigned{f.type});
            deviceFrame(f);
        }
    }
};

void checkFirmware(const Bytes& input, Rng& rng)
{
    static const std::uint32_t kBauds[] = {9600, 115200, 115200, 921600};
    const bool stage = (rng.next() & 1) != 0;
    const sim::MachineConfig cfg = stage ? sim::stageConfig() : sim::analyzerConfig();
    sim::Firmware fw(cfg, kBauds[rng.below(4)]);
    FirmwareChecker c{fw, static_cast<int>(cfg.axes.size()), cfg.kind, {}, 0, 0, 0, {}, {}};

    // The mirror decoder sees the same chunks as the firmware, so it knows which
    // requests each receive() call completes.
    FrameDecoder mirror;
    auto feed = [&](const std::uint8_t* data, std::size_t size) {
        std::vector<Frame> chunkFrames;
        mirror.feed(data, size, chunkFrames);
        c.receive(data, size, chunkFrames);
    };
    // Now and then home every axis first, so that soft limits, absolute moves and
    // limit switches are reachable (homing takes 10–15 s of virtual time).
    if (rng.below(200) == 0) {
        Bytes home;
        proto::encodeFrame(static_cast<std::uint8_t>(MsgType::Home), 0xFFFE, proto::encode(proto::HomeRequest{0}).data(), 1, home);
        feed(home.data(), home.size());
        auto allHomed = [&] {
            for (int i = 0; i < fw.machine().axisCount(); ++i)
                if (!fw.machine().homed(i))
                    return false;
            return true;
        };
        for (int k = 0; k < 40 && !allHomed(); ++k)
            c.advance(0.5);
        CHECK(allHomed(), "homing all axes did not finish within 20 s");
        c.advance(0.5);
    }
    const auto cuts = randomCuts(rng, input.size(), rng.chance(50) ? 40 : 400);
    double virtualS = 0;
    std::size_t at = 0;
    for (std::size_t k = 0; k <= cuts.size(); ++k) {
        const std::size_t end = k < cuts.size() ? cuts[k] : input.size();
        feed(input.data() + at, end - at);
        at = end;
        static const double kSteps[] = {0, 0, 100e-6, 1e-3, 3e-3};
        const double dt = kSteps[rng.below(5)];
        if (virtualS < 0.05) {
            c.advance(dt);
            virtualS += dt;
        }
    }
    CHECK(sameStats(fw.decoderStats(), mirror.stats()), "firmware decoder {%s}, mirror {%s}",
          statsText(fw.decoderStats()).c_str(), statsText(mirror.stats()).c_str());
    // Let motion and the jog watchdog play out now and then.
    if (rng.chance(10))
        c.advance(0.3);

    // An explicit retransmission of the newest executed request: answered from
    // the cache, not executed. (Its leading delimiter may also complete a frame
    // the input left unfinished; the model accounts for that one.)
    const std::uint8_t delimiter = 0;
    feed(&delimiter, 1);  // settles a frame the input left unfinished
    if (const CachedModel* newest = c.cache.newest()) {
        Bytes wire;
        const Frame f{newest->type, newest->seq, newest->payload};
        CHECK(proto::encodeFrame(f, wire), "cannot re-encode a cached request");
        const std::uint64_t dupsBefore = fw.duplicateRequests();
        feed(wire.data(), wire.size());
        CHECK(fw.duplicateRequests() > dupsBefore, "a retransmitted request was executed again");
    }
}

void fuzzOne(const std::uint8_t* data, std::size_t size)
{
    const Bytes input(data, data + size);
    g_input = &input;
    Rng rng(hashBytes(data, size));
    checkFrameDecoder(input, rng);
    checkAllDecoders(input);
    if (size > 1)
        checkAllDecoders(Bytes(input.begin() + 1, input.end()));
    checkFirmware(input, rng);
    g_input = nullptr;
}

} // namespace

#ifdef BP_LIBFUZZER
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    fuzzOne(data, size);
    return 0;
}
#else

namespace {

// ---- input generation (standalone mode) ----------------------------------------------

std::int32_t randPosition(Rng& r)
{
    switch (r.below(4)) {
    case 0: return static_cast<std::int32_t>(r.range(-2000000, 2000000));        // ±2 mm
    case 1: return static_cast<std::int32_t>(r.range(-250000000, 250000000));    // ±250 mm
    case 2: return r.chance(50) ? INT32_MAX : INT32_MIN;
    default: return static_cast<std::int32_t>(r.next());
    }
}

std::uint32_t randSpeed(Rng& r)
{
    switch (r.below(4)) {
    case 0: return 0;
    case 1: return static_cast<std::uint32_t>(r.range(1, 100000000));
    case 2: return static_cast<std::uint32_t>(r.range(1, 1000));
    default: return static_cast<std::uint32_t>(r.next());
    }
}

std::uint8_t randMask(Rng& r)
{
    switch (r.below(10)) {
    case 0: return r.byte();
    case 1:
    case 2: return static_cast<std::uint8_t>(r.below(16));
    default: return static_cast<std::uint8_t>(1u << r.below(r.chance(80) ? 2 : 4));
    }
}

std::string randText(Rng& r)
{
    std::string s(r.below(r.chance(5) ? 300 : 24), 'a');
    for (auto& ch : s)
        ch = static_cast<char>(r.chance(90) ? 'a' + r.below(26) : r.byte());
    return s;
}

std::vector<proto::ChannelRef> randChannels(Rng& r)
{
    std::vector<proto::ChannelRef> ch(r.below(r.chance(5) ? 200 : 6));
    for (auto& c : ch) {
        c.axis = r.chance(10) ? proto::kNoAxis : static_cast<std::uint8_t>(r.below(r.chance(90) ? 4 : 256));
        c.kind = static_cast<proto::ChannelKind>(r.below(7));
    }
    return ch;
}

Bytes validPayload(Rng& r, std::uint8_t type)
{
    using namespace proto;
    switch (type) {
    case 0x03: return encode(HomeRequest{randMask(r)});
    case 0x04: {
        MoveRequest m;
        m.relative = r.chance(60);
        m.speed = randSpeed(r);
        m.axisMask = randMask(r);
        if (m.axisMask == 0)
            m.axisMask = 1;
        for (int i = 0; i < popcount8(m.axisMask); ++i)
            m.targets.push_back(randPosition(r));
        return encode(m);
    }
    case 0x05: return encode(JogStepRequest{static_cast<std::uint8_t>(r.chance(90) ? r.below(5) : r.byte()), randPosition(r), randSpeed(r)});
    case 0x06:
    case 0x21: return encode(AxisMaskRequest{randMask(r)});
    case 0x08: {
        const std::int32_t a = randPosition(r), b = randPosition(r);
        return encode(SetLimitsRequest{static_cast<std::uint8_t>(r.below(6)), {std::min(a, b), r.chance(80) ? std::max(a, b) : a}});
    }
    case 0x09: {
        SubscribeRequest s;
        s.rateHz = r.chance(20) ? 0 : static_cast<std::uint32_t>(r.chance(80) ? r.range(1, 2000) : r.range(0, 100000));
        s.channels = randChannels(r);
        return encode(s);
    }
    case 0x20: {
        JogVelocityRequest j;
        j.axisMask = randMask(r);
        if (j.axisMask == 0)
            j.axisMask = 1;
        for (int i = 0; i < popcount8(j.axisMask); ++i)
            j.velocities.push_back(r.chance(70) ? static_cast<std::int32_t>(r.range(-20000000, 20000000)) : randPosition(r));
        return encode(j);
    }
    case 0x81: {
        HelloReply h;
        h.kind = r.chance(50) ? DeviceKind::Analyzer : DeviceKind::Stage;
        h.capabilities = static_cast<std::uint32_t>(r.next());
        h.model = randText(r);
        h.firmware = randText(r);
        h.axes.resize(r.below(9));
        for (auto& a : h.axes)
            a = {static_cast<char>('X' + r.below(4)), r.chance(80) ? AxisUnit::Millimetre : AxisUnit::Microlitre, randPosition(r),
                 randPosition(r), randSpeed(r), randSpeed(r)};
        return encode(h);
    }
    case 0x82: {
        StatusReply s;
        s.deviceFlags = r.byte();
        s.deviceTimeUs = r.next();
        s.axes.resize(r.below(9));
        for (auto& a : s.axes)
            a = {randPosition(r), randPosition(r), static_cast<std::uint16_t>(r.next())};
        return encode(s);
    }
    case 0x87: {
        LimitsReply l;
        l.axes.resize(r.below(9));
        for (auto& a : l.axes)
            a = {randPosition(r), randPosition(r)};
        return encode(l);
    }
    case 0x89: return encode(SubscribeReply{static_cast<std::uint32_t>(r.next()), static_cast<std::uint16_t>(r.next())});
    case 0xE0: {
        EventMsg e;
        e.kind = static_cast<EventKind>(1 + r.below(9));
        e.axis = r.byte();
        e.deviceTimeUs = r.next();
        e.position = randPosition(r);
        e.text = randText(r);
        return encode(e);
    }
    case 0xE1: {
        TelemetryBatch t;
        t.firstSampleIndex = static_cast<std::uint32_t>(r.next());
        t.firstSampleTimeUs = r.next();
        t.periodUs = static_cast<std::uint32_t>(r.next());
        t.channels = randChannels(r);
        if (t.channels.size() > 8)
            t.channels.resize(8);
        t.sampleCount = static_cast<std::uint16_t>(r.below(20));
        for (std::size_t i = 0; i < t.sampleCount * t.channels.size(); ++i)
            t.values.push_back(randPosition(r));
        return encode(t);
    }
    case 0xFF: {
        ErrorReply e;
        e.code = static_cast<ErrorCode>(1 + r.below(10));
        e.axis = r.byte();
        e.value = randPosition(r);
        e.message = randText(r);
        return encode(e);
    }
    default: return {};  // HELLO, STATUS, GET_LIMITS, RESET, E-STOP and replies without payload
    }
}

void mutatePayload(Rng& r, Bytes& p)
{
    const int n = 1 + static_cast<int>(r.below(3));
    for (int k = 0; k < n; ++k) {
        switch (r.below(6)) {
        case 0:
            if (!p.empty())
                p[r.below(p.size())] ^= static_cast<std::uint8_t>(1u << r.below(8));
            break;
        case 1:
            if (!p.empty())
                p.resize(r.below(p.size()));
            break;
        case 2: p.push_back(r.byte()); break;
        case 3:
            if (!p.empty())
                p[r.below(p.size())] = r.chance(50) ? 0x00 : 0xFF;
            break;
        case 4:
            if (!p.empty())
                p.erase(p.begin() + static_cast<std::ptrdiff_t>(r.below(p.size())));
            break;
        default:
            if (!p.empty())
                p[r.below(p.size())] = r.byte();
            break;
        }
    }
}

std::uint8_t randType(Rng& r)
{
    // Weighted: E-STOP latches every later motion request into an error, so it
    // and RESET are rare; motion requests are common.
    static const std::uint8_t kRequests[] = {0x01, 0x02, 0x02, 0x03, 0x04, 0x04, 0x04, 0x05, 0x05, 0x06, 0x07,
                                             0x08, 0x08, 0x09, 0x09, 0x20, 0x20, 0x20, 0x21, 0x21};
    if (r.chance(2))
        return r.chance(50) ? 0x22 : 0x0A;
    static const std::uint8_t kOthers[] = {0x81, 0x82, 0x87, 0x89, 0xA0, 0xE0, 0xE1, 0xFF, 0x0B, 0x1F, 0x23, 0x3F, 0x40, 0x00};
    if (r.chance(75))
        return kRequests[r.below(sizeof kRequests)];
    if (r.chance(85))
        return kOthers[r.below(sizeof kOthers)];
    return r.byte();
}

std::uint16_t randSeq(Rng& r)
{
    if (r.chance(60))
        return static_cast<std::uint16_t>(r.below(4));
    if (r.chance(20))
        return r.chance(50) ? 0xFFFF : 0x0100;
    return static_cast<std::uint16_t>(r.next());
}

/// A stream of valid frames, some with damaged payloads, some retransmitted.
Bytes validStream(Rng& r)
{
    std::vector<Frame> frames;
    const std::size_t n = 1 + r.below(r.chance(10) ? 60 : 10);
    for (std::size_t i = 0; i < n; ++i) {
        if (!frames.empty() && r.chance(15)) {
            frames.push_back(frames[r.below(frames.size())]);  // retransmission
            continue;
        }
        Frame f;
        f.type = randType(r);
        f.seq = randSeq(r);
        f.payload = validPayload(r, f.type);
        if (r.chance(25))
            mutatePayload(r, f.payload);
        if (f.payload.size() > proto::kMaxPayloadBytes)
            f.payload.resize(proto::kMaxPayloadBytes);
        frames.push_back(std::move(f));
    }
    Bytes wire;
    for (const auto& f : frames) {
        if (r.chance(10))
            wire.insert(wire.end(), r.below(4), 0x00);  // idle fill
        proto::encodeFrame(f, wire);
    }
    return wire;
}

Bytes garbage(Rng& r, std::size_t n, bool zeros)
{
    Bytes g(n);
    for (auto& b : g)
        b = zeros ? r.byte() : static_cast<std::uint8_t>(1 + r.below(255));
    return g;
}

void mutateStream(Rng& r, Bytes& s)
{
    const int n = static_cast<int>(r.below(4));
    for (int k = 0; k < n; ++k) {
        switch (r.below(9)) {
        case 0:  // bit flips
            for (std::size_t j = 0, m = 1 + r.below(4); j < m && !s.empty(); ++j)
                s[r.below(s.size())] ^= static_cast<std::uint8_t>(1u << r.below(8));
            break;
        case 1:  // truncation
            if (!s.empty())
                s.resize(r.below(s.size()));
            break;
        case 2: {  // garbage inserted anywhere
            const Bytes g = garbage(r, 1 + r.below(64), r.chance(50));
            s.insert(s.begin() + static_cast<std::ptrdiff_t>(r.below(s.size() + 1)), g.begin(), g.end());
            break;
        }
        case 3: {  // splice: head of this stream, tail of another
            const Bytes other = validStream(r);
            s.resize(r.below(s.size() + 1));
            s.insert(s.end(), other.begin() + static_cast<std::ptrdiff_t>(r.below(other.size() + 1)), other.end());
            break;
        }
        case 4: {  // a range repeated
            if (s.empty())
                break;
            const std::size_t a = r.below(s.size()), len = 1 + r.below(s.size() - a);
            const Bytes part(s.begin() + static_cast<std::ptrdiff_t>(a), s.begin() + static_cast<std::ptrdiff_t>(a + len));
            s.insert(s.begin() + static_cast<std::ptrdiff_t>(r.below(s.size() + 1)), part.begin(), part.end());
            break;
        }
        case 5: {  // a range removed
            if (s.empty())
                break;
            const std::size_t a = r.below(s.size()), len = 1 + r.below(std::min<std::size_t>(s.size() - a, 32));
            s.erase(s.begin() + static_cast<std::ptrdiff_t>(a), s.begin() + static_cast<std::ptrdiff_t>(a + len));
            break;
        }
        case 6: {  // a long run without delimiters: oversize
            if (!r.chance(30))
                break;
            const Bytes g = garbage(r, 1000 + r.below(2200), false);
            s.insert(s.begin() + static_cast<std::ptrdiff_t>(r.below(s.size() + 1)), g.begin(), g.end());
            break;
        }
        case 7:
            if (r.chance(50)) {  // a delimiter dropped or added
                if (!s.empty()) {
                    const std::size_t at = r.below(s.size());
                    s[at] = s[at] == 0 ? static_cast<std::uint8_t>(1 + r.below(255)) : 0;
                }
            } else {  // a frame at or just over the size cap, valid CRC
                Bytes body(proto::kMaxBodyBytes - 6 + r.below(10));
                for (auto& b : body)
                    b = r.chance(30) ? 0 : r.byte();
                const std::uint16_t crc = proto::crc16Ccitt(body.data(), body.size() - 2);
                body[body.size() - 2] = static_cast<std::uint8_t>(crc & 0xFF);
                body[body.size() - 1] = static_cast<std::uint8_t>(crc >> 8);
                Bytes wire{0};
                proto::cobsEncode(body.data(), body.size(), wire);
                wire.push_back(0);
                s.insert(s.begin() + static_cast<std::ptrdiff_t>(r.below(s.size() + 1)), wire.begin(), wire.end());
            }
            break;
        default: {  // a byte replaced
            if (!s.empty())
                s[r.below(s.size())] = r.byte();
            break;
        }
        }
    }
}

Bytes generate(Rng& r)
{
    if (r.chance(4))
        return garbage(r, r.below(3000), r.chance(70));
    Bytes s = validStream(r);
    if (r.chance(75))
        mutateStream(r, s);
    return s;
}

bool readFile(const char* path, Bytes& out)
{
    std::ifstream in(path, std::ios::binary);
    if (!in)
        return false;
    out.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    return true;
}

} // namespace

int main(int argc, char** argv)
{
    std::uint64_t iterations = 20000, seed = 0xB1F0C0DEC;
    std::vector<const char*> files;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--iterations" && i + 1 < argc) {
            iterations = std::strtoull(argv[++i], nullptr, 10);
        } else if (a == "--seed" && i + 1 < argc) {
            seed = std::strtoull(argv[++i], nullptr, 0);
        } else if (a == "--help" || a == "-h") {
            std::printf("usage: fuzz_codec [--iterations N] [--seed S] [FILE...]\n");
            return 0;
        } else if (!a.empty() && a[0] == '-') {
            std::fprintf(stderr, "fuzz_codec: unknown option %s\n", a.c_str());
            return 2;
        } else {
            files.push_back(argv[i]);
        }
    }
    if (!files.empty()) {
        for (const char* path : files) {
            Bytes data;
            if (!readFile(path, data)) {
                std::fprintf(stderr, "fuzz_codec: cannot read %s\n", path);
                return 2;
            }
            fuzzOne(data.data(), data.size());
            std::printf("fuzz_codec: %s (%zu bytes) ok\n", path, data.size());
        }
        return 0;
    }
    Rng rng(seed);
    std::uint64_t bytes = 0;
    for (g_iteration = 0; g_iteration < iterations; ++g_iteration) {
        const Bytes input = generate(rng);
        bytes += input.size();
        fuzzOne(input.data(), input.size());
    }
    std::printf("fuzz_codec: %" PRIu64 " inputs, %" PRIu64 " bytes, seed 0x%" PRIX64 ": all invariants held\n", iterations,
                bytes, seed);
    std::printf("  frames %" PRIu64 ", CRC errors %" PRIu64 ", malformed %" PRIu64 ", oversize %" PRIu64
                ", payloads accepted %" PRIu64 "\n  firmware: executed %" PRIu64 " (errors %" PRIu64 "), duplicates %" PRIu64
                ", events %" PRIu64 ", telemetry batches %" PRIu64 "\n",
                g_cov.frames, g_cov.crcErrors, g_cov.malformed, g_cov.oversize, g_cov.payloadsAccepted, g_cov.executed,
                g_cov.errorReplies, g_cov.duplicates, g_cov.events, g_cov.batches);
    std::printf("  errors by code:");
    for (std::size_t k = 1; k <= 10; ++k)
        std::printf(" %" PRIu64, g_cov.errorByCode[k]);
    std::printf("\n  events by kind:");
    for (std::size_t k = 1; k <= 9; ++k)
        std::printf(" %" PRIu64, g_cov.eventByKind[k]);
    std::printf("\n");
    return 0;
}
#endif
