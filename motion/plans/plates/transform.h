#pragma once
// Plate frame → machine XY: machine = M · plate + t, with M a 2 × 2 matrix.
// A slot's nominal placement is a rotation; a calibration adds scale (and the
// taught offset). See calibration.h for how M is fitted.
#include <cmath>

namespace motion::plates {

struct PointMm {
    double x = 0, y = 0;
};

struct PlateTransform {
    double m11 = 1, m12 = 0, m21 = 0, m22 = 1;  ///< linear part
    double txMm = 0, tyMm = 0;                  ///< where the plate frame's origin lands

    PointMm apply(const PointMm& p) const { return {m11 * p.x + m12 * p.y + txMm, m21 * p.x + m22 * p.y + tyMm}; }
    /// A direction in the plate frame (touch-off offsets): no translation.
    PointMm applyVector(const PointMm& v) const { return {m11 * v.x + m12 * v.y, m21 * v.x + m22 * v.y}; }

    /// Rotation by `rotationDeg` (counter-clockwise in machine XY), scales per
    /// plate axis, then the offset.
    static PlateTransform make(double originXMm, double originYMm, double rotationDeg, double scaleX = 1, double scaleY = 1)
    {
        const double a = rotationDeg * 3.14159265358979323846 / 180.0;
        PlateTransform t;
        t.m11 = std::cos(a) * scaleX;
        t.m12 = -std::sin(a) * scaleY;
        t.m21 = std::sin(a) * scaleX;
        t.m22 = std::cos(a) * scaleY;
        t.txMm = originXMm;
        t.tyMm = originYMm;
        return t;
    }
};

} // namespace motion::plates
