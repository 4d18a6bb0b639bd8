#pragma once
// Protocol v1 messages of the device path queue: LINE and ARC segments with a feed rate, queued
// on the device and run point by point with look-ahead (docs/protocol.md, "Path queue"). Plain
// C++ like messages.h: shared by the host's path client, the simulator firmware and the fuzzer.
#include "device/protocol/messages.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace dev::proto {

/// Segments one PATH_APPEND may carry (and the simulator's queue capacity): 32 × 25 bytes fit a frame.
constexpr int kMaxPathSegmentsPerAppend = 32;
/// A running path is held when nothing at all has come from the host for this long
/// (BenchPilot polls STATUS every 50 ms, so only a lost host goes quiet this long).
constexpr std::uint32_t kPathHostSilenceMs = 1000;

enum class PathSegmentKind : std::uint8_t { Line = 1, ArcCw = 2, ArcCcw = 3 };
constexpr std::uint8_t kPathSegmentHasZ = 0x80;  ///< in the kind byte: a Z target follows

struct PathSegmentWire {
    PathSegmentKind kind = PathSegmentKind::Line;
    std::uint32_t feed = 0;          ///< path speed, nm/s
    WireUnits x = 0, y = 0;          ///< end point, nm (the start is where the previous segment ended)
    WireUnits cx = 0, cy = 0;        ///< arcs: centre, nm
    bool hasZ = false;
    WireUnits z = 0;                 ///< with hasZ: Z moves here once the XY part has arrived
};

struct PathBeginRequest {
    std::uint32_t firstIndex = 0;          ///< index of the first segment to come (a restart keeps its numbering)
    std::uint32_t junctionDeviation = 0;   ///< nm; 0 = the device's default
    std::uint32_t accel = 0;               ///< path acceleration, nm/s²; 0 = the device's default
};

enum PathAppendFlag : std::uint8_t {
    PathAppendStart = 1u << 0,  ///< start running now (otherwise when the queue fills or the path's end arrives)
    PathAppendLast = 1u << 1,   ///< these are the path's last segments: it ends at rest after them
};

struct PathAppendRequest {
    std::uint32_t firstIndex = 0;    ///< must be the index the device expects next
    std::uint8_t flags = 0;
    std::vector<PathSegmentWire> segments;  ///< 1 … kMaxPathSegmentsPerAppend
};

enum class PathState : std::uint8_t {
    Idle = 0,      ///< no path
    Filling = 1,   ///< begun, segments arriving, not started yet
    Running = 2,
    Starved = 3,   ///< ran dry before the last segment: at rest, runs on when more arrive
    Holding = 4,   ///< feed hold: slowing down along the path
    Held = 5,      ///< at rest on the path, queue kept; PATH_RESUME goes on
    Done = 6,      ///< last segment completed
    Aborted = 7,   ///< ended early (see the reason); the queue is empty
};
const char* pathStateName(PathState s);

/// Why a path is held or ended.
enum class PathReason : std::uint8_t {
    None = 0,
    HostHold = 1,     ///< PATH_HOLD
    HostSilent = 2,   ///< nothing from the host for kPathHostSilenceMs: held
    Stop = 3,         ///< STOP of a path axis
    EStop = 4,
    LimitSwitch = 5,
    NewSession = 6,   ///< a host started a new session (HELLO): it does not know this path
    Cleared = 7,      ///< PATH_CLEAR
};
const char* pathReasonName(PathReason r);

/// Reply to PATH_BEGIN, PATH_APPEND and PATH_STATUS: the queue's fill state, for flow control.
struct PathStatusReply {
    PathState state = PathState::Idle;
    std::uint8_t capacity = 0;           ///< segments the queue holds
    std::uint8_t freeSlots = 0;          ///< segments it can take now
    std::uint32_t nextIndex = 0;         ///< the index the next PATH_APPEND must start with
    std::uint32_t executingIndex = 0;    ///< segment in progress (or next to run); segments before it are done
    std::uint32_t speed = 0;             ///< commanded path speed now, nm/s
    std::uint16_t underruns = 0;         ///< times the queue ran dry in this path
    PathReason reason = PathReason::None;
    std::uint32_t accel = 0;             ///< path acceleration in effect (or the default when idle), nm/s²
    std::uint32_t junctionDeviation = 0; ///< nm, likewise: with accel, what a host needs to time a path
};

Bytes encode(const PathBeginRequest&);
Bytes encode(const PathAppendRequest&);
Bytes encode(const PathStatusReply&);
/// Wire bytes of one segment (1 + 4 + 8, + 8 for an arc, + 4 with Z).
std::size_t pathSegmentBytes(const PathSegmentWire& s);

std::optional<PathBeginRequest> decodePathBeginRequest(const Bytes&);
std::optional<PathAppendRequest> decodePathAppendRequest(const Bytes&);
std::optional<PathStatusReply> decodePathStatusReply(const Bytes&);

} // namespace dev::proto
