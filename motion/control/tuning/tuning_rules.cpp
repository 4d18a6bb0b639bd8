#include "motion/control/tuning/tuning_rules.h"

namespace motion::control {

const std::vector<TuningRule>& tuningRules()
{
    // Seed 002 Table 1 prints Ki and Kd directly: PI Ki = 1.2·Kp/Tu is Ti = Tu/1.2,
    // PID Ki = 2·Kp/Tu is Ti = Tu/2 and Kd = Kp·Tu/8 is Td = Tu/8, the 1942 values.
    static const std::vector<TuningRule> rules = {
        {"zn-p", "Ziegler–Nichols P", "seed 002 Table 1 (Ziegler & Nichols 1942)", 1 / 2.0, 0, 0},
        {"zn-pi", "Ziegler–Nichols PI", "seed 002 Table 1 (Ziegler & Nichols 1942)", 1 / 2.2, 1 / 1.2, 0},
        {"zn-pid", "Ziegler–Nichols PID", "seed 002 Table 1 (Ziegler & Nichols 1942)", 0.6, 1 / 2.0, 1 / 8.0},
        {"tl-pi", "Tyreus–Luyben PI", "Tyreus & Luyben 1992, Ind. Eng. Chem. Res. 31:2625", 1 / 3.2, 2.2, 0},
        {"tl-pid", "Tyreus–Luyben PID", "Tyreus & Luyben 1992, Ind. Eng. Chem. Res. 31:2625", 1 / 2.2, 2.2, 1 / 6.3},
        {"pessen", "Pessen integral rule PID", "Pessen 1994, J. Dyn. Syst. Meas. Control 116:553", 0.7, 0.4, 0.15},
        {"some-overshoot", "Z-N \"some overshoot\" PID", "Z-N variant as tabulated by Microstar Laboratories", 1 / 3.0, 0.5, 1 / 3.0},
        {"no-overshoot", "Z-N \"no overshoot\" PID", "Z-N variant as tabulated by Microstar Laboratories", 0.2, 0.5, 1 / 3.0},
    };
    return rules;
}

const TuningRule* findRule(const std::string& id)
{
    for (const auto& r : tuningRules())
        if (id == r.id)
            return &r;
    return nullptr;
}

ContinuousGains applyRule(const TuningRule& rule, double ku, double tuS)
{
    ContinuousGains g;
    g.kp = rule.kpPerKu * ku;
    g.kiPerS = rule.tiPerTu > 0 ? g.kp / (rule.tiPerTu * tuS) : 0;
    g.kdS = g.kp * rule.tdPerTu * tuS;
    return g;
}

} // namespace motion::control
