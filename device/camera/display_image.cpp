#include "device/camera/display_image.h"

#include <algorithm>
#include <cstring>
#include <vector>

namespace dev::camera {

namespace {
/// The share of pixels clipped at each end by the stretch.
constexpr double kClipShare = 0.001;
/// Every k-th pixel feeds the histogram: plenty for percentiles, and a quarter of the reads.
constexpr std::size_t kHistogramStride = 4;

inline int rawAt(const Frame& f, std::size_t i)
{
    if (f.format == PixelFormat::Grey16) {
        std::uint16_t v;
        std::memcpy(&v, f.pixels.data() + 2 * i, 2);
        return v;
    }
    return f.pixels[i];
}
} // namespace

QImage toDisplayImage(const Frame& f, bool autoContrast, DisplayStretch* used)
{
    if (f.isEmpty())
        return {};
    const std::size_t n = static_cast<std::size_t>(f.width) * static_cast<std::size_t>(f.height);
    if (f.format == PixelFormat::Rgb8) {
        QImage img(f.width, f.height, QImage::Format_RGB888);
        for (int y = 0; y < f.height; ++y)
            std::memcpy(img.scanLine(y), f.pixels.data() + static_cast<std::size_t>(y) * static_cast<std::size_t>(f.width) * 3,
                        static_cast<std::size_t>(f.width) * 3);
        if (used)
            *used = {0, 255};
        return img;
    }
    const int levels = f.format == PixelFormat::Grey16 ? 65536 : 256;
    int lo = 0, hi = f.format == PixelFormat::Grey16 ? (1 << std::clamp(f.bitDepth, 1, 16)) - 1 : 255;
    if (autoContrast) {
        std::vector<std::uint32_t> hist(static_cast<std::size_t>(levels), 0);
        std::size_t counted = 0;
        for (std::size_t i = 0; i < n; i += kHistogramStride, ++counted)
            ++hist[static_cast<std::size_t>(rawAt(f, i))];
        const auto clip = static_cast<std::size_t>(static_cast<double>(counted) * kClipShare);
        std::size_t acc = 0;
        for (lo = 0; lo < levels - 1 && (acc += hist[static_cast<std::size_t>(lo)]) <= clip; ++lo) {}
        acc = 0;
        for (hi = levels - 1; hi > 0 && (acc += hist[static_cast<std::size_t>(hi)]) <= clip; --hi) {}
        if (hi <= lo)
            hi = std::min(levels - 1, lo + 1);
    }
    if (used)
        *used = {lo, hi};
    std::vector<std::uint8_t> lut(static_cast<std::size_t>(levels));
    for (int v = 0; v < levels; ++v)
        lut[static_cast<std::size_t>(v)] = static_cast<std::uint8_t>(std::clamp((v - lo) * 255 / std::max(1, hi - lo), 0, 255));
    QImage img(f.width, f.height, QImage::Format_Grayscale8);
    for (int y = 0; y < f.height; ++y) {
        std::uint8_t* out = img.scanLine(y);
        const std::size_t base = static_cast<std::size_t>(y) * static_cast<std::size_t>(f.width);
        if (f.format == PixelFormat::Grey16) {
            const std::uint8_t* in = f.pixels.data() + 2 * base;
            for (int x = 0; x < f.width; ++x) {
                std::uint16_t v;
                std::memcpy(&v, in + 2 * x, 2);
                out[x] = lut[v];
            }
        } else {
            for (int x = 0; x < f.width; ++x)
                out[x] = lut[f.pixels[base + static_cast<std::size_t>(x)]];
        }
    }
    return img;
}

} // namespace dev::camera
