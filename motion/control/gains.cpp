#include "motion/control/gains.h"

#include <cmath>
#include <cstdio>
#include <limits>

namespace motion::control {

double ContinuousGains::tiS() const
{
    return kiPerS > 0 ? kp / kiPerS : std::numeric_limits<double>::infinity();
}

double ContinuousGains::tdS() const { return kp > 0 ? kdS / kp : 0.0; }

DiscreteGains toDiscrete(const ContinuousGains& g, double periodS)
{
    return {g.kp, g.kiPerS * periodS, g.kdS / periodS};
}

ContinuousGains toContinuous(const DiscreteGains& g, double periodS)
{
    return {g.kp, g.ki / periodS, g.kd * periodS};
}

std::vector<GainProblem> checkGains(const DiscreteGains& g, const GainLimits& limits)
{
    std::vector<GainProblem> out;
    const char* names[3] = {"kp", "ki", "kd"};
    const double values[3] = {g.kp, g.ki, g.kd};
    const double maxima[3] = {limits.kpMax, limits.kiMax, limits.kdMax};
    for (int i = 0; i < 3; ++i) {
        const double v = values[i];
        char buf[160];
        if (!std::isfinite(v))
            std::snprintf(buf, sizeof buf, "%s is %s: a gain must be a finite number", names[i], std::isnan(v) ? "NaN" : "infinite");
        else if (v < 0)
            std::snprintf(buf, sizeof buf, "%s = %g must not be negative", names[i], v);
        else if (v > maxima[i])
            std::snprintf(buf, sizeof buf, "%s = %g is above the largest accepted %g per control period", names[i], v, maxima[i]);
        else
            continue;
        out.push_back({i, names[i], v, buf});
    }
    return out;
}

} // namespace motion::control
