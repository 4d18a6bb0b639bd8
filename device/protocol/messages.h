#pragma once
// Protocol v1 message types and payloads. Plain C++: shared by the host clients,
// the simulator firmware and the fuzzer. docs/protocol.md is the byte-level spec.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace dev::proto {

constexpr std::uint8_t kProtocolVersion = 1;
constexpr std::uint8_t kNoAxis = 0xFF;
constexpr int kMaxAxes = 8;
/// A velocity move not refreshed is at rest this long after its last refresh
/// (the device trips at 200 ms and brakes hard; see docs/protocol.md).
constexpr std::uint32_t kJogWatchdogMs = 250;

/// Types 0x01–0x1F are queued requests, 0x20–0x3F realtime requests (acted on
/// the moment they are decoded, ahead of anything queued), 0x80|type their
/// replies, 0xE0–0xEF device-initiated messages, 0xFF the error reply. A device
/// answers every type below 0x80, undefined ones with ERROR UnknownCommand;
/// 0x40–0x7F stay undefined because their reply types would collide with
/// 0xC0–0xFF. See docs/protocol.md.
enum class MsgType : std::uint8_t {
    Hello = 0x01,
    Status = 0x02,
    Home = 0x03,
    Move = 0x04,
    JogStep = 0x05,
    SetZero = 0x06,
    GetLimits = 0x07,
    SetLimits = 0x08,
    Subscribe = 0x09,
    Reset = 0x0A,
    // 0x0B–0x0F: PID gains and step tests (tuning); 0x10–0x14: queued LINE/ARC
    // paths; 0x15–0x17: plates and recipes; 0x18–0x1A: stitching scans;
    // 0x1B–0x1D: axis error compensation (messages_compensation.h).
    PathBegin = 0x10,   ///< messages_path.h
    PathAppend = 0x11,
    PathStatus = 0x12,
    ArchMove = 0x13,    ///< messages_arch.h: Z up, XY across, Z down, blended
    JogVelocity = 0x20,
    Stop = 0x21,
    EStop = 0x22,
    // 0x23: tuning; 0x24–0x26: paths (feed hold, resume, …).
    PathHold = 0x24,
    PathResume = 0x25,
    PathClear = 0x26,
    Event = 0xE0,
    TelemetryBatch = 0xE1,
    Error = 0xFF,
};
constexpr std::uint8_t kReplyFlag = 0x80;
constexpr std::uint8_t replyTypeOf(MsgType t) { return static_cast<std::uint8_t>(static_cast<std::uint8_t>(t) | kReplyFlag); }
constexpr bool isRequestType(std::uint8_t t) { return t >= 0x01 && t <= 0x3F; }
constexpr bool isRealtimeType(std::uint8_t t) { return t >= 0x20 && t <= 0x3F; }
constexpr bool isReplyType(std::uint8_t t) { return t >= 0x81 && t <= 0xBF; }

enum class DeviceKind : std::uint8_t { Analyzer = 1, Stage = 2 };
enum class AxisUnit : std::uint8_t { Millimetre = 0, Microlitre = 1 };

/// Capability bits in HELLO.
enum Capability : std::uint32_t {
    CapHoming = 1u << 0,
    CapEncoder = 1u << 1,      ///< incremental encoder per axis (measured position)
    CapGrating = 1u << 2,      ///< linear grating scale per axis (measured position)
    CapClosedLoopPid = 1u << 3,
    CapPump = 1u << 4,         ///< plunger pump axis in µL
    CapTelemetry = 1u << 5,
    CapJogVelocity = 1u << 6,
    CapCoupledXyThenZ = 1u << 7,
    // Bits 8–9: tuning (gains, step test); 10–11: path queue; 12: plates; 13: scans;
    // 14: compensation.
    CapPathQueue = 1u << 10,   ///< PATH_BEGIN/APPEND/STATUS, feed hold/resume/clear (messages_path.h)
    CapPathZFollow = 1u << 11, ///< path segments may carry a Z target, run after their XY part (seed 000)
};

