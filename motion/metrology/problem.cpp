#include "motion/metrology/problem.h"

#include <cmath>

namespace motion::metrology {

bool checkRange(motion::msg::Problems& out, const std::string& path, double value, double min, double max, motion::msg::Unit unit)
{
    if (!std::isfinite(value)) {
        out.push_back({path, motion::msg::make("accuracy.value_not_finite")});
        return false;
    }
    if (value < min) {
        out.push_back({path, motion::msg::make("accuracy.value_below", {motion::msg::real("value", value, unit), motion::msg::real("min", min, unit)})});
        return false;
    }
    if (value > max) {
        out.push_back({path, motion::msg::make("accuracy.value_above", {motion::msg::real("value", value, unit), motion::msg::real("max", max, unit)})});
        return false;
    }
    return true;
}

} // namespace motion::metrology
