#include "motion/metrology/grid/grid_map.h"

#include <algorithm>
#include <cmath>

namespace motion::metrology {
namespace {

/// Least-squares slope of v over t (µm per mm), n ≥ 2 distinct t.
double lsSlope(const double* t, const double* v, std::size_t n, std::size_t stride)
{
    double tm = 0, vm = 0;
    for (std::size_t k = 0; k < n; ++k) {
        tm += t[k];
        vm += v[k * stride];
    }
    tm /= static_cast<double>(n);
    vm /= static_cast<double>(n);
    double stv = 0, stt = 0;
    for (std::size_t k = 0; k < n; ++k) {
        const double dt = t[k] - tm;
        stv += dt * (v[k * stride] - vm);
        stt += dt * dt;
    }
    return stt > 0 ? stv / stt : 0;
}

/// Peak to valley of v over t after its least-squares line is removed (ISO 230-1's
/// least-squares reference straight line).
double lsPeakToValley(const double* t, const double* v, std::size_t n, std::size_t stride)
{
    const double slope = lsSlope(t, v, n, stride);
    double lo = 0, hi = 0;
    for (std::size_t k = 0; k < n; ++k) {
        const double r = v[k * stride] - slope * t[k];
        if (k == 0 || r < lo)
            lo = r;
        if (k == 0 || r > hi)
            hi = r;
    }
    return hi - lo;
}

void removePlacement(const std::vector<double>& xMm, const std::vector<double>& yMm, const GridPlacement& p,
                     std::vector<double>& ex, std::vector<double>& ey)
{
    const std::size_t nx = xMm.size();
    for (std::size_t j = 0; j < yMm.size(); ++j)
        for (std::size_t i = 0; i < nx; ++i) {
            const std::size_t k = j * nx + i;
            // A rotation θ (rad) about the centre moves a point at (dx, dy) mm by
            // (−θ·dy, θ·dx) mm; θ in µrad times mm is nm.
            ex[k] -= p.offsetXUm - p.rotationUrad * (yMm[j] - p.centreYMm) * 1e-3;
            ey[k] -= p.offsetYUm + p.rotationUrad * (xMm[i] - p.centreXMm) * 1e-3;
        }
}

} // namespace

GridPlacement fitPlacement(const std::vector<double>& xMm, const std::vector<double>& yMm, const std::vector<double>& ex,
                           const std::vector<double>& ey)
{
    // About the centroid the three unknowns decouple: the offsets are the mean
    // errors, and θ = Σ(dx·ey − dy·ex) / Σ(dx² + dy²) (µm/mm = mrad, so ×1000 for µrad).
    GridPlacement p;
    const std::size_t nx = xMm.size(), ny = yMm.size(), n = nx * ny;
    for (double x : xMm)
        p.centreXMm += x;
    for (double y : yMm)
        p.centreYMm += y;
    p.centreXMm /= static_cast<double>(nx);
    p.centreYMm /= static_cast<double>(ny);
    double num = 0, den = 0;
    for (std::size_t j = 0; j < ny; ++j)
        for (std::size_t i = 0; i < nx; ++i) {
            const std::size_t k = j * nx + i;
            const double dx = xMm[i] - p.centreXMm, dy = yMm[j] - p.centreYMm;
            p.offsetXUm += ex[k];
            p.offsetYUm += ey[k];
            num += dx * ey[k] - dy * ex[k];
            den += dx * dx + dy * dy;
        }
    p.offsetXUm /= static_cast<double>(n);
    p.offsetYUm /= static_cast<double>(n);
    p.rotationUrad = den > 0 ? num / den * 1e3 : 0;
    return p;
}

motion::msg::Problems validate(const GridMapInput& in)
{
    motion::msg::Problems out;
    constexpr std::size_t kMin = 3;
    if (in.columns() < kMin || in.rows() < kMin) {
        out.push_back(motion::msg::error("nodes", motion::msg::make("grid.too_few_nodes",
                                                    {motion::msg::integer("columns", static_cast<long long>(in.columns())),
                                                     motion::msg::integer("rows", static_cast<long long>(in.rows())),
                                                     motion::msg::integer("min", static_cast<long long>(kMin))})));
        return out;
    }
    auto increasing = [&](const std::vector<double>& v, const char* path) {
        for (std::size_t k = 0; k < v.size(); ++k) {
            if (!std::isfinite(v[k])) {
                out.push_back(motion::msg::error(indexPath(path, k), motion::msg::make("accuracy.value_not_finite")));
            } else if (k > 0 && !(v[k] > v[k - 1])) {
                out.push_back(motion::msg::error(indexPath(path, k), motion::msg::make("grid.positions_not_increasing",
                                                                        {motion::msg::real("value", v[k], motion::msg::Unit::Mm),
                                                                         motion::msg::real("previous", v[k - 1], motion::msg::Unit::Mm)})));
            }
        }
    };
    increasing(in.xMm, "x_mm");
    increasing(in.yMm, "y_mm");
    const std::size_t n = in.columns() * in.rows();
    auto complete = [&](const std::vector<double>& v, const char* path, bool optional) {
        if (optional && v.empty())
            return;
        if (v.size() != n) {
            out.push_back(motion::msg::error(path, motion::msg::make("grid.node_count_wrong",
                                                     {motion::msg::integer("count", static_cast<long long>(v.size())),
                                                      motion::msg::integer("expected", static_cast<long long>(n))})));
            return;
        }
        for (std::size_t k = 0; k < n; ++k)
            if (!std::isfinite(v[k]))
                out.push_back(motion::msg::error(indexPath(path, k), motion::msg::make("accuracy.value_not_finite")));
    };
    complete(in.exUm, "ex_um", false);
    complete(in.eyUm, "ey_um", false);
    const bool reverse = !in.reverseExUm.empty() || !in.reverseEyUm.empty();
    complete(in.reverseExUm, "reverse_ex_um", !reverse);
    complete(in.reverseEyUm, "reverse_ey_um", !reverse);
    return out;
}

double GridMapNode::reversalUm() const { return bidirectional() ? std::hypot(*reversalXUm, *reversalYUm) : 0.0; }

std::optional<GridMapResult> analyseGridMap(const GridMapInput& in)
{
    if (hasErrors(validate(in)))
        return std::nullopt;
    const std::size_t nx = in.columns(), ny = in.rows(), n = nx * ny;
    const bool reverse = !in.reverseExUm.empty();
    GridMapResult r;
    // Both directions: the map is their mean (ISO 230-2's mean bidirectional position),
    // so the placement and every figure are of where the stage is on average.
    std::vector<double> ex = in.exUm, ey = in.eyUm;
    if (reverse)
        for (std::size_t k = 0; k < n; ++k) {
            ex[k] = 0.5 * (in.exUm[k] + in.reverseExUm[k]);
            ey[k] = 0.5 * (in.eyUm[k] + in.reverseEyUm[k]);
        }
    r.placement = fitPlacement(in.xMm, in.yMm, ex, ey);
    removePlacement(in.xMm, in.yMm, r.placement, ex, ey);
    GridMapFigures& f = r.figures;
    double slopeExAlongX = 0, slopeEyAlongX = 0, pvEyAlongX = 0;
    for (std::size_t j = 0; j < ny; ++j) {
        slopeExAlongX += lsSlope(in.xMm.data(), &ex[j * nx], nx, 1);
        slopeEyAlongX += lsSlope(in.xMm.data(), &ey[j * nx], nx, 1);
        pvEyAlongX += lsPeakToValley(in.xMm.data(), &ey[j * nx], nx, 1);
    }
    slopeExAlongX /= static_cast<double>(ny);
    slopeEyAlongX /= static_cast<double>(ny);
    double slopeEyAlongY = 0, slopeExAlongY = 0, pvExAlongY = 0;
    for (std::size_t i = 0; i < nx; ++i) {
        slopeEyAlongY += lsSlope(in.yMm.data(), &ey[i], ny, nx);
        slopeExAlongY += lsSlope(in.yMm.data(), &ex[i], ny, nx);
        pvExAlongY += lsPeakToValley(in.yMm.data(), &ex[i], ny, nx);
    }
    slopeEyAlongY /= static_cast<double>(nx);
    slopeExAlongY /= static_cast<double>(nx);
    // µm/mm is 1e-3: ×1000 gives ppm (a length) or µrad (an angle).
    f.scaleXPpm = slopeExAlongX * 1e3;
    f.scaleYPpm = slopeEyAlongY * 1e3;
    f.straightnessXUm = pvEyAlongX / static_cast<double>(ny);
    f.straightnessYUm = pvExAlongY / static_cast<double>(nx);
    f.squarenessUrad = (slopeExAlongY + slopeEyAlongX) * 1e3;

    // The additive model: ex = mean profile along Y (g, squareness and straightness
    // of Y included) + the scale line along X; ey likewise the other way round.
    const double xm = [&] { double s = 0; for (double x : in.xMm) s += x; return s / static_cast<double>(nx); }();
    const double ym = [&] { double s = 0; for (double y : in.yMm) s += y; return s / static_cast<double>(ny); }();
    std::vector<double> gRow(ny, 0), kCol(nx, 0);
    for (std::size_t j = 0; j < ny; ++j)
        for (std::size_t i = 0; i < nx; ++i) {
            gRow[j] += (ex[j * nx + i] - slopeExAlongX * (in.xMm[i] - xm)) / static_cast<double>(nx);
            kCol[i] += (ey[j * nx + i] - slopeEyAlongY * (in.yMm[j] - ym)) / static_cast<double>(ny);
        }

    std::vector<double> fex, fey, rex, rey;
    if (reverse) {
        // The plate stays where it lay between the passes: one placement comes off both
        // directions, so a lost motion that is the same everywhere stays in the reversal.
        fex = in.exUm;
        fey = in.eyUm;
        rex = in.reverseExUm;
        rey = in.reverseEyUm;
        removePlacement(in.xMm, in.yMm, r.placement, fex, fey);
        removePlacement(in.xMm, in.yMm, r.placement, rex, rey);
        f.maxReversalUm = 0.0;
        f.meanReversalXUm = 0.0;
        f.meanReversalYUm = 0.0;
    }
    double sumE2 = 0, sumR2 = 0;
    r.nodes.reserve(n);
    for (std::size_t j = 0; j < ny; ++j)
        for (std::size_t i = 0; i < nx; ++i) {
            const std::size_t k = j * nx + i;
            GridMapNode node;
            node.xMm = in.xMm[i];
            node.yMm = in.yMm[j];
            node.exUm = ex[k];
            node.eyUm = ey[k];
            node.residualXUm = ex[k] - gRow[j] - slopeExAlongX * (in.xMm[i] - xm);
            node.residualYUm = ey[k] - kCol[i] - slopeEyAlongY * (in.yMm[j] - ym);
            const double len = std::hypot(ex[k], ey[k]);
            sumE2 += len * len;
            f.maxErrorUm = std::max(f.maxErrorUm, len);
            sumR2 += node.residualXUm * node.residualXUm + node.residualYUm * node.residualYUm;
            if (reverse) {
                node.forwardExUm = fex[k];
                node.forwardEyUm = fey[k];
                node.reverseExUm = rex[k];
                node.reverseEyUm = rey[k];
                node.reversalXUm = fex[k] - rex[k];
                node.reversalYUm = fey[k] - rey[k];
                f.maxReversalUm = std::max(*f.maxReversalUm, node.reversalUm());
                *f.meanReversalXUm += *node.reversalXUm / static_cast<double>(n);
                *f.meanReversalYUm += *node.reversalYUm / static_cast<double>(n);
            }
            r.nodes.push_back(node);
        }
    f.rmsErrorUm = std::sqrt(sumE2 / static_cast<double>(n));
    f.rmsResidualUm = std::sqrt(sumR2 / static_cast<double>(n));
    return r;
}

} // namespace motion::metrology
