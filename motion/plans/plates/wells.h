#pragma once
// Well names ("A1", "P24", "AF48") and well sets as people write them in a
// recipe: a single well, a range "A1:H1", "row B", "column 3", "all", or a
// comma-separated list of these.
#include "motion/plans/plates/problem.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace motion::plates {

class Labware;

/// Zero-based row (A = 0) and column (1 = 0) on a plate's grid.
struct WellId {
    int row = 0;
    int column = 0;
    bool operator==(const WellId& o) const { return row == o.row && column == o.column; }
    bool operator!=(const WellId& o) const { return !(*this == o); }
    bool operator<(const WellId& o) const { return row != o.row ? row < o.row : column < o.column; }
};

/// Rows and columns a well name can have (1536-well plates: 32 × 48).
constexpr int kMaxRows = 32;
constexpr int kMaxColumns = 48;

/// 0 → "A", 25 → "Z", 26 → "AA" (as plate makers letter rows past Z).
std::string rowName(int row);
std::string wellName(const WellId& w);
/// "A1", "a1", "H12", "A01", "AF48". nullopt for anything else, or beyond kMaxRows/kMaxColumns.
std::optional<WellId> parseWellName(std::string_view text);

struct WellSet {
    std::vector<WellId> wells;  ///< in the order written; a range runs row by row from its first corner
    motion::msg::Problems problems;          ///< at `path`, or `path[k]` for the k-th spec of a list
};

/// Expands well specs against `labware`. `path` names the field for messages
/// (a single spec is reported at `path`, several at `path[k]`). A well named
/// twice is an error: a recipe that doses a well twice says so with two steps.
WellSet expandWells(const std::vector<std::string>& specs, const Labware& labware, const std::string& path);

/// Compact specs for a set of wells, in row order: one range when they fill a
/// rectangle ("A1:H12"), else runs along each row ("A1:A5", "C7"). Used when the
/// GUI turns a selection into a step; expandWells() gives the same wells back.
std::vector<std::string> describeWells(std::vector<WellId> wells);

} // namespace motion::plates