enum class ErrorCode : std::uint8_t {
    UnknownCommand = 1,
    BadPayload = 2,
    BadAxis = 3,
    NotHomed = 4,
    SoftLimit = 5,
    Busy = 6,
    EStopActive = 7,
    OverCapacity = 8,
    OutOfRange = 9,
    Fault = 10,
    // 11–14: tuning; 15–18: path queue; 19–20: plates; 21–22: scans; 23–25: compensation.
    PathQueueFull = 15,  ///< value = free slots
    PathSequence = 16,   ///< value = the segment index the device expects next
    PathGeometry = 17,   ///< value = the index of the segment at fault
    PathState = 18,      ///< no path begun, or the path already ended / was aborted
};
/// Codes up to this decode, so an older host still shows a newer device's refusal.
constexpr std::uint8_t kMaxErrorCode = 0x7F;
const char* errorCodeName(ErrorCode c);  ///< for logs and tests: "soft limit"
/// The term a person reads for a code ("device.error.soft_limit"; tuning codes
/// included), worded by ui::words::term; "device.error.unknown" for a code this host
/// does not know.
const char* errorCodeTerm(ErrorCode c);

enum class EventKind : std::uint8_t {
    MotionDone = 1,  ///< a move, jog step or homing finished on this axis
    HomeDone = 2,
    LimitHit = 3,    ///< a switch stopped the axis
    Fault = 4,
    EStop = 5,
    JogExpired = 6,  ///< velocity move not refreshed in time: stopped by the watchdog
    Stopped = 7,     ///< a stop request brought the axis to rest
    LostSteps = 8,   ///< measured position left the commanded one by more than the tolerance
    Reset = 9,       ///< E-stop/fault latch cleared
    // 10–19: tuning; 20–29: path queue; 30–34: plates; 35–39: scans; 40–44: compensation.
    // Path events: axis 0xFF, position = the segment index they are about.
    PathStarted = 20,     ///< execution began at this segment
    PathSegmentDone = 21, ///< this segment was completed
    PathUnderrun = 22,    ///< the queue ran dry before the path's last segment: at rest after this one
    PathDone = 23,        ///< the path's last segment was completed, at rest
    PathHeld = 24,        ///< feed hold reached rest on this segment (text says who held it)
    PathAborted = 25,     ///< the path ended early; this segment was not completed (text says why)
};
/// Kinds up to this decode, so an older host still logs a newer device's events.
constexpr std::uint8_t kMaxEventKind = 0x7F;
const char* eventKindName(EventKind k);  ///< for logs and tests: "limit hit"
/// "device.event.limit_hit", …; "device.event.unknown" for a newer kind.
const char* eventKindTerm(EventKind k);

/// Position units on the wire: nanometres for linear axes, nanolitres for the pump;
/// speeds in the same unit per second. int32 covers ±2.1 m / ±2.1 L.
using WireUnits = std::int32_t;

struct AxisInfo {
    char letter = 'X';
    AxisUnit unit = AxisUnit::Millimetre;
    WireUnits travelMin = 0;           ///< hard travel, switches at both ends
    WireUnits travelMax = 0;
    std::uint32_t maxSpeed = 0;        ///< per second
    std::uint32_t resolution = 0;      ///< one count of the measuring system
};

/// HELLO's request payload: empty from a host of protocol 1.0, one flags byte from a
/// host that reads the reply's extension blocks (docs/protocol.md, "HELLO").
enum HelloFlag : std::uint8_t {
    HelloReadsExtensions = 1u << 0,  ///< append the extension blocks to the reply
    HelloReadsEventReasons = 1u << 1,  ///< append each EVENT's reason (event_reasons.h) this session
};
struct HelloRequest { std::uint8_t flags = 0; };

