// Fuzz target "stitch-run-log": the scan run log as stitching reads it
// (device/files/stitch_positions.h): each tile's image and measured position.
// Invariants: no crash; every problem names the file; every tile accepted has a
// plain file name, finite coordinates, and neither its name nor its number twice.
#include "fuzz_files.h"

#include "device/files/stitch_positions.h"

#include <cmath>
#include <set>

namespace {

std::vector<std::string> seeds()
{
    const std::string head = "{\"schema\":\"benchpilot.scan-run\",\"version\":1,\"plan\":\"Slide\",\"fingerprint\":\"9f0c4d51b2e8a377\",\"tiles\":3}\n";
    return {
        head + "{\"tile\":0,\"label\":\"tile_001.tif\",\"planned_mm\":[20.5,41.5],\"commanded_mm\":[20.5,41.5],\"measured_mm\":[20.5005,41.4995],"
               "\"device_time_us\":22056800,\"settle_s\":0.0059}\n"
               "{\"tile\":1,\"label\":\"tile_002.tif\",\"planned_mm\":[21.5,41.5],\"commanded_mm\":[21.5,41.5],\"measured_mm\":[21.5,41.5],"
               "\"device_time_us\":22156800,\"settle_s\":0.006,\"image\":\"tile_002.tif\",\"sha256\":\"ab12\"}\n",
        head + "{\"tile\":2,\"label\":\"x\",\"measured_mm\":[1,2],\"image\":\"../x.tif\"}\n{\"tile\":2,\"label\":\"y\",\"measured_mm\":[1,2]}\n{\"tile\":1,",
    };
}

void check(std::string_view input)
{
    const auto r = dev::files::scan::parseTakenTiles(input, "scan-run.jsonl");
    for (const motion::msg::Problem& p : r.problems())
        if (p.message.id.empty() || (p.file != "scan-run.jsonl" && p.message.text("file") != "scan-run.jsonl"))
            fuzzfiles::fail("a problem that does not say where or what: " + motion::msg::debugFormat(r.problems()));
    if (!r.ok())
        return;
    std::set<int> tiles;
    std::set<std::string> names;
    for (const dev::files::scan::TakenTile& t : *r) {
        if (t.image.empty() || t.image.find('/') != std::string::npos || t.image.find('\\') != std::string::npos)
            fuzzfiles::fail("a tile image that is not a plain file name: " + t.image);
        if (!std::isfinite(t.measuredXMm) || !std::isfinite(t.measuredYMm))
            fuzzfiles::fail("a tile at a position that is not a number");
        if (!tiles.insert(t.tile).second || !names.insert(t.image).second)
            fuzzfiles::fail("a tile taken twice: " + t.image);
    }
}

} // namespace

BP_FUZZ_FILE_TARGET({"stitch-run-log", seeds, check});
