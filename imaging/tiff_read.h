#pragma once
// Reading tiles from TIFF files: 8- or 16-bit grey, or 8-bit RGB (kept as its
// luminance), stripped or tiled, the first image of the file. What cannot be read
// is a problem naming the file (imaging.tiff.*), never a crash or a partial image.
#include "imaging/image.h"
#include "motion/checked.h"

#include <string>

namespace imaging {

struct TiffInfo {
    int width = 0;
    int height = 0;
    SampleKind kind = SampleKind::Grey16;
};

/// The size and sample kind of `path`'s first image, without its pixels.
motion::msg::Checked<TiffInfo> readTiffInfo(const std::string& path, const std::string& shownName = {});
/// The first image of `path`. `shownName` is how problems name the file ("" = path).
motion::msg::Checked<TileImage> readTiff(const std::string& path, const std::string& shownName = {});

/// What libtiff said last on this thread (its warnings and errors go here, not to stderr).
std::string lastTiffMessage();
/// Routes libtiff's messages into lastTiffMessage(); every imaging entry point calls it.
void quietTiff();

} // namespace imaging