/// How the device's planner shapes a rest-to-rest move, so a host can time one the way
/// the device will run it.
enum class MotionProfile : std::uint8_t {
    Unstated = 0,
    Trapezoid = 1,    ///< acceleration-limited, jerk not limited (GRBL's planner)
    JerkLimited = 2,  ///< time-optimal 7-segment (motion/jerk_limited.h)
    SeedSCurve = 3,   ///< seed 000's S-curve, its acceleration phase stretched until 1.5·v/t2 ≤ the acceleration limit
};
/// One axis' planner limits. Rates of change in thousandths of the axis unit (µm or nL)
/// per s² and per s³: nanometres would overflow a u32 at 4.3 m/s² and 4.3 m/s³.
struct AxisMotionLimits {
    std::uint32_t maxAccel = 0;        ///< µm/s² (nL/s² on the pump)
    std::uint32_t maxJerk = 0;         ///< µm/s³ (nL/s³); 0: the planner does not limit jerk
    std::uint32_t defaultSpeed = 0;    ///< wire units per second: what a MOVE with speed 0 runs at
    std::uint32_t minAccelTimeUs = 0;  ///< SeedSCurve: the shortest acceleration phase t2; 0 for the other profiles
};
/// Extension block 1 of the HELLO reply: the planner's limits, one entry per axis.
struct MotionLimits {
    MotionProfile profile = MotionProfile::Unstated;
    std::vector<AxisMotionLimits> axes;
};
constexpr std::uint8_t kHelloBlockMotionLimits = 1;
/// An extension block this host does not read, kept as it came.
struct HelloBlock {
    std::uint8_t id = 0;
    std::vector<std::uint8_t> body;
    bool operator==(const HelloBlock& o) const { return id == o.id && body == o.body; }
};

struct HelloReply {
    std::uint8_t protocolVersion = kProtocolVersion;
    DeviceKind kind = DeviceKind::Analyzer;
    std::uint32_t capabilities = 0;
    std::uint32_t controlPeriodUs = 0;
    std::uint32_t maxTelemetryRateHz = 0;
    std::uint16_t jogWatchdogMs = kJogWatchdogMs;
    std::uint32_t linkBaud = 0;        ///< the device's idea of its link speed; telemetry capacity follows it
    std::string model;
    std::string firmware;
    std::vector<AxisInfo> axes;
    /// Sent only to a host whose HELLO asked for extension blocks: the reply to an empty
    /// HELLO is byte for byte what protocol 1.0 defined, so an older host reads it.
    std::optional<MotionLimits> motionLimits;
    std::vector<HelloBlock> otherBlocks;  ///< blocks of ids above 1, in increasing id order
};

enum AxisFlag : std::uint16_t {
    AxisHomed = 1u << 0,
    AxisMoving = 1u << 1,
    AxisHoming = 1u << 2,
    AxisHomeSwitch = 1u << 3,
    AxisLimitSwitch = 1u << 4,
    AxisFault = 1u << 5,
    AxisJogging = 1u << 6,
};
enum DeviceFlag : std::uint8_t { DeviceEStop = 1u << 0, DeviceFault = 1u << 1 };

struct AxisStatus {
    WireUnits commanded = 0;
    WireUnits measured = 0;
    std::uint16_t flags = 0;
};
struct StatusReply {
    std::uint8_t deviceFlags = 0;
    std::uint64_t deviceTimeUs = 0;
    std::vector<AxisStatus> axes;
};

struct HomeRequest { std::uint8_t axisMask = 0; };          ///< 0 = all axes in the device's order
struct MoveRequest {
    bool relative = false;
    std::uint32_t speed = 0;                               ///< in the lowest axis' unit per second; 0 = the axes' default speed
    std::uint8_t axisMask = 0;
    std::vector<WireUnits> targets;                        ///< one per set bit, lowest bit first
};
struct JogStepRequest { std::uint8_t axis = 0; WireUnits delta = 0; std::uint32_t speed = 0; };
struct AxisMaskRequest { std::uint8_t axisMask = 0; };      ///< SetZero, Stop (0 = all)
struct AxisLimits { WireUnits min = 0; WireUnits max = 0; };
struct LimitsReply { std::vector<AxisLimits> axes; };
struct SetLimitsRequest { std::uint8_t axis = 0; AxisLimits limits; };
struct JogVelocityRequest { std::uint8_t axisMask = 0; std::vector<std::int32_t> velocities; };  ///< per second; 0 stops that axis

enum class ChannelKind : std::uint8_t {
    Commanded = 0,
    Measured = 1,
    Velocity = 2,         ///< measured, per second
    FollowingError = 3,   ///< measured − commanded
    ControllerOutput = 4, ///< stage PID output, step rate in steps/s
    Switches = 5,         ///< bit0 home, bit1 limit
    ContourError = 6,     ///< instrument-wide (axis kNoAxis): XY distance from the commanded path, nm
    ControllerU = 7,      ///< tuning: the loop's controller output u (eq. 2's running sum), nm of motor correction
    // 8–9: tuning; 10–12: path queue; 13: plates; 14: scans.
};
struct ChannelRef {
    std::uint8_t axis = 0;
    ChannelKind kind = ChannelKind::Commanded;
    bool operator==(const ChannelRef& o) const { return axis == o.axis && kind == o.kind; }
};
struct SubscribeRequest { std::uint32_t rateHz = 0; std::vector<ChannelRef> channels; };  ///< rate 0 = off
struct SubscribeReply { std::uint32_t rateHz = 0; std::uint16_t samplesPerBatch = 0; };

