#pragma once
// Where each tile of a folder was taken, for stitching: read from the scan's run
// log (docs/scan.md, "The run log"). Only what stitching needs is read — each tile
// line's image file (`"image"` when the camera wrote one, else its `label`) and its
// `measured_mm` — and members this reader does not know are let be, so a log from a
// newer BenchPilot still stitches. A last line cut short by a crash is dropped, as
// the run's own reader does. Plain C++ (fuzzed: fuzz_files "stitch-run-log").
#include "motion/checked.h"

#include <string>
#include <string_view>
#include <vector>

namespace dev::files::scan {

struct TakenTile {
    int tile = 0;              ///< its number in the plan
    std::string image;         ///< the image's file name in the folder
    double measuredXMm = 0;    ///< the grating's reading at the trigger
    double measuredYMm = 0;
    int line = 0;              ///< 1-based line in the log
};

/// The tiles a run log says were taken, in the order taken. A tile taken twice (a
/// resumed run never does that) is refused. `fileName` names the file in problems.
motion::msg::Checked<std::vector<TakenTile>> parseTakenTiles(std::string_view text, const std::string& fileName);

} // namespace dev::files::scan
