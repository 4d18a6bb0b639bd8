#pragma once
// A pyramidal OME-TIFF written row band by row band, so a mosaic larger than memory
// can be written (docs/stitching.md, "The mosaic file"):
//   - one image plane, 8- or 16-bit grey, tiled 256 × 256, uncompressed;
//   - the full resolution in the first IFD with the OME-XML in its ImageDescription
//     (physical pixel size, the stage position of its top-left corner);
//   - each half-size level as a SubIFD of it (NewSubfileType = reduced image), the
//     layout the OME-TIFF specification gives for pyramids (Bio-Formats 6, QuPath,
//     napari's readers), halving until the longer side is at most 1024 px;
//   - BigTIFF when the file could pass 2 GiB.
// The full resolution goes to the file as it comes; each smaller level is kept in
// a temporary file beside it until the full one is done. The file is written under
// a temporary name and renamed over `path` only when complete: a failure (a full
// disk) leaves nothing under `path`.
#include "motion/checked.h"

#include <cstdint>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace imaging {

struct OmeTiffOptions {
    int bitsPerSample = 16;                     ///< 8 or 16
    double pixelSizeUm = 0;                     ///< at the sample; 0 when unknown (left out of the XML)
    std::optional<double> stageXMm, stageYMm;   ///< where the top-left pixel was, when known
    std::string imageName = "mosaic";
    bool forceBigTiff = false;
    int tileSize = 256;
    int smallestLevelPx = 1024;                 ///< stop halving once the longer side is at most this
};

class OmeTiffWriter {
public:
    /// Opens `path`'s temporary sibling for a width × height mosaic.
    static motion::msg::Checked<std::shared_ptr<OmeTiffWriter>> open(const std::string& path, int width, int height, const OmeTiffOptions& options);
    ~OmeTiffWriter();
    OmeTiffWriter(const OmeTiffWriter&) = delete;
    OmeTiffWriter& operator=(const OmeTiffWriter&) = delete;

    int width() const { return m_width; }
    int height() const { return m_height; }
    /// The next `count` rows, top to bottom, `width()` samples each.
    motion::msg::Problems writeRows(const std::uint16_t* rows, int count);
    /// Writes the smaller levels and renames the file into place. After an error the
    /// temporary file is removed and `path` is untouched.
    motion::msg::Problems finish();
    /// The OME-XML written into the file (for tests and the docs).
    static std::string omeXml(int width, int height, const OmeTiffOptions& options);

private:
    OmeTiffWriter() = default;
    struct Level;
    motion::msg::Problems writeBand(int level, const std::uint16_t* band, int rows);
    motion::msg::Problems failure(const char* what);
    void discard();

    std::string m_path, m_tempPath;
    int m_width = 0, m_height = 0;
    OmeTiffOptions m_options;
    void* m_tif = nullptr;  ///< TIFF*, kept out of this header
    std::vector<std::uint16_t> m_band;  ///< rows of the full level waiting for a whole tile band
    int m_bandRows = 0;
    int m_rowsDone = 0;
    std::vector<std::unique_ptr<Level>> m_levels;  ///< [0] the full size, then the halvings
    bool m_failed = false;
    bool m_finished = false;
};

/// Reads back what OME-XML an OME-TIFF holds in its first ImageDescription ("" if none).
std::string readImageDescription(const std::string& path);

} // namespace imaging
