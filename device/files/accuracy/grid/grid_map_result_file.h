#pragma once
// A grid plate's map as a result file: schema "benchpilot.grid-map-result", version 1
// (docs/accuracy.md, "Grid map result file"): the plate's placement, the figures of
// the decomposition and a row per node (its nominal stage position, its error once
// the placement is removed, the residual and, for a map read both ways, the error of
// each direction and the reversal, with ex and ey their mean). What `compensation
// fit-2d` reads.
#include "motion/checked.h"
#include "device/files/accuracy/file_problem.h"
#include "motion/metrology/grid/grid_map.h"

#include <QString>

#include <optional>
#include <string>
#include <string_view>

namespace dev::files::accuracy {

constexpr const char* kGridMapResultSchema = "benchpilot.grid-map-result";
constexpr int kGridMapResultVersion = 1;

struct GridMapResultFile {
    motion::metrology::GridMapResult result;
    std::string source;  ///< free text: the plate, the run
};

std::string gridMapResultToJson(const GridMapResultFile& f);

/// The value, or every problem why not (motion/checked.h).
using GridMapResultRead = motion::msg::Checked<GridMapResultFile>;
/// Plain C++: what the fuzzer drives. The nodes must lie on one regular grid, row
/// by row (grid.node_off_grid names the first that does not).
GridMapResultRead gridMapResultFromJson(std::string_view text, std::string_view fileName);
GridMapResultRead loadGridMapResultFile(const QString& path);
bool saveGridMapResultFile(const QString& path, const GridMapResultFile& f, motion::msg::Message* error);

} // namespace dev::files::accuracy
