#include "motion/metrology/grid/stage_errors.h"

#include <cmath>
#include <string>

namespace motion::metrology {

StageErrors builtInStageErrors()
{
    StageErrors e;
    e.x.pitchPolyUm = {1.563, 0.9473, -0.0006};
    e.y.pitchPolyUm = {1.021, 0.6397, 0.0168};
    return e;
}

double polynomialUm(const std::vector<double>& c, double mm)
{
    double v = 0;
    for (auto it = c.rbegin(); it != c.rend(); ++it)
        v = v * mm + *it;
    return v;
}

namespace {

double halfBacklashAgainst(std::optional<Direction> approach, double backlashUm)
{
    if (!approach)
        return 0;
    return *approach == Direction::Up ? -0.5 * backlashUm : 0.5 * backlashUm;
}

void checkStagePolynomial(motion::msg::Problems& out, const std::string& path, const std::vector<double>& c, double travelMm)
{
    if (c.size() > kMaxStageErrorCoefficients) {
        out.push_back(motion::msg::error(path, motion::msg::make("stage_errors.too_many_coefficients",
                                                 {motion::msg::integer("count", static_cast<long long>(c.size())),
                                                  motion::msg::integer("max", static_cast<long long>(kMaxStageErrorCoefficients))})));
        return;
    }
    bool finite = true;
    for (std::size_t k = 0; k < c.size(); ++k)
        finite = checkRange(out, indexPath(path, k), c[k], -kMaxStageErrorUm, kMaxStageErrorUm, motion::msg::Unit::None) && finite;
    if (!finite)
        return;
    // Checked at 101 points of the travel: a curve that leaves ±10 mm is a typo in a
    // coefficient's power, not a stage.
    for (int i = 0; i <= 100; ++i) {
        const double mm = travelMm * i / 100.0;
        const double v = polynomialUm(c, mm);
        if (std::abs(v) > kMaxStageErrorUm) {
            out.push_back(motion::msg::error(path, motion::msg::make("stage_errors.curve_too_large",
                                                     {motion::msg::real("position", mm, motion::msg::Unit::Mm),
                                                      motion::msg::real("value", v, motion::msg::Unit::Um),
                                                      motion::msg::real("max", kMaxStageErrorUm, motion::msg::Unit::Um)})));
            return;
        }
    }
}

} // namespace

ErrorVectorUm stageErrorUm(const StageErrors& e, double xMm, double yMm, std::optional<Direction> approachX,
                           std::optional<Direction> approachY)
{
    ErrorVectorUm v;
    v.xUm = polynomialUm(e.x.pitchPolyUm, xMm) + polynomialUm(e.y.straightnessPolyUm, yMm)
            + e.squarenessUrad * yMm * 1e-3 + halfBacklashAgainst(approachX, e.backlashXUm);
    v.yUm = polynomialUm(e.y.pitchPolyUm, yMm) + polynomialUm(e.x.straightnessPolyUm, xMm)
            + halfBacklashAgainst(approachY, e.backlashYUm);
    return v;
}

motion::msg::Problems validate(const StageErrors& e, double travelMm)
{
    motion::msg::Problems out;
    checkStagePolynomial(out, "x.pitch_poly_um", e.x.pitchPolyUm, travelMm);
    checkStagePolynomial(out, "x.straightness_poly_um", e.x.straightnessPolyUm, travelMm);
    checkStagePolynomial(out, "y.pitch_poly_um", e.y.pitchPolyUm, travelMm);
    checkStagePolynomial(out, "y.straightness_poly_um", e.y.straightnessPolyUm, travelMm);
    checkRange(out, "squareness_urad", e.squarenessUrad, -kMaxSquarenessUrad, kMaxSquarenessUrad, motion::msg::Unit::None);
    checkRange(out, "backlash_um.x", e.backlashXUm, 0, kMaxStageErrorUm, motion::msg::Unit::Um);
    checkRange(out, "backlash_um.y", e.backlashYUm, 0, kMaxStageErrorUm, motion::msg::Unit::Um);
    return out;
}

} // namespace motion::metrology
