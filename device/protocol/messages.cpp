#include "device/protocol/messages.h"

#include "device/protocol/bytes.h"
#include "device/protocol/frame_codec.h"

#include <cmath>

namespace dev::proto {

int popcount8(std::uint8_t mask)
{
    int n = 0;
    for (; mask; mask = static_cast<std::uint8_t>(mask & (mask - 1)))
        ++n;
    return n;
}

const char* errorCodeName(ErrorCode c)
{
    switch (c) {
    case ErrorCode::UnknownCommand: return "unknown command";
    case ErrorCode::BadPayload: return "bad payload";
    case ErrorCode::BadAxis: return "bad axis";
    case ErrorCode::NotHomed: return "axis not homed";
    case ErrorCode::SoftLimit: return "soft limit";
    case ErrorCode::Busy: return "busy";
    case ErrorCode::EStopActive: return "E-stop active";
    case ErrorCode::OverCapacity: return "over link capacity";
    case ErrorCode::OutOfRange: return "out of range";
    case ErrorCode::Fault: return "fault";
    case ErrorCode::PathQueueFull: return "path queue full";
    case ErrorCode::PathSequence: return "path segment out of sequence";
    case ErrorCode::PathGeometry: return "bad path segment";
    case ErrorCode::PathState: return "no path to add to";
    }
    return "unknown error";
}

const char* errorCodeTerm(ErrorCode c)
{
    switch (static_cast<int>(c)) {
    case 1: return "device.error.unknown_command";
    case 2: return "device.error.bad_payload";
    case 3: return "device.error.bad_axis";
    case 4: return "device.error.not_homed";
    case 5: return "device.error.soft_limit";
    case 6: return "device.error.busy";
    case 7: return "device.error.estop_active";
    case 8: return "device.error.over_capacity";
    case 9: return "device.error.out_of_range";
    case 10: return "device.error.fault";
    case 11: return "device.error.bad_gains";
    case 12: return "device.error.test_active";
    case 13: return "device.error.not_closed_loop";
    case 14: return "device.error.no_capture";
    case 15: return "device.error.path_queue_full";
    case 16: return "device.error.path_sequence";
    case 17: return "device.error.path_geometry";
    case 18: return "device.error.path_state";
    case 23: return "device.error.comp_invalid";
    case 24: return "device.error.comp_sequence";
    case 25: return "device.error.comp_missing";
    }
    return "device.error.unknown";
}

const char* eventKindTerm(EventKind k)
{
    switch (static_cast<int>(k)) {
    case 1: return "device.event.motion_done";
    case 2: return "device.event.home_done";
    case 3: return "device.event.limit_hit";
    case 4: return "device.event.fault";
    case 5: return "device.event.estop";
    case 6: return "device.event.jog_expired";
    case 7: return "device.event.stopped";
    case 8: return "device.event.lost_steps";
    case 9: return "device.event.reset";
    case 10: return "device.event.test_ended";
    case 11: return "device.event.test_tripped";
    case 12: return "device.event.test_aborted";
    case 13: return "device.event.gains_changed";
    case 20: return "device.event.path_started";
    case 21: return "device.event.path_segment_done";
    case 22: return "device.event.path_underrun";
    case 23: return "device.event.path_done";
    case 24: return "device.event.path_held";
    case 25: return "device.event.path_aborted";
    case 40: return "device.event.comp_changed";
    }
    return "device.event.unknown";
}

const char* eventKindName(EventKind k)
{
    // Kinds defined beside their features (messages_tuning.h, messages_compensation.h) by number.
    switch (static_cast<int>(k)) {
    case 10: return "test ended";
    case 11: return "test tripped";
    case 12: return "test aborted";
    case 13: return "gains changed";
    case 40: return "compensation changed";
    default: break;
    }
    switch (k) {
    case EventKind::MotionDone: return "motion done";
    case EventKind::HomeDone: return "home done";
    case EventKind::LimitHit: return "limit hit";
    case EventKind::Fault: return "fault";
    case EventKind::EStop: return "E-stop";
    case EventKind::JogExpired: return "jog expired";
    case EventKind::Stopped: return "stopped";
    case EventKind::LostSteps: return "lost steps";
    case EventKind::Reset: return "reset";
    case EventKind::PathStarted: return "path started";
    case EventKind::PathSegmentDone: return "path segment done";
    case EventKind::PathUnderrun: return "path underrun";
    case EventKind::PathDone: return "path done";
    case EventKind::PathHeld: return "path held";
    case EventKind::PathAborted: return "path aborted";
    }
    return "unknown event";
}

std::size_t telemetryHeaderBytes(std::size_t channelCount) { return 4 + 8 + 4 + 1 + 2 * channelCount + 2; }

// ---- encoders ---------------------------------------------------------------

Bytes encode(const HelloReply& m)
{
    Bytes b;
    ByteWriter w(b);
    w.u8(m.protocolVersion);
    w.u8(static_cast<std::uint8_t>(m.kind));
    w.u32(m.capabilities);
    w.u32(m.controlPeriodUs);
    w.u32(m.maxTelemetryRateHz);
    w.u16(m.jogWatchdogMs);
    w.u32(m.linkBaud);
    w.str(m.model);
    w.str(m.firmware);
    w.u8(static_cast<std::uint8_t>(m.axes.size()));
    for (const auto& a : m.axes) {
        w.u8(static_cast<std::uint8_t>(a.letter));
        w.u8(static_cast<std::uint8_t>(a.unit));
        w.i32(a.travelMin);
        w.i32(a.travelMax);
        w.u32(a.maxSpeed);
        w.u32(a.resolution);
    }
    if (!m.motionLimits && m.otherBlocks.empty())
        return b;
    // Extension blocks: a count, then (id, length, body) each in increasing id order, so
    // a host skips the ones it does not know. The limits block has one entry per axis.
    w.u8(static_cast<std::uint8_t>((m.motionLimits ? 1 : 0) + m.otherBlocks.size()));
    if (m.motionLimits) {
        w.u8(kHelloBlockMotionLimits);
        w.u16(static_cast<std::uint16_t>(1 + 16 * m.motionLimits->axes.size()));
        w.u8(static_cast<std::uint8_t>(m.motionLimits->profile));
        for (const auto& l : m.motionLimits->axes) {
            w.u32(l.maxAccel);
            w.u32(l.maxJerk);
            w.u32(l.defaultSpeed);
            w.u32(l.minAccelTimeUs);
        }
    }
    for (const auto& o : m.otherBlocks) {
        w.u8(o.id);
        w.u16(static_cast<std::uint16_t>(o.body.size()));
        for (auto byte : o.body)
            w.u8(byte);
    }
    return b;
}

Bytes encode(const HelloRequest& m) { return Bytes{m.flags}; }

Bytes encode(const StatusReply& m)
{
    Bytes b;
    ByteWriter w(b);
    w.u8(m.deviceFlags);
    w.u64(m.deviceTimeUs);
    w.u8(static_cast<std::uint8_t>(m.axes.size()));
    for (const auto& a : m.axes) {
        w.i32(a.commanded);
        w.i32(a.measured);
        w.u16(a.flags);
    }
    return b;
}

Bytes encode(const HomeRequest& m) { return Bytes{m.axisMask}; }
Bytes encode(const AxisMaskRequest& m) { return Bytes{m.axisMask}; }

Bytes encode(const MoveRequest& m)
{
    Bytes b;
    ByteWriter w(b);
    w.u8(m.relative ? 1 : 0);
    w.u32(m.speed);
    w.u8(m.axisMask);
    for (auto t : m.targets)
        w.i32(t);
    return b;
}

Bytes encode(const JogStepRequest& m)
{
    Bytes b;
    ByteWriter w(b);
    w.u8(m.axis);
    w.i32(m.delta);
    w.u32(m.speed);
    return b;
}

Bytes encode(const LimitsReply& m)
{
    Bytes b;
    ByteWriter w(b);
    w.u8(static_cast<std::uint8_t>(m.axes.size()));
    for (const auto& l : m.axes) {
        w.i32(l.min);
        w.i32(l.max);
    }
    return b;
}

Bytes encode(const SetLimitsRequest& m)
{
    Bytes b;
    ByteWriter w(b);
    w.u8(m.axis);
    w.i32(m.limits.min);
    w.i32(m.limits.max);
    return b;
}

Bytes encode(const JogVelocityRequest& m)
{
    Bytes b;
    ByteWriter w(b);
    w.u8(m.axisMask);
    for (auto v : m.velocities)
        w.i32(v);
    return b;
}

Bytes encode(const SubscribeRequest& m)
{
    Bytes b;
    ByteWriter w(b);
    w.u32(m.rateHz);
    w.u8(static_cast<std::uint8_t>(m.channels.size()));
    for (const auto& c : m.channels) {
        w.u8(c.axis);
        w.u8(static_cast<std::uint8_t>(c.kind));
    }
    return b;
}

Bytes encode(const SubscribeReply& m)
{
    Bytes b;
    ByteWriter w(b);
    w.u32(m.rateHz);
    w.u16(m.samplesPerBatch);
    return b;
}

Bytes encode(const TelemetryBatch& m)
{
    Bytes b;
    b.reserve(telemetryHeaderBytes(m.channels.size()) + 4 * m.values.size());
    ByteWriter w(b);
    w.u32(m.firstSampleIndex);
    w.u64(m.firstSampleTimeUs);
    w.u32(m.periodUs);
    w.u8(static_cast<std::uint8_t>(m.channels.size()));
    for (const auto& c : m.channels) {
        w.u8(c.axis);
        w.u8(static_cast<std::uint8_t>(c.kind));
    }
    w.u16(m.sampleCount);
    for (auto v : m.values)
        w.i32(v);
    return b;
}

Bytes encode(const EventMsg& m)
{
    Bytes b;
    ByteWriter w(b);
    w.u8(static_cast<std::uint8_t>(m.kind));
    w.u8(m.axis);
    w.u64(m.deviceTimeUs);
    w.i32(m.position);
    w.str(m.text);
    if (m.reason) {
        w.u8(m.reason->code);
        w.u8(static_cast<std::uint8_t>(m.reason->values.size()));
        for (double v : m.reason->values)
            w.f64(v);
    }
    return b;
}

Bytes encode(const ErrorReply& m)
{
    Bytes b;
    ByteWriter w(b);
    w.u8(static_cast<std::uint8_t>(m.code));
    w.u8(m.axis);
    w.i32(m.value);
    w.str(m.message);
    return b;
}

// ---- decoders ---------------------------------------------------------------

namespace {
/// The extension blocks after HELLO's axes (docs/protocol.md, "HELLO"). A device that
/// sends them sends at least one; a block of an id this host does not know is skipped.
bool readHelloBlocks(ByteReader& r, HelloReply& m)
{
    const int blocks = r.u8();
    if (blocks == 0)
        return false;
    int lastId = 0;
    for (int b = 0; b < blocks && r.ok(); ++b) {
        const std::uint8_t id = r.u8();
        const std::size_t length = r.u16();
        if (!r.ok() || length > r.remaining() || id <= lastId)
            return false;  // short, or ids not strictly increasing
        lastId = id;
        if (id != kHelloBlockMotionLimits) {
            HelloBlock other{id, {}};
            for (std::size_t k = 0; k < length; ++k)
                other.body.push_back(r.u8());
            m.otherBlocks.push_back(std::move(other));
            continue;
        }
        if (length != 1 + 16 * m.axes.size())
            return false;  // not one entry per axis
        MotionLimits l;
        const std::uint8_t profile = r.u8();
        if (profile > static_cast<std::uint8_t>(MotionProfile::SeedSCurve))
            return false;
        l.profile = static_cast<MotionProfile>(profile);
        for (std::size_t i = 0; i < m.axes.size(); ++i) {
            AxisMotionLimits a;
            a.maxAccel = r.u32();
            a.maxJerk = r.u32();
            a.defaultSpeed = r.u32();
            a.minAccelTimeUs = r.u32();
            l.axes.push_back(a);
        }
        m.motionLimits = std::move(l);
    }
    return r.ok();
}

bool knownChannel(std::uint8_t k) { return k <= static_cast<std::uint8_t>(ChannelKind::ControllerU); }
} // namespace

std::optional<HelloReply> decodeHelloReply(const Bytes& p)
{
    ByteReader r(p);
    HelloReply m;
    m.protocolVersion = r.u8();
    const std::uint8_t kind = r.u8();
    if (kind != 1 && kind != 2)
        return std::nullopt;
    m.kind = static_cast<DeviceKind>(kind);
    m.capabilities = r.u32();
    m.controlPeriodUs = r.u32();
    m.maxTelemetryRateHz = r.u32();
    m.jogWatchdogMs = r.u16();
    m.linkBaud = r.u32();
    m.model = r.str();
    m.firmware = r.str();
    const int n = r.u8();
    if (n > kMaxAxes)
        return std::nullopt;
    for (int i = 0; i < n && r.ok(); ++i) {
        AxisInfo a;
        a.letter = static_cast<char>(r.u8());
        const std::uint8_t unit = r.u8();
        if (unit > 1)
            return std::nullopt;
        a.unit = static_cast<AxisUnit>(unit);
        a.travelMin = r.i32();
        a.travelMax = r.i32();
        a.maxSpeed = r.u32();
        a.resolution = r.u32();
        m.axes.push_back(a);
    }
    if (r.ok() && r.remaining() > 0 && !readHelloBlocks(r, m))
        return std::nullopt;
    return finish(r, std::move(m));
}

std::optional<HelloRequest> decodeHelloRequest(const Bytes& p)
{
    if (p.empty())
        return HelloRequest{};
    if (p.size() != 1)
        return std::nullopt;
    return HelloRequest{p[0]};
}

std::optional<StatusReply> decodeStatusReply(const Bytes& p)
{
    ByteReader r(p);
    StatusReply m;
    m.deviceFlags = r.u8();
    m.deviceTimeUs = r.u64();
    const int n = r.u8();
    if (n > kMaxAxes)
        return std::nullopt;
    for (int i = 0; i < n && r.ok(); ++i) {
        AxisStatus a;
        a.commanded = r.i32();
        a.measured = r.i32();
        a.flags = r.u16();
        m.axes.push_back(a);
    }
    return finish(r, std::move(m));
}

std::optional<HomeRequest> decodeHomeRequest(const Bytes& p)
{
    if (p.size() != 1)
        return std::nullopt;
    return HomeRequest{p[0]};
}

std::optional<AxisMaskRequest> decodeAxisMaskRequest(const Bytes& p)
{
    if (p.size() != 1)
        return std::nullopt;
    return AxisMaskRequest{p[0]};
}

std::optional<MoveRequest> decodeMoveRequest(const Bytes& p)
{
    ByteReader r(p);
    MoveRequest m;
    const std::uint8_t flags = r.u8();
    if (flags > 1)
        return std::nullopt;
    m.relative = flags & 1;
    m.speed = r.u32();
    m.axisMask = r.u8();
    const int n = popcount8(m.axisMask);
    for (int i = 0; i < n; ++i)
        m.targets.push_back(r.i32());
    if (n == 0)
        return std::nullopt;
    return finish(r, std::move(m));
}

std::optional<JogStepRequest> decodeJogStepRequest(const Bytes& p)
{
    ByteReader r(p);
    JogStepRequest m;
    m.axis = r.u8();
    m.delta = r.i32();
    m.speed = r.u32();
    return finish(r, std::move(m));
}

std::optional<LimitsReply> decodeLimitsReply(const Bytes& p)
{
    ByteReader r(p);
    LimitsReply m;
    const int n = r.u8();
    if (n > kMaxAxes)
        return std::nullopt;
    for (int i = 0; i < n && r.ok(); ++i) {
        AxisLimits l;
        l.min = r.i32();
        l.max = r.i32();
        m.axes.push_back(l);
    }
    return finish(r, std::move(m));
}

std::optional<SetLimitsRequest> decodeSetLimitsRequest(const Bytes& p)
{
    ByteReader r(p);
    SetLimitsRequest m;
    m.axis = r.u8();
    m.limits.min = r.i32();
    m.limits.max = r.i32();
    return finish(r, std::move(m));
}

std::optional<JogVelocityRequest> decodeJogVelocityRequest(const Bytes& p)
{
    ByteReader r(p);
    JogVelocityRequest m;
    m.axisMask = r.u8();
    const int n = popcount8(m.axisMask);
    if (n == 0)
        return std::nullopt;
    for (int i = 0; i < n; ++i)
        m.velocities.push_back(r.i32());
    return finish(r, std::move(m));
}

std::optional<SubscribeRequest> decodeSubscribeRequest(const Bytes& p)
{
    ByteReader r(p);
    SubscribeRequest m;
    m.rateHz = r.u32();
    const int n = r.u8();
    for (int i = 0; i < n && r.ok(); ++i) {
        ChannelRef c;
        c.axis = r.u8();
        const std::uint8_t k = r.u8();
        if (!knownChannel(k))
            return std::nullopt;
        c.kind = static_cast<ChannelKind>(k);
        m.channels.push_back(c);
    }
    return finish(r, std::move(m));
}

std::optional<SubscribeReply> decodeSubscribeReply(const Bytes& p)
{
    ByteReader r(p);
    SubscribeReply m;
    m.rateHz = r.u32();
    m.samplesPerBatch = r.u16();
    return finish(r, std::move(m));
}

std::optional<TelemetryBatch> decodeTelemetryBatch(const Bytes& p)
{
    ByteReader r(p);
    TelemetryBatch m;
    m.firstSampleIndex = r.u32();
    m.firstSampleTimeUs = r.u64();
    m.periodUs = r.u32();
    const int n = r.u8();
    for (int i = 0; i < n && r.ok(); ++i) {
        ChannelRef c;
        c.axis = r.u8();
        const std::uint8_t k = r.u8();
        if (!knownChannel(k))
            return std::nullopt;
        c.kind = static_cast<ChannelKind>(k);
        m.channels.push_back(c);
    }
    m.sampleCount = r.u16();
    const std::size_t count = static_cast<std::size_t>(m.sampleCount) * m.channels.size();
    if (!r.ok() || r.remaining() != 4 * count)
        return std::nullopt;
    m.values.resize(count);
    for (std::size_t i = 0; i < count; ++i)
        m.values[i] = r.i32();
    return finish(r, std::move(m));
}

std::optional<EventMsg> decodeEvent(const Bytes& p)
{
    ByteReader r(p);
    EventMsg m;
    const std::uint8_t k = r.u8();
    if (k < 1 || k > kMaxEventKind)
        return std::nullopt;
    m.kind = static_cast<EventKind>(k);
    m.axis = r.u8();
    m.deviceTimeUs = r.u64();
    m.position = r.i32();
    m.text = r.str();
    if (r.ok() && r.remaining() > 0) {
        EventReason why;
        why.code = r.u8();
        const std::size_t n = r.u8();
        if (why.code == 0 || n > kMaxEventReasonValues)
            return std::nullopt;
        for (std::size_t i = 0; i < n; ++i) {
            why.values.push_back(r.f64());
            if (!std::isfinite(why.values.back()))
                return std::nullopt;
        }
        m.reason = std::move(why);
    }
    return finish(r, std::move(m));
}

std::optional<ErrorReply> decodeErrorReply(const Bytes& p)
{
    ByteReader r(p);
    ErrorReply m;
    const std::uint8_t c = r.u8();
    if (c < 1 || c > kMaxErrorCode)
        return std::nullopt;
    m.code = static_cast<ErrorCode>(c);
    m.axis = r.u8();
    m.value = r.i32();
    m.message = r.str();
    return finish(r, std::move(m));
}

} // namespace dev::proto
