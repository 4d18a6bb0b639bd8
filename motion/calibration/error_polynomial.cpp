#include "motion/calibration/error_polynomial.h"

#include <cmath>

namespace motion {

double ErrorPolynomial::errorUm(double x) const
{
    double sum = 0;
    for (auto it = coefficientsUm.rbegin(); it != coefficientsUm.rend(); ++it)
        sum = sum * x + *it;  // Horner, highest power first
    return sum;
}

double ErrorPolynomial::slopeUmPerMm(double x) const
{
    double sum = 0;
    for (std::size_t k = coefficientsUm.size(); k-- > 1;)
        sum = sum * x + static_cast<double>(k) * coefficientsUm[k];
    return sum;
}

double compensatedCommandMm(const ErrorPolynomial& e, double targetMm)
{
    // f(c) = c + e(c)/1000 − target; f′(c) = 1 + e′(c)/1000, within a few per mille
    // of 1 for any sane stage, so Newton converges to rounding in two or three steps.
    double c = targetMm - e.errorUm(targetMm) * 1e-3;
    for (int i = 0; i < 8; ++i) {
        const double f = c + e.errorUm(c) * 1e-3 - targetMm;
        const double slope = 1.0 + e.slopeUmPerMm(c) * 1e-3;
        if (!(std::fabs(slope) > 1e-6))
            break;  // a curve this steep is not a positioning error; leave the one-step answer
        const double next = c - f / slope;
        if (std::fabs(next - c) < 1e-12)
            return next;
        c = next;
    }
    return c;
}

} // namespace motion
