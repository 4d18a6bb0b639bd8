#pragma once
// What the accuracy-bench validators return: every problem at once, each with
// the path of the field at fault ("targets_mm[3]", "settle.timeout_s") and a
// message for a person (an id plus typed arguments, worded in widgets/ or app/).
// A warning does not stop a run (ISO 230-2 recommends five cycles; two can still
// be measured); an error does.
#include "motion/message.h"

#include <string>
#include <vector>

namespace motion::metrology {

struct Problem {
    std::string path;     ///< "" for the whole definition or data set
    msg::Message message;
    bool warning = false;
};
using Problems = std::vector<Problem>;

bool hasErrors(const Problems& problems);

/// "settle" + "timeout_s" → "settle.timeout_s"; "" + "cycles" → "cycles".
std::string fieldPath(const std::string& parent, const std::string& key);
/// "targets_mm" + 3 → "targets_mm[3]".
std::string indexPath(const std::string& parent, std::size_t index);

/// Shared checks that record a problem and return false when `value` is not a
/// finite number in [min, max]. Messages: accuracy.value_not_finite,
/// accuracy.value_below, accuracy.value_above, each with the value and its unit.
bool checkRange(Problems& out, const std::string& path, double value, double min, double max, msg::Unit unit);

} // namespace motion::metrology
