#pragma once
// Least-squares polynomial fits of a positioning error curve, as seed 002 does
// with MATLAB's Curve Fitting toolbox (§3.2–3.3): orders 1–5 side by side with
// SSE, R² and adjusted R², and the order to use.
//
// Numerics: positions are centred and scaled to t ∈ [−1, 1] before the
// Vandermonde matrix is built, and the system is solved by column-pivoting
// Householder QR, never by the normal equations (whose condition number is the
// square of an already poor one: x⁵ over 0–100 mm spans ten decades). The
// coefficients are converted back to powers of the position in mm at the end.
#include "motion/calibration/error_polynomial.h"
#include "motion/metrology/problem.h"

#include <cstddef>
#include <optional>
#include <vector>

namespace motion::metrology {

struct FitPoint {
    double positionMm = 0;
    double errorUm = 0;   ///< measured − nominal, as seed 002 §3.1 defines it
};

struct PolynomialFit {
    int order = 0;
    bool available = false;               ///< enough distinct points for this order with a residual left
    ErrorPolynomial polynomial;           ///< c0 first; position in mm, error in µm
    double sseUm2 = 0;                    ///< Σ residual², µm²
    double r2 = 0;                        ///< 1 − SSE/SST
    double adjustedR2 = 0;                ///< 1 − (1 − R²)(n − 1)/(n − p − 1), p = order
    std::size_t points = 0;
};

/// The table of orders 1…maxOrder and the one chosen.
struct FitTable {
    std::vector<PolynomialFit> orders;    ///< orders[k] has order k + 1
    int chosenOrder = 0;                  ///< 0 when nothing could be fitted
    bool chosenByOperator = false;
    motion::msg::Problems problems;

    const PolynomialFit* chosen() const;
};

constexpr int kMaxFitOrder = 5;
/// A higher order replaces the one chosen so far only when its partial F statistic
/// against it reaches this: the F-to-enter of stepwise regression. Adjusted R² alone
/// rises whenever F > 1, which noise does about one time in three for each extra
/// term; F ≥ 4 is roughly the 5–10 % significance level at these sample sizes.
constexpr double kFToEnter = 4.0;

/// One order. Not available (and all figures 0) when there are fewer than order + 2
/// points or fewer than order + 1 distinct positions.
PolynomialFit fitPolynomial(const std::vector<FitPoint>& points, int order);

/// Orders 1…5. Without `operatorOrder` the order is chosen by adjusted R² with a
/// significance margin: start from the lowest available order and move to a higher
/// one m when F = ((SSE_k − SSE_m)/(m − k)) / (SSE_m/(n − m − 1)) ≥ kFToEnter against
/// the order k chosen so far (F > 1 is exactly "adjusted R² is higher", so the order
/// chosen always has a higher adjusted R² than every order it replaced). Residuals at
/// rounding level count as none, so exact data picks the lowest exact order.
/// motion::msg::Problems: fewer than 3 points, a value that is not finite, an operator's order
/// outside 1–5 or without enough points.
FitTable fitPolynomials(const std::vector<FitPoint>& points, std::optional<int> operatorOrder = std::nullopt);

/// Partial F statistic of `higher` against `lower` (both available, same points);
/// 0 when the higher order explains nothing more.
double partialF(const PolynomialFit& lower, const PolynomialFit& higher);

} // namespace motion::metrology
