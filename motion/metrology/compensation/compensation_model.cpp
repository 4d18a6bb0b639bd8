#include "motion/metrology/compensation/compensation_model.h"

#include <algorithm>
#include <cmath>
#include <functional>

namespace motion::metrology {

namespace {

/// The c with c + error(c)/1000 = target. The slope 1 + error′/1000 is within a few
/// per mille of 1 for any real axis, so Newton converges to rounding in 2–3 steps.
double solveCommand(double targetMm, const std::function<double(double)>& errorUm, const std::function<double(double)>& slopeUmPerMm)
{
    double c = targetMm - errorUm(targetMm) * 1e-3;
    for (int i = 0; i < 20; ++i) {
        const double f = c + errorUm(c) * 1e-3 - targetMm;
        const double slope = 1 + slopeUmPerMm(c) * 1e-3;
        if (!(std::fabs(slope) > 1e-6))
            break;
        const double next = c - f / slope;
        if (std::fabs(next - c) < 1e-13)
            return next;
        c = next;
    }
    return c;
}

/// Piecewise-linear through (x[i], y[i]), held at the end values outside.
double interpolate(const std::vector<double>& x, const std::vector<double>& y, double at)
{
    if (at <= x.front())
        return y.front();
    if (at >= x.back())
        return y.back();
    const auto it = std::upper_bound(x.begin(), x.end(), at);
    const auto i = static_cast<std::size_t>(it - x.begin());
    const double w = (at - x[i - 1]) / (x[i] - x[i - 1]);
    return y[i - 1] + w * (y[i] - y[i - 1]);
}

double interpolationSlope(const std::vector<double>& x, const std::vector<double>& y, double at)
{
    if (at <= x.front() || at >= x.back())
        return 0;
    const auto i = static_cast<std::size_t>(std::upper_bound(x.begin(), x.end(), at) - x.begin());
    return (y[i] - y[i - 1]) / (x[i] - x[i - 1]);
}

/// Corrections (µm) that cancel a piecewise-linear error (µm) at its own nodes.
std::vector<double> cancellingCorrections(const std::vector<double>& x, const std::vector<double>& errorUm)
{
    std::vector<double> k;
    for (double target : x) {
        const double c = solveCommand(
            target, [&](double p) { return interpolate(x, errorUm, p); }, [&](double p) { return interpolationSlope(x, errorUm, p); });
        k.push_back((c - target) * 1e3);
    }
    return k;
}

double tableCorrectionUm(const CompensationModel& m, double targetMm, Direction approach)
{
    std::vector<double> x, k;
    for (const TablePoint& p : m.table) {
        x.push_back(p.nominalMm);
        k.push_back(approach == Direction::Up ? p.correctionUpUm : p.correctionDownUm);
    }
    if (x.empty())
        return 0;
    return interpolate(x, k, targetMm);
}

} // namespace

double CompensationModel::commandMm(double targetMm, Direction approach) const
{
    const double halfB = backlashUm / 2;
    if (kind == Kind::Table) {
        const double extra = perDirection ? 0 : (approach == Direction::Up ? halfB : -halfB);
        return targetMm + (tableCorrectionUm(*this, targetMm, approach) + extra) * 1e-3;
    }
    const double shift = approach == Direction::Up ? -halfB : halfB;
    auto clamp = [&](double x) { return std::clamp(x, validFromMm, validToMm); };
    return solveCommand(
        targetMm, [&](double x) { return polynomial.errorUm(clamp(x)) + shift; },
        [&](double x) { return x < validFromMm || x > validToMm ? 0.0 : polynomial.slopeUmPerMm(x); });
}

double CompensationModel::meanCommandMm(double targetMm) const
{
    if (kind == Kind::Table)
        return targetMm + (tableCorrectionUm(*this, targetMm, Direction::Up) + tableCorrectionUm(*this, targetMm, Direction::Down)) / 2 * 1e-3;
    CompensationModel noBacklash = *this;
    noBacklash.backlashUm = 0;
    return noBacklash.commandMm(targetMm, Direction::Up);
}

double CompensationModel::correctionUm(double targetMm, Direction approach) const
{
    return (commandMm(targetMm, approach) - targetMm) * 1e3;
}

motion::msg::Problems validate(const CompensationModel& m)
{
    motion::msg::Problems out;
    if (m.axis.size() != 1 || m.axis[0] < 'A' || m.axis[0] > 'Z')
        out.push_back({"axis", motion::msg::make("accuracy.axis_name_invalid", {motion::msg::verbatim("axis", m.axis)})});
    if (m.kind == CompensationModel::Kind::Polynomial) {
        const auto& c = m.polynomial.coefficientsUm;
        if (c.empty())
            out.push_back({"polynomial.coefficients_um", motion::msg::make("compensation.no_coefficients")});
        if (c.size() > 6)
            out.push_back({"polynomial.coefficients_um",
                           motion::msg::make("compensation.too_many_coefficients",
                                     {motion::msg::integer("count", static_cast<long long>(c.size())), motion::msg::integer("max", 6)})});
        for (std::size_t i = 0; i < c.size(); ++i)
            if (!std::isfinite(c[i]))
                out.push_back({indexPath("polynomial.coefficients_um", i), motion::msg::make("accuracy.value_not_finite")});
        const bool from = checkRange(out, "polynomial.valid_from_mm", m.validFromMm, -1e6, 1e6, motion::msg::Unit::Mm);
        const bool to = checkRange(out, "polynomial.valid_to_mm", m.validToMm, -1e6, 1e6, motion::msg::Unit::Mm);
        if (from && to && !(m.validToMm - m.validFromMm >= 2 * kMinTableSpacingMm))
            out.push_back({"polynomial.valid_to_mm", motion::msg::make("compensation.range_too_short",
                                                               {motion::msg::real("from", m.validFromMm, motion::msg::Unit::Mm), motion::msg::real("to", m.validToMm, motion::msg::Unit::Mm),
                                                                motion::msg::real("min", 2 * kMinTableSpacingMm, motion::msg::Unit::Mm)})});
        else if (from && to && !hasErrors(out)) {
            // A curve a device can apply: bounded and gentle over the range it is used on.
            for (int i = 0; i <= 100; ++i) {
                const double x = m.validFromMm + (m.validToMm - m.validFromMm) * i / 100;
                const double e = m.polynomial.errorUm(x), slope = m.polynomial.slopeUmPerMm(x);
                if (!(std::fabs(e) <= kMaxCorrectionUm)) {
                    out.push_back({"polynomial.coefficients_um", motion::msg::make("compensation.curve_too_large",
                                                                           {motion::msg::real("position", x, motion::msg::Unit::Mm), motion::msg::real("value", e, motion::msg::Unit::Um),
                                                                            motion::msg::real("max", kMaxCorrectionUm, motion::msg::Unit::Um)})});
                    break;
                }
                if (!(std::fabs(slope) <= kMaxSlopeUmPerMm)) {
                    out.push_back({"polynomial.coefficients_um", motion::msg::make("compensation.curve_too_steep",
                                                                           {motion::msg::real("position", x, motion::msg::Unit::Mm), motion::msg::real("value", slope),
                                                                            motion::msg::real("max", kMaxSlopeUmPerMm)})});
                    break;
                }
            }
        }
    } else {
        const auto n = static_cast<long long>(m.table.size());
        if (n < 2)
            out.push_back({"table.points", motion::msg::make("compensation.too_few_table_points", {motion::msg::integer("count", n), motion::msg::integer("min", 2)})});
        if (m.table.size() > kMaxTablePoints)
            out.push_back({"table.points", motion::msg::make("compensation.too_many_table_points",
                                                     {motion::msg::integer("count", n), motion::msg::integer("max", static_cast<long long>(kMaxTablePoints))})});
        for (std::size_t i = 0; i < m.table.size(); ++i) {
            const std::string path = indexPath("table.points", i);
            const TablePoint& p = m.table[i];
            if (checkRange(out, fieldPath(path, "nominal_mm"), p.nominalMm, -1e6, 1e6, motion::msg::Unit::Mm) && i > 0
                && std::isfinite(m.table[i - 1].nominalMm)) {
                const double previous = m.table[i - 1].nominalMm;
                if (!(p.nominalMm > previous))
                    out.push_back({fieldPath(path, "nominal_mm"),
                                   motion::msg::make("compensation.nominals_not_increasing",
                                             {motion::msg::real("value", p.nominalMm, motion::msg::Unit::Mm), motion::msg::real("previous", previous, motion::msg::Unit::Mm)})});
                else if (p.nominalMm - previous < kMinTableSpacingMm * (1 - 1e-9))
                    out.push_back({fieldPath(path, "nominal_mm"),
                                   motion::msg::make("compensation.nominals_too_close",
                                             {motion::msg::real("value", p.nominalMm, motion::msg::Unit::Mm), motion::msg::real("previous", previous, motion::msg::Unit::Mm),
                                              motion::msg::real("min", kMinTableSpacingMm, motion::msg::Unit::Mm)})});
            }
            checkRange(out, fieldPath(path, m.perDirection ? "correction_up_um" : "correction_um"), p.correctionUpUm, -kMaxCorrectionUm,
                       kMaxCorrectionUm, motion::msg::Unit::Um);
            if (m.perDirection)
                checkRange(out, fieldPath(path, "correction_down_um"), p.correctionDownUm, -kMaxCorrectionUm, kMaxCorrectionUm, motion::msg::Unit::Um);
        }
        if (m.perDirection && m.backlashUm != 0)
            out.push_back({"backlash_um", motion::msg::make("compensation.backlash_with_directions", {motion::msg::real("value", m.backlashUm, motion::msg::Unit::Um)})});
    }
    checkRange(out, "backlash_um", m.backlashUm, -kMaxCorrectionUm, kMaxCorrectionUm, motion::msg::Unit::Um);
    return out;
}

double backlashUmFrom(const Evaluation& e)
{
    return e.figures.bMeanMm ? -*e.figures.bMeanMm * 1e3 : 0.0;
}

CompensationModel polynomialModel(const std::string& axis, const ErrorPolynomial& curve, double fromMm, double toMm, double backlashUm)
{
    CompensationModel m;
    m.axis = axis;
    m.kind = CompensationModel::Kind::Polynomial;
    m.polynomial = curve;
    m.validFromMm = fromMm;
    m.validToMm = toMm;
    m.backlashUm = backlashUm;
    return m;
}

CompensationModel tableModel(const std::string& axis, const Evaluation& e, bool perDirection)
{
    CompensationModel m;
    m.axis = axis;
    m.kind = CompensationModel::Kind::Table;
    m.perDirection = perDirection && e.bidirectional;
    std::vector<double> x, up, down, mean;
    for (const TargetStatistics& t : e.targets) {
        x.push_back(t.targetMm);
        up.push_back(t.meanUpMm * 1e3);
        down.push_back(t.meanDownMm.value_or(t.meanUpMm) * 1e3);
        mean.push_back(t.meanMm * 1e3);
    }
    if (x.empty())
        return m;
    if (m.perDirection) {
        const auto ku = cancellingCorrections(x, up), kd = cancellingCorrections(x, down);
        for (std::size_t i = 0; i < x.size(); ++i)
            m.table.push_back({x[i], ku[i], kd[i]});
    } else {
        const auto k = cancellingCorrections(x, mean);
        for (std::size_t i = 0; i < x.size(); ++i)
            m.table.push_back({x[i], k[i], k[i]});
        m.backlashUm = backlashUmFrom(e);
    }
    return m;
}

std::vector<TablePoint> sampleTable(const CompensationModel& m, const std::vector<double>& nominalsMm)
{
    std::vector<TablePoint> out;
    for (double x : nominalsMm)
        out.push_back({x, m.correctionUm(x, Direction::Up), m.correctionUm(x, Direction::Down)});
    return out;
}

} // namespace motion::metrology
