#pragma once
// Pass or fail: an axis's limits on the ISO 230-2 figures, and the verdict of an
// evaluation against them. Seed 000's Table 1 gives the analyzer's limits.
#include "motion/metrology/linear/iso230_2.h"
#include "motion/metrology/problem.h"

#include <optional>
#include <string>
#include <vector>

namespace motion::metrology {

/// Upper limits in mm; an empty one is not judged.
struct AxisTolerances {
    std::optional<double> aMm;  ///< positioning accuracy A (A↑ for a unidirectional test)
    std::optional<double> rMm;  ///< repeatability R (R↑)
    std::optional<double> eMm;  ///< systematic positioning error E (E↑)
    std::optional<double> mMm;  ///< mean positioning error M (bidirectional only)
    std::optional<double> bMm;  ///< reversal value B (bidirectional only)

    bool empty() const { return !aMm && !rMm && !eMm && !mMm && !bMm; }
};

/// Seed 000, Table 1 (the analyzer's manipulator): positioning accuracy ≤ 0.4 mm
/// and repeatability ≤ 0.2 mm on X and Y, ≤ 0.3 and ≤ 0.15 mm on Z. Other axes
/// (the pump P) have no limits there: empty.
AxisTolerances analyzerTolerances(char axis);

struct Verdict {
    std::string figure;  ///< the key of the figure judged: "A", "A_up", "R", …
    double valueMm = 0;
    double limitMm = 0;
    bool pass = false;
};

/// One verdict per limit that applies. A unidirectional evaluation is judged on
/// A↑, R↑, E↑; limits on M and B do not apply to it and are skipped.
std::vector<Verdict> judge(const Evaluation& e, const AxisTolerances& t);
bool allPass(const std::vector<Verdict>& verdicts);

/// Each limit present must be a finite number above 0 (path "tolerances.a_mm", …).
void validateTolerances(const AxisTolerances& t, const std::string& path, motion::msg::Problems& out);

} // namespace motion::metrology
