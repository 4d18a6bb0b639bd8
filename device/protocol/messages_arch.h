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
};

Bytes encode(const ArchMoveRequest&);
std::optional<ArchMoveRequest> decodeArchMoveRequest(const Bytes&);

} // namespace dev::proto