struct TelemetryBatch {
    std::uint32_t firstSampleIndex = 0;   ///< counts every sample since subscribe: a gap is a loss
    std::uint64_t firstSampleTimeUs = 0;  ///< device clock
    std::uint32_t periodUs = 0;
    std::vector<ChannelRef> channels;
    std::uint16_t sampleCount = 0;
    std::vector<std::int32_t> values;     ///< sampleCount × channels.size(), sample-major
};
/// Bytes of a batch payload that are not sample values.
std::size_t telemetryHeaderBytes(std::size_t channelCount);

/// Why an event was raised, as numbers a host words in its operator's language
/// (docs/protocol.md, "Event reasons"). A device appends it only for a host whose
/// HELLO set HelloReadsEventReasons; any other host reads the text alone.
struct EventReason {
    std::uint8_t code = 0;        ///< per event kind (event_reasons.h), 1–255
    std::vector<double> values;   ///< finite, at most kMaxEventReasonValues; units fixed by kind and code
    bool operator==(const EventReason& o) const { return code == o.code && values == o.values; }
};
constexpr std::size_t kMaxEventReasonValues = 8;

struct EventMsg {
    EventKind kind = EventKind::MotionDone;
    std::uint8_t axis = kNoAxis;
    std::uint64_t deviceTimeUs = 0;
    WireUnits position = 0;
    std::string text;                    ///< for people, in the device's language; may be empty
    std::optional<EventReason> reason;
};

struct ErrorReply {
    ErrorCode code = ErrorCode::BadPayload;
    std::uint8_t axis = kNoAxis;
    std::int32_t value = 0;               ///< the limit, capacity or value at fault
    std::string message;
};

using Bytes = std::vector<std::uint8_t>;

Bytes encode(const HelloRequest&);
Bytes encode(const HelloReply&);
Bytes encode(const StatusReply&);
Bytes encode(const HomeRequest&);
Bytes encode(const MoveRequest&);
Bytes encode(const JogStepRequest&);
Bytes encode(const AxisMaskRequest&);
Bytes encode(const LimitsReply&);
Bytes encode(const SetLimitsRequest&);
Bytes encode(const JogVelocityRequest&);
Bytes encode(const SubscribeRequest&);
Bytes encode(const SubscribeReply&);
Bytes encode(const TelemetryBatch&);
Bytes encode(const EventMsg&);
Bytes encode(const ErrorReply&);

/// Decoders return nullopt unless the payload is exactly one well-formed message.
/// An empty payload (a 1.0 host) decodes as flags 0.
std::optional<HelloRequest> decodeHelloRequest(const Bytes&);
/// Reads the reply with or without extension blocks (ids strictly increasing); blocks of
/// an id it does not know land in otherBlocks.
std::optional<HelloReply> decodeHelloReply(const Bytes&);
std::optional<StatusReply> decodeStatusReply(const Bytes&);
std::optional<HomeRequest> decodeHomeRequest(const Bytes&);
std::optional<MoveRequest> decodeMoveRequest(const Bytes&);
std::optional<JogStepRequest> decodeJogStepRequest(const Bytes&);
std::optional<AxisMaskRequest> decodeAxisMaskRequest(const Bytes&);
std::optional<LimitsReply> decodeLimitsReply(const Bytes&);
std::optional<SetLimitsRequest> decodeSetLimitsRequest(const Bytes&);
std::optional<JogVelocityRequest> decodeJogVelocityRequest(const Bytes&);
std::optional<SubscribeRequest> decodeSubscribeRequest(const Bytes&);
std::optional<SubscribeReply> decodeSubscribeReply(const Bytes&);
std::optional<TelemetryBatch> decodeTelemetryBatch(const Bytes&);
std::optional<EventMsg> decodeEvent(const Bytes&);
std::optional<ErrorReply> decodeErrorReply(const Bytes&);

int popcount8(std::uint8_t mask);

} // namespace dev::proto
