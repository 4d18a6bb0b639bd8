#pragma once
// Protocol v1 messages of an XY stage's 2D compensation table: X and Y corrections
// at the nodes of a regular grid, bilinearly interpolated, uploaded in parts,
// enabled, disabled and kept for power-up. Plain C++, like messages.h;
// docs/protocol.md ("2D compensation") is the byte-level spec.
//
// Positions and corrections travel as i32 nanometres; positions are the X and Y
// axes' home coordinates, as the per-axis compensation's (messages_compensation.h).
#include "device/protocol/messages.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace dev::proto {

// Message types (queued 0x1E–0x1F) and capability bit 15, as allocated in messages.h.
// Errors reuse the per-axis compensation's codes (CompInvalid, CompSequence,
// CompMissing) and its event kind 40, on axis 0xFF.
constexpr MsgType kComp2dUpload = static_cast<MsgType>(0x1E);
constexpr MsgType kComp2dEnable = static_cast<MsgType>(0x1F);

constexpr std::uint32_t CapCompensation2d = 1u << 15;  ///< COMP2D_UPLOAD / COMP2D_ENABLE on axes 0 (X) and 1 (Y)

/// Nodes of one COMP2D_UPLOAD part (8 bytes each).
constexpr std::uint8_t kMaxComp2dNodesPerFrame = 96;

struct Comp2dNode {
    std::int32_t correctionX = 0;  ///< nm, added to the X command
    std::int32_t correctionY = 0;  ///< nm, added to the Y command
    bool operator==(const Comp2dNode& o) const { return correctionX == o.correctionX && correctionY == o.correctionY; }
};

/// COMP2D_UPLOAD: one part of the table, nodes row by row (index j·columns + i). A
/// part with first = 0 starts a new upload; each part repeats the grid, which must
/// not change within an upload; the part that completes columns × rows installs it.
struct Comp2dUploadRequest {
    std::uint8_t columns = 0;
    std::uint8_t rows = 0;
    std::int32_t originX = 0;  ///< nm
    std::int32_t originY = 0;
    std::int32_t pitchX = 0;   ///< nm
    std::int32_t pitchY = 0;
    std::uint16_t first = 0;
    std::vector<Comp2dNode> nodes;
};

struct Comp2dUploadReply {
    std::uint16_t received = 0;  ///< nodes of this upload the device holds
    std::uint8_t installed = 0;  ///< 1: complete, checked, and now the table (disabled)
};

enum Comp2dEnableFlag : std::uint8_t {
    Comp2dEnableOn = 1u << 0,     ///< enable (clear: disable)
    Comp2dEnableSave = 1u << 1,   ///< also keep the table and this state for power-up
    Comp2dEnableQuery = 1u << 2,  ///< change nothing: only report the state
};

struct Comp2dEnableRequest {
    std::uint8_t flags = 0;
};

enum Comp2dState : std::uint8_t {
    Comp2dInstalled = 1u << 0,  ///< the device holds a table
    Comp2dEnabled = 1u << 1,    ///< the operator enabled it
    Comp2dApplied = 1u << 2,    ///< enabled, X and Y homed: targets are being compensated
    Comp2dSaved = 1u << 3,      ///< the table and its enabled state are the power-up ones
};

struct Comp2dEnableReply {
    std::uint8_t state = 0;
    std::uint8_t columns = 0;  ///< of the table held (0: none)
    std::uint8_t rows = 0;
};

Bytes encode(const Comp2dUploadRequest&);
Bytes encode(const Comp2dUploadReply&);
Bytes encode(const Comp2dEnableRequest&);
Bytes encode(const Comp2dEnableReply&);

std::optional<Comp2dUploadRequest> decodeComp2dUploadRequest(const Bytes&);
std::optional<Comp2dUploadReply> decodeComp2dUploadReply(const Bytes&);
std::optional<Comp2dEnableRequest> decodeComp2dEnableRequest(const Bytes&);
std::optional<Comp2dEnableReply> decodeComp2dEnableReply(const Bytes&);

const char* compensation2dTypeName(std::uint8_t type);  ///< "COMP2D_UPLOAD", … or nullptr

} // namespace dev::proto
