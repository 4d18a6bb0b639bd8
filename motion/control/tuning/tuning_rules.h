#pragma once
// Tuning rules from the ultimate point (Ku, Tu): each gives continuous-form
// gains (Kp, Ki = Kp/Ti in 1/s, Kd = Kp·Td in s) and names its source.
#include "motion/control/gains.h"

#include <string>
#include <vector>

namespace motion::control {

struct TuningRule {
    const char* id;        ///< stable key for files and the CLI: "zn-p", "zn-pid", "tl-pi", …
    const char* name;      ///< for people (translated by the GUI)
    const char* source;
    double kpPerKu;        ///< Kp = kpPerKu·Ku
    double tiPerTu;        ///< Ti = tiPerTu·Tu; 0: no integral action
    double tdPerTu;        ///< Td = tdPerTu·Tu; 0: no derivative action
};

/// In display order: seed 002's Ziegler–Nichols rows first.
const std::vector<TuningRule>& tuningRules();
const TuningRule* findRule(const std::string& id);

/// The gains a rule gives for (Ku, Tu).
ContinuousGains applyRule(const TuningRule& rule, double ku, double tuS);

} // namespace motion::control
