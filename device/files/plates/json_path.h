#pragma once
// What the plate file readers share: parsing with the error placed, and where a
// field path ("steps[4].wells[1]") stood in the parsed document, so the problems
// a data model's validator finds (paths only) are reported with the file's line
// and column like the reader's own.
#include "device/files/json.h"

#include "device/files/json_fields.h"

#include <optional>
#include <string_view>

namespace dev::files::plates {

/// Parses `text`; when it is not JSON, the reason goes to `problems` with its position.
std::optional<dev::files::json::Value> parseOrReport(std::string_view text, dev::files::json::Problems& problems);

/// The position of the deepest value along `path` that exists (the document's
/// start when none does).
dev::files::json::Position positionOfPath(const dev::files::json::Value& root, std::string_view path);

} // namespace dev::files::plates
