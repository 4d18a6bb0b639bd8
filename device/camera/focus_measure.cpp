#include "device/camera/focus_measure.h"

#include <algorithm>
#include <cstring>
#include <vector>

namespace dev::camera {

double focusMeasure(const Frame& frame, int maxSidePx)
{
    const std::size_t n = std::size_t(std::max(0, frame.width)) * std::size_t(std::max(0, frame.height));
    if (frame.isEmpty() || frame.pixels.size() < n * std::size_t(bytesPerPixel(frame.format)))
        return 0;
    // Block-average down: noise is averaged away and the cost stays small on a big sensor.
    const int block = std::max(1, (std::max(frame.width, frame.height) + std::max(1, maxSidePx) - 1) / std::max(1, maxSidePx));
    const int w = frame.width / block, h = frame.height / block;
    if (w < 3 || h < 3)
        return 0;
    const double full = frame.format == PixelFormat::Grey16 ? double((1u << std::clamp(frame.bitDepth, 1, 16)) - 1) : 255.0;
    std::vector<double> small(std::size_t(w) * std::size_t(h), 0.0);
    for (int y = 0; y < h * block; ++y) {
        double* row = &small[std::size_t(y / block) * std::size_t(w)];
        for (int x = 0; x < w * block; ++x) {
            const std::size_t i = std::size_t(y) * std::size_t(frame.width) + std::size_t(x);
            double v;
            switch (frame.format) {
            case PixelFormat::Grey8: v = frame.pixels[i]; break;
            case PixelFormat::Grey16: {
                std::uint16_t u;
                std::memcpy(&u, &frame.pixels[2 * i], 2);
                v = u;
                break;
            }
            case PixelFormat::Rgb8:
            default: v = (double(frame.pixels[3 * i]) + frame.pixels[3 * i + 1] + frame.pixels[3 * i + 2]) / 3.0; break;
            }
            row[x / block] += v;
        }
    }
    const double norm = 1.0 / (double(block) * double(block) * full);
    for (double& v : small)
        v *= norm;
    double sum = 0, sumSq = 0;
    std::size_t count = 0;
    for (int y = 1; y + 1 < h; ++y)
        for (int x = 1; x + 1 < w; ++x) {
            const std::size_t i = std::size_t(y) * std::size_t(w) + std::size_t(x);
            const double lap = small[i - 1] + small[i + 1] + small[i - std::size_t(w)] + small[i + std::size_t(w)] - 4 * small[i];
            sum += lap;
            sumSq += lap * lap;
            ++count;
        }
    const double mean = sum / double(count);
    return std::max(0.0, sumSq / double(count) - mean * mean);
}

} // namespace dev::camera
