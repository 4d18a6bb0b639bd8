#pragma once
// Protocol v1 messages of axis error compensation: upload an axis's
// compensation (an error polynomial, or a table of up to 256 points, plus a
// backlash), read it back, enable or disable it and keep it for power-up. Plain C++,
// like messages.h; docs/protocol.md ("Compensation") is the byte-level spec.
//
// Positions travel as i32 nanometres in the axis's home coordinates (where it reads
// after homing, before any set-zero); polynomial coefficients as IEEE-754 float64
// (little-endian), the error curve in µm over mm, c0 first, as the compensation file
// keeps them: a float64 carries what a fifth-order fit needs and NaN, which the
// device refuses with a reason.
#include "device/protocol/messages.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace dev::proto {

// Message types (queued 0x1B–0x1D), capability bit 14, error codes 23–25 and event kind
// 40, as allocated in messages.h.
constexpr MsgType kCompUpload = static_cast<MsgType>(0x1B);
constexpr MsgType kCompGet = static_cast<MsgType>(0x1C);
constexpr MsgType kCompEnable = static_cast<MsgType>(0x1D);

constexpr std::uint32_t CapCompensation = 1u << 14;  ///< COMP_UPLOAD / COMP_GET / COMP_ENABLE

constexpr ErrorCode kErrCompInvalid = static_cast<ErrorCode>(23);   ///< the model a device could not apply; value: the entry at fault, or −1
constexpr ErrorCode kErrCompSequence = static_cast<ErrorCode>(24);  ///< an upload's part out of order; value: the entry the device expects next
constexpr ErrorCode kErrCompMissing = static_cast<ErrorCode>(25);   ///< the axis has no compensation to enable

constexpr EventKind kEvCompChanged = static_cast<EventKind>(40);    ///< installed, enabled, disabled or saved; text says which

enum class CompKind : std::uint8_t {
    None = 0,
    Polynomial = 1,
    Table = 2,              ///< one correction column, plus the backlash
    TablePerDirection = 3,  ///< a column for each approach direction, no backlash
};

/// Coefficients of a polynomial (order 5 at most).
constexpr std::uint16_t kMaxCompCoefficients = 6;
/// Points of a table.
constexpr std::uint16_t kMinCompPoints = 2;
constexpr std::uint16_t kMaxCompPoints = 256;
/// Table points that fit one COMP_UPLOAD or COMP_GET reply (12 bytes each).
constexpr std::uint8_t kMaxCompPointsPerFrame = 80;

struct CompPoint {
    std::int32_t nominal = 0;          ///< nm
    std::int32_t correctionUp = 0;     ///< nm, added to the command approaching from below
    std::int32_t correctionDown = 0;   ///< nm, from above (equal to Up in a single-column table)
    bool operator==(const CompPoint& o) const
    {
        return nominal == o.nominal && correctionUp == o.correctionUp && correctionDown == o.correctionDown;
    }
};

/// COMP_UPLOAD: one part of an axis's compensation. A part with first = 0 starts a
/// new upload for the axis; the last part (first + count = total) installs it.
struct CompUploadRequest {
    std::uint8_t axis = 0;
    CompKind kind = CompKind::Polynomial;
    std::int32_t backlash = 0;         ///< nm (0 for a per-direction table)
    std::uint16_t total = 0;           ///< coefficients or points of the whole compensation
    std::uint16_t first = 0;           ///< index of this part's first entry
    // Polynomial (one part: first 0, all coefficients):
    std::int32_t validFrom = 0;        ///< nm
    std::int32_t validTo = 0;          ///< nm
    std::vector<double> coefficients;  ///< µm over mm, c0 first
    // Table:
    std::vector<CompPoint> points;
};

struct CompUploadReply {
    std::uint8_t axis = 0;
    std::uint16_t received = 0;        ///< entries of this upload the device holds
    std::uint8_t installed = 0;        ///< 1: complete, checked, and now the axis's compensation (disabled)
};

struct CompGetRequest {
    std::uint8_t axis = 0;
    std::uint16_t first = 0;           ///< first table point wanted
    std::uint8_t maxCount = kMaxCompPointsPerFrame;
};

enum CompFlag : std::uint8_t {
    CompEnabled = 1u << 0,  ///< the operator enabled it
    CompApplied = 1u << 1,  ///< enabled and the axis is homed: targets are being compensated
    CompSaved = 1u << 2,    ///< this compensation and its enabled state are the power-up ones
};

struct CompGetReply {
    std::uint8_t axis = 0;
    CompKind kind = CompKind::None;
    std::uint8_t flags = 0;
    std::int32_t backlash = 0;
    std::uint16_t total = 0;
    std::uint16_t first = 0;
    std::int32_t validFrom = 0;        ///< polynomial
    std::int32_t validTo = 0;
    std::vector<double> coefficients;  ///< polynomial: all of them
    std::vector<CompPoint> points;     ///< table: points first … first + count − 1
};

/// COMP_ENABLE: enable or disable the compensation of the axes in the mask (0 = all
/// axes that have one), and optionally keep it and this state for power-up.
struct CompEnableRequest {
    std::uint8_t axisMask = 0;
    std::uint8_t flags = 0;
};
enum CompEnableFlag : std::uint8_t {
    CompEnableOn = 1u << 0,   ///< enable (clear: disable)
    CompEnableSave = 1u << 1, ///< also keep for power-up
};

Bytes encode(const CompUploadRequest&);
Bytes encode(const CompUploadReply&);
Bytes encode(const CompGetRequest&);
Bytes encode(const CompGetReply&);
Bytes encode(const CompEnableRequest&);

std::optional<CompUploadRequest> decodeCompUploadRequest(const Bytes&);
std::optional<CompUploadReply> decodeCompUploadReply(const Bytes&);
std::optional<CompGetRequest> decodeCompGetRequest(const Bytes&);
std::optional<CompGetReply> decodeCompGetReply(const Bytes&);
std::optional<CompEnableRequest> decodeCompEnableRequest(const Bytes&);

const char* compensationTypeName(std::uint8_t type);  ///< "COMP_UPLOAD", … or nullptr

} // namespace dev::proto
