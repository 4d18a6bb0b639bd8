#pragma once
// What the plate and recipe models share: the validators return every problem at
// once as motion::msg::Problems, each with the path of the field at fault ("steps[4].wells"),
// so the file layer can add the line and column and the GUI can point at the step.
// Messages are data (plate.*, recipe.*), worded in widgets/wording/.
#include "motion/message.h"
#include "motion/problem.h"

#include <string>
#include <vector>

namespace motion::plates {

// The plate models report motion::msg::Problem (motion/problem.h); their paths join the same way.
using motion::msg::fieldPath;
using motion::msg::hasErrors;
using motion::msg::indexPath;

/// Numbers for logs and labels: up to 6 significant digits, no trailing zeros ("12.5", "1000").
std::string formatMm(double v);

/// Message arguments in the units the plate models use.
inline motion::msg::Arg mmArg(std::string name, double v) { return motion::msg::real(std::move(name), v, motion::msg::Unit::Mm); }
inline motion::msg::Arg ulArg(std::string name, double v) { return motion::msg::real(std::move(name), v, motion::msg::Unit::Ul); }
inline motion::msg::Arg textArg(std::string name, std::string v) { return motion::msg::verbatim(std::move(name), std::move(v)); }

} // namespace motion::plates
