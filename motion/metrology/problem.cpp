#include "motion/metrology/problem.h"

#include <cmath>

namespace motion::metrology {

bool checkRange(msg::Problems& out, const std::string& path, double value, double min, double max, msg::Unit unit)
{
    if (!std::isfinite(value)) {
        out.push_back({path, msg::make("accuracy.value_not_finite")});
        return false;
    }
    if (value < min) {
        out.push_back({path, msg::make("accuracy.value_below", {msg::real("value", value, unit), msg::real("min", min, unit)})});
        return false;
    }
    if (value > max) {
        out.push_back({path, msg::make("accuracy.value_above", {msg::real("value", value, unit), msg::real("max", max, unit)})});
        return false;
    }
    return true;
}

} // namespace motion::metrology
