#pragma once
// Synthetic graduation lines and dots for the finder tests: chrome marks on glass,
// each pixel the mean of the blurred mark over its area, with sensor-like noise.
#include "imaging/image.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace imagingtest {

constexpr double kGlass = 20000;  // counts through bare glass
constexpr double kChrome = 1300;  // counts through chrome

/// The mean over [x − 0.5, x + 0.5] of a box of width `widthPx` at `centre`, blurred
/// by a Gaussian of σ `blurPx`: 1 on the mark, 0 beside it.
inline double boxCover(double x, double centre, double widthPx, double blurPx)
{
    double acc = 0;
    const int sub = 16;
    for (int k = 0; k < sub; ++k) {
        const double u = x - 0.5 + (k + 0.5) / sub - centre;
        const double s = std::sqrt(2.0) * std::max(blurPx, 1e-6);
        acc += 0.5 * (std::erf((u + widthPx / 2) / s) - std::erf((u - widthPx / 2) / s));
    }
    return acc / sub;
}

struct LineMark {
    double at;          // px: x of a vertical line, y of a horizontal one
    double widthPx = 4;
};

/// Lines across a w × h image; `vertical` lines run down the image. A slow gradient
/// of 3 % across the field stands for vignetting.
inline imaging::ImageU16 renderLines(int w, int h, bool vertical, const std::vector<LineMark>& lines, double blurPx, double noiseSigma,
                                     unsigned seed, bool bright = false)
{
    const int n = vertical ? w : h;
    std::vector<double> cover(static_cast<std::size_t>(n), 0.0);
    for (int i = 0; i < n; ++i)
        for (const LineMark& l : lines)
            cover[static_cast<std::size_t>(i)] = std::min(1.0, cover[static_cast<std::size_t>(i)] + boxCover(i, l.at, l.widthPx, blurPx));
    std::mt19937 rng(seed);
    std::normal_distribution<double> noise(0, noiseSigma);
    imaging::ImageU16 im(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const double c = cover[static_cast<std::size_t>(vertical ? x : y)];
            const double glass = kGlass * (1 - 0.03 * x / w);
            const double v = bright ? kChrome + c * (glass - kChrome) : glass - c * (glass - kChrome);
            im.at(x, y) = static_cast<std::uint16_t>(std::clamp(std::lround(v + noise(rng)), 0L, 65535L));
        }
    return im;
}

struct DotMark {
    double x, y;         // px
    double radiusPx = 10;
};

/// Round chrome dots on glass, each pixel the mean of 4 × 4 samples of the blurred disc
/// (an erfc edge: exact for a straight edge, symmetric about the centre either way).
inline imaging::ImageU16 renderDots(int w, int h, const std::vector<DotMark>& dots, double blurPx, double noiseSigma, unsigned seed)
{
    std::mt19937 rng(seed);
    std::normal_distribution<double> noise(0, noiseSigma);
    imaging::ImageU16 im(w, h);
    const double s = std::sqrt(2.0) * std::max(blurPx, 1e-6);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            double c = 0;
            for (const DotMark& d : dots) {
                if (std::hypot(x - d.x, y - d.y) > d.radiusPx + 6 * blurPx + 2)
                    continue;
                double acc = 0;
                for (int j = 0; j < 4; ++j)
                    for (int i = 0; i < 4; ++i) {
                        const double r = std::hypot(x - 0.5 + (i + 0.5) / 4 - d.x, y - 0.5 + (j + 0.5) / 4 - d.y);
                        acc += 0.5 * std::erfc((r - d.radiusPx) / s);
                    }
                c = std::min(1.0, c + acc / 16);
            }
            const double glass = kGlass * (1 - 0.03 * y / h);
            const double v = glass - c * (glass - kChrome);
            im.at(x, y) = static_cast<std::uint16_t>(std::clamp(std::lround(v + noise(rng)), 0L, 65535L));
        }
    return im;
}

/// `im` out of focus: blurred by a Gaussian of σ `blurPx` (separable, edges repeated),
/// then noise of σ `noiseSigma` added. The erfc edge of renderDots is only right for a
/// blur much smaller than the dot; this is right for any.
inline imaging::ImageU16 defocus(const imaging::ImageU16& im, double blurPx, double noiseSigma, unsigned seed)
{
    const int r = static_cast<int>(std::ceil(4 * blurPx));
    std::vector<double> k(static_cast<std::size_t>(2 * r + 1));
    double sum = 0;
    for (int i = -r; i <= r; ++i)
        sum += k[static_cast<std::size_t>(i + r)] = std::exp(-0.5 * i * i / (blurPx * blurPx));
    for (double& v : k)
        v /= sum;
    const int w = im.width, h = im.height;
    std::vector<double> a(im.px.begin(), im.px.end()), b(a.size());
    const auto idx = [w](int x, int y) { return static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x); };
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            double acc = 0;
            for (int i = -r; i <= r; ++i)
                acc += k[static_cast<std::size_t>(i + r)] * a[idx(std::clamp(x + i, 0, w - 1), y)];
            b[idx(x, y)] = acc;
        }
    std::mt19937 rng(seed);
    std::normal_distribution<double> noise(0, noiseSigma);
    imaging::ImageU16 out(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            double acc = 0;
            for (int i = -r; i <= r; ++i)
                acc += k[static_cast<std::size_t>(i + r)] * b[idx(x, std::clamp(y + i, 0, h - 1))];
            out.at(x, y) = static_cast<std::uint16_t>(std::clamp(std::lround(acc + noise(rng)), 0L, 65535L));
        }
    return out;
}

} // namespace imagingtest
