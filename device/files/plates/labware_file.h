#pragma once
// Plate definitions on disk: our own format (benchpilot.labware, docs/plates.md)
// and, for interop, Opentrons labware definitions (schema 2), which people
// already have for most plates on the market. Plain C++ like json.h, so the
// readers are fuzzed (tests/fuzz/files/fuzz_plates.cpp).
#include "device/files/json_fields.h"
#include "motion/plans/plates/labware.h"

#include <optional>
#include <string>
#include <string_view>

namespace dev::files::plates {

constexpr const char* kLabwareSchema = "benchpilot.labware";
constexpr int kLabwareVersion = 1;

struct LabwareRead {
    std::optional<motion::plates::Labware> labware;  ///< only when there are no problems
    dev::files::json::Problems problems;
    bool opentrons = false;                  ///< the text was an Opentrons definition
};

/// Either format: a document with "schemaVersion" is read as Opentrons, one
/// with "schema" as ours. Every problem at once, with positions.
LabwareRead parseLabware(std::string_view text);

/// Our format. A regular grid is written as its A1 position and pitch, anything
/// else well by well; both read back to the same wells.
std::string writeLabware(const motion::plates::Labware& labware);

/// An Opentrons labware definition (schema 2) from its parsed JSON. Its frame
/// has the origin at the front-left corner with y toward the back; ours has it
/// at the back-left with y toward the front, so y_ours = yDimension − y. Fields
/// we do not use (brand ids, groups, stacking offsets, …) are passed over, as
/// the format grows; what we use is checked strictly.
std::optional<motion::plates::Labware> readOpentronsLabware(const dev::files::json::Value& root, dev::files::json::Problems& problems);

} // namespace dev::files::plates
