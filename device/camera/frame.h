#pragma once
// One image from a camera, as every source hands it over: the pixels, tightly packed,
// and what is known of how and when it was taken. Plain C++, so the imaging library,
// the TIFF writer and the tests can take it without Qt.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace dev::camera {

enum class PixelFormat {
    Grey8,   ///< one byte a pixel
    Grey16,  ///< two bytes a pixel, host byte order; `bitDepth` says how many bits are used
    Rgb8,    ///< three bytes a pixel, R G B
};

int bytesPerPixel(PixelFormat format);

struct Frame {
    int width = 0;
    int height = 0;
    PixelFormat format = PixelFormat::Grey16;
    int bitDepth = 16;                        ///< significant bits (12 for a 12-bit sensor in Grey16)
    std::vector<std::uint8_t> pixels;         ///< row-major, top row first, no padding
    double exposureMs = 0;                    ///< as the source set it; 0 when it does not say
    double gain = 0;                          ///< as the source set it; 0 when it does not say
    std::int64_t startedHostUs = 0;           ///< host steady-clock time the exposure started (best known)
    std::optional<std::uint64_t> deviceTimeUs;  ///< the instrument's clock at the trigger, where a trigger was fired
    double pixelUm = 0;                       ///< at the sample; 0 when the source does not know it
    std::uint64_t sequence = 0;               ///< counts up per opened source; a gap is a dropped frame

    bool isEmpty() const { return width <= 0 || height <= 0 || pixels.empty(); }
};

} // namespace dev::camera
