#include "motion/plans/recipes/move_time.h"

#include "motion/seed_scurve.h"

#include <algorithm>
#include <cmath>

namespace motion::plates {

double moveTimeS(const std::vector<AxisDelta>& axes, double speed)
{
    const auto p = moveProfile(axes, speed);
    return p ? p->duration() : 0;
}

std::optional<motion::SeedSCurve> moveProfile(const std::vector<AxisDelta>& axes, double speed)
{
    double len2 = 0, vDefault = 1e300;
    for (const AxisDelta& a : axes) {
        len2 += a.delta * a.delta;
        vDefault = std::min(vDefault, a.axis->defaultSpeed);
    }
    const double len = std::sqrt(len2);
    if (len < 1e-9 || axes.empty())
        return std::nullopt;
    double vPath = speed > 0 ? speed : vDefault, aPath = 1e300, accelTime = 0;
    for (const AxisDelta& a : axes) {
        const double u = std::abs(a.delta) / len;
        if (u < 1e-12)
            continue;
        vPath = std::min(vPath, a.axis->maxSpeed / u);
        aPath = std::min(aPath, a.axis->maxAccel / u);
        accelTime = std::max(accelTime, a.axis->accelTimeS);
    }
    accelTime = std::max(accelTime, 1.5 * vPath / aPath);
    return motion::SeedSCurve::plan(len, vPath, accelTime);
}

} // namespace motion::plates
