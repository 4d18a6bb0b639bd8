#pragma once
// A positioning error curve e(x) = c0 + c1·x + c2·x² + … (µm over mm), as seed 002
// fits to laser-interferometer data (work point minus command, its §3.1), and the
// command that cancels it. Shared by the scan planner's compensation and, later,
// the calibration bench that fits such curves.
#include <vector>

namespace motion {

struct ErrorPolynomial {
    std::vector<double> coefficientsUm;  ///< c0 first; x in mm, e in µm

    double errorUm(double positionMm) const;
    double slopeUmPerMm(double positionMm) const;
};

/// The command c that puts the work point on `targetMm`: the root of
/// c + e(c)/1000 = target, by Newton's method from the target.
///
/// Seed 002 (§3.1) subtracts e(target) from the command instead. That misses by
/// e(target) − e(target − e(target)) ≈ e′·e: on its Y curve 0.93 µm at 100 mm,
/// a fifth of its ±5 µm budget (tests/motion/scan_compensation_test.cpp).
double compensatedCommandMm(const ErrorPolynomial& e, double targetMm);

} // namespace motion
