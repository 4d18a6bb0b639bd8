#pragma once
// How sharp a frame is, for focusing by hand: the variance of the Laplacian of a
// downscaled grey copy. It rises as edges get crisper; it also grows with contrast (a
// brighter image of the same scene scores higher), so it compares frames of one scene
// at one exposure, which is what turning the focus knob gives. Plain C++, any thread.
#include "device/camera/frame.h"

namespace dev::camera {

/// The variance of the 4-neighbour Laplacian of the frame averaged down in blocks so
/// that its longer side is at most `maxSidePx`, with grey levels scaled to 0–1 of the
/// frame's bit depth (so 8- and 16-bit frames of one scene score alike). 0 for an
/// empty frame or one smaller than 3 × 3.
double focusMeasure(const Frame& frame, int maxSidePx = 256);

} // namespace dev::camera
