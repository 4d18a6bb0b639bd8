#pragma once
// Tile file names from a pattern such as "tile_{i:03}.tif", as the exports write
// them. The names must survive Fiji's TileConfiguration reader, which splits a
// line at ';', trims it, and skips lines starting with '#'.
#include "motion/plans/scan/scan_plan.h"

#include "motion/message.h"

#include <optional>
#include <string>

namespace motion::scan {

struct Tile;

/// nullopt when the pattern is usable, else why not (scan.naming.*: "unknown placeholder {x}").
std::optional<motion::msg::Message> checkFilePattern(const std::string& pattern);

/// The file name of a tile. The pattern must have passed checkFilePattern.
std::string tileFileName(const ExportNaming& naming, int index, int row, int col);

} // namespace motion::scan
