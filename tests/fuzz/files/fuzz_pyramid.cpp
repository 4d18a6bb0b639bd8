// Fuzz target "pyramid": the mosaic viewer's reader of the pyramidal OME-TIFF
// (imaging/pyramid_reader.h), on small mosaics the writer made, mutated. Invariants: no
// crash, hang or unbounded allocation; a refused file is named, with an id; an accepted
// one has levels of bounded, shrinking sizes, and every region read is either exactly
// the size asked (clipped to the level) or refused as damaged, naming the file.
#include "fuzz_files.h"

#include "imaging/ome_tiff_writer.h"
#include "imaging/pyramid_reader.h"

#include <cstdio>
#include <fstream>
#include <iterator>
#include <unistd.h>

namespace {

std::string pyramidFuzzPath()
{
    return "/tmp/bp_fuzz_pyramid_" + std::to_string(::getpid()) + ".ome.tif";
}

std::string writtenMosaic(int w, int h, int bits)
{
    const std::string path = pyramidFuzzPath();
    imaging::OmeTiffOptions o;
    o.bitsPerSample = bits;
    o.pixelSizeUm = 0.65;
    o.stageXMm = 1.5;
    o.stageYMm = 2.5;
    o.tileSize = 16;
    o.smallestLevelPx = 16;
    auto writer = imaging::OmeTiffWriter::open(path, w, h, o);
    if (!writer)
        fuzzfiles::fail("the writer refused a seed");
    std::vector<std::uint16_t> rows(static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
    for (std::size_t i = 0; i < rows.size(); ++i)
        rows[i] = static_cast<std::uint16_t>((i * 37) % (bits == 8 ? 256 : 65536));
    if (!(*writer)->writeRows(rows.data(), h).empty() || !(*writer)->finish().empty())
        fuzzfiles::fail("the writer failed on a seed");
    std::ifstream in(path, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::remove(path.c_str());
    return bytes;
}

std::vector<std::string> seeds() { return {writtenMosaic(40, 30, 16), writtenMosaic(33, 20, 8)}; }

void named(const motion::msg::Problems& problems)
{
    if (problems.empty() || problems.front().file != "fuzz.ome.tif" || problems.front().message.id.empty())
        fuzzfiles::fail("a problem that does not name the file: " + motion::msg::debugFormat(problems));
}

void check(std::string_view input)
{
    const std::string path = pyramidFuzzPath();
    std::ofstream(path, std::ios::binary | std::ios::trunc).write(input.data(), static_cast<std::streamsize>(input.size()));
    auto r = imaging::PyramidReader::open(path, "fuzz.ome.tif");
    if (!r) {
        named(r.problems());
        std::remove(path.c_str());
        return;
    }
    const auto& levels = (*r)->levels();
    if (levels.empty())
        fuzzfiles::fail("accepted with no level");
    for (std::size_t k = 0; k < levels.size(); ++k) {
        const auto& l = levels[k];
        if (l.width <= 0 || l.height <= 0 || l.width > (1 << 20) || l.height > (1 << 20) || l.blockWidth <= 0 || l.blockHeight <= 0)
            fuzzfiles::fail("a level of unbounded size accepted");
        if (k > 0 && l.width >= levels[k - 1].width && l.height >= levels[k - 1].height)
            fuzzfiles::fail("a level not smaller than the one above");
        // A corner, at most 64 px each way (what a hostile size could make a whole read allocate).
        const int w = std::min(l.width, 64), h = std::min(l.height, 64);
        auto px = (*r)->readRegion(static_cast<int>(k), l.width - w, l.height - h, w, h);
        if (px) {
            if (px->width != w || px->height != h)
                fuzzfiles::fail("a region read at the wrong size");
        } else {
            named(px.problems());
        }
    }
    std::remove(path.c_str());
}

} // namespace

BP_FUZZ_FILE_TARGET({"pyramid", seeds, check});
