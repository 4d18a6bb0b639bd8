#pragma once
// A frame made fit for a screen: 8 bits a channel, its contrast stretched so that a
// 12- or 16-bit image that uses a small part of its range is not black. Plain C++
// (the widgets wrap the result in a QImage without copying), so it can run on any
// thread and be measured without a GUI.
#include "device/camera/frame.h"

#include <cstdint>
#include <vector>

namespace dev::camera {

/// How the grey levels are mapped to 0–255.
struct DisplayOptions {
    bool autoContrast = true;   ///< stretch between two percentiles; off: the full bit depth maps to 0–255
    double lowPercent = 0.5;    ///< the level below which this share of pixels lies shows black
    double highPercent = 99.5;  ///< the level above which the rest lies shows white
};

/// The grey levels that became 0 and 255 (in the frame's own units, e.g. 0–65535).
struct Stretch {
    double black = 0;
    double white = 255;
};

struct DisplayImage {
    int width = 0;
    int height = 0;
    int channels = 1;                 ///< 1: grey, 3: R G B
    std::vector<std::uint8_t> pixels; ///< row-major, `width * channels` bytes a row, no padding
    Stretch stretch;
    bool isEmpty() const { return width <= 0 || height <= 0 || pixels.empty(); }
};

/// The levels at `lowPercent` and `highPercent` of the frame's pixels (grey, or the
/// mean of R, G and B); a flat image gives black == white - 1 so it still maps.
Stretch percentileStretch(const Frame& frame, double lowPercent, double highPercent);

/// The frame in 8 bits for a screen, stretched as `options` say.
DisplayImage toDisplay(const Frame& frame, const DisplayOptions& options = {});

} // namespace dev::camera
