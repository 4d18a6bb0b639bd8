// Standalone mode of the protocol fuzz driver: deterministic inputs (mutations of
// valid frame streams) or replayed files, fed to fuzz::fuzzOne. Not built with
// -DBP_LIBFUZZER, where libFuzzer supplies main() and the inputs.
#ifndef BP_LIBFUZZER
#include "fuzz_support.h"
#include "tests/fuzz/corpus_files.h"

#include "device/protocol/cobs.h"
#include "device/protocol/crc16.h"
#include "device/protocol/messages.h"
#include "device/protocol/messages_arch.h"
#include "device/protocol/messages_tuning.h"
#include "device/protocol/messages_path.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>

namespace {

using namespace fuzz;

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

std::vector<dev::proto::ChannelRef> randChannels(Rng& r)
{
    std::vector<dev::proto::ChannelRef> ch(r.below(r.chance(5) ? 200 : 6));
    for (auto& c : ch) {
        c.axis = r.chance(10) ? dev::proto::kNoAxis : static_cast<std::uint8_t>(r.below(r.chance(90) ? 4 : 256));
        c.kind = static_cast<dev::proto::ChannelKind>(r.below(7));
    }
    return ch;
}

dev::proto::WireGains randGains(Rng& r)
{
    auto one = [&]() -> float {
        switch (r.below(8)) {
        case 0: return std::numeric_limits<float>::quiet_NaN();
        case 1: return r.chance(50) ? std::numeric_limits<float>::infinity() : -std::numeric_limits<float>::infinity();
        case 2: return -static_cast<float>(r.below(100)) / 10.0f;
        case 3: return 1e9f;
        default: return static_cast<float>(r.below(10000)) / 1000.0f;
        }
    };
    return {one(), one(), one()};
}

dev::proto::WireEnvelope randEnvelope(Rng& r)
{
    auto lim = [&]() { return static_cast<std::uint32_t>(r.chance(80) ? r.range(0, 200000) : r.next()); };
    return {lim(), lim(), static_cast<std::uint32_t>(r.chance(80) ? r.range(0, 3000) : r.next())};
}

/// Segments near the machine's start positions (so some are accepted once homed), some arcs
/// with ends on their circle, some nonsense.
dev::proto::PathAppendRequest randPathAppend(Rng& r)
{
    using namespace dev::proto;
    PathAppendRequest a;
    a.firstIndex = r.chance(80) ? static_cast<std::uint32_t>(r.below(40)) : static_cast<std::uint32_t>(r.next());
    a.flags = static_cast<std::uint8_t>(r.below(4));
    a.segments.resize(1 + r.below(r.chance(10) ? kMaxPathSegmentsPerAppend : 4));
    for (auto& s : a.segments) {
        s.kind = static_cast<PathSegmentKind>(1 + r.below(3));
        s.feed = r.chance(80) ? static_cast<std::uint32_t>(r.range(1, 20000000)) : randSpeed(r);
        const std::int32_t cx = static_cast<std::int32_t>(r.range(5000000, 95000000));
        const std::int32_t cy = static_cast<std::int32_t>(r.range(5000000, 95000000));
        const std::int32_t rad = static_cast<std::int32_t>(r.range(0, 5000000));
        s.cx = r.chance(90) ? cx : randPosition(r);
        s.cy = r.chance(90) ? cy : randPosition(r);
        s.x = r.chance(50) ? cx + rad : randPosition(r);
        s.y = r.chance(50) ? cy : randPosition(r);
        s.hasZ = r.chance(10);
        s.z = randPosition(r);
    }
    return a;
}

Bytes validPayload(Rng& r, std::uint8_t type)
{
    using namespace dev::proto;
    switch (type) {
    // HELLO: as a 1.0 host (empty), or with flags, so sessions that read extension blocks
    // and event reasons (bit 1) are driven too.
    case 0x01: return r.chance(30) ? Bytes{} : encode(HelloRequest{static_cast<std::uint8_t>(r.below(4))});
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
    case 0x13: {
        // Arched moves near the analyzer's travel, half of them with the pump block
        // (some with its plunger past its travel or its liquid height above the clearance).
        ArchMoveRequest a;
        a.xySpeed = r.chance(70) ? 0 : randSpeed(r);
        a.zSpeed = r.chance(70) ? 0 : randSpeed(r);
        a.x = r.chance(80) ? static_cast<std::int32_t>(r.range(10000000, 190000000)) : randPosition(r);
        a.y = r.chance(80) ? static_cast<std::int32_t>(r.range(10000000, 190000000)) : randPosition(r);
        a.clearZ = r.chance(80) ? static_cast<std::int32_t>(r.range(20000000, 60000000)) : randPosition(r);
        a.z = r.chance(80) ? static_cast<std::int32_t>(r.range(40000000, 90000000)) : randPosition(r);
        a.departRadius = static_cast<std::uint32_t>(r.range(0, 4000000));
        a.approachRadius = static_cast<std::uint32_t>(r.range(0, 4000000));
        if (r.chance(50)) {
            ArchPump p;
            p.delta = r.chance(80) ? static_cast<std::int32_t>(r.range(-200000, 200000)) : randPosition(r);
            p.speed = r.chance(70) ? 0 : randSpeed(r);
            p.liquidZ = r.chance(80) ? static_cast<std::int32_t>(r.range(30000000, 80000000)) : randPosition(r);
            p.leaveZ = r.chance(80) ? a.clearZ : randPosition(r);
            a.pump = p;
        }
        return encode(a);
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
    case 0x0B: return encode(AxisRequest{static_cast<std::uint8_t>(r.below(r.chance(90) ? 2 : 256))});
    case 0x0C: return encode(SetGainsRequest{static_cast<std::uint8_t>(r.below(3)), static_cast<std::uint8_t>(r.below(2)), randGains(r)});
    case 0x0D: {
        StepTestRequest s;
        s.axis = static_cast<std::uint8_t>(r.below(r.chance(90) ? 2 : 4));
        s.step = r.chance(80) ? static_cast<std::int32_t>(r.range(-50000, 50000)) : randPosition(r);
        s.settleBand = static_cast<std::uint32_t>(r.range(0, 5000));
        s.settleHoldMs = static_cast<std::uint16_t>(r.below(100));
        s.runMs = static_cast<std::uint32_t>(r.chance(50) ? r.range(0, 500) : r.next());
        s.envelope = randEnvelope(r);
        if (r.chance(50))
            s.trialGains = randGains(r);
        return encode(s);
    }
    case 0x0E: {
        RelayTestRequest q;
        q.axis = static_cast<std::uint8_t>(r.below(r.chance(90) ? 2 : 4));
        q.amplitude = static_cast<std::uint32_t>(r.chance(80) ? r.range(0, 50000) : r.next());
        q.hysteresis = static_cast<std::uint32_t>(r.range(0, 5000));
        q.forcedPeriodUs = static_cast<std::uint32_t>(r.chance(50) ? 0 : r.range(0, 20000));
        q.cycles = static_cast<std::uint16_t>(r.below(r.chance(80) ? 30 : 65536));
        q.envelope = randEnvelope(r);
        return encode(q);
    }
    case 0x0F: return encode(CaptureRequest{static_cast<std::uint8_t>(r.below(3)), static_cast<std::uint32_t>(r.chance(70) ? r.below(200) : r.next()),
                                            static_cast<std::uint16_t>(r.below(r.chance(80) ? 100 : 65536))});
    case 0x23: return encode(AbortRequest{randMask(r)});
    case 0x8B: {
        GainsReply g;
        g.axis = r.byte();
        g.controlPeriodUs = static_cast<std::uint32_t>(r.next());
        g.gains = randGains(r);
        g.saved = randGains(r);
        g.flags = static_cast<std::uint8_t>(r.below(2));
        g.limits = randGains(r);
        return encode(g);
    }
    case 0x8F: {
        CaptureReply c;
        c.axis = r.byte();
        c.kind = static_cast<std::uint8_t>(r.below(3));
        c.reason = static_cast<std::uint8_t>(r.below(10));
        c.testId = static_cast<std::uint32_t>(r.next());
        c.periodUs = static_cast<std::uint32_t>(r.next());
        c.total = static_cast<std::uint32_t>(r.next());
        c.startPosition = randPosition(r);
        c.gains = randGains(r);
        c.samples.resize(r.below(r.chance(5) ? 81 : 6));
        for (auto& s : c.samples)
            s = {randPosition(r), randPosition(r), randPosition(r)};
        return encode(c);
    }
    case 0x10: {
        PathBeginRequest b;
        b.firstIndex = r.chance(80) ? 0 : static_cast<std::uint32_t>(r.next());
        b.junctionDeviation = r.chance(70) ? 0 : static_cast<std::uint32_t>(r.range(0, 2000000));
        b.accel = r.chance(70) ? 0 : static_cast<std::uint32_t>(r.next());
        return encode(b);
    }
    case 0x11: return encode(randPathAppend(r));
    case 0x92: {
        PathStatusReply s;
        s.state = static_cast<PathState>(r.below(8));
        s.capacity = static_cast<std::uint8_t>(r.below(64));
        s.freeSlots = static_cast<std::uint8_t>(r.below(s.capacity + 1u));
        s.nextIndex = static_cast<std::uint32_t>(r.next());
        s.executingIndex = static_cast<std::uint32_t>(r.next());
        s.speed = randSpeed(r);
        s.underruns = static_cast<std::uint16_t>(r.next());
        s.reason = static_cast<PathReason>(r.below(8));
        s.accel = randSpeed(r);
        s.junctionDeviation = randSpeed(r);
        return encode(s);
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
        if (r.chance(50)) {  // a host that asked for the extension blocks
            MotionLimits l;
            l.profile = static_cast<MotionProfile>(r.below(4));
            for (std::size_t i = 0; i < h.axes.size(); ++i)
                l.axes.push_back({randSpeed(r), randSpeed(r), randSpeed(r), randSpeed(r)});
            h.motionLimits = l;
            if (r.chance(20))
                h.otherBlocks.push_back({static_cast<std::uint8_t>(2 + r.below(200)), {1, 2, 3}});
        }
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
        e.kind = static_cast<EventKind>(r.chance(80) ? 1 + r.below(9) : 20 + r.below(6));
        e.axis = r.byte();
        e.deviceTimeUs = r.next();
        e.position = randPosition(r);
        e.text = randText(r);
        if (r.chance(50)) {
            EventReason why{static_cast<std::uint8_t>(1 + r.below(255)), {}};
            for (std::size_t i = r.below(kMaxEventReasonValues + 1); i > 0; --i)
                why.values.push_back(static_cast<double>(randPosition(r)) / 1e6);
            e.reason = std::move(why);
        }
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
                                             0x08, 0x08, 0x09, 0x09, 0x20, 0x20, 0x20, 0x21, 0x21,
                                             0x0B, 0x0C, 0x0C, 0x0D, 0x0D, 0x0E, 0x0E, 0x0F, 0x23,
                                             0x10, 0x11, 0x11, 0x11, 0x12, 0x13, 0x13, 0x24, 0x25, 0x26};
    if (r.chance(2))
        return r.chance(50) ? 0x22 : 0x0A;
    static const std::uint8_t kOthers[] = {0x81, 0x82, 0x87, 0x89, 0x8B, 0x8F, 0x92, 0xA0, 0xE0, 0xE1, 0xFF, 0x1F, 0x3F, 0x40, 0x00};
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
        if (f.payload.size() > dev::proto::kMaxPayloadBytes)
            f.payload.resize(dev::proto::kMaxPayloadBytes);
        frames.push_back(std::move(f));
    }
    Bytes wire;
    for (const auto& f : frames) {
        if (r.chance(10))
            wire.insert(wire.end(), r.below(4), 0x00);  // idle fill
        dev::proto::encodeFrame(f, wire);
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
                Bytes body(dev::proto::kMaxBodyBytes - 6 + r.below(10));
                for (auto& b : body)
                    b = r.chance(30) ? 0 : r.byte();
                const std::uint16_t crc = dev::proto::crc16Ccitt(body.data(), body.size() - 2);
                body[body.size() - 2] = static_cast<std::uint8_t>(crc & 0xFF);
                body[body.size() - 1] = static_cast<std::uint8_t>(crc >> 8);
                Bytes wire{0};
                dev::proto::cobsEncode(body.data(), body.size(), wire);
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
    std::string corpus, seedDir;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--iterations" && i + 1 < argc) {
            iterations = std::strtoull(argv[++i], nullptr, 10);
        } else if (a == "--seed" && i + 1 < argc) {
            seed = std::strtoull(argv[++i], nullptr, 0);
        } else if (a == "--corpus" && i + 1 < argc) {
            corpus = argv[++i];
        } else if (a == "--emit" && i + 1 < argc) {
            seedDir = argv[++i];
        } else if (a == "--help" || a == "-h") {
            std::printf("usage: fuzz_codec [--iterations N] [--seed S] [--corpus DIR] [FILE...]\n"
                        "       fuzz_codec --emit DIR [--iterations N] [--seed S]   (writes the generated inputs, as libFuzzer seeds)\n"
                        "  --corpus DIR  replays every file of DIR (a kept corpus) before the N generated inputs\n");
            return 0;
        } else if (!a.empty() && a[0] == '-') {
            std::fprintf(stderr, "fuzz_codec: unknown option %s\n", a.c_str());
            return 2;
        } else {
            files.push_back(argv[i]);
        }
    }
    if (!seedDir.empty()) {
        Rng rng(seed);
        for (std::uint64_t k = 0; k < iterations; ++k) {
            const Bytes input = generate(rng);
            if (!fuzzcorpus::write(seedDir + "/gen-" + std::to_string(k), input.data(), input.size())) {
                std::fprintf(stderr, "fuzz_codec: cannot write into %s\n", seedDir.c_str());
                return 2;
            }
        }
        return 0;
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
    if (!corpus.empty()) {
        // A kept corpus that went missing would leave the test passing on less than it claims.
        const auto paths = fuzzcorpus::files(corpus);
        if (!paths || paths->empty()) {
            std::fprintf(stderr, "fuzz_codec: no corpus in %s\n", corpus.c_str());
            return 2;
        }
        for (const std::string& path : *paths) {
            Bytes data;
            if (!readFile(path.c_str(), data)) {
                std::fprintf(stderr, "fuzz_codec: cannot read %s\n", path.c_str());
                return 2;
            }
            fuzzOne(data.data(), data.size());
        }
        std::printf("fuzz_codec: %zu corpus inputs of %s replayed\n", paths->size(), corpus.c_str());
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
