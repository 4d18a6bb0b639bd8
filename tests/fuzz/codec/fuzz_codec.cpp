// Fuzz driver for protocol v1, its checks: the streaming FrameDecoder, every
// payload decoder and the simulator firmware's receive path. The standalone
// input generator and main() are in fuzz_inputs.cpp.
//
// Standalone (the default): `fuzz_codec [--iterations N] [--seed S] [FILE...]`
// generates N deterministic inputs (mutations of valid frame streams: bit flips,
// truncation, splicing, garbage, oversize runs, retransmissions) or replays FILEs,
// and exits 1 on the first violated invariant, after writing the input to
// fuzz_codec-failure.bin; `--corpus DIR` replays a kept corpus (tests/fuzz/corpus/codec)
// before the generated inputs. Built with -DBP_LIBFUZZER=ON (clang; cmake/libfuzzer.cmake,
// docs/testing.md "Fuzzing") the same checks run as LLVMFuzzerTestOneInput:
//   ./build-libfuzzer/tests/fuzz/fuzz_codec -max_len=4096 CORPUS_DIR
// (A single clang++ line over device/protocol, device/sim and motion/*.cpp no longer
// links: motion has subfolders and the simulator needs them.)
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
//    type, seq and payload to one of the last 256 executed is not executed again and
//    is answered with the identical reply; every byte it sends decodes cleanly;
//    replies, events and telemetry batches decode with their decoders; events and
//    batches carry consecutive sequence numbers.
#include "fuzz_support.h"

#include "device/protocol/cobs.h"
#include "device/protocol/crc16.h"
#include "device/protocol/frame_codec.h"
#include "device/protocol/messages_arch.h"
#include "device/protocol/messages.h"
#include "device/protocol/messages_compensation.h"
#include "device/protocol/messages_compensation_2d.h"
#include "device/protocol/messages_tuning.h"
#include "device/protocol/messages_path.h"
#include "device/sim/firmware.h"
#include "device/sim/machine_config.h"

#include <algorithm>
#include <array>
#include <cinttypes>
#include <cmath>
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

