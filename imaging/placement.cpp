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

/// A model must move some tile by more than this to be worth applying (px).
constexpr double kModelMinEffectPx = 0.5;
/// ... and differ from the identity by this many standard errors in some entry.
constexpr double kModelSignificance = 3.0;
/// Fewer pairs than this cannot tell a stage model from a few tiles' own errors.
constexpr int kModelMinPairs = 6;

struct ModelFit {
    Eigen::Matrix2d m = Eigen::Matrix2d::Identity();
    Eigen::Matrix2d se = Eigen::Matrix2d::Constant(1e9);  ///< standard error of each entry
    std::vector<double> residual;                         ///< per used pair
    bool ok = false;
};

// Weighted least squares of shift ≈ M·d, x and y rows apart (they share the normal matrix).
ModelFit solveModel(const std::vector<Eigen::Vector2d>& d, const std::vector<Eigen::Vector2d>& shift, const std::vector<double>& w)
{
    ModelFit f;
    Eigen::Matrix2d n = Eigen::Matrix2d::Zero();
    Eigen::Vector2d bx(0, 0), by(0, 0);
    for (std::size_t k = 0; k < d.size(); ++k) {
        n += w[k] * d[k] * d[k].transpose();
        bx += w[k] * shift[k].x() * d[k];
        by += w[k] * shift[k].y() * d[k];
    }
    // Pairs all one way (a single row) leave the other column unknown.
    const double det = n(0, 0) * n(1, 1) - n(0, 1) * n(1, 0);
    if (d.size() < static_cast<std::size_t>(kModelMinPairs) || !(std::abs(det) > 1e-9 * n.squaredNorm()))
        return f;
    Eigen::Matrix2d inv;
    inv << n(1, 1) / det, -n(0, 1) / det, -n(1, 0) / det, n(0, 0) / det;
    f.m.row(0) = (inv * bx).transpose();
    f.m.row(1) = (inv * by).transpose();
    double ss = 0;
    for (std::size_t k = 0; k < d.size(); ++k) {
        const double r = (shift[k] - f.m * d[k]).norm();
        f.residual.push_back(r);
        ss += w[k] * r * r;
    }
    // The variance of unit weight over both components (2n values, 4 unknowns); each
    // row's covariance is that times the inverse normal matrix.
    const double sigma2 = ss / std::max(1.0, 2.0 * static_cast<double>(d.size()) - 4.0);
    for (int c = 0; c < 2; ++c)
        f.se(0, c) = f.se(1, c) = std::sqrt(std::max(0.0, sigma2 * inv(c, c)));
    f.ok = true;
    return f;
}

double residual(const std::vector<Eigen::Vector2d>& p, const TilePair& pair)
{
    return (p[static_cast<std::size_t>(pair.b)] - p[static_cast<std::size_t>(pair.a)] - pair.reg.shiftPx).norm();
}

} // namespace

StageModel fitStageModel(const std::vector<Eigen::Vector2d>& stagePx, const std::vector<TilePair>& pairs)
{
    StageModel model;
    if (stagePx.empty())
        return model;
    for (const Eigen::Vector2d& s : stagePx)
        model.centrePx += s;
    model.centrePx /= static_cast<double>(stagePx.size());
    std::vector<Eigen::Vector2d> d, shift;
    std::vector<double> w;
    for (const TilePair& p : pairs)
        if (p.reg.accepted() && p.a >= 0 && p.b >= 0 && p.a < static_cast<int>(stagePx.size()) && p.b < static_cast<int>(stagePx.size())) {
            d.push_back(stagePx[static_cast<std::size_t>(p.b)] - stagePx[static_cast<std::size_t>(p.a)]);
            shift.push_back(p.reg.shiftPx);
            w.push_back(std::max(0.05, p.reg.ncc) * std::max(0.05, p.reg.ncc));
        }
    ModelFit f = solveModel(d, shift, w);
    if (!f.ok)
        return model;
    // One refit without the pairs a bad registration or a displaced row put far off.
    std::vector<double> sorted = f.residual;
    std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2), sorted.end());
    const double limit = std::max(0.5, 3 * sorted[sorted.size() / 2]);
    std::vector<Eigen::Vector2d> d2, shift2;
    std::vector<double> w2;
    for (std::size_t k = 0; k < d.size(); ++k)
        if (f.residual[k] <= limit) {
            d2.push_back(d[k]);
            shift2.push_back(shift[k]);
            w2.push_back(w[k]);
        }
    const ModelFit refit = solveModel(d2, shift2, w2);
    if (!refit.ok)
        return model;
    model.m = refit.m;
    model.pairs = static_cast<int>(d2.size());
    const Eigen::Matrix2d dev = refit.m - Eigen::Matrix2d::Identity();
    bool significant = false;
    for (int r = 0; r < 2; ++r)
        for (int c = 0; c < 2; ++c)
            significant = significant || std::abs(dev(r, c)) > kModelSignificance * refit.se(r, c);
    double effect = 0;
    for (const Eigen::Vector2d& s : stagePx)
        effect = std::max(effect, (dev * (s - model.centrePx)).norm());
    model.used = significant && effect > kModelMinEffectPx;
    return model;
}

Placement placeTiles(const std::vector<Eigen::Vector2d>& measuredPx, std::vector<TilePair>& pairs, const PlacementOptions& o)
{
    Placement out;
    if (o.fitStageModel)
        out.stageModel = fitStageModel(measuredPx, pairs);
    // From here on "stage" is the prior: the measured positions, through the model when used.
    std::vector<Eigen::Vector2d> stagePx = measuredPx;
    if (out.stageModel.used)
        for (Eigen::Vector2d& s : stagePx)
            s = out.stageModel.apply(s);
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
    double sum2 = 0, sum2Model = 0;
    int counted = 0;
    for (int i = 0; i < n; ++i) {
        const std::size_t k = static_cast<std::size_t>(i);
        if (out.placedByStage[k]) {
            // Exactly its (modelled) stage position: the solve gives it that up to rounding.
            out.positionsPx[k] = stagePx[k];
            continue;
        }
        const double d = (out.positionsPx[k] - measuredPx[k]).norm();
        const double dm = (out.positionsPx[k] - stagePx[k]).norm();
        sum2 += d * d;
        sum2Model += dm * dm;
        out.worstCorrectionPx = std::max(out.worstCorrectionPx, d);
        out.worstBeyondModelPx = std::max(out.worstBeyondModelPx, dm);
        ++counted;
    }
    out.rmsBeyondModelPx = counted ? std::sqrt(sum2Model / counted) : 0.0;
    out.rmsCorrectionPx = counted ? std::sqrt(sum2 / counted) : 0.0;
    return out;
}

} // namespace imaging
