#pragma once
// Fusion of placed tiles into one mosaic, streamed by bands of rows into an
// OmeTiffWriter: only the tiles that cross the current band are held, so memory is
// about two rows of tiles plus one band, whatever the mosaic's size.
// Linear feathering (docs/stitching.md, "Fusion"): in an overlap each tile weighs
// (distance to its nearest left/right edge) × (distance to its nearest top/bottom
// edge), so seams fade over the whole overlap; overlay instead lets the later tile
// cover the earlier. Positions are rounded to whole pixels (a resampled tile would
// blur; the registered subpixel positions are in the TileConfiguration and the JSON).
#include "imaging/image.h"
#include "imaging/ome_tiff_writer.h"
#include "motion/problem.h"

#include <Eigen/Core>

#include <functional>
#include <vector>

namespace imaging {

enum class Blend {
    Feather,  ///< linear weights falling to the tile edges
    Overlay,  ///< the later tile (by index) covers the earlier
};

struct FusionOptions {
    Blend blend = Blend::Feather;
    int bandRows = 512;  ///< rows accumulated at a time
};

/// Loads tile `index` (the caller reads its file; a problem stops the fusion).
using TileLoader = std::function<motion::msg::Checked<TileImage>(int index)>;

/// The mosaic's size for tiles of `tileW` × `tileH` at `positionsPx` (each rounded),
/// and the offset that moves the top-left-most tile to (0, 0).
struct MosaicFrame {
    int width = 0, height = 0;
    Eigen::Vector2i originPx{0, 0};  ///< subtract from a rounded position to get mosaic pixels
};
MosaicFrame mosaicFrame(const std::vector<Eigen::Vector2d>& positionsPx, int tileW, int tileH);

/// Fuses every tile into `out` (opened with mosaicFrame's size) and finishes it.
motion::msg::Problems fuseTiles(const std::vector<Eigen::Vector2d>& positionsPx, int tileW, int tileH, const TileLoader& load,
                        OmeTiffWriter& out, const FusionOptions& options = {});

} // namespace imaging
