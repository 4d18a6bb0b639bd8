#include "imaging/line_finder.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace imaging {
namespace {

using motion::msg::Checked;

constexpr int kMinProfileLength = 16;

double medianOfLine(std::vector<double> v)
{
    if (v.empty())
        return 0;
    const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
    std::nth_element(v.begin(), mid, v.end());
    return *mid;
}

// σ of white noise on the profile from its first differences (robust to the line
// and to a slow background: both change little from one sample to the next).
double profileNoise(const std::vector<double>& p)
{
    std::vector<double> d;
    d.reserve(p.size());
    for (std::size_t i = 1; i < p.size(); ++i)
        d.push_back(std::abs(p[i] - p[i - 1]));
    return 1.4826 * medianOfLine(std::move(d)) / std::sqrt(2.0);
}

std::vector<double> smoothLine(const std::vector<double>& p, double sigma)
{
    const int r = std::max(1, static_cast<int>(std::ceil(3 * sigma)));
    std::vector<double> k(static_cast<std::size_t>(2 * r + 1));
    double sum = 0;
    for (int i = -r; i <= r; ++i)
        sum += k[static_cast<std::size_t>(i + r)] = std::exp(-0.5 * i * i / (sigma * sigma));
    const int n = static_cast<int>(p.size());
    std::vector<double> out(p.size());
    for (int i = 0; i < n; ++i) {
        double acc = 0;
        for (int j = -r; j <= r; ++j)
            acc += k[static_cast<std::size_t>(j + r)] * p[static_cast<std::size_t>(std::clamp(i + j, 0, n - 1))];
        out[static_cast<std::size_t>(i)] = acc / sum;
    }
    return out;
}

struct LineFit {
    bool ok = false;
    double centre = 0, sigma = 0, amplitude = 0, background = 0;
};

// Gaussian on a sloping background, b0 + b1·(x − x0) + A·exp(−(x − μ)² / 2σ²), fitted
// by Levenberg–Marquardt over p[lo … hi].
LineFit fitLineGaussian(const std::vector<double>& p, int lo, int hi, double mu0, double sigma0, double amp0, double bg0)
{
    const double x0 = mu0;
    Eigen::Matrix<double, 5, 1> q;
    q << bg0, 0, amp0, mu0, std::max(0.5, sigma0);
    auto cost = [&](const Eigen::Matrix<double, 5, 1>& v) {
        double c = 0;
        for (int i = lo; i <= hi; ++i) {
            const double t = i - v(3);
            const double r = p[static_cast<std::size_t>(i)] - (v(0) + v(1) * (i - x0) + v(2) * std::exp(-0.5 * t * t / (v(4) * v(4))));
            c += r * r;
        }
        return c;
    };
    double lambda = 1e-3;
    double c = cost(q);
    for (int iter = 0; iter < 60; ++iter) {
        Eigen::Matrix<double, 5, 5> jtj = Eigen::Matrix<double, 5, 5>::Zero();
        Eigen::Matrix<double, 5, 1> jtr = Eigen::Matrix<double, 5, 1>::Zero();
        for (int i = lo; i <= hi; ++i) {
            const double t = i - q(3);
            const double s2 = q(4) * q(4);
            const double g = std::exp(-0.5 * t * t / s2);
            const double r = p[static_cast<std::size_t>(i)] - (q(0) + q(1) * (i - x0) + q(2) * g);
            Eigen::Matrix<double, 5, 1> j;
            j << 1, i - x0, g, q(2) * g * t / s2, q(2) * g * t * t / (s2 * q(4));
            jtj += j * j.transpose();
            jtr += j * r;
        }
        bool improved = false;
        for (int tries = 0; tries < 10 && !improved; ++tries) {
            Eigen::Matrix<double, 5, 5> a = jtj;
            for (int d = 0; d < 5; ++d)
                a(d, d) *= 1 + lambda;
            const Eigen::Matrix<double, 5, 1> step = a.ldlt().solve(jtr);
            Eigen::Matrix<double, 5, 1> next = q + step;
            next(4) = std::abs(next(4));
            const double cn = (next.allFinite() && next(4) > 1e-3) ? cost(next) : INFINITY;
            if (cn <= c) {
                const bool small = std::abs(step(3)) < 1e-6 && c - cn <= 1e-12 * (1 + c);
                q = next;
                c = cn;
                lambda = std::max(1e-9, lambda / 4);
                improved = true;
                if (small)
                    iter = 1000;
            } else {
                lambda *= 8;
            }
        }
        if (!improved)
            break;
    }
    LineFit f;
    f.centre = q(3);
    f.sigma = std::abs(q(4));
    f.amplitude = q(2);
    f.background = q(0) + q(1) * (q(3) - x0);
    f.ok = q.allFinite() && f.centre >= lo && f.centre <= hi;
    return f;
}

struct LineCandidate {
    int peak = 0;
    double strength = 0;  // smoothed depth or height against the median, profile units
    double sign = -1;     // −1 dark, +1 bright
};

// Local maxima of sign·(s − bg) above `floor`, closer ones merged into the stronger.
std::vector<LineCandidate> peaksOf(const std::vector<double>& s, double bg, double sign, double floor, int mergePx)
{
    std::vector<LineCandidate> out;
    const int n = static_cast<int>(s.size());
    for (int i = 1; i + 1 < n; ++i) {
        const double v = sign * (s[static_cast<std::size_t>(i)] - bg);
        if (v < floor || v < sign * (s[static_cast<std::size_t>(i - 1)] - bg) || v <= sign * (s[static_cast<std::size_t>(i + 1)] - bg))
            continue;
        if (!out.empty() && i - out.back().peak <= mergePx) {
            if (v > out.back().strength)
                out.back() = {i, v, sign};
            continue;
        }
        out.push_back({i, v, sign});
    }
    return out;
}

// The candidate fitted where it stands: its window spans the line and some background
// each side, re-centred once on the first answer.
LineFit fitCandidate(const std::vector<double>& p, const std::vector<double>& smooth, double bg, const LineCandidate& c,
                     double smoothSigma)
{
    const int n = static_cast<int>(p.size());
    // Width at half depth of the smoothed peak, less the smoothing, as σ's first guess.
    int l = c.peak, r = c.peak;
    const double half = 0.5 * c.strength;
    while (l > 0 && c.sign * (smooth[static_cast<std::size_t>(l)] - bg) > half)
        --l;
    while (r + 1 < n && c.sign * (smooth[static_cast<std::size_t>(r)] - bg) > half)
        ++r;
    const double fwhmSigma = std::max(0.5, (r - l) / 2.355);
    const double sigma0 = std::sqrt(std::max(0.25, fwhmSigma * fwhmSigma - smoothSigma * smoothSigma));
    double mu = c.peak;
    LineFit f;
    for (int pass = 0; pass < 2; ++pass) {
        const int halfWin = std::max(5, static_cast<int>(std::ceil(4 * (pass ? f.sigma : sigma0) + 3)));
        const int centre = static_cast<int>(std::lround(mu));
        const int lo = std::max(0, centre - halfWin), hi = std::min(n - 1, centre + halfWin);
        if (hi - lo < 6)
            return {};
        f = fitLineGaussian(p, lo, hi, mu, pass ? f.sigma : sigma0, c.sign * c.strength * 1.2, bg);
        if (!f.ok)
            return f;
        mu = f.centre;
    }
    return f;
}

} // namespace

