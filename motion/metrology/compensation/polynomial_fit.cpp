#include "motion/metrology/compensation/polynomial_fit.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

namespace motion::metrology {

namespace {

double binomial(int n, int k)
{
    double r = 1;
    for (int i = 1; i <= k; ++i)
        r = r * (n - k + i) / i;
    return r;
}

std::size_t distinctPositions(const std::vector<FitPoint>& points)
{
    std::set<long long> nm;
    for (const FitPoint& p : points)
        nm.insert(std::llround(p.positionMm * 1e6));
    return nm.size();
}

/// Below this an SSE is rounding, not misfit: a picometre rms per point, or the
/// twelfth digit of the largest error.
double sseFloorUm2(const std::vector<FitPoint>& points)
{
    double big = 0;
    for (const FitPoint& p : points)
        big = std::max(big, std::fabs(p.errorUm));
    const double rms = std::max(1e-6, big * 1e-12);
    return static_cast<double>(points.size()) * rms * rms;
}

double fStatistic(double sseLow, int orderLow, double sseHigh, int orderHigh, std::size_t n)
{
    const double dfHigh = static_cast<double>(n) - orderHigh - 1;
    if (!(sseLow > sseHigh) || dfHigh <= 0)
        return 0;
    if (sseHigh <= 0)
        return std::numeric_limits<double>::infinity();
    return ((sseLow - sseHigh) / (orderHigh - orderLow)) / (sseHigh / dfHigh);
}

} // namespace

const PolynomialFit* FitTable::chosen() const
{
    if (chosenOrder < 1 || chosenOrder > static_cast<int>(orders.size()))
        return nullptr;
    return &orders[static_cast<std::size_t>(chosenOrder - 1)];
}

PolynomialFit fitPolynomial(const std::vector<FitPoint>& points, int order)
{
    PolynomialFit f;
    f.order = order;
    f.points = points.size();
    const std::size_t n = points.size();
    if (order < 1 || n < static_cast<std::size_t>(order) + 2 || distinctPositions(points) < static_cast<std::size_t>(order) + 1)
        return f;

    double lo = points.front().positionMm, hi = lo;
    for (const FitPoint& p : points) {
        lo = std::min(lo, p.positionMm);
        hi = std::max(hi, p.positionMm);
    }
    const double centre = (lo + hi) / 2, half = (hi - lo) / 2;
    const int cols = order + 1;
    Eigen::MatrixXd v(static_cast<Eigen::Index>(n), cols);
    Eigen::VectorXd y(static_cast<Eigen::Index>(n));
    for (std::size_t r = 0; r < n; ++r) {
        const double t = (points[r].positionMm - centre) / half;
        double power = 1;
        for (int c = 0; c < cols; ++c) {
            v(static_cast<Eigen::Index>(r), c) = power;
            power *= t;
        }
        y(static_cast<Eigen::Index>(r)) = points[r].errorUm;
    }
    const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(v);
    if (qr.rank() < cols)
        return f;
    const Eigen::VectorXd a = qr.solve(y);

    // Residuals in the scaled basis, where the fit was made, not through the
    // converted coefficients.
    const Eigen::VectorXd residual = y - v * a;
    f.sseUm2 = residual.squaredNorm();
    const double mean = y.mean();
    const double sst = (y.array() - mean).square().sum();
    if (sst > 0) {
        f.r2 = 1 - f.sseUm2 / sst;
        f.adjustedR2 = 1 - (1 - f.r2) * static_cast<double>(n - 1) / static_cast<double>(n - static_cast<std::size_t>(order) - 1);
    } else {
        f.r2 = f.adjustedR2 = 1;  // a flat curve: every order explains all there is
    }

    // p(x) = Σ a_k (u·x + d)^k with u = 1/half, d = −centre/half; expand by the binomial theorem.
    const double u = 1 / half, d = -centre / half;
    std::vector<double> c(static_cast<std::size_t>(cols), 0.0);
    for (int k = 0; k < cols; ++k)
        for (int j = 0; j <= k; ++j)
            c[static_cast<std::size_t>(j)] += a(k) * binomial(k, j) * std::pow(u, j) * std::pow(d, k - j);
    f.polynomial.coefficientsUm = c;
    f.available = true;
    return f;
}

double partialF(const PolynomialFit& lower, const PolynomialFit& higher)
{
    if (!lower.available || !higher.available || higher.order <= lower.order)
        return 0;
    return fStatistic(lower.sseUm2, lower.order, higher.sseUm2, higher.order, higher.points);
}

FitTable fitPolynomials(const std::vector<FitPoint>& points, std::optional<int> operatorOrder)
{
    FitTable out;
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (!std::isfinite(points[i].positionMm))
            out.problems.push_back({fieldPath(indexPath("points", i), "position_mm"), motion::msg::make("accuracy.value_not_finite")});
        if (!std::isfinite(points[i].errorUm))
            out.problems.push_back({fieldPath(indexPath("points", i), "error_um"), motion::msg::make("accuracy.value_not_finite")});
    }
    if (operatorOrder && (*operatorOrder < 1 || *operatorOrder > kMaxFitOrder))
        out.problems.push_back({"order", motion::msg::make("compensation.order_out_of_range",
                                                   {motion::msg::integer("order", *operatorOrder), motion::msg::integer("min", 1), motion::msg::integer("max", kMaxFitOrder)})});
    if (points.size() < 3)
        out.problems.push_back({"points", motion::msg::make("compensation.too_few_points",
                                                    {motion::msg::integer("count", static_cast<long long>(points.size())), motion::msg::integer("min", 3)})});
    if (hasErrors(out.problems))
        return out;

    for (int order = 1; order <= kMaxFitOrder; ++order)
        out.orders.push_back(fitPolynomial(points, order));

    if (operatorOrder) {
        const PolynomialFit& f = out.orders[static_cast<std::size_t>(*operatorOrder - 1)];
        if (!f.available) {
            out.problems.push_back({"order", motion::msg::make("compensation.order_needs_more_points",
                                                       {motion::msg::integer("order", *operatorOrder),
                                                        motion::msg::integer("count", static_cast<long long>(points.size())),
                                                        motion::msg::integer("min", *operatorOrder + 2)})});
            return out;
        }
        out.chosenOrder = *operatorOrder;
        out.chosenByOperator = true;
        return out;
    }

    const double floor = sseFloorUm2(points);
    auto sse = [&](const PolynomialFit& f) { return f.sseUm2 <= floor ? 0.0 : f.sseUm2; };
    const PolynomialFit* best = nullptr;
    for (const PolynomialFit& f : out.orders) {
        if (!f.available)
            continue;
        if (!best || fStatistic(sse(*best), best->order, sse(f), f.order, f.points) >= kFToEnter)
            best = &f;
    }
    if (!best) {
        out.problems.push_back({"points", motion::msg::make("compensation.too_few_points",
                                                    {motion::msg::integer("count", static_cast<long long>(distinctPositions(points))), motion::msg::integer("min", 3)})});
        return out;
    }
    out.chosenOrder = best->order;
    return out;
}

} // namespace motion::metrology
