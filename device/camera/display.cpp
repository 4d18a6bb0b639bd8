#include "device/camera/display.h"

#include <algorithm>
#include <cmath>

namespace dev::camera {

namespace {

/// Grey level of pixel `i` in the frame's own units.
inline unsigned levelAt(const Frame& f, std::size_t i)
{
    switch (f.format) {
    case PixelFormat::Grey8: return f.pixels[i];
    case PixelFormat::Grey16: {
        std::uint16_t v;
        std::copy_n(&f.pixels[2 * i], 2, reinterpret_cast<std::uint8_t*>(&v));
        return v;
    }
    case PixelFormat::Rgb8: return (unsigned(f.pixels[3 * i]) + f.pixels[3 * i + 1] + f.pixels[3 * i + 2]) / 3;
    }
    return 0;
}

unsigned maxLevel(const Frame& f)
{
    if (f.format != PixelFormat::Grey16)
        return 255;
    const int bits = std::clamp(f.bitDepth, 1, 16);
    return (1u << bits) - 1;
}

} // namespace

Stretch percentileStretch(const Frame& frame, double lowPercent, double highPercent)
{
    Stretch s{0, double(maxLevel(frame))};
    const std::size_t n = std::size_t(std::max(0, frame.width)) * std::size_t(std::max(0, frame.height));
    if (frame.isEmpty() || frame.pixels.size() < n * std::size_t(bytesPerPixel(frame.format)))
        return s;
    // A histogram over every level: exact percentiles in two passes, whatever the size.
    std::vector<std::uint32_t> histogram(std::size_t(maxLevel(frame) > 255 ? 65536 : 256), 0);
    for (std::size_t i = 0; i < n; ++i)
        ++histogram[std::min<std::size_t>(levelAt(frame, i), histogram.size() - 1)];
    auto levelAtShare = [&](double percent) {
        const double target = std::clamp(percent, 0.0, 100.0) / 100.0 * double(n);
        double seen = 0;
        for (std::size_t level = 0; level < histogram.size(); ++level) {
            seen += histogram[level];
            if (seen >= target && histogram[level] > 0)
                return double(level);
        }
        return double(histogram.size() - 1);
    };
    s.black = levelAtShare(lowPercent);
    s.white = levelAtShare(highPercent);
    if (s.white <= s.black)
        s.white = s.black + 1;
    return s;
}

DisplayImage toDisplay(const Frame& frame, const DisplayOptions& options)
{
    DisplayImage out;
    const std::size_t n = std::size_t(std::max(0, frame.width)) * std::size_t(std::max(0, frame.height));
    if (frame.isEmpty() || frame.pixels.size() < n * std::size_t(bytesPerPixel(frame.format)))
        return out;
    out.width = frame.width;
    out.height = frame.height;
    out.channels = frame.format == PixelFormat::Rgb8 ? 3 : 1;
    out.stretch = options.autoContrast ? percentileStretch(frame, options.lowPercent, options.highPercent)
                                       : Stretch{0, double(maxLevel(frame))};
    const double black = out.stretch.black;
    const double scale = 255.0 / (out.stretch.white - black);
    // One table from level to byte: a 16-bit frame is then one lookup a pixel.
    std::vector<std::uint8_t> lut(std::size_t(frame.format == PixelFormat::Grey16 ? 65536 : 256));
    for (std::size_t level = 0; level < lut.size(); ++level)
        lut[level] = std::uint8_t(std::clamp(std::lround((double(level) - black) * scale), 0L, 255L));
    out.pixels.resize(n * std::size_t(out.channels));
    if (frame.format == PixelFormat::Grey16) {
        for (std::size_t i = 0; i < n; ++i)
            out.pixels[i] = lut[levelAt(frame, i)];
    } else {
        for (std::size_t i = 0; i < out.pixels.size(); ++i)
            out.pixels[i] = lut[frame.pixels[i]];
    }
    return out;
}

} // namespace dev::camera
