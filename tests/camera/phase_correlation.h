#pragma once
// A plain phase correlation for the camera tests: how far image B is shifted against
// image A (B(x) ≈ A(x + t)), from the peak of the normalised cross-power spectrum, with
// the wrap-around ambiguity settled by the normalised cross-correlation of the overlap.
// Power-of-two sizes only; a naive radix-2 FFT is plenty for test images.
#include "device/camera/frame.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstring>
#include <vector>

namespace camtest {

using Cx = std::complex<double>;

inline void fft1(std::vector<Cx>& a, bool inverse)
{
    const std::size_t n = a.size();
    for (std::size_t i = 1, j = 0; i < n; ++i) {
        std::size_t bit = n >> 1;
        for (; j & bit; bit >>= 1)
            j ^= bit;
        j ^= bit;
        if (i < j)
            std::swap(a[i], a[j]);
    }
    for (std::size_t len = 2; len <= n; len <<= 1) {
        const double ang = 2 * M_PI / static_cast<double>(len) * (inverse ? 1 : -1);
        const Cx wl(std::cos(ang), std::sin(ang));
        for (std::size_t i = 0; i < n; i += len) {
            Cx w(1);
            for (std::size_t k = 0; k < len / 2; ++k) {
                const Cx u = a[i + k], v = a[i + k + len / 2] * w;
                a[i + k] = u + v;
                a[i + k + len / 2] = u - v;
                w *= wl;
            }
        }
    }
}

inline void fft2(std::vector<Cx>& a, int w, int h, bool inverse)
{
    std::vector<Cx> line;
    for (int y = 0; y < h; ++y) {
        line.assign(a.begin() + static_cast<std::ptrdiff_t>(y) * w, a.begin() + static_cast<std::ptrdiff_t>(y + 1) * w);
        fft1(line, inverse);
        std::copy(line.begin(), line.end(), a.begin() + static_cast<std::ptrdiff_t>(y) * w);
    }
    line.resize(static_cast<std::size_t>(h));
    for (int x = 0; x < w; ++x) {
        for (int y = 0; y < h; ++y)
            line[static_cast<std::size_t>(y)] = a[static_cast<std::size_t>(y) * w + x];
        fft1(line, inverse);
        for (int y = 0; y < h; ++y)
            a[static_cast<std::size_t>(y) * w + x] = line[static_cast<std::size_t>(y)];
    }
}

/// The frame's grey values less their local mean (a box 2r+1 wide): what the vignetting
/// and the slow changes of brightness share between every pair of images (and would make
/// a peak at no shift at all) is taken out; the texture that registers is kept.
inline std::vector<double> grey(const dev::camera::Frame& f, int r = 8)
{
    const int w = f.width, h = f.height;
    std::vector<double> out(static_cast<std::size_t>(w) * h);
    for (std::size_t i = 0; i < out.size(); ++i) {
        if (f.format == dev::camera::PixelFormat::Grey16) {
            std::uint16_t v;
            std::memcpy(&v, f.pixels.data() + 2 * i, 2);
            out[i] = v;
        } else {
            out[i] = f.pixels[i];
        }
    }
    std::vector<double> sum(static_cast<std::size_t>(w + 1) * (h + 1), 0.0);  // integral image
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            sum[static_cast<std::size_t>(y + 1) * (w + 1) + x + 1] = out[static_cast<std::size_t>(y) * w + x]
                + sum[static_cast<std::size_t>(y) * (w + 1) + x + 1] + sum[static_cast<std::size_t>(y + 1) * (w + 1) + x]
                - sum[static_cast<std::size_t>(y) * (w + 1) + x];
    std::vector<double> hp(out.size());
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const int x0 = std::max(0, x - r), x1 = std::min(w, x + r + 1), y0 = std::max(0, y - r), y1 = std::min(h, y + r + 1);
            const double s = sum[static_cast<std::size_t>(y1) * (w + 1) + x1] - sum[static_cast<std::size_t>(y0) * (w + 1) + x1]
                - sum[static_cast<std::size_t>(y1) * (w + 1) + x0] + sum[static_cast<std::size_t>(y0) * (w + 1) + x0];
            hp[static_cast<std::size_t>(y) * w + x] = out[static_cast<std::size_t>(y) * w + x] - s / ((x1 - x0) * (y1 - y0));
        }
    return hp;
}