Checked<FoundLine> findLineInProfile(const std::vector<double>& p, const LineFinderOptions& o)
{
    const int n = static_cast<int>(p.size());
    if (n < kMinProfileLength)
        return Checked<FoundLine>::fail(motion::msg::make("imaging.line.too_short", {motion::msg::integer("length", n), motion::msg::integer("minimum", kMinProfileLength)}));
    const double centre = 0.5 * (n - 1);
    const double bg = medianOfLine(p);
    const double scale = std::max(std::abs(bg), 1e-12);
    const double noise = profileNoise(p);
    const std::vector<double> s = smoothLine(p, o.smoothSigmaPx);
    const double floor = std::max(o.minContrast * scale, o.minSnr * noise);
    const int mergePx = static_cast<int>(std::ceil(2 * o.smoothSigmaPx + 2));

    std::vector<LineCandidate> cands;
    double best = 0;  // the deepest smoothed deviation, for the failure's contrast
    for (double sign : {-1.0, 1.0}) {
        if ((o.polarity == Polarity::Dark && sign > 0) || (o.polarity == Polarity::Bright && sign < 0))
            continue;
        for (double v : s)
            best = std::max(best, sign * (v - bg));
        std::vector<LineCandidate> c = peaksOf(s, bg, sign, floor, mergePx);
        if (o.polarity == Polarity::Either && !cands.empty() && !c.empty()) {
            // Either: the polarity whose strongest candidate is stronger.
            auto strongest = [](const std::vector<LineCandidate>& v) {
                double m = 0;
                for (const LineCandidate& k : v)
                    m = std::max(m, k.strength);
                return m;
            };
            if (strongest(c) > strongest(cands))
                cands = std::move(c);
            continue;
        }
        if (cands.empty())
            cands = std::move(c);
    }
    std::sort(cands.begin(), cands.end(), [&](const LineCandidate& a, const LineCandidate& b) { return std::abs(a.peak - centre) < std::abs(b.peak - centre); });

    struct Fitted {
        LineFit fit;
        double distance;
    };
    std::vector<Fitted> lines;
    for (const LineCandidate& c : cands) {
        // Fitted until two are known and the next cannot come nearer than the second.
        if (lines.size() >= 2 && std::abs(c.peak - centre) > lines[1].distance + 2)
            break;
        const LineFit f = fitCandidate(p, s, bg, c, o.smoothSigmaPx);
        if (!f.ok || f.sigma > o.maxSigmaPx || f.amplitude * c.sign <= 0)
            continue;
        const double contrast = std::abs(f.amplitude) / std::max(std::abs(f.background), 1e-12);
        if (contrast < o.minContrast)
            continue;
        lines.push_back({f, std::abs(f.centre - centre)});
        std::sort(lines.begin(), lines.end(), [](const Fitted& a, const Fitted& b) { return a.distance < b.distance; });
    }
    if (lines.empty()) {
        return Checked<FoundLine>::fail(motion::msg::make("imaging.line.not_found", {motion::msg::real("contrast", 100 * best / scale, motion::msg::Unit::Percent),
                                                                                     motion::msg::real("minimum", 100 * o.minContrast, motion::msg::Unit::Percent)}));
    }
    if (lines.size() >= 2 && lines[1].distance - lines[0].distance < o.ambiguousPx) {
        return Checked<FoundLine>::fail(motion::msg::make("imaging.line.ambiguous", {motion::msg::real("first", lines[0].fit.centre - centre),
                                                                                     motion::msg::real("second", lines[1].fit.centre - centre)}));
    }
    const LineFit& f = lines[0].fit;
    FoundLine out;
    out.offsetPx = f.centre - centre;
    out.contrast = std::abs(f.amplitude) / std::max(std::abs(f.background), 1e-12);
    out.sigmaPx = f.sigma;
    out.dark = f.amplitude < 0;
    return Checked<FoundLine>::ok(out);
}

