#pragma once
// Protocol v1's arched move (docs/protocol.md, "ARCH_MOVE"): Z up to a clearance, XY
// across, Z down, as one request the device blends — XY starts while Z still rises and
// Z starts down before XY ends, each only as far as the request's radii allow. Plain
// C++ like messages.h: shared by the host client, the simulator firmware and the fuzzer.
#include "device/protocol/messages.h"

#include <cstdint>
#include <optional>

namespace dev::proto {

/// HELLO capability bit: the device takes ARCH_MOVE (an analyzer's Z and XY blended).
constexpr std::uint32_t kCapArchMove = 1u << 16;
/// HELLO capability bit: an ARCH_MOVE may carry a plunger move run while the tip is
/// down inside the target well, and a rise after it (the pump block).
constexpr std::uint32_t kCapArchPump = 1u << 17;

/// The optional pump block of an ARCH_MOVE (kCapArchPump): the plunger starts once the way
/// down has passed `liquidZ` and Z rises to `leaveZ` after it, reaching `liquidZ` again no
/// earlier than the plunger has stopped — so everything the plunger moves, it moves with the
/// tip below `liquidZ` (a well's rim) inside the target's opening.
struct ArchPump {
    std::int32_t delta = 0;      ///< plunger, relative, nL (+ draws in, − pushes out)
    std::uint32_t speed = 0;     ///< nL/s; 0 = the plunger's default speed
    WireUnits liquidZ = 0;       ///< nm: the plunger runs only while Z is at or below this
    WireUnits leaveZ = 0;        ///< nm: where Z rises to after the plunger (= Z target: stays down)
};

struct ArchMoveRequest {
    std::uint32_t xySpeed = 0;   ///< XY path speed, nm/s; 0 = X's and Y's default speed
    std::uint32_t zSpeed = 0;    ///< nm/s; 0 = Z's default speed
    WireUnits x = 0, y = 0;      ///< XY target, nm
    WireUnits clearZ = 0;        ///< nm: Z rises to here (toward its home end) first, unless already above it
    WireUnits z = 0;             ///< Z target, nm
    /// nm: how far XY may go from where it starts while Z is still below the clearance.
    std::uint32_t departRadius = 0;
    /// nm: how far from its target XY must be before Z goes below the clearance again.
    std::uint32_t approachRadius = 0;
    std::optional<ArchPump> pump;  ///< 16 more bytes when present
};

Bytes encode(const ArchMoveRequest&);
std::optional<ArchMoveRequest> decodeArchMoveRequest(const Bytes&);

} // namespace dev::proto
