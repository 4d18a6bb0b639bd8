#include "device/protocol/messages_path.h"

#include "device/protocol/bytes.h"

namespace dev::proto {

const char* pathStateName(PathState s)
{
    switch (s) {
    case PathState::Idle: return "idle";
    case PathState::Filling: return "filling";
    case PathState::Running: return "running";
    case PathState::Starved: return "starved";
    case PathState::Holding: return "holding";
    case PathState::Held: return "held";
    case PathState::Done: return "done";
    case PathState::Aborted: return "aborted";
    }
    return "unknown";
}

const char* pathReasonName(PathReason r)
{
    switch (r) {
    case PathReason::None: return "none";
    case PathReason::HostHold: return "feed hold";
    case PathReason::HostSilent: return "host silent";
    case PathReason::Stop: return "stop";
    case PathReason::EStop: return "E-stop";
    case PathReason::LimitSwitch: return "limit switch";
    case PathReason::NewSession: return "new host session";
    case PathReason::Cleared: return "cleared";
    }
    return "unknown";
}

std::size_t pathSegmentBytes(const PathSegmentWire& s)
{
    return 1 + 4 + 8 + (s.kind == PathSegmentKind::Line ? 0 : 8) + (s.hasZ ? 4 : 0);
}

Bytes encode(const PathBeginRequest& m)
{
    Bytes b;
    ByteWriter w(b);
    w.u32(m.firstIndex);
    w.u32(m.junctionDeviation);
    w.u32(m.accel);
    return b;
}

Bytes encode(const PathAppendRequest& m)
{
    Bytes b;
    ByteWriter w(b);
    w.u32(m.firstIndex);
    w.u8(m.flags);
    w.u8(static_cast<std::uint8_t>(m.segments.size()));
    for (const auto& s : m.segments) {
        w.u8(static_cast<std::uint8_t>(static_cast<std::uint8_t>(s.kind) | (s.hasZ ? kPathSegmentHasZ : 0)));
        w.u32(s.feed);
        w.i32(s.x);
        w.i32(s.y);
        if (s.kind != PathSegmentKind::Line) {
            w.i32(s.cx);
            w.i32(s.cy);
        }
        if (s.hasZ)
            w.i32(s.z);
    }
    return b;
}

Bytes encode(const PathStatusReply& m)
{
    Bytes b;
    ByteWriter w(b);
    w.u8(static_cast<std::uint8_t>(m.state));
    w.u8(m.capacity);
    w.u8(m.freeSlots);
    w.u32(m.nextIndex);
    w.u32(m.executingIndex);
    w.u32(m.speed);
    w.u16(m.underruns);
    w.u8(static_cast<std::uint8_t>(m.reason));
    w.u32(m.accel);
    w.u32(m.junctionDeviation);
    return b;
}

std::optional<PathBeginRequest> decodePathBeginRequest(const Bytes& p)
{
    ByteReader r(p);
    PathBeginRequest m;
    m.firstIndex = r.u32();
    m.junctionDeviation = r.u32();
    m.accel = r.u32();
    if (!r.done())
        return std::nullopt;
    return m;
}

std::optional<PathAppendRequest> decodePathAppendRequest(const Bytes& p)
{
    ByteReader r(p);
    PathAppendRequest m;
    m.firstIndex = r.u32();
    m.flags = r.u8();
    if (m.flags & ~(PathAppendStart | PathAppendLast))
        return std::nullopt;
    const int n = r.u8();
    if (!r.ok() || n < 1 || n > kMaxPathSegmentsPerAppend)
        return std::nullopt;
    for (int i = 0; i < n; ++i) {
        const std::uint8_t kind = r.u8();
        const std::uint8_t base = kind & static_cast<std::uint8_t>(~kPathSegmentHasZ);
        if (!r.ok() || base < 1 || base > 3)
            return std::nullopt;
        PathSegmentWire s;
        s.kind = static_cast<PathSegmentKind>(base);
        s.hasZ = kind & kPathSegmentHasZ;
        s.feed = r.u32();
        s.x = r.i32();
        s.y = r.i32();
        if (s.kind != PathSegmentKind::Line) {
            s.cx = r.i32();
            s.cy = r.i32();
        }
        if (s.hasZ)
            s.z = r.i32();
        m.segments.push_back(s);
    }
    if (!r.done())
        return std::nullopt;
    return m;
}

std::optional<PathStatusReply> decodePathStatusReply(const Bytes& p)
{
    ByteReader r(p);
    PathStatusReply m;
    const std::uint8_t state = r.u8();
    if (state > static_cast<std::uint8_t>(PathState::Aborted))
        return std::nullopt;
    m.state = static_cast<PathState>(state);
    m.capacity = r.u8();
    m.freeSlots = r.u8();
    m.nextIndex = r.u32();
    m.executingIndex = r.u32();
    m.speed = r.u32();
    m.underruns = r.u16();
    const std::uint8_t reason = r.u8();
    if (reason > static_cast<std::uint8_t>(PathReason::Cleared))
        return std::nullopt;
    m.reason = static_cast<PathReason>(reason);
    m.accel = r.u32();
    m.junctionDeviation = r.u32();
    if (!r.done() || m.freeSlots > m.capacity)
        return std::nullopt;
    return m;
}

} // namespace dev::proto
