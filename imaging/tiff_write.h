#pragma once
// Writing plain TIFF files: what the tests make their tiles with, and what a tool
// writes a single image with. Written to a temporary name and renamed into place.
#include "imaging/image.h"
#include "motion/problem.h"

#include <string>

namespace imaging {

/// `samples` interleaved samples per pixel (1 grey, 3 RGB) of `bits` (8 or 16) each,
/// row after row. An empty list means written.
motion::msg::Problems writeTiffSamples(const std::string& path, int width, int height, int samples, int bits, const void* data);
/// A grey image at 16 bits, or at 8 bits (values above 255 clipped).
motion::msg::Problems writeTiff(const std::string& path, const ImageU16& image, int bits = 16);

} // namespace imaging
