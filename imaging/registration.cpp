#include "imaging/registration.h"

#include "imaging/fft_plans.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

namespace imaging {
namespace {

constexpr double kPi = 3.14159265358979323846;

struct Rect {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;  ///< half-open
    int w() const { return x1 - x0; }
    int h() const { return y1 - y0; }
};

/// Where b (its top-left at `ox`, `oy` in a) overlaps a, in a's pixels.
Rect overlapIn(const ImageF& a, const ImageF& b, int ox, int oy)
{
    return {std::max(0, ox), std::max(0, oy), std::min(a.width, ox + b.width), std::min(a.height, oy + b.height)};
}

std::vector<float> hann(int n)
{
    std::vector<float> w(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i)
        w[static_cast<std::size_t>(i)] = static_cast<float>(0.5 - 0.5 * std::cos(2 * kPi * (i + 0.5) / n));
    return w;
}

/// Copies a w × h window of `src` at (x0, y0), mean removed and Hann-windowed, into `dst`.
void windowedPatch(const ImageF& src, int x0, int y0, int w, int h, const std::vector<float>& wx, const std::vector<float>& wy,
                   float* dst)
{
    double sum = 0;
    for (int y = 0; y < h; ++y) {
        const float* r = src.row(y0 + y) + x0;
        for (int x = 0; x < w; ++x)
            sum += r[x];
    }
    const float mean = static_cast<float>(sum / (static_cast<double>(w) * h));
    for (int y = 0; y < h; ++y) {
        const float* r = src.row(y0 + y) + x0;
        float* d = dst + static_cast<std::size_t>(y) * static_cast<std::size_t>(w);
        for (int x = 0; x < w; ++x)
            d[x] = (r[x] - mean) * wx[static_cast<std::size_t>(x)] * wy[static_cast<std::size_t>(y)];
    }
}

struct Candidate {
    int dx = 0, dy = 0;  ///< integer shift from the expected offset
    float peak = 0;
    double ncc = -2;
};

/// Keys' cubic convolution kernel (a = −0.5): exact for quadratics, the usual
/// choice for resampling without the bias of bilinear interpolation.
inline void cubicWeights(double t, double w[4])
{
    const double a = -0.5;
    auto k = [a](double x) {
        x = std::abs(x);
        if (x < 1)
            return (a + 2) * x * x * x - (a + 3) * x * x + 1;
        if (x < 2)
            return a * x * x * x - 5 * a * x * x + 8 * a * x - 4 * a;
        return 0.0;
    };
    w[0] = k(1 + t);
    w[1] = k(t);
    w[2] = k(1 - t);
    w[3] = k(2 - t);
}

struct Refined {
    Eigen::Vector2d offset;
    double ncc = -1;
    bool ok = false;
};

// Gauss–Newton on  b(x − t) ≈ α·a(x) + β  over the overlap (inverse-compositional
// form: a's gradients are taken once). Converges in a few steps from an integer start.
Refined refine(const ImageF& a, const ImageF& b, Eigen::Vector2d t)
{
    const Eigen::Vector2d start = t;
    Refined out;
    out.offset = t;
    // The region: a's pixels whose gradient exists and whose b-sample has its
    // 4 × 4 neighbourhood inside b for any t within 2 px of the start.
    const int m = 4;
    const int x0 = std::max(1, static_cast<int>(std::floor(start.x())) + m), x1 = std::min(a.width - 1, static_cast<int>(std::floor(start.x())) + b.width - m);
    const int y0 = std::max(1, static_cast<int>(std::floor(start.y())) + m), y1 = std::min(a.height - 1, static_cast<int>(std::floor(start.y())) + b.height - m);
    if (x1 - x0 < 4 || y1 - y0 < 4)
        return out;
    // At most ~65 000 samples: the error of the mean shift falls as 1/√n, and at this
    // many it is already far below the interpolation's own bias, so more only costs.
    const double area = static_cast<double>(x1 - x0) * (y1 - y0);
    const int step = std::max(1, static_cast<int>(std::floor(std::sqrt(area / 65000.0))));
    std::vector<int> xs, ys;
    for (int y = y0; y < y1; y += step)
        ys.push_back(y);
    for (int x = x0; x < x1; x += step)
        xs.push_back(x);
    const std::size_t n = xs.size() * ys.size();
    std::vector<float> av(n), gx(n), gy(n), bv(n);
    std::size_t i = 0;
    for (int y : ys)
        for (int x : xs) {
            av[i] = a.at(x, y);
            gx[i] = 0.5f * (a.at(x + 1, y) - a.at(x - 1, y));
            gy[i] = 0.5f * (a.at(x, y + 1) - a.at(x, y - 1));
            ++i;
        }
    double amean = 0;
    for (float v : av)
        amean += v;
    amean /= static_cast<double>(n);
    Eigen::Matrix2d H = Eigen::Matrix2d::Zero();
    for (std::size_t k = 0; k < n; ++k) {
        H(0, 0) += double(gx[k]) * gx[k];
        H(0, 1) += double(gx[k]) * gy[k];
        H(1, 1) += double(gy[k]) * gy[k];
    }
    H(1, 0) = H(0, 1);
    if (H.determinant() <= 1e-12 * (H.trace() * H.trace() + 1e-30))
        return out;
    const Eigen::Matrix2d Hinv = H.inverse();

    auto sampleB = [&](const Eigen::Vector2d& off) {
        // b(x − off): split once, since every sample shares the fractional part.
        const double fx = -off.x(), fy = -off.y();
        const int ix = static_cast<int>(std::floor(fx)), iy = static_cast<int>(std::floor(fy));
        double wx[4], wy[4];
        cubicWeights(fx - ix, wx);
        cubicWeights(fy - iy, wy);
        std::size_t k = 0;
        for (int y : ys)
            for (int x : xs) {
                const int bx = x + ix - 1, by = y + iy - 1;
                double s = 0;
                for (int r = 0; r < 4; ++r) {
                    const float* row = b.row(by + r) + bx;
                    s += wy[r] * (wx[0] * row[0] + wx[1] * row[1] + wx[2] * row[2] + wx[3] * row[3]);
                }
                bv[k++] = static_cast<float>(s);
            }
    };
    auto fit = [&](double& alpha, double& beta, double& ncc) {
        double bmean = 0;
        for (float v : bv)
            bmean += v;
        bmean /= static_cast<double>(n);
        double sab = 0, saa = 0, sbb = 0;
        for (std::size_t k = 0; k < n; ++k) {
            const double da = av[k] - amean, db = bv[k] - bmean;
            sab += da * db;
            saa += da * da;
            sbb += db * db;
        }
        alpha = saa > 0 ? sab / saa : 0;
        beta = bmean - alpha * amean;
        ncc = (saa > 0 && sbb > 0) ? sab / std::sqrt(saa * sbb) : 0;
    };
    for (int iter = 0; iter < 12; ++iter) {
        sampleB(t);
        double alpha, beta, ncc;
        fit(alpha, beta, ncc);
        if (alpha <= 1e-9)
            return out;
        Eigen::Vector2d g(0, 0);
        for (std::size_t k = 0; k < n; ++k) {
            const double e = (bv[k] - beta) / alpha - av[k];
            g.x() += gx[k] * e;
            g.y() += gy[k] * e;
        }
        // b(x − t) = a(x − t + t_true) ≈ a(x) + ∇a·(t_true − t): the step is t_true − t.
        const Eigen::Vector2d delta = Hinv * g;
        t += delta;
        if ((t - start).cwiseAbs().maxCoeff() > 2.0)
            return out;  // wandered off: keep the integer answer
        if (delta.norm() < 1e-3)
            break;
    }
    sampleB(t);
    double alpha, beta, ncc;
    fit(alpha, beta, ncc);
    out.offset = t;
    out.ncc = ncc;
    out.ok = true;
    return out;
}

} // namespace

const char* pairStatusName(PairStatus s)
{
    switch (s) {
    case PairStatus::Accepted:
        return "accepted";
    case PairStatus::LowScore:
        return "low_score";
    case PairStatus::Ambiguous:
        return "ambiguous";
    case PairStatus::AtBound:
        return "at_bound";
    case PairStatus::NoOverlap:
        return "no_overlap";
    case PairStatus::Outlier:
        return "outlier";
    }
    return "no_overlap";
}

namespace {

/// NCC over every `rowStep`-th row of the overlap. Sums run in float along a row
/// (vectorised) and in double across rows, which keeps 7 digits on 2048² overlaps.
double sampledNcc(const ImageF& a, const ImageF& b, int ox, int oy, int rowStep)
{
    const Rect r = overlapIn(a, b, ox, oy);
    if (r.w() <= 1 || r.h() <= 1)
        return -1;
    // Centre on a's first overlap sample, so the float sums hold deviations, not levels.
    const float ca = a.at(r.x0, r.y0), cb = b.at(r.x0 - ox, r.y0 - oy);
    double sa = 0, sb = 0, saa = 0, sbb = 0, sab = 0;
    long long n = 0;
    for (int y = r.y0; y < r.y1; y += rowStep) {
        const float* pa = a.row(y) + r.x0;
        const float* pb = b.row(y - oy) + (r.x0 - ox);
        float ra = 0, rb = 0, raa = 0, rbb = 0, rab = 0;
        for (int x = 0; x < r.w(); ++x) {
            const float va = pa[x] - ca, vb = pb[x] - cb;
            ra += va;
            rb += vb;
            raa += va * va;
            rbb += vb * vb;
            rab += va * vb;
        }
        sa += ra;
        sb += rb;
        saa += raa;
        sbb += rbb;
        sab += rab;
        n += r.w();
    }
    const double dn = static_cast<double>(n);
    const double cov = sab - sa * sb / dn, va = saa - sa * sa / dn, vb = sbb - sb * sb / dn;
    if (va <= 1e-9 * dn || vb <= 1e-9 * dn)
        return 0;
    return cov / std::sqrt(va * vb);
}

} // namespace

double overlapNcc(const ImageF& a, const ImageF& b, int ox, int oy)
{
    return sampledNcc(a, b, ox, oy, 1);
}

PairRegistration registerPair(const ImageF& a, const ImageF& b, const Eigen::Vector2d& expectedPx, const RegistrationOptions& opt)
{
    PairRegistration out;
    out.shiftPx = expectedPx;
    const int ex = static_cast<int>(std::lround(expectedPx.x())), ey = static_cast<int>(std::lround(expectedPx.y()));
    const Rect ov = overlapIn(a, b, ex, ey);
    if (ov.w() < opt.minOverlapPx || ov.h() < opt.minOverlapPx)
        return out;
    const int w = fastFftSize(ov.w()), h = fastFftSize(ov.h());
    const int ax = ov.x0 + (ov.w() - w) / 2, ay = ov.y0 + (ov.h() - h) / 2;
    const std::vector<float> wx = hann(w), wy = hann(h);
    const std::size_t nr = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
    const std::size_t nc = static_cast<std::size_t>(h) * static_cast<std::size_t>(w / 2 + 1);
    FloatBuffer pa = fftFloats(nr), pb = fftFloats(nr);
    ComplexBuffer fa = fftComplex(nc), fb = fftComplex(nc);
    windowedPatch(a, ax, ay, w, h, wx, wy, pa.get());
    windowedPatch(b, ax - ex, ay - ey, w, h, wx, wy, pb.get());
    forwardFft(w, h, pa.get(), fa.get());
    forwardFft(w, h, pb.get(), fb.get());
    // The magnitudes are kept in fb's storage (its spectrum is no longer needed).
    float* mag = reinterpret_cast<float*>(fb.get());
    double meanMag = 0;
    for (std::size_t k = 0; k < nc; ++k) {
        fa[k] *= std::conj(fb[k]);
        const float re = fa[k].real(), im = fa[k].imag();
        mag[k] = std::sqrt(re * re + im * im);
        meanMag += mag[k];
    }
    meanMag /= static_cast<double>(nc);
    const float lambda = static_cast<float>(opt.regularisation * meanMag) + 1e-30f;
    for (std::size_t k = 0; k < nc; ++k)
        fa[k] *= 1.0f / (mag[k] + lambda);
    inverseFft(w, h, fa.get(), pa.get());
    const float* c = pa.get();

    // Local maxima of the surface whose wrap readings fall within the bound.
    const int bound = static_cast<int>(std::floor(opt.maxShiftPx));
    std::vector<Candidate> peaks;
    auto at = [&](int x, int y) { return c[static_cast<std::size_t>((y + h) % h) * static_cast<std::size_t>(w) + static_cast<std::size_t>((x + w) % w)]; };
    auto inBound = [&](int px, int len) { return px <= bound || len - px <= bound; };
    for (int y = 0; y < h; ++y) {
        if (!inBound(y, h))
            continue;
        for (int x = 0; x < w; ++x) {
            if (!inBound(x, w))
                continue;
            const float v = at(x, y);
            bool isMax = true;
            for (int dy = -1; dy <= 1 && isMax; ++dy)
                for (int dx = -1; dx <= 1; ++dx)
                    if ((dx || dy) && at(x + dx, y + dy) > v) {
                        isMax = false;
                        break;
                    }
            if (isMax)
                peaks.push_back({x, y, v, -2});
        }
    }
    const std::size_t keep = std::min<std::size_t>(peaks.size(), static_cast<std::size_t>(std::max(1, opt.peakCandidates)));
    std::partial_sort(peaks.begin(), peaks.begin() + static_cast<std::ptrdiff_t>(keep), peaks.end(),
                      [](const Candidate& p, const Candidate& q) { return p.peak > q.peak; });
    peaks.resize(keep);
    // The search scores offsets on every other row of a large overlap (the winner is
    // scored again on all of them by the refinement), each offset once.
    const int rowStep = static_cast<double>(ov.w()) * ov.h() > 100000 ? 2 : 1;
    std::map<std::pair<int, int>, double> scored;
    auto score = [&](int dx, int dy) {
        auto it = scored.find({dx, dy});
        if (it != scored.end())
            return it->second;
        const double v = sampledNcc(a, b, ex + dx, ey + dy, rowStep);
        scored.emplace(std::make_pair(dx, dy), v);
        return v;
    };
    std::vector<Candidate> readings;
    for (const Candidate& p : peaks)
        for (int dx : {p.dx, p.dx - w})
            for (int dy : {p.dy, p.dy - h}) {
                if (std::abs(dx) > bound || std::abs(dy) > bound)
                    continue;
                const Rect r = overlapIn(a, b, ex + dx, ey + dy);
                if (r.w() < opt.minOverlapPx || r.h() < opt.minOverlapPx)
                    continue;
                Candidate q{dx, dy, p.peak, score(dx, dy)};
                readings.push_back(q);
            }
    if (readings.empty())
        return out;
    std::sort(readings.begin(), readings.end(), [](const Candidate& p, const Candidate& q) { return p.ncc > q.ncc; });
    const Candidate best = readings.front();
    // Hill-climb the NCC over integer offsets (MIST's local search): a correlation
    // peak blurred by the window may sit a pixel or two off the best offset.
    auto climb = [&](Candidate from) {
        for (int step = 0; step < 4 * bound + 8; ++step) {
            Candidate next = from;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    if ((!dx && !dy) || std::abs(from.dx + dx) > bound || std::abs(from.dy + dy) > bound)
                        continue;
                    const Rect r = overlapIn(a, b, ex + from.dx + dx, ey + from.dy + dy);
                    if (r.w() < opt.minOverlapPx || r.h() < opt.minOverlapPx)
                        continue;
                    const double v = score(from.dx + dx, from.dy + dy);
                    if (v > next.ncc) {
                        next = from;
                        next.dx += dx;
                        next.dy += dy;
                        next.ncc = v;
                    }
                }
            if (next.dx == from.dx && next.dy == from.dy)
                break;
            from = next;
        }
        return from;
    };
    const Candidate top = climb(best);
    const int bx = top.dx, by = top.dy;
    const double bestNcc = top.ncc;
    // The runner-up is another hill of the NCC, not the slope of the winner's: a
    // rival candidate climbs to its own maximum, and counts only if that lies apart.
    out.secondNcc = 0;
    int tried = 0;
    for (const Candidate& q : readings) {
        if (tried >= 3)
            break;
        if (std::max(std::abs(q.dx - bx), std::abs(q.dy - by)) <= 2)
            continue;
        // A rival far below the winner cannot climb to an ambiguous score from the
        // slope of a hill; only the close ones are worth the climb.
        if (q.ncc < 0.8 * opt.ambiguousRatio * bestNcc)
            break;
        ++tried;
        const Candidate rival = climb(q);
        if (std::max(std::abs(rival.dx - bx), std::abs(rival.dy - by)) > 1) {
            out.secondNcc = rival.ncc;
            break;
        }
    }
    const Eigen::Vector2d integer(ex + bx, ey + by);
    const Refined r = refine(a, b, integer);
    out.shiftPx = r.ok ? r.offset : integer;
    out.ncc = r.ok ? r.ncc : bestNcc;
    if ((out.shiftPx - expectedPx).cwiseAbs().maxCoeff() > opt.maxShiftPx)
        out.shiftPx = integer;
    if (out.ncc < opt.minNcc)
        out.status = PairStatus::LowScore;
    else if (std::abs(bx) >= bound || std::abs(by) >= bound)
        out.status = PairStatus::AtBound;
    else if (out.secondNcc >= opt.ambiguousRatio * out.ncc)
        out.status = PairStatus::Ambiguous;
    else
        out.status = PairStatus::Accepted;
    return out;
}

