#pragma once
// Where a field path ("steps[4].wells[1]") stood in a parsed document, so the
// problems a data model's validator finds (paths only) are reported with the
// file's line and column like the reader's own.
#include "device/files/json.h"

#include <string_view>

namespace platefiles {

/// The position of the deepest value along `path` that exists (the document's
/// start when none does).
jsonio::Position positionOfPath(const jsonio::Value& root, std::string_view path);

} // namespace platefiles