/// NCC of A(x + tx, y + ty) against B(x, y) over their overlap; −2 when it is under `minShare`.
inline double overlapNcc(const std::vector<double>& a, const std::vector<double>& b, int w, int h, int tx, int ty, double minShare = 0.02)
{
    const int x0 = std::max(0, -tx), x1 = std::min(w, w - tx), y0 = std::max(0, -ty), y1 = std::min(h, h - ty);
    if (x1 <= x0 || y1 <= y0 || (x1 - x0) * (y1 - y0) < minShare * w * h)
        return -2;
    double sa = 0, sb = 0, saa = 0, sbb = 0, sab = 0;
    const double n = static_cast<double>(x1 - x0) * (y1 - y0);
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) {
            const double va = a[static_cast<std::size_t>(y + ty) * w + x + tx], vb = b[static_cast<std::size_t>(y) * w + x];
            sa += va, sb += vb, saa += va * va, sbb += vb * vb, sab += va * vb;
        }
    const double cov = sab - sa * sb / n, va = saa - sa * sa / n, vb = sbb - sb * sb / n;
    return va > 0 && vb > 0 ? cov / std::sqrt(va * vb) : -2;
}

struct Shift {
    double x = 0, y = 0;  ///< sub-pixel: a parabola through the peak and its neighbours
    double ncc = -2;
};

/// The shift t with B(x) ≈ A(x + t).
inline Shift phaseCorrelate(const dev::camera::Frame& fa, const dev::camera::Frame& fb)
{
    const int w = fa.width, h = fa.height;
    const std::vector<double> a = grey(fa), b = grey(fb);
    std::vector<Cx> A(a.begin(), a.end()), B(b.begin(), b.end());
    fft2(A, w, h, false);
    fft2(B, w, h, false);
    // Whitened, then weighted towards the frequencies the optics pass: above them the
    // spectrum is noise alone, and whitening would give it as much say as the texture.
    for (std::size_t i = 0; i < A.size(); ++i) {
        const Cx p = B[i] * std::conj(A[i]);
        const int kx = static_cast<int>(i % static_cast<std::size_t>(w)), ky = static_cast<int>(i / static_cast<std::size_t>(w));
        const double fx = std::min(kx, w - kx) / static_cast<double>(w), fy = std::min(ky, h - ky) / static_cast<double>(h);
        const double weight = std::exp(-(fx * fx + fy * fy) / (0.2 * 0.2));
        A[i] = std::abs(p) > 1e-12 ? p / std::abs(p) * weight : Cx(0);
    }
    A[0] = 0;  // the mean says nothing about the shift
    fft2(A, w, h, true);
    auto at = [&](int x, int y) { return A[static_cast<std::size_t>(((y % h) + h) % h) * w + static_cast<std::size_t>(((x % w) + w) % w)].real(); };
    // The 32 highest peaks (each at least 4 px from a higher one; a 15 % overlap gives a
    // weak one), each tried with its
    // wrap-around readings: the one whose overlap agrees best wins.
    std::vector<std::size_t> order(A.size());
    for (std::size_t i = 0; i < order.size(); ++i)
        order[i] = i;
    std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) { return A[i].real() > A[j].real(); });
    std::vector<std::pair<int, int>> peaks;
    for (std::size_t k = 0; k < order.size() && peaks.size() < 32; ++k) {
        const int px = static_cast<int>(order[k] % static_cast<std::size_t>(w)), py = static_cast<int>(order[k] / static_cast<std::size_t>(w));
        bool near = false;
        for (const auto& [qx, qy] : peaks) {
            const int dx = std::min(std::abs(px - qx), w - std::abs(px - qx)), dy = std::min(std::abs(py - qy), h - std::abs(py - qy));
            near = near || (dx < 4 && dy < 4);
        }
        if (!near)
            peaks.emplace_back(px, py);
    }
    Shift best;
    int bx = 0, by = 0;
    for (const auto& [px, py] : peaks)
        for (int tx : {-px, w - px})
            for (int ty : {-py, h - py}) {
                const double c = overlapNcc(a, b, w, h, tx, ty);
                if (c > best.ncc) {
                    best = {static_cast<double>(tx), static_cast<double>(ty), c};
                    bx = px, by = py;
                }
            }
    auto vertex = [](double m, double c, double p) {
        const double d = m - 2 * c + p;
        return std::fabs(d) > 1e-12 ? 0.5 * (m - p) / d : 0.0;
    };
    // The peak sits at −t: its sub-pixel offset counts the other way.
    best.x -= vertex(at(bx - 1, by), at(bx, by), at(bx + 1, by));
    best.y -= vertex(at(bx, by - 1), at(bx, by), at(bx, by + 1));
    return best;
}

} // namespace camtest
