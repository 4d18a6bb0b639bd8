#pragma once
// Flat-field correction (docs/stitching.md, "Flat-field"): a camera's illumination
// and optics make the middle of each tile brighter than its corners, and dust on the
// sensor leaves the same shadow on every tile. In a mosaic both repeat at every tile
// and the seams show. An image of blank glass (or an empty field) taken with the same
// light and exposure records them; each tile is divided by it, normalised to its mean,
// so a sample's brightness no longer depends on where in the field it fell:
//     corrected = (raw − dark) × mean(flat − dark) / (flat − dark)
// `dark` is a constant camera offset (a dark frame's mean), 0 by default.
// Plain C++: the caller reads the blank image.
#include "imaging/image.h"
#include "motion/checked.h"

#include <string>
#include <vector>

namespace imaging {

class FlatField {
public:
    /// From a blank image. Refused (imaging.flat.*) when it is mostly at the dark level
    /// or clipped: a gain from it would amplify noise or saturate.
    static motion::msg::Checked<FlatField> fromBlank(const ImageU16& blank, double darkLevel, const std::string& shownName);

    /// From a blank image's TIFF file (problems name `shownName`, "" = the path).
    static motion::msg::Checked<FlatField> fromFile(const std::string& path, double darkLevel, const std::string& shownName = {});

    int width() const { return m_width; }
    int height() const { return m_height; }
    /// Refused (imaging.flat.size) when a tile of `width` × `height` is not the blank's size.
    motion::msg::Problems checkSize(int width, int height, const std::string& shownName) const;
    /// Tile `tile` corrected in place, clipped to its sample kind's range; refused when
    /// its size is not the blank's.
    motion::msg::Problems apply(TileImage& tile, const std::string& shownName) const;
    /// The largest gain: how much the darkest corner is lifted.
    double maxGain() const { return m_maxGain; }
    const std::string& name() const { return m_name; }  ///< the blank image's file, as shown

private:
    std::string m_name;
    int m_width = 0, m_height = 0;
    double m_dark = 0;
    double m_maxGain = 1;
    std::vector<float> m_gain;  ///< per pixel: mean(flat − dark) / (flat − dark)
};

} // namespace imaging
