#include "device/camera/sim_render.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <random>

namespace dev::camera {

namespace {

constexpr int kGaussBits = 12;  ///< 4096 pre-drawn normal deviates

const std::array<float, 1u << kGaussBits>& gaussTable()
{
    // Deterministic and built once (C++11 magic static: thread-safe). Drawn by inverting
    // the normal CDF at the bin centres, so the table is exactly N(0, 1)'s quantiles.
    static const std::array<float, 1u << kGaussBits> table = [] {
        std::array<float, 1u << kGaussBits> t{};
        for (std::size_t i = 0; i < t.size(); ++i) {
            const double p = (static_cast<double>(i) + 0.5) / static_cast<double>(t.size());
            // Bisection on erfc: once, 4096 entries, exact enough for noise.
            double lo = -8, hi = 8;
            for (int it = 0; it < 60; ++it) {
                const double mid = (lo + hi) / 2;
                (0.5 * std::erfc(-mid / std::sqrt(2.0)) < p ? lo : hi) = mid;
            }
            t[i] = static_cast<float>((lo + hi) / 2);
        }
        return t;
    }();
    return table;
}

inline std::uint64_t mix(std::uint64_t z)
{
    z += 0x9E3779B97F4A7C15ull;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

} // namespace

Frame renderSimFrame(const Specimen& specimen, const CameraGeometry& g, const SimOptics& optics, double xMm, double yMm,
                     double exposureMs, std::uint64_t seed)
{
    Frame f;
    f.width = std::max(1, g.sensorWidthPx);
    f.height = std::max(1, g.sensorHeightPx);
    const bool eight = optics.bitDepth <= 8;
    f.format = eight ? PixelFormat::Grey8 : PixelFormat::Grey16;
    f.bitDepth = eight ? 8 : 16;
    f.exposureMs = exposureMs;
    f.pixelUm = g.pixelUm;
    f.pixels.resize(static_cast<std::size_t>(f.width) * static_cast<std::size_t>(f.height) * (eight ? 1u : 2u));

    double exX, exY, eyX, eyY;
    g.axes(&exX, &exY, &eyX, &eyY);
    const double cx = (f.width - 1) / 2.0, cy = (f.height - 1) / 2.0;
    // Vignetting as the product of a row and a column falloff: 1 − v/2 at each edge,
    // about 1 − v in the corners, and one multiply a pixel.
    std::vector<float> vx(static_cast<std::size_t>(f.width)), vy(static_cast<std::size_t>(f.height));
    for (int i = 0; i < f.width; ++i)
        vx[static_cast<std::size_t>(i)] = static_cast<float>(1 - optics.vignetting / 2 * std::pow((i - cx) / std::max(1.0, cx), 2));
    for (int j = 0; j < f.height; ++j)
        vy[static_cast<std::size_t>(j)] = static_cast<float>(1 - optics.vignetting / 2 * std::pow((j - cy) / std::max(1.0, cy), 2));

    const double maxDn = eight ? 255.0 : 65535.0;
    const auto electrons = static_cast<float>(std::max(0.0, optics.fluxEPerMs * exposureMs));
    const auto fullWell = static_cast<float>(optics.fullWellE);
    const auto dnPerE = static_cast<float>(maxDn / optics.fullWellE);
    const float read2 = static_cast<float>(optics.readNoiseE * optics.readNoiseE);
    const auto top = static_cast<float>(maxDn);
    // The noise's seed: the camera's seed, the work point to the nanometre and the exposure
    // to the microsecond, so the same shot gives the same image and another shot another.
    const std::uint64_t frameSeed = mix(seed ^ mix(static_cast<std::uint64_t>(std::llround(xMm * 1e6)))
                                        ^ mix(static_cast<std::uint64_t>(std::llround(yMm * 1e6)) + 7)
                                        ^ mix(static_cast<std::uint64_t>(std::llround(exposureMs * 1e3)) + 13));
    const auto& gauss = gaussTable();
    std::vector<float> row(static_cast<std::size_t>(f.width));
    for (int j = 0; j < f.height; ++j) {
        const double x0 = xMm + (0 - cx) * exX + (j - cy) * eyX;
        const double y0 = yMm + (0 - cx) * exY + (j - cy) * eyY;
        specimen.sampleRow(row.data(), f.width, x0, y0, exX, exY);
        std::uint64_t state = mix(frameSeed + static_cast<std::uint64_t>(j)) | 1u;
        const float rowGain = electrons * vy[static_cast<std::size_t>(j)];
        std::uint8_t* out8 = f.pixels.data() + static_cast<std::size_t>(j) * static_cast<std::size_t>(f.width) * (eight ? 1u : 2u);
        for (int i = 0; i < f.width; ++i) {
            // xorshift64, one step for every four pixels, each taking 12 of its top 48 bits:
            // a step a pixel made its three dependent shifts the frame's critical path.
            if ((i & 3) == 0) {
                state ^= state << 13;
                state ^= state >> 7;
                state ^= state << 17;
            }
            const auto pick = static_cast<std::size_t>((state >> (64 - kGaussBits * (1 + (i & 3)))) & ((1u << kGaussBits) - 1));
            const float e = std::min(fullWell, row[static_cast<std::size_t>(i)] * rowGain * vx[static_cast<std::size_t>(i)]);
            const float noisy = e + std::sqrt(e + read2) * gauss[pick];
            const float dn = std::clamp(noisy * dnPerE + 0.5f, 0.0f, top);
            if (eight) {
                out8[i] = static_cast<std::uint8_t>(dn);
            } else {
                const auto v = static_cast<std::uint16_t>(dn);
                std::memcpy(out8 + 2 * i, &v, 2);
            }
        }
    }
    return f;
}

} // namespace dev::camera
