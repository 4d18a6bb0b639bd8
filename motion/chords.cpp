#include "motion/chords.h"
#include "motion/numbers.h"

#include <algorithm>
#include <cmath>

namespace motion {

std::vector<PointMm> functionChords(const std::function<double(double)>& f, double x0, double x1,
                                    double maxAbsSecondDerivative, double toleranceMm)
{
    std::vector<PointMm> out;
    if (!std::isfinite(x0) || !std::isfinite(x1) || !(x1 > x0) || !(toleranceMm > 0.0)
        || !std::isfinite(maxAbsSecondDerivative) || maxAbsSecondDerivative < 0.0)
        return out;
    const double span = x1 - x0;
    const double h = maxAbsSecondDerivative > 0.0 ? std::sqrt(8.0 * toleranceMm / maxAbsSecondDerivative) : span;
    const auto parts = static_cast<long long>(std::max(1.0, std::ceil(span / h - 1e-12)));
    out.reserve(static_cast<std::size_t>(parts + 1));
    for (long long i = 0; i <= parts; ++i) {
        const double x = i == parts ? x1 : x0 + span * static_cast<double>(i) / static_cast<double>(parts);
        out.push_back({x, f(x)});
    }
    return out;
}

std::vector<PointMm> sineChords(double amplitudeMm, double wavelengthMm, double lengthMm, double toleranceMm,
                                bool cosine)
{
    if (!std::isfinite(amplitudeMm) || !(wavelengthMm > 0.0) || !std::isfinite(wavelengthMm))
        return {};
    const double k = 2.0 * kPi / wavelengthMm;
    const auto f = [=](double x) { return amplitudeMm * (cosine ? std::cos(k * x) : std::sin(k * x)); };
    return functionChords(f, 0.0, lengthMm, std::fabs(amplitudeMm) * k * k, toleranceMm);
}

std::vector<GridPoint> interpolatePolyline(const std::vector<PointMm>& vertices, double stepMm)
{
    std::vector<GridPoint> out;
    if (vertices.empty() || !(stepMm > 0.0))
        return out;
    const auto toGrid = [&](const PointMm& p) {
        return GridPoint{std::llround(p.x / stepMm), std::llround(p.y / stepMm)};
    };
    GridPoint at = toGrid(vertices.front());
    out.push_back(at);
    for (std::size_t i = 1; i < vertices.size(); ++i) {
        const GridPoint to = toGrid(vertices[i]);
        LineInterpolator line(to.x - at.x, to.y - at.y);
        while (!line.done()) {
            const GridStep s = line.next();
            at.x += s.dx;
            at.y += s.dy;
            out.push_back(at);
        }
    }
    return out;
}

double maxDistanceToGraphMm(const std::vector<PointMm>& points, const std::function<double(double)>& f,
                            double windowMm)
{
    double worst = 0.0;
    for (const PointMm& p : points) {
        // Golden-section search of the squared distance over a small window: the graph is smooth
        // and the point is close to it, so the minimum is unimodal there.
        double lo = p.x - windowMm, hi = p.x + windowMm;
        const double g = 0.5 * (std::sqrt(5.0) - 1.0);
        const auto d2 = [&](double x) {
            const double dy = f(x) - p.y, dx = x - p.x;
            return dx * dx + dy * dy;
        };
        double c = hi - g * (hi - lo), d = lo + g * (hi - lo);
        double fc = d2(c), fd = d2(d);
        for (int it = 0; it < 60; ++it) {
            if (fc < fd) {
                hi = d;
                d = c;
                fd = fc;
                c = hi - g * (hi - lo);
                fc = d2(c);
            } else {
                lo = c;
                c = d;
                fc = fd;
                d = lo + g * (hi - lo);
                fd = d2(d);
            }
        }
        worst = std::max(worst, std::sqrt(std::min({fc, fd, d2(p.x)})));
    }
    return worst;
}

}  // namespace motion
