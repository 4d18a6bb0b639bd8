#include "device/protocol/messages_tuning.h"

#include "device/protocol/bytes.h"

#include <cstring>

namespace dev::proto {
namespace {

std::uint32_t bitsOf(float f)
{
    std::uint32_t u;
    std::memcpy(&u, &f, 4);
    return u;
}

float floatOf(std::uint32_t u)
{
    float f;
    std::memcpy(&f, &u, 4);
    return f;
}

void put(ByteWriter& w, const WireGains& g)
{
    w.u32(bitsOf(g.kp));
    w.u32(bitsOf(g.ki));
    w.u32(bitsOf(g.kd));
}

WireGains getGains(ByteReader& r)
{
    WireGains g;
    g.kp = floatOf(r.u32());
    g.ki = floatOf(r.u32());
    g.kd = floatOf(r.u32());
    return g;
}

void put(ByteWriter& w, const WireEnvelope& e)
{
    w.u32(e.maxExcursion);
    w.u32(e.maxFollowingError);
    w.u32(e.maxDurationMs);
}

WireEnvelope getEnvelope(ByteReader& r)
{
    WireEnvelope e;
    e.maxExcursion = r.u32();
    e.maxFollowingError = r.u32();
    e.maxDurationMs = r.u32();
    return e;
}


} // namespace

bool WireGains::operator==(const WireGains& o) const
{
    return bitsOf(kp) == bitsOf(o.kp) && bitsOf(ki) == bitsOf(o.ki) && bitsOf(kd) == bitsOf(o.kd);
}

const char* tuningTypeName(std::uint8_t type)
{
    switch (type) {
    case 0x0B: return "GET_GAINS";
    case 0x0C: return "SET_GAINS";
    case 0x0D: return "STEP_TEST";
    case 0x0E: return "RELAY_TEST";
    case 0x0F: return "GET_CAPTURE";
    case 0x23: return "TEST_ABORT";
    default: return nullptr;
    }
}

Bytes encode(const AxisRequest& m) { return Bytes{m.axis}; }
Bytes encode(const AbortRequest& m) { return Bytes{m.axisMask}; }

Bytes encode(const GainsReply& m)
{
    Bytes b;
    ByteWriter w(b);
    w.u8(m.axis);
    w.u32(m.controlPeriodUs);
    put(w, m.gains);
    put(w, m.saved);
    w.u8(m.flags);
    put(w, m.limits);
    return b;
}

Bytes encode(const SetGainsRequest& m)
{
    Bytes b;
    ByteWriter w(b);
    w.u8(m.axis);
    w.u8(m.flags);
    put(w, m.gains);
    return b;
}

Bytes encode(const StepTestRequest& m)
{
    Bytes b;
    ByteWriter w(b);
    w.u8(m.axis);
    w.u8(m.trialGains ? 1 : 0);
    w.i32(m.step);
    w.u32(m.settleBand);
    w.u16(m.settleHoldMs);
    w.u32(m.runMs);
    put(w, m.envelope);
    if (m.trialGains)
        put(w, *m.trialGains);
    return b;
}

Bytes encode(const RelayTestRequest& m)
{
    Bytes b;
    ByteWriter w(b);
    w.u8(m.axis);
    w.u32(m.amplitude);
    w.u32(m.hysteresis);
    w.u32(m.forcedPeriodUs);
    w.u16(m.cycles);
    put(w, m.envelope);
    return b;
}

Bytes encode(const CaptureRequest& m)
{
    Bytes b;
    ByteWriter w(b);
    w.u8(m.axis);
    w.u32(m.first);
    w.u16(m.maxCount);
    return b;
}

Bytes encode(const CaptureReply& m)
{
    Bytes b;
    ByteWriter w(b);
    w.u8(m.axis);
    w.u8(m.kind);
    w.u8(m.reason);
    w.u32(m.testId);
    w.u32(m.periodUs);
    w.u32(m.total);
    w.i32(m.startPosition);
    w.u32(m.tripValue);
    w.u32(m.tripLimit);
    put(w, m.gains);
    w.u32(m.first);
    w.u16(static_cast<std::uint16_t>(m.samples.size()));
    for (const auto& s : m.samples) {
        w.i32(s.setpoint);
        w.i32(s.measured);
        w.i32(s.output);
    }
    return b;
}

std::optional<AxisRequest> decodeAxisRequest(const Bytes& p)
{
    if (p.size() != 1)
        return std::nullopt;
    return AxisRequest{p[0]};
}

std::optional<AbortRequest> decodeAbortRequest(const Bytes& p)
{
    if (p.size() != 1)
        return std::nullopt;
    return AbortRequest{p[0]};
}

std::optional<GainsReply> decodeGainsReply(const Bytes& p)
{
    ByteReader r(p);
    GainsReply m;
    m.axis = r.u8();
    m.controlPeriodUs = r.u32();
    m.gains = getGains(r);
    m.saved = getGains(r);
    m.flags = r.u8();
    if (m.flags > 1)
        return std::nullopt;
    m.limits = getGains(r);
    return finish(r, std::move(m));
}

std::optional<SetGainsRequest> decodeSetGainsRequest(const Bytes& p)
{
    ByteReader r(p);
    SetGainsRequest m;
    m.axis = r.u8();
    m.flags = r.u8();
    if (m.flags > 1)
        return std::nullopt;
    m.gains = getGains(r);
    return finish(r, std::move(m));
}

std::optional<StepTestRequest> decodeStepTestRequest(const Bytes& p)
{
    ByteReader r(p);
    StepTestRequest m;
    m.axis = r.u8();
    const std::uint8_t flags = r.u8();
    if (flags > 1)
        return std::nullopt;
    m.step = r.i32();
    m.settleBand = r.u32();
    m.settleHoldMs = r.u16();
    m.runMs = r.u32();
    m.envelope = getEnvelope(r);
    if (flags & 1)
        m.trialGains = getGains(r);
    return finish(r, std::move(m));
}

std::optional<RelayTestRequest> decodeRelayTestRequest(const Bytes& p)
{
    ByteReader r(p);
    RelayTestRequest m;
    m.axis = r.u8();
    m.amplitude = r.u32();
    m.hysteresis = r.u32();
    m.forcedPeriodUs = r.u32();
    m.cycles = r.u16();
    m.envelope = getEnvelope(r);
    return finish(r, std::move(m));
}

std::optional<CaptureRequest> decodeCaptureRequest(const Bytes& p)
{
    ByteReader r(p);
    CaptureRequest m;
    m.axis = r.u8();
    m.first = r.u32();
    m.maxCount = r.u16();
    return finish(r, std::move(m));
}

std::optional<CaptureReply> decodeCaptureReply(const Bytes& p)
{
    ByteReader r(p);
    CaptureReply m;
    m.axis = r.u8();
    m.kind = r.u8();
    m.reason = r.u8();
    if (m.kind > 2 || m.reason > 9)
        return std::nullopt;
    m.testId = r.u32();
    m.periodUs = r.u32();
    m.total = r.u32();
    m.startPosition = r.i32();
    m.tripValue = r.u32();
    m.tripLimit = r.u32();
    m.gains = getGains(r);
    m.first = r.u32();
    const std::size_t n = r.u16();
    if (!r.ok() || r.remaining() != 12 * n)
        return std::nullopt;
    m.samples.resize(n);
    for (auto& s : m.samples) {
        s.setpoint = r.i32();
        s.measured = r.i32();
        s.output = r.i32();
    }
    return finish(r, std::move(m));
}

} // namespace dev::proto