namespace {

// The image averaged along the line: one value per row (a horizontal line) or per
// column (a vertical one). Rows are read in memory order either way.
template <class T>
std::vector<double> lineProfile(const Plane<T>& im, LineDirection dir)
{
    const bool horizontal = dir == LineDirection::Horizontal;
    std::vector<double> prof(static_cast<std::size_t>(horizontal ? im.height : im.width), 0.0);
    if (horizontal) {
        for (int y = 0; y < im.height; ++y) {
            const T* row = im.row(y);
            double acc = 0;
            for (int x = 0; x < im.width; ++x)
                acc += row[x];
            prof[static_cast<std::size_t>(y)] = acc / im.width;
        }
    } else {
        std::vector<float> acc(static_cast<std::size_t>(im.width), 0.0f);
        // float sums per block of rows, then double: fast and without drift.
        for (int y0 = 0; y0 < im.height; y0 += 64) {
            std::fill(acc.begin(), acc.end(), 0.0f);
            const int y1 = std::min(im.height, y0 + 64);
            for (int y = y0; y < y1; ++y) {
                const T* row = im.row(y);
                for (int x = 0; x < im.width; ++x)
                    acc[static_cast<std::size_t>(x)] += static_cast<float>(row[x]);
            }
            for (int x = 0; x < im.width; ++x)
                prof[static_cast<std::size_t>(x)] += acc[static_cast<std::size_t>(x)];
        }
        for (double& v : prof)
            v /= im.height;
    }
    return prof;
}

template <class T>
Checked<FoundLine> findLineIn(const Plane<T>& im, const LineFinderOptions& o)
{
    if (im.width < kMinProfileLength || im.height < kMinProfileLength) {
        return Checked<FoundLine>::fail(motion::msg::make("imaging.line.image_too_small", {motion::msg::integer("width", im.width), motion::msg::integer("height", im.height),
                                                                                           motion::msg::integer("minimum", kMinProfileLength)}));
    }
    return findLineInProfile(lineProfile(im, o.direction), o);
}

} // namespace

Checked<FoundLine> findLine(const ImageF& image, const LineFinderOptions& options) { return findLineIn(image, options); }
Checked<FoundLine> findLine(const ImageU16& image, const LineFinderOptions& options) { return findLineIn(image, options); }

} // namespace imaging
