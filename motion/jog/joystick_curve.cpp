#include "motion/jog/joystick_curve.h"

#include <algorithm>
#include <cmath>

namespace motion::jog {

namespace {
double shapeMagnitude(double m, const StickShaping& s)
{
    const double dead = std::clamp(s.deadband, 0.0, 0.9);
    const double e = std::clamp(s.expo, 0.0, 1.0);
    if (!(m > dead))
        return 0.0;
    const double u = std::min(1.0, (m - dead) / (1.0 - dead));
    return (1.0 - e) * u + e * u * u * u;
}
} // namespace

double shapeAxis(double deflection, const StickShaping& s)
{
    if (!std::isfinite(deflection))
        return 0.0;
    const double out = shapeMagnitude(std::fabs(deflection), s);
    return deflection < 0 ? -out : out;
}

motion::path::Vec2 shapeStick(motion::path::Vec2 d, const StickShaping& s)
{
    const double m = motion::path::norm(d);
    if (!std::isfinite(m) || m <= 0)
        return {0, 0};
    const double out = shapeMagnitude(std::min(m, 1.0), s);
    return (out / m) * d;
}

} // namespace motion::jog
