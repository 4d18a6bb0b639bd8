#include "imaging/dot_finder.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace imaging {
namespace {

using motion::msg::Checked;

constexpr int kMinDotImagePx = 16;

double medianOfSamples(std::vector<float> v)
{
    if (v.empty())
        return 0;
    const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
    std::nth_element(v.begin(), mid, v.end());
    return *mid;
}

template <class T>
ImageF binned(const Plane<T>& im, int bin)
{
    const int bw = im.width / bin, bh = im.height / bin;
    ImageF out(bw, bh, 0.0f);
    const float norm = 1.0f / static_cast<float>(bin * bin);
    // Rows summed first (vectorised, in memory order), then their columns in groups.
    std::vector<float> acc(static_cast<std::size_t>(bw * bin));
    for (int by = 0; by < bh; ++by) {
        std::fill(acc.begin(), acc.end(), 0.0f);
        for (int k = 0; k < bin; ++k) {
            const T* row = im.row(by * bin + k);
            for (std::size_t x = 0; x < acc.size(); ++x)
                acc[x] += static_cast<float>(row[x]);
        }
        float* o = out.row(by);
        for (int bx = 0; bx < bw; ++bx) {
            float v = 0;
            for (int j = 0; j < bin; ++j)
                v += acc[static_cast<std::size_t>(bx * bin + j)];
            o[bx] = v * norm;
        }
    }
    return out;
}

struct Region {
    double sum = 0, sx = 0, sy = 0;  // binned pixels, weighted by depth
    int area = 0;
    bool touchesEdge = false;
};

std::vector<Region> regionsAbove(const ImageF& b, double bg, double sign, double threshold)
{
    std::vector<Region> out;
    std::vector<std::uint8_t> seen(b.px.size(), 0);
    std::vector<int> stack;
    for (int y = 0; y < b.height; ++y) {
        for (int x = 0; x < b.width; ++x) {
            const std::size_t i0 = static_cast<std::size_t>(y) * static_cast<std::size_t>(b.width) + static_cast<std::size_t>(x);
            if (seen[i0] || sign * (b.px[i0] - bg) < threshold)
                continue;
            Region r;
            seen[i0] = 1;
            stack.assign(1, static_cast<int>(i0));
            while (!stack.empty()) {
                const int i = stack.back();
                stack.pop_back();
                const int px = i % b.width, py = i / b.width;
                const double w = sign * (b.px[static_cast<std::size_t>(i)] - bg);
                r.sum += w;
                r.sx += w * px;
                r.sy += w * py;
                ++r.area;
                if (px == 0 || py == 0 || px == b.width - 1 || py == b.height - 1)
                    r.touchesEdge = true;
                const int nx[4] = {px - 1, px + 1, px, px};
                const int ny[4] = {py, py, py - 1, py + 1};
                for (int k = 0; k < 4; ++k) {
                    if (nx[k] < 0 || ny[k] < 0 || nx[k] >= b.width || ny[k] >= b.height)
                        continue;
                    const std::size_t j = static_cast<std::size_t>(ny[k]) * static_cast<std::size_t>(b.width) + static_cast<std::size_t>(nx[k]);
                    if (!seen[j] && sign * (b.px[j] - bg) >= threshold) {
                        seen[j] = 1;
                        stack.push_back(static_cast<int>(j));
                    }
                }
            }
            out.push_back(r);
        }
    }
    return out;
}

struct RefinedDot {
    enum { Ok, AtEdge, Lost } status = Ok;
    double x = 0, y = 0, mass = 0, depth = 0, background = 0;
};

// Centroid of the depth below (or height above) the background, as a share of it, in
// a window around (x, y): the background is a quadratic surface fitted to the window's
// two-pixel border; the window is re-centred on each answer until it stops moving.
template <class T>
RefinedDot refineDot(const Plane<T>& im, double x, double y, double radiusPx, double sign)
{
    const int half = static_cast<int>(std::ceil(radiusPx + std::max(4.0, 0.5 * radiusPx) + 2));
    RefinedDot r;
    r.x = x;
    r.y = y;
    for (int iter = 0; iter < 12; ++iter) {
        const int cx = static_cast<int>(std::lround(r.x)), cy = static_cast<int>(std::lround(r.y));
        const int x0 = cx - half, x1 = cx + half, y0 = cy - half, y1 = cy + half;
        if (x0 < 0 || y0 < 0 || x1 >= im.width || y1 >= im.height) {
            r.status = RefinedDot::AtEdge;
            return r;
        }
        // The background: a quadratic surface through the border (vignetting is
        // curved; a plane would pull the centre towards the image's middle).
        const double sc = 1.0 / half;
        const auto basis = [&](int xx, int yy) {
            const double u = (xx - cx) * sc, v = (yy - cy) * sc;
            Eigen::Matrix<double, 6, 1> a;
            a << 1, u, v, u * u, u * v, v * v;
            return a;
        };
        Eigen::Matrix<double, 6, 6> n = Eigen::Matrix<double, 6, 6>::Zero();
        Eigen::Matrix<double, 6, 1> rhs = Eigen::Matrix<double, 6, 1>::Zero();
        for (int yy = y0; yy <= y1; ++yy) {
            const bool rowBorder = yy < y0 + 2 || yy > y1 - 2;
            const T* row = im.row(yy);
            for (int xx = x0; xx <= x1; ++xx) {
                if (!rowBorder && xx >= x0 + 2 && xx <= x1 - 2)
                    continue;
                const Eigen::Matrix<double, 6, 1> a = basis(xx, yy);
                n.noalias() += a * a.transpose();
                rhs += a * static_cast<double>(row[xx]);
            }
        }
        const Eigen::Matrix<double, 6, 1> bgq = n.ldlt().solve(rhs);
        // Weights relative to the background, so a dot dimmed on one side by vignetting
        // weighs the same all over.
        double sum = 0, sx = 0, sy = 0;
        for (int yy = y0; yy <= y1; ++yy) {
            const T* row = im.row(yy);
            const double v = (yy - cy) * sc;
            const double c0 = bgq(0) + bgq(2) * v + bgq(5) * v * v, c1 = bgq(1) + bgq(4) * v;
            for (int xx = x0; xx <= x1; ++xx) {
                const double u = (xx - cx) * sc;
                const double base = c0 + c1 * u + bgq(3) * u * u;
                const double w = sign * (static_cast<double>(row[xx]) - base) / std::max(std::abs(base), 1e-9);
                sum += w;
                sx += w * xx;
                sy += w * yy;
            }
        }
        if (!(sum > 0)) {
            // Nothing darker (or brighter) than the background in the window: noise
            // that passed the coarse search, not a dot.
            r.status = RefinedDot::Lost;
            return r;
        }
        const double nx = sx / sum, ny = sy / sum;
        const double moved = std::hypot(nx - r.x, ny - r.y);
        r.x = nx;
        r.y = ny;
        r.mass = sum;
        r.background = bgq(0);
        if (moved < 1e-4 && iter > 0)
            break;
    }
    // The depth at the centre, on a 3 × 3 mean, for the contrast and the diameter.
    const int cx = static_cast<int>(std::lround(r.x)), cy = static_cast<int>(std::lround(r.y));
    double d = 0;
    for (int yy = cy - 1; yy <= cy + 1; ++yy)
        for (int xx = cx - 1; xx <= cx + 1; ++xx)
            d += sign * (static_cast<double>(im.at(xx, yy)) - r.background);
    r.depth = d / 9 / std::max(std::abs(r.background), 1e-9);  // as a share of the background
    return r;
}

template <class T>
Checked<FoundDot> findDotIn(const Plane<T>& im, const DotFinderOptions& o)
{
    if (im.width < kMinDotImagePx || im.height < kMinDotImagePx) {
        return Checked<FoundDot>::fail(motion::msg::make("imaging.dot.image_too_small", {motion::msg::integer("width", im.width), motion::msg::integer("height", im.height),
                                                                                         motion::msg::integer("minimum", kMinDotImagePx)}));
    }
    const int bin = std::min(im.width, im.height) >= 512 ? 4 : (std::min(im.width, im.height) >= 64 ? 2 : 1);
    const ImageF b = binned(im, bin);
    // Background and noise from a sample of the binned image (a quarter-million
    // samples would cost more than the rest of the search).
    const std::size_t stride = std::max<std::size_t>(1, b.px.size() / 40000);
    std::vector<float> sample, diffs;
    for (std::size_t i = 0; i + 1 < b.px.size(); i += stride) {
        sample.push_back(b.px[i]);
        if ((i + 1) % static_cast<std::size_t>(b.width) != 0)
            diffs.push_back(std::abs(b.px[i + 1] - b.px[i]));
    }
    const double bg = medianOfSamples(std::move(sample));
    const double noise = 1.4826 * medianOfSamples(std::move(diffs)) / std::sqrt(2.0);
    const double scale = std::max(std::abs(bg), 1e-12);
    const double floor = std::max(o.minContrast * scale, o.minSnr * noise);

    double darkPeak = 0, brightPeak = 0;
    for (float v : b.px) {
        darkPeak = std::max(darkPeak, bg - v);
        brightPeak = std::max(brightPeak, v - bg);
    }
    double sign = -1;
    if (o.polarity == Polarity::Bright || (o.polarity == Polarity::Either && brightPeak > darkPeak))
        sign = 1;
    const double peak = sign < 0 ? darkPeak : brightPeak;
    const auto notFound = [&](double contrast) {
        return Checked<FoundDot>::fail(motion::msg::make("imaging.dot.not_found", {motion::msg::real("contrast", 100 * contrast, motion::msg::Unit::Percent),
                                                                                   motion::msg::real("minimum", 100 * o.minContrast, motion::msg::Unit::Percent)}));
    };
    if (peak < floor)
        return notFound(peak / scale);

    std::vector<Region> regions = regionsAbove(b, bg, sign, std::max(0.5 * floor, 0.5 * peak));
    regions.erase(std::remove_if(regions.begin(), regions.end(), [&](const Region& r) { return r.area < o.minBinnedArea; }), regions.end());
    if (regions.empty())
        return notFound(peak / scale);

    const double cx = 0.5 * (im.width - 1), cy = 0.5 * (im.height - 1);
    const double off = 0.5 * (bin - 1);
    const auto fullX = [&](const Region& r) { return r.sx / r.sum * bin + off; };
    const auto fullY = [&](const Region& r) { return r.sy / r.sum * bin + off; };
    const auto dist = [&](const Region& r) { return std::hypot(fullX(r) - cx, fullY(r) - cy); };
    std::sort(regions.begin(), regions.end(), [&](const Region& a, const Region& c) { return dist(a) < dist(c); });

    struct Measured {
        RefinedDot dot;
        double distance;
        bool cutByFrame;
    };
    std::vector<Measured> dots;
    for (const Region& r : regions) {
        // Another dot is measured only when its coarse centre (within a binned pixel
        // or two) could make it as near as the nearest one.
        if (!dots.empty() && dist(r) > dots[0].distance + o.ambiguousPx + 2 * bin + 2)
            break;
        const double radius = std::sqrt(r.area * bin * bin / M_PI);
        RefinedDot d = refineDot(im, fullX(r), fullY(r), radius, sign);
        if (d.status == RefinedDot::Lost)
            continue;
        const bool cut = r.touchesEdge || d.status == RefinedDot::AtEdge;
        dots.push_back({d, std::hypot(d.x - cx, d.y - cy), cut});
        std::sort(dots.begin(), dots.end(), [](const Measured& a, const Measured& c) { return a.distance < c.distance; });
    }
    if (dots.empty())
        return notFound(peak / scale);
    const Measured& m = dots[0];
    if (dots.size() >= 2 && dots[1].distance - m.distance < o.ambiguousPx) {
        return Checked<FoundDot>::fail(motion::msg::make("imaging.dot.ambiguous", {motion::msg::real("first", m.distance), motion::msg::real("second", dots[1].distance)}));
    }
    if (m.cutByFrame)
        return Checked<FoundDot>::fail(motion::msg::make("imaging.dot.at_edge", {motion::msg::real("x", m.dot.x - cx), motion::msg::real("y", m.dot.y - cy)}));
    FoundDot out;
    out.xPx = m.dot.x - cx;
    out.yPx = m.dot.y - cy;
    out.contrast = m.dot.depth;
    out.diameterPx = m.dot.depth > 0 ? 2 * std::sqrt(m.dot.mass / (m.dot.depth * M_PI)) : 0;
    out.dark = sign < 0;
    return Checked<FoundDot>::ok(out);
}

} // namespace

Checked<FoundDot> findDot(const ImageF& image, const DotFinderOptions& options) { return findDotIn(image, options); }
Checked<FoundDot> findDot(const ImageU16& image, const DotFinderOptions& options) { return findDotIn(image, options); }

} // namespace imaging
