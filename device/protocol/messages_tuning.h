#pragma once
// Protocol v1 messages of PID tuning: gains, step and relay tests,
// the device's capture of a test, and the realtime abort. Plain C++, like
// messages.h; docs/protocol.md ("Tuning") is the byte-level spec.
//
// Gains travel as IEEE-754 float32 (little-endian) in the discrete form the
// device runs (seed 002 eq. 2, per control period): a float carries NaN and
// infinities, so the device itself sees and refuses them, with a reason.
#include "device/protocol/messages.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace dev::proto {

// Message types (queued 0x0B–0x0F, realtime 0x23), capability bits 8–9, error
// codes 11–14, event kinds 10–13 and telemetry channel kind 7, as allocated in messages.h.
constexpr MsgType kGetGains = static_cast<MsgType>(0x0B);
constexpr MsgType kSetGains = static_cast<MsgType>(0x0C);
constexpr MsgType kStepTest = static_cast<MsgType>(0x0D);
constexpr MsgType kRelayTest = static_cast<MsgType>(0x0E);
constexpr MsgType kGetCapture = static_cast<MsgType>(0x0F);
constexpr MsgType kTestAbort = static_cast<MsgType>(0x23);

constexpr std::uint32_t CapGains = 1u << 8;        ///< GET_GAINS / SET_GAINS on closed-loop axes
constexpr std::uint32_t CapExperiments = 1u << 9;  ///< STEP_TEST, RELAY_TEST, GET_CAPTURE, TEST_ABORT

constexpr ErrorCode kErrBadGains = static_cast<ErrorCode>(11);      ///< value: index of the first bad gain (0 kp, 1 ki, 2 kd)
constexpr ErrorCode kErrTestActive = static_cast<ErrorCode>(12);    ///< a test runs on the axis
constexpr ErrorCode kErrNotClosedLoop = static_cast<ErrorCode>(13); ///< the axis has no PID to tune
constexpr ErrorCode kErrNoCapture = static_cast<ErrorCode>(14);     ///< nothing captured there; value: samples captured

constexpr EventKind kEvTestEnded = static_cast<EventKind>(10);    ///< settled or completed
constexpr EventKind kEvTestTripped = static_cast<EventKind>(11);  ///< the abort envelope stopped it; text: which limit, by how much
constexpr EventKind kEvTestAborted = static_cast<EventKind>(12);  ///< STOP, TEST_ABORT, E-stop, host silence, a switch or fault
constexpr EventKind kEvGainsChanged = static_cast<EventKind>(13); ///< SET_GAINS took effect; text: the new set

// Telemetry: ChannelKind::ControllerU (7) in messages.h, the loop's controller output u.

/// Float32 gains in eq. 2's discrete form.
struct WireGains {
    float kp = 0, ki = 0, kd = 0;
    bool operator==(const WireGains& o) const;  ///< bitwise, so NaN payloads round-trip in tests
};

struct AxisRequest { std::uint8_t axis = 0; };  ///< GET_GAINS

struct GainsReply {
    std::uint8_t axis = 0;
    std::uint32_t controlPeriodUs = 0;
    WireGains gains;            ///< the operator's set: in force except while a test runs with trial gains
    WireGains saved;            ///< what the device starts with after power-up
    std::uint8_t flags = 0;     ///< bit 0: a test runs on the axis
    WireGains limits;           ///< the largest gains the device accepts
};
constexpr std::uint8_t kGainsTestRunning = 1;

struct SetGainsRequest {
    std::uint8_t axis = 0;
    std::uint8_t flags = 0;     ///< bit 0: also keep as the power-up set
    WireGains gains;
};
constexpr std::uint8_t kSetGainsSave = 1;

/// The abort envelope on the wire.
struct WireEnvelope {
    std::uint32_t maxExcursion = 0;       ///< nm, |measured − start|
    std::uint32_t maxFollowingError = 0;  ///< nm, |setpoint − measured|
    std::uint32_t maxDurationMs = 0;
};

struct StepTestRequest {
    std::uint8_t axis = 0;
    std::int32_t step = 0;            ///< nm, signed, not 0
    std::uint32_t settleBand = 0;     ///< nm; 0: never ends on settling
    std::uint16_t settleHoldMs = 0;
    std::uint32_t runMs = 0;          ///< 0: until settled
    WireEnvelope envelope;
    std::optional<WireGains> trialGains;  ///< used for this test only, then the operator's set is back
};

struct RelayTestRequest {
    std::uint8_t axis = 0;
    std::uint32_t amplitude = 0;      ///< nm of controller output, d
    std::uint32_t hysteresis = 0;     ///< nm, ε
    std::uint32_t forcedPeriodUs = 0; ///< 0: self-oscillating relay
    std::uint16_t cycles = 0;
    WireEnvelope envelope;
};

struct CaptureRequest {
    std::uint8_t axis = 0;
    std::uint32_t first = 0;          ///< sample index
    std::uint16_t maxCount = 0;
};

struct CaptureSample {
    std::int32_t setpoint = 0;        ///< nm, host coordinates
    std::int32_t measured = 0;        ///< nm
    std::int32_t output = 0;          ///< nm, controller output relative to its value at the start
};

struct CaptureReply {
    std::uint8_t axis = 0;
    std::uint8_t kind = 0;            ///< 0 none yet, 1 step test, 2 relay test
    std::uint8_t reason = 0;          ///< motion::control::EndReason; 0 while running
    std::uint32_t testId = 0;         ///< counts tests since power-up: a new test replaces the capture
    std::uint32_t periodUs = 0;       ///< between samples (the control period, doubled each time a long test filled the buffer)
    std::uint32_t total = 0;          ///< samples captured so far
    std::int32_t startPosition = 0;   ///< nm
    std::uint32_t tripValue = 0;      ///< nm, or ms for the duration limit
    std::uint32_t tripLimit = 0;
    WireGains gains;                  ///< the gains the step test ran with (0 for a relay)
    std::uint32_t first = 0;
    std::vector<CaptureSample> samples;
};
/// Samples that fit one GET_CAPTURE reply.
constexpr std::uint16_t kMaxCaptureSamplesPerReply = 80;

struct AbortRequest { std::uint8_t axisMask = 0; };  ///< TEST_ABORT; 0 = every axis

Bytes encode(const AxisRequest&);
Bytes encode(const GainsReply&);
Bytes encode(const SetGainsRequest&);
Bytes encode(const StepTestRequest&);
Bytes encode(const RelayTestRequest&);
Bytes encode(const CaptureRequest&);
Bytes encode(const CaptureReply&);
Bytes encode(const AbortRequest&);

std::optional<AxisRequest> decodeAxisRequest(const Bytes&);
std::optional<GainsReply> decodeGainsReply(const Bytes&);
std::optional<SetGainsRequest> decodeSetGainsRequest(const Bytes&);
std::optional<StepTestRequest> decodeStepTestRequest(const Bytes&);
std::optional<RelayTestRequest> decodeRelayTestRequest(const Bytes&);
std::optional<CaptureRequest> decodeCaptureRequest(const Bytes&);
std::optional<CaptureReply> decodeCaptureReply(const Bytes&);
std::optional<AbortRequest> decodeAbortRequest(const Bytes&);

const char* tuningTypeName(std::uint8_t type);  ///< "GET_GAINS", … or nullptr

} // namespace dev::proto
