#include "imaging/placement.h"

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <cmath>

namespace imaging {
namespace {

std::vector<Eigen::Vector2d> solvePositions(const std::vector<Eigen::Vector2d>& stage, const std::vector<TilePair>& pairs,
                                            const PlacementOptions& o)
{
    const int n = static_cast<int>(stage.size());
    const double ws = 1.0 / (o.stageSigmaPx * o.stageSigmaPx);
    std::vector<Eigen::Triplet<double>> t;
    t.reserve(static_cast<std::size_t>(n) + 4 * pairs.size());
    Eigen::VectorXd bx(n), by(n);
    for (int i = 0; i < n; ++i) {
        t.emplace_back(i, i, ws);
        bx[i] = ws * stage[static_cast<std::size_t>(i)].x();
        by[i] = ws * stage[static_cast<std::size_t>(i)].y();
    }
    for (const TilePair& p : pairs) {
        if (!p.reg.accepted())
            continue;
        const double s = std::max(0.05, p.reg.ncc) / o.registrationSigmaPx;
        const double w = s * s;
        t.emplace_back(p.a, p.a, w);
        t.emplace_back(p.b, p.b, w);
        t.emplace_back(p.a, p.b, -w);
        t.emplace_back(p.b, p.a, -w);
        bx[p.b] += w * p.reg.shiftPx.x();
        bx[p.a] -= w * p.reg.shiftPx.x();
        by[p.b] += w * p.reg.shiftPx.y();
        by[p.a] -= w * p.reg.shiftPx.y();
    }
    Eigen::SparseMatrix<double> A(n, n);
    A.setFromTriplets(t.begin(), t.end());
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(A);
    const Eigen::VectorXd x = solver.solve(bx), y = solver.solve(by);
    std::vector<Eigen::Vector2d> out(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i)
        out[static_cast<std::size_t>(i)] = {x[i], y[i]};
    return out;
}

double residual(const std::vector<Eigen::Vector2d>& p, const TilePair& pair)
{
    return (p[static_cast<std::size_t>(pair.b)] - p[static_cast<std::size_t>(pair.a)] - pair.reg.shiftPx).norm();
}

} // namespace

Placement placeTiles(const std::vector<Eigen::Vector2d>& stagePx, std::vector<TilePair>& pairs, const PlacementOptions& o)
{
    Placement out;
    const int n = static_cast<int>(stagePx.size());
    // A pair naming a tile that is not there cannot take part.
    for (TilePair& p : pairs)
        if (p.a < 0 || p.b < 0 || p.a >= n || p.b >= n || p.a == p.b)
            p.reg.status = PairStatus::NoOverlap;
    if (n == 0)
        return out;
    std::vector<Eigen::Vector2d> pos;
    // Each pass rejects at most one pair (or one tile's pairs), so this ends.
    for (std::size_t pass = 0; pass <= pairs.size() + 1; ++pass) {
        pos = solvePositions(stagePx, pairs, o);
        std::vector<double> res;
        for (const TilePair& p : pairs)
            if (p.reg.accepted())
                res.push_back(residual(pos, p));
        if (res.empty())
            break;
        std::vector<double> sorted = res;
        std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2), sorted.end());
        const double limit = std::max(o.outlierFloorPx, o.outlierMedians * sorted[sorted.size() / 2]);
        TilePair* worst = nullptr;
        double worstRes = limit;
        for (TilePair& p : pairs)
            if (p.reg.accepted()) {
                const double r = residual(pos, p);
                if (r > worstRes) {
                    worstRes = r;
                    worst = &p;
                }
            }
        if (worst) {
            worst->reg.status = PairStatus::Outlier;
            ++out.rejectedPairs;
            continue;
        }
        // The bound: the tile moved furthest beyond it loses its pairs.
        int farTile = -1;
        double far = o.maxCorrectionPx;
        for (int i = 0; i < n; ++i) {
            const double d = (pos[static_cast<std::size_t>(i)] - stagePx[static_cast<std::size_t>(i)]).cwiseAbs().maxCoeff();
            if (d > far) {
                far = d;
                farTile = i;
            }
        }
        if (farTile < 0)
            break;
        for (TilePair& p : pairs)
            if (p.reg.accepted() && (p.a == farTile || p.b == farTile)) {
                p.reg.status = PairStatus::Outlier;
                ++out.rejectedPairs;
            }
    }
    out.positionsPx = pos;
    out.placedByStage.assign(static_cast<std::size_t>(n), true);
    for (const TilePair& p : pairs) {
        out.residualPx.push_back(p.reg.accepted() || p.reg.status == PairStatus::Outlier ? residual(pos, p) : 0.0);
        if (p.reg.accepted()) {
            out.placedByStage[static_cast<std::size_t>(p.a)] = false;
            out.placedByStage[static_cast<std::size_t>(p.b)] = false;
        }
    }
    double sum2 = 0;
    int counted = 0;
    for (int i = 0; i < n; ++i) {
        if (out.placedByStage[static_cast<std::size_t>(i)]) {
            // Exactly its stage position: the solve gives it that up to rounding.
            out.positionsPx[static_cast<std::size_t>(i)] = stagePx[static_cast<std::size_t>(i)];
            continue;
        }
        const double d = (out.positionsPx[static_cast<std::size_t>(i)] - stagePx[static_cast<std::size_t>(i)]).norm();
        sum2 += d * d;
        out.worstCorrectionPx = std::max(out.worstCorrectionPx, d);
        ++counted;
    }
    out.rmsCorrectionPx = counted ? std::sqrt(sum2 / counted) : 0.0;
    return out;
}

} // namespace imaging
