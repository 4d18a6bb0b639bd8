#pragma once
// Fiji/ImageJ's TileConfiguration.txt (Grid/Collection stitching, "Positions from
// file"), read as Fiji's own reader reads it and written as it expects
// (docs/scan.md, "Exports"): lines trimmed, `#` comments and lines of three
// characters or fewer skipped, `dim = 2` before the tiles, each tile line split
// at `;` into exactly three fields: file name, image name (may be empty), "(x, y)"
// in pixels, the image's top-left corner. Plain C++ (fuzzed: fuzz_files "tileconfig").
#include "motion/checked.h"

#include <Eigen/Core>

#include <string>
#include <string_view>
#include <vector>

namespace imaging {

struct TileEntry {
    std::string file;            ///< as written: relative to the file's folder
    Eigen::Vector2d positionPx;  ///< top-left corner
    int line = 0;                ///< 1-based, where it was read (0 when made)
};

/// The tiles of a TileConfiguration; `fileName` names the file in problems.
motion::msg::Checked<std::vector<TileEntry>> parseTileConfiguration(std::string_view text, const std::string& fileName);
/// The text of a TileConfiguration (2-D) of these tiles, positions with 3 decimals.
std::string tileConfigurationText(const std::vector<TileEntry>& tiles);

} // namespace imaging
