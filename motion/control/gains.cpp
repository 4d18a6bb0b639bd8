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
        const char* id = nullptr;
        if (!std::isfinite(v))
            id = "tuning.gain_not_finite";
        else if (v < 0)
            id = "tuning.gain_negative";
        else if (v > maxima[i])
            id = "tuning.gain_above_limit";
        else
            continue;
        out.push_back({i, names[i], v, maxima[i],
                       motion::msg::make(id, {motion::msg::verbatim("gain", names[i]), motion::msg::real("value", v), motion::msg::real("max", maxima[i])})});
    }
    return out;
}

std::string wireText(const GainProblem& p)
{
    char buf[160];
    if (!std::isfinite(p.value))
        std::snprintf(buf, sizeof buf, "%s is %s: a gain must be a finite number", p.field.c_str(), std::isnan(p.value) ? "NaN" : "infinite");
    else if (p.value < 0)
        std::snprintf(buf, sizeof buf, "%s = %g must not be negative", p.field.c_str(), p.value);
    else
        std::snprintf(buf, sizeof buf, "%s = %g is above the largest accepted %g per control period", p.field.c_str(), p.value, p.limit);
    return buf;
}

} // namespace motion::control
