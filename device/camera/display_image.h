#pragma once
// A frame made fit to look at: 8-bit grey (or RGB as it came), its contrast stretched so
// that the darkest and brightest 0.1 % of the pixels clip, which is what makes a 12- or
// 16-bit image visible at all. The live view calls this off the GUI thread.
#include "device/camera/frame.h"

#include <QImage>

namespace dev::camera {

struct DisplayStretch {
    int low = 0;    ///< the raw value shown black
    int high = 0;   ///< … and white
};

/// `autoContrast` false: the raw values scaled by the bit depth only.
QImage toDisplayImage(const Frame& frame, bool autoContrast = true, DisplayStretch* used = nullptr);

} // namespace dev::camera