PairRegistration registerPair(const ImageU16& a, const ImageU16& b, const Eigen::Vector2d& expectedPx, const RegistrationOptions& opt)
{
    // Only the expected overlap, grown by the bound and a margin, takes part.
    const int margin = static_cast<int>(std::ceil(opt.maxShiftPx)) + 4;
    const int ex = static_cast<int>(std::lround(expectedPx.x())), ey = static_cast<int>(std::lround(expectedPx.y()));
    const int ax0 = std::max(0, ex - margin), ay0 = std::max(0, ey - margin);
    const int ax1 = std::min(a.width, ex + b.width + margin), ay1 = std::min(a.height, ey + b.height + margin);
    if (ax1 <= ax0 || ay1 <= ay0)
        return {};
    // The same rectangle in b's pixels.
    const int bx0 = std::max(0, ax0 - ex), by0 = std::max(0, ay0 - ey);
    const int bx1 = std::min(b.width, ax1 - ex), by1 = std::min(b.height, ay1 - ey);
    if (bx1 <= bx0 || by1 <= by0)
        return {};
    auto cut = [](const ImageU16& s, int x0, int y0, int x1, int y1) {
        ImageF o(x1 - x0, y1 - y0);
        for (int y = y0; y < y1; ++y) {
            const std::uint16_t* r = s.row(y) + x0;
            float* d = o.row(y - y0);
            for (int x = 0; x < x1 - x0; ++x)
                d[x] = r[x];
        }
        return o;
    };
    const ImageF ca = cut(a, ax0, ay0, ax1, ay1);
    const ImageF cb = cut(b, bx0, by0, bx1, by1);
    // b's crop starts at (bx0, by0) in b, i.e. at expected + (bx0, by0) − (ax0, ay0) in a's crop.
    const Eigen::Vector2d shift(bx0 - ax0, by0 - ay0);
    PairRegistration r = registerPair(ca, cb, expectedPx + shift, opt);
    r.shiftPx -= shift;
    return r;
}

} // namespace imaging