namespace fuzz {

const Bytes* g_input = nullptr;
std::uint64_t g_iteration = 0;
Coverage g_cov;

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


namespace {

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
    constexpr std::size_t kMaxBlock = dev::proto::kMaxBodyBytes + dev::proto::kMaxBodyBytes / 254 + 1;
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
        if (body && body->size() > dev::proto::kMaxBodyBytes) {
            ++r.stats.oversize;
        } else if (!body || body->size() < 5) {
            ++r.stats.malformed;
        } else {
            const std::size_t n = body->size();
            const unsigned want = (*body)[n - 2] | ((*body)[n - 1] << 8);
            if (dev::proto::crc16Ccitt(body->data(), n - 2) != want) {
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
    const Bytes again = dev::proto::encode(*d);
    CHECK(again == p, "%s accepted a %zu-byte payload that re-encodes to %zu different bytes", name, p.size(), again.size());
}

void checkAllDecoders(const Bytes& p)
{
    checkDecoder(p, &dev::proto::decodeHelloReply, "decodeHelloReply");
    checkDecoder(p, &dev::proto::decodeStatusReply, "decodeStatusReply");
    checkDecoder(p, &dev::proto::decodeHomeRequest, "decodeHomeRequest");
    checkDecoder(p, &dev::proto::decodeMoveRequest, "decodeMoveRequest");
    checkDecoder(p, &dev::proto::decodeArchMoveRequest, "decodeArchMoveRequest");
    checkDecoder(p, &dev::proto::decodeJogStepRequest, "decodeJogStepRequest");
    checkDecoder(p, &dev::proto::decodeAxisMaskRequest, "decodeAxisMaskRequest");
    checkDecoder(p, &dev::proto::decodeLimitsReply, "decodeLimitsReply");
    checkDecoder(p, &dev::proto::decodeSetLimitsRequest, "decodeSetLimitsRequest");
    checkDecoder(p, &dev::proto::decodeJogVelocityRequest, "decodeJogVelocityRequest");
    checkDecoder(p, &dev::proto::decodeSubscribeRequest, "decodeSubscribeRequest");
    checkDecoder(p, &dev::proto::decodeSubscribeReply, "decodeSubscribeReply");
    checkDecoder(p, &dev::proto::decodeTelemetryBatch, "decodeTelemetryBatch");
    checkDecoder(p, &dev::proto::decodeEvent, "decodeEvent");
    checkDecoder(p, &dev::proto::decodeErrorReply, "decodeErrorReply");
    checkDecoder(p, &dev::proto::decodeAxisRequest, "decodeAxisRequest");
    checkDecoder(p, &dev::proto::decodeGainsReply, "decodeGainsReply");
    checkDecoder(p, &dev::proto::decodeSetGainsRequest, "decodeSetGainsRequest");
    checkDecoder(p, &dev::proto::decodeStepTestRequest, "decodeStepTestRequest");
    checkDecoder(p, &dev::proto::decodeRelayTestRequest, "decodeRelayTestRequest");
    checkDecoder(p, &dev::proto::decodeCaptureRequest, "decodeCaptureRequest");
    checkDecoder(p, &dev::proto::decodeCaptureReply, "decodeCaptureReply");
    checkDecoder(p, &dev::proto::decodeAbortRequest, "decodeAbortRequest");
    checkDecoder(p, &dev::proto::decodePathBeginRequest, "decodePathBeginRequest");
    checkDecoder(p, &dev::proto::decodePathAppendRequest, "decodePathAppendRequest");
    checkDecoder(p, &dev::proto::decodePathStatusReply, "decodePathStatusReply");
    checkDecoder(p, &dev::proto::decodeCompUploadRequest, "decodeCompUploadRequest");
    checkDecoder(p, &dev::proto::decodeCompUploadReply, "decodeCompUploadReply");
    checkDecoder(p, &dev::proto::decodeCompGetRequest, "decodeCompGetRequest");
    checkDecoder(p, &dev::proto::decodeCompGetReply, "decodeCompGetReply");
    checkDecoder(p, &dev::proto::decodeCompEnableRequest, "decodeCompEnableRequest");
    checkDecoder(p, &dev::proto::decodeComp2dUploadRequest, "decodeComp2dUploadRequest");
    checkDecoder(p, &dev::proto::decodeComp2dUploadReply, "decodeComp2dUploadReply");
    checkDecoder(p, &dev::proto::decodeComp2dEnableRequest, "decodeComp2dEnableRequest");
    checkDecoder(p, &dev::proto::decodeComp2dEnableReply, "decodeComp2dEnableReply");
    if (const auto u = dev::proto::decodeComp2dUploadRequest(p))
        CHECK(u->nodes.size() <= dev::proto::kMaxComp2dNodesPerFrame, "COMP2D_UPLOAD node count");
    if (const auto a = dev::proto::decodePathAppendRequest(p))
        CHECK(!a->segments.empty() && a->segments.size() <= std::size_t(dev::proto::kMaxPathSegmentsPerAppend), "PATH_APPEND segment count");
    const auto move = dev::proto::decodeMoveRequest(p);
    if (move)
        CHECK(static_cast<int>(move->targets.size()) == dev::proto::popcount8(move->axisMask), "MOVE target count != axes");
    const auto jog = dev::proto::decodeJogVelocityRequest(p);
    if (jog)
        CHECK(static_cast<int>(jog->velocities.size()) == dev::proto::popcount8(jog->axisMask), "JOG_VELOCITY count != axes");
    const auto batch = dev::proto::decodeTelemetryBatch(p);
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
        CHECK(f.payload.size() <= dev::proto::kMaxPayloadBytes, "decoded payload of %zu bytes is over the cap", f.payload.size());
        Bytes wire;
        CHECK(dev::proto::encodeFrame(f, wire), "a decoded frame does not re-encode");
        CHECK(wire.size() >= 2 && wire.front() == 0 && wire.back() == 0, "re-encoded frame is not delimited");
        CHECK(std::count(wire.begin() + 1, wire.end() - 1, 0) == 0, "re-encoded frame has a zero inside");
        CHECK(wire.size() <= dev::proto::wireBytesForPayload(f.payload.size()), "re-encoded frame longer than wireBytesForPayload");
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

/// The duplicate-request cache as docs/protocol.md specifies it: the last 256
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
        if (m_entries.size() == 256)
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
    return (t >= 0x01 && t <= 0x0A) || (t >= 0x20 && t <= 0x22) || dev::proto::tuningTypeName(t) != nullptr
        || (t >= 0x10 && t <= 0x13) || (t >= 0x24 && t <= 0x26) || dev::proto::compensationTypeName(t) != nullptr
        || dev::proto::compensation2dTypeName(t) != nullptr;
}

struct FirmwareChecker {
    dev::sim::Firmware& fw;
    int axes;
    dev::proto::DeviceKind kind;
    FrameDecoder outDecoder;
    std::uint16_t nextDeviceSeq = 0;
    std::uint64_t executed = 0, duplicates = 0;
    bool haveMotionSeq = false;
    std::uint16_t lastMotionSeq = 0;  ///< the last velocity, stop or E-stop executed
    ReplyCacheModel cache;
    std::optional<Frame> lastQueued;  ///< type, seq and payload of the last executed queued request

    /// Checks a device-initiated frame (event or telemetry batch).
    void deviceFrame(const Frame& f)
    {
        CHECK(f.seq == nextDeviceSeq, "device frame seq %u, expected %u", unsigned{f.seq}, unsigned{nextDeviceSeq});
        ++nextDeviceSeq;
        if (f.type == static_cast<std::uint8_t>(MsgType::Event)) {
            ++g_cov.events;
            const auto e = dev::proto::decodeEvent(f.payload);
            CHECK(e.has_value(), "EVENT payload does not decode");
            CHECK(e->axis == dev::proto::kNoAxis || e->axis < axes, "event on axis %u", unsigned{e->axis});
            ++g_cov.eventByKind[static_cast<std::size_t>(e->kind) & 15];
        } else {
            ++g_cov.batches;
            const auto b = dev::proto::decodeTelemetryBatch(f.payload);
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
            const auto e = dev::proto::decodeErrorReply(rep.payload);
            CHECK(e.has_value(), "ERROR reply to 0x%02X does not decode", unsigned{req.type});
            ++g_cov.errorByCode[static_cast<std::size_t>(e->code) & 15];
            if (!knownRequest(req.type))
                CHECK(e->code == dev::proto::ErrorCode::UnknownCommand && e->value == req.type,
                      "unknown request 0x%02X answered with error %d", unsigned{req.type}, int(e->code));
            return;
        }
        CHECK(knownRequest(req.type), "unknown request 0x%02X got a success reply", unsigned{req.type});
        CHECK(rep.type == (req.type | dev::proto::kReplyFlag), "reply type 0x%02X to request 0x%02X", unsigned{rep.type},
              unsigned{req.type});
        switch (static_cast<MsgType>(req.type)) {
        case MsgType::Hello: {
            const auto h = dev::proto::decodeHelloReply(rep.payload);
            CHECK(h && h->kind == kind && static_cast<int>(h->axes.size()) == axes
                      && h->protocolVersion == dev::proto::kProtocolVersion,
                  "HELLO reply wrong");
            CHECK(req.payload.size() <= 1, "HELLO with a payload of more than its flags byte was accepted");
            CHECK(h->motionLimits.has_value() == (req.payload.size() == 1 && (req.payload[0] & dev::proto::HelloReadsExtensions)),
                  "HELLO's extension blocks do not follow the request's flags");
            break;
        }
        case MsgType::Status: {
            const auto st = dev::proto::decodeStatusReply(rep.payload);
            CHECK(st && static_cast<int>(st->axes.size()) == axes, "STATUS reply wrong");
            break;
        }
        case MsgType::GetLimits: {
            const auto l = dev::proto::decodeLimitsReply(rep.payload);
            CHECK(l && static_cast<int>(l->axes.size()) == axes, "GET_LIMITS reply wrong");
            for (const auto& a : l->axes)
                CHECK(a.min < a.max, "soft limits out of order");
            break;
        }
        case MsgType::PathBegin:
        case MsgType::PathAppend:
        case MsgType::PathStatus: {
            const auto st = dev::proto::decodePathStatusReply(rep.payload);
            CHECK(st.has_value(), "path reply to 0x%02X does not decode", unsigned{req.type});
            CHECK(st->freeSlots <= st->capacity && st->executingIndex <= st->nextIndex, "path status inconsistent");
            break;
        }
        case MsgType::Subscribe: {
            const auto r = dev::proto::decodeSubscribeReply(rep.payload);
            CHECK(r.has_value(), "SUBSCRIBE reply does not decode");
            CHECK((r->rateHz == 0) == (r->samplesPerBatch == 0), "SUBSCRIBE reply rate/batch inconsistent");
            break;
        }
        default:
            if (req.type == static_cast<std::uint8_t>(dev::proto::kGetGains)) {
                const auto g = dev::proto::decodeGainsReply(rep.payload);
                CHECK(g && g->axis < axes && g->controlPeriodUs > 0, "GET_GAINS reply wrong");
                CHECK(std::isfinite(g->gains.kp) && g->gains.kp >= 0 && std::isfinite(g->gains.ki) && g->gains.ki >= 0
                          && std::isfinite(g->gains.kd) && g->gains.kd >= 0,
                      "the device holds gains it should have refused");
                break;
            }
            if (req.type == static_cast<std::uint8_t>(dev::proto::kGetCapture)) {
                const auto c = dev::proto::decodeCaptureReply(rep.payload);
                CHECK(c && c->axis < axes && c->first + c->samples.size() <= c->total, "GET_CAPTURE reply wrong");
                break;
            }
            if (req.type == static_cast<std::uint8_t>(dev::proto::kComp2dUpload)) {
                const auto u = dev::proto::decodeComp2dUploadReply(rep.payload);
                CHECK(u.has_value(), "COMP2D_UPLOAD reply does not decode");
                break;
            }
            if (req.type == static_cast<std::uint8_t>(dev::proto::kComp2dEnable)) {
                const auto e = dev::proto::decodeComp2dEnableReply(rep.payload);
                CHECK(e && ((e->state & dev::proto::Comp2dInstalled) != 0) == (e->columns >= 2 && e->rows >= 2),
                      "COMP2D_ENABLE reply's state and grid disagree");
                break;
            }
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
            if (dev::proto::isRealtimeType(f.type))
                order.push_back(&f);
        for (const auto& f : chunkFrames)
            if (f.type < 0x80 && !dev::proto::isRealtimeType(f.type))
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
            {
                cache.clear();
                haveMotionSeq = false;
            }
            const bool velocity = req.type == static_cast<std::uint8_t>(MsgType::JogVelocity);
            if (CachedModel* c = cache.find(req)) {
                ++duplicates;
                ++g_cov.duplicates;
                CHECK(sameFrame(rep, c->reply), "retransmitted request 0x%02X seq %u got a different reply",
                      unsigned{req.type}, unsigned{req.seq});
            } else if (velocity && haveMotionSeq && static_cast<std::int16_t>(req.seq - lastMotionSeq) < 0) {
                // A late velocity command (docs/protocol.md): answered, never acted on, not cached.
                CHECK(rep.type == dev::proto::replyTypeOf(MsgType::JogVelocity) && rep.payload.empty(),
                      "a late JOG_VELOCITY seq %u got 0x%02X", unsigned{req.seq}, unsigned{rep.type});
            } else {
                if (velocity || req.type == static_cast<std::uint8_t>(MsgType::Stop) || req.type == static_cast<std::uint8_t>(MsgType::EStop)) {
                    haveMotionSeq = true;
                    lastMotionSeq = req.seq;
                }
                ++executed;
                ++g_cov.executed;
                g_cov.errorReplies += rep.type == static_cast<std::uint8_t>(MsgType::Error);
                cache.insert(req).reply = rep;
                if (!dev::proto::isRealtimeType(req.type))
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
    const dev::sim::MachineConfig cfg = stage ? dev::sim::stageConfig() : dev::sim::analyzerConfig();
    dev::sim::Firmware fw(cfg, kBauds[rng.below(4)]);
    FirmwareChecker c{fw, static_cast<int>(cfg.axes.size()), cfg.kind, {}, 0, 0, 0, false, 0, {}, {}};

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
        dev::proto::encodeFrame(static_cast<std::uint8_t>(MsgType::Home), 0xFFFE, dev::proto::encode(dev::proto::HomeRequest{0}).data(), 1, home);
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
        CHECK(dev::proto::encodeFrame(f, wire), "cannot re-encode a cached request");
        const std::uint64_t dupsBefore = fw.duplicateRequests();
        feed(wire.data(), wire.size());
        CHECK(fw.duplicateRequests() > dupsBefore, "a retransmitted request was executed again");
    }
}

} // namespace

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

} // namespace fuzz

#ifdef BP_LIBFUZZER
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    fuzz::fuzzOne(data, size);
    return 0;
}
#endif
