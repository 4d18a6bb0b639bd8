#pragma once
// Synthetic tiles for the imaging tests: a procedural texture defined everywhere in
// the plane (a seeded sum of sinusoids over several scales, plus Gaussian blobs
// like cells), so a tile cut at any subpixel position is exact, and shot-like noise.
#include "imaging/image.h"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

namespace imagingtest {

class Texture {
public:
    explicit Texture(unsigned seed, int waves = 32, int blobs = 150, double extentPx = 3000)
    {
        std::mt19937 rng(seed);
        std::uniform_real_distribution<double> u(0, 1);
        for (int i = 0; i < waves; ++i) {
            // Periods from ~6 px to ~200 px, amplitude falling with frequency (blurred texture).
            const double period = 6 * std::pow(35.0, u(rng));
            const double angle = 2 * M_PI * u(rng);
            m_waves.push_back({std::cos(angle) / period, std::sin(angle) / period, 2 * M_PI * u(rng), std::sqrt(period) * 8});
        }
        for (int i = 0; i < blobs; ++i)
            m_blobs.push_back({u(rng) * extentPx - 100, u(rng) * extentPx - 100, 3 + 10 * u(rng), 1500 * u(rng)});
    }
    double operator()(double x, double y) const
    {
        double v = 20000;
        for (const Wave& w : m_waves)
            v += w.amp * std::sin(2 * M_PI * (w.fx * x + w.fy * y) + w.phase);
        for (const Blob& b : m_blobs) {
            const double dx = x - b.x, dy = y - b.y;
            const double r2 = dx * dx + dy * dy;
            if (r2 < 16 * b.r * b.r)
                v += b.amp * std::exp(-r2 / (2 * b.r * b.r));
        }
        return v;
    }

private:
    struct Wave {
        double fx, fy, phase, amp;
    };
    struct Blob {
        double x, y, r, amp;
    };
    std::vector<Wave> m_waves;
    std::vector<Blob> m_blobs;
};

/// A w × h tile whose top-left sits at (x0, y0) in the texture, with Gaussian noise of `noise` grey levels.
inline imaging::ImageU16 cutTile(const Texture& t, double x0, double y0, int w, int h, double noise, unsigned seed)
{
    std::mt19937 rng(seed);
    std::normal_distribution<double> n(0, noise);
    imaging::ImageU16 out(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            out.at(x, y) = static_cast<std::uint16_t>(std::clamp(t(x0 + x, y0 + y) + n(rng), 0.0, 65535.0));
    return out;
}

/// A tile of noise only around a constant level: bare glass, an empty field.
inline imaging::ImageU16 blankTile(int w, int h, double level, double noise, unsigned seed)
{
    std::mt19937 rng(seed);
    std::normal_distribution<double> n(0, noise);
    imaging::ImageU16 out(w, h);
    for (auto& v : out.px)
        v = static_cast<std::uint16_t>(std::clamp(level + n(rng), 0.0, 65535.0));
    return out;
}

} // namespace imagingtest
