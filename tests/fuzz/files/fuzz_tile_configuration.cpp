// Fuzz target "tileconfig": Fiji's TileConfiguration.txt as benchpilot-cli stitch reads
// it (imaging/tile_configuration.h). Invariants: no crash; every problem names the file
// and its line; what is accepted writes back and reads again to the same files and
// positions (to the 0.001 px the writer keeps).
#include "fuzz_files.h"

#include "imaging/tile_configuration.h"

#include <cmath>

namespace {

std::vector<std::string> seeds()
{
    return {
        "# Define the number of dimensions we are working on\ndim = 2\n\n# Define the image coordinates\n"
        "tile_001.tif; ; (0.000, 0.000)\ntile_002.tif; ; (1843.200, 0.000)\ntile_003.tif; ; (0.000, 1843.200)\n",
        "dim=3\r\na.tif;x;(1,2,3)\r\n  b c.tif ; ; ( -1.5e2 , 2 , 0 )\r\n#c.tif; ; (0, 0, 0)\n",
        "dim = 2\nimg;;(1,2)\nimg2;;(1;2)\n;;(0,0)\nx\n",
    };
}

void check(std::string_view input)
{
    const auto r = imaging::parseTileConfiguration(input, "fuzz.txt");
    for (const motion::msg::Problem& p : r.problems())
        if (p.file != "fuzz.txt" || p.message.id.empty())
            fuzzfiles::fail("a problem that does not say where or what: " + motion::msg::debugFormat(r.problems()));
    if (!r.ok())
        return;
    std::vector<imaging::TileEntry> flat = *r;
    const auto again = imaging::parseTileConfiguration(imaging::tileConfigurationText(flat), "again.txt");
    if (!again.ok() || again->size() != flat.size())
        fuzzfiles::fail("written tiles do not read back: " + motion::msg::debugFormat(again.problems()));
    for (std::size_t i = 0; i < flat.size(); ++i) {
        const auto& a = flat[i];
        const auto& b = (*again)[i];
        if (a.file != b.file || std::abs(a.positionPx.x() - b.positionPx.x()) > 0.0006 || std::abs(a.positionPx.y() - b.positionPx.y()) > 0.0006)
            fuzzfiles::fail("write → read changed tile " + std::to_string(i));
    }
}

} // namespace

BP_FUZZ_FILE_TARGET({"tileconfig", seeds, check});
