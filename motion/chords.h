#pragma once
// Seed 002: sine and cosine moves by straight chords. The seed divides the curve into equal
// angle (= equal x) parts, joins the ends of each part by a line and runs each line by
// point-by-point interpolation. It gives no rule for the number of parts; we take it from a
// chord-error tolerance: the gap between y = f(x) and a chord of width h is at most
// h²/8·max|f''|, so h = √(8·tol / max|f''|). For y = A·sin(2πx/W), max|f''| = A(2π/W)².
// That gap is vertical; the normal distance to the curve is never larger.

#include "motion/interpolation.h"

#include <functional>
#include <vector>

namespace motion {

struct PointMm {
    double x = 0, y = 0;
};

/// Vertices of equal-width chords of y = f(x) on [x0, x1], with |f''| ≤ maxAbsSecondDerivative,
/// each chord within toleranceMm of the curve. Empty when the inputs are not finite/positive.
std::vector<PointMm> functionChords(const std::function<double(double)>& f, double x0, double x1,
                                    double maxAbsSecondDerivative, double toleranceMm);

/// y = A·sin(2πx/W) (or cosine) on [0, length].
std::vector<PointMm> sineChords(double amplitudeMm, double wavelengthMm, double lengthMm, double toleranceMm,
                                bool cosine = false);

/// Runs a polyline (mm) through point-by-point line interpolation at stepMm. Vertices are rounded
/// to the step grid; returns every grid point visited (in steps), starting at the first vertex.
std::vector<GridPoint> interpolatePolyline(const std::vector<PointMm>& vertices, double stepMm);

/// Largest normal distance (mm) of the points from y = f(x), searched within ±window of each x.
double maxDistanceToGraphMm(const std::vector<PointMm>& points, const std::function<double(double)>& f,
                            double windowMm);

}  // namespace motion
