#include "motion/metrology/linear/tolerances.h"

#include <cmath>

namespace motion::metrology {

AxisTolerances analyzerTolerances(char axis)
{
    AxisTolerances t;
    if (axis == 'X' || axis == 'Y') {
        t.aMm = 0.4;
        t.rMm = 0.2;
    } else if (axis == 'Z') {
        t.aMm = 0.3;
        t.rMm = 0.15;
    }
    return t;
}

std::vector<Verdict> judge(const Evaluation& e, const AxisTolerances& t)
{
    std::vector<Verdict> out;
    if (!e.ok())
        return out;
    const Figures& f = e.figures;
    auto add = [&](const char* key, std::optional<double> value, std::optional<double> limit) {
        if (value && limit)
            out.push_back({key, *value, *limit, *value <= *limit});
    };
    if (e.bidirectional) {
        add("A", f.aMm, t.aMm);
        add("R", f.rMm, t.rMm);
        add("E", f.eMm, t.eMm);
        add("M", f.mMm, t.mMm);
        add("B", f.bMm, t.bMm);
    } else {
        add("A_up", f.aUpMm, t.aMm);
        add("R_up", f.rUpMm, t.rMm);
        add("E_up", f.eUpMm, t.eMm);
    }
    return out;
}

bool allPass(const std::vector<Verdict>& verdicts)
{
    for (const Verdict& v : verdicts)
        if (!v.pass)
            return false;
    return true;
}

void validateTolerances(const AxisTolerances& t, const std::string& path, motion::msg::Problems& out)
{
    auto check = [&](const char* key, const std::optional<double>& v) {
        if (!v)
            return;
        const std::string p = fieldPath(path, key);
        if (checkRange(out, p, *v, -INFINITY, 1000, motion::msg::Unit::Mm) && !(*v > 0))
            out.push_back({p, motion::msg::make("accuracy.value_not_positive", {motion::msg::real("value", *v, motion::msg::Unit::Mm)})});
    };
    check("a_mm", t.aMm);
    check("r_mm", t.rMm);
    check("e_mm", t.eMm);
    check("m_mm", t.mMm);
    check("b_mm", t.bMm);
}

} // namespace motion::metrology
