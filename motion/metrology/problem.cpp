#include "motion/metrology/problem.h"

#include <cmath>

namespace motion::metrology {

bool hasErrors(const Problems& problems)
{
    for (const Problem& p : problems)
        if (!p.warning)
            return true;
    return false;
}

std::string fieldPath(const std::string& parent, const std::string& key)
{
    return parent.empty() ? key : parent + "." + key;
}

std::string indexPath(const std::string& parent, std::size_t index)
{
    return parent + "[" + std::to_string(index) + "]";
}

bool checkRange(Problems& out, const std::string& path, double value, double min, double max, msg::Unit unit)
{
    if (!std::isfinite(value)) {
        out.push_back({path, msg::make("accuracy.value_not_finite"), false});
        return false;
    }
    if (value < min) {
        out.push_back({path, msg::make("accuracy.value_below", {msg::real("value", value, unit), msg::real("min", min, unit)}), false});
        return false;
    }
    if (value > max) {
        out.push_back({path, msg::make("accuracy.value_above", {msg::real("value", value, unit), msg::real("max", max, unit)}), false});
        return false;
    }
    return true;
}

} // namespace motion::metrology
