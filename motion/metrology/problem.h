#pragma once
// What the accuracy-bench validators share: they return every problem at once as
// motion::msg::Problems, each with the path of the field at fault ("targets_mm[3]",
// "settle.timeout_s") and a message for a person (an id plus typed arguments,
// worded in widgets/ or app/). A warning does not stop a run (ISO 230-2 recommends
// five cycles; two can still be measured); an error does.
#include "motion/message.h"
#include "motion/problem.h"

#include <string>
#include <vector>

namespace motion::metrology {

// The accuracy bench's models report motion::msg::Problem (motion/problem.h); their paths
// join the same way.
using motion::msg::fieldPath;
using motion::msg::hasErrors;
using motion::msg::indexPath;

/// Shared checks that record a problem and return false when `value` is not a
/// finite number in [min, max]. Messages: accuracy.value_not_finite,
/// accuracy.value_below, accuracy.value_above, each with the value and its unit.
bool checkRange(motion::msg::Problems& out, const std::string& path, double value, double min, double max, motion::msg::Unit unit);

} // namespace motion::metrology
