#pragma once
// Reading a rectangle of one level of a pyramidal OME-TIFF (the layout OmeTiffWriter
// writes: the full resolution in the first IFD, each half-size level a SubIFD of it)
// without reading the rest of the file: only the TIFF tiles (or strips) the rectangle
// crosses are decoded. A plain TIFF reads as a pyramid of one level. 8- or 16-bit grey.
//
// open() walks every level's directory, so a file whose directories are damaged or cut
// short is refused at once with a problem naming it (imaging.pyramid.*, imaging.tiff.*);
// a tile whose data is cut short is refused when it is read, never shown half-read.
// One reader is one libtiff handle: use it from one thread at a time (it locks itself,
// so a second thread waits rather than corrupting the handle's directory state).
#include "imaging/image.h"
#include "motion/checked.h"

#include <Eigen/Core>

#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace imaging {

struct PyramidLevel {
    int width = 0, height = 0;    ///< pixels of this level
    int blockWidth = 0;           ///< the TIFF tile's size (a strip: the image's width)
    int blockHeight = 0;
    double scale = 1;             ///< full-resolution pixels per pixel of this level (x)
};

class PyramidReader {
public:
    /// Opens `path`; `shownName` is how problems name it ("" = path).
    static motion::msg::Checked<std::shared_ptr<PyramidReader>> open(const std::string& path, const std::string& shownName = {});
    ~PyramidReader();
    PyramidReader(const PyramidReader&) = delete;
    PyramidReader& operator=(const PyramidReader&) = delete;

    const std::vector<PyramidLevel>& levels() const { return m_levels; }
    int width() const { return m_levels.front().width; }
    int height() const { return m_levels.front().height; }
    int bitsPerSample() const { return m_bits; }
    /// From the OME-XML's Pixels PhysicalSizeX (µm), or the resolution tags; 0 = not said.
    double pixelSizeUm() const { return m_pixelUm; }
    /// The stage position (mm) of the top-left pixel as the OME-XML's Plane gives it.
    const std::optional<Eigen::Vector2d>& stageMm() const { return m_stageMm; }

    /// The pixels of `level` in [x, x + w) × [y, y + h), clipped to the level (an empty
    /// image when nothing is left). 8-bit samples are kept as 0 … 255.
    motion::msg::Checked<ImageU16> readRegion(int level, int x, int y, int w, int h);
    /// TIFF blocks decoded since open (for tests: that a region read touches only its blocks).
    long blocksRead() const { return m_blocksRead; }

private:
    PyramidReader() = default;
    bool selectLevel(int level);

    std::string m_path, m_shown;
    void* m_tif = nullptr;        ///< TIFF*, kept out of this header
    std::vector<PyramidLevel> m_levels;
    std::vector<unsigned long long> m_subIfdOffsets;  ///< levels ≥ 1
    bool m_tiled = true;
    int m_bits = 16;
    int m_current = -1;           ///< the level whose directory libtiff has selected
    double m_pixelUm = 0;
    std::optional<Eigen::Vector2d> m_stageMm;
    long m_blocksRead = 0;
    std::mutex m_lock;
};

/// The number in `xml`'s attribute `name="…"` (the first one), in the C locale.
std::optional<double> xmlAttributeNumber(const std::string& xml, const std::string& name);

} // namespace imaging
