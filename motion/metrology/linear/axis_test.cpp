#include "motion/metrology/linear/axis_test.h"

#include <algorithm>
#include <cmath>

namespace motion::metrology {

namespace {

/// Grid targets closer than this are a typo, not a positioning test.
constexpr double kMinSpacingMm = 0.01;

/// To 1/perMm of a millimetre; dividing by a whole number gives the double nearest
/// the decimal (0.1, not 0.1000000000000000055).
double roundTo(double v, double perMm)
{
    return std::round(v * perMm) / perMm;
}

void checkPositive(msg::Problems& out, const std::string& path, double v, double max, msg::Unit unit)
{
    if (!checkRange(out, path, v, -INFINITY, max, unit))
        return;
    if (!(v > 0))
        out.push_back({path, msg::make("accuracy.value_not_positive", {msg::real("value", v, unit)})});
}

void checkCount(msg::Problems& out, const std::string& path, long long count, int min, int recommended, int max, const char* tooFew,
                const char* fewerThanIso)
{
    if (count < min)
        out.push_back({path, msg::make(tooFew, {msg::integer("count", count), msg::integer("min", min)})});
    else if (count > max)
        out.push_back({path, msg::make("accuracy.value_above", {msg::integer("value", count), msg::integer("max", max)})});
    else if (count < recommended)
        out.push_back({path, msg::make(fewerThanIso, {msg::integer("count", count), msg::integer("recommended", recommended)}), msg::Severity::Warning});
}

} // namespace

void validateSettle(const SettleRule& s, msg::Problems& out)
{
    checkPositive(out, "settle.tolerance_um", s.toleranceUm, 1000, msg::Unit::Um);
    const bool window = checkRange(out, "settle.window_s", s.windowS, 0, 600, msg::Unit::S);
    const bool timeout = checkRange(out, "settle.timeout_s", s.timeoutS, 0, 3600, msg::Unit::S);
    if (window && timeout && s.timeoutS < s.windowS)
        out.push_back({"settle.timeout_s", msg::make("accuracy.settle_timeout_below_window",
                                                     {msg::real("timeout", s.timeoutS, msg::Unit::S), msg::real("window", s.windowS, msg::Unit::S)})});
}

std::vector<double> gridTargets(const TargetGrid& g)
{
    std::vector<double> out;
    if (g.count < 2 || g.count > kMaxTargets || !std::isfinite(g.startMm) || !std::isfinite(g.endMm))
        return out;
    const double p = (g.endMm - g.startMm) / (g.count - 1);
    const double phi = (std::sqrt(5.0) - 1) / 2;
    for (int i = 0; i < g.count; ++i) {
        double v = i == g.count - 1 ? g.endMm : g.startMm + i * p;
        if (g.irregular && i > 0 && i < g.count - 1) {
            const double frac = i * phi - std::floor(i * phi);
            v = roundTo(v + (frac - 0.5) * p / 2, 1e3);
        } else {
            v = roundTo(v, 1e6);
        }
        out.push_back(v);
    }
    return out;
}

std::vector<double> targetsOf(const AxisTest& t)
{
    if (!t.targetsMm.empty() || !t.grid)
        return t.targetsMm;
    return gridTargets(*t.grid);
}

msg::Problems validate(const AxisTest& t, const AxisLimits& limits)
{
    msg::Problems out;
    if (t.axis.size() != 1 || t.axis[0] < 'A' || t.axis[0] > 'Z')
        out.push_back({"axis", msg::make("accuracy.axis_name_invalid", {msg::verbatim("axis", t.axis)})});

    // Targets: exactly one of the list and the grid.
    std::vector<double> targets;
    bool targetsUsable = false;
    if (!t.targetsMm.empty() && t.grid) {
        out.push_back({"grid", msg::make("accuracy.targets_and_grid")});
    } else if (t.grid) {
        const TargetGrid& g = *t.grid;
        const bool startOk = checkRange(out, "grid.start_mm", g.startMm, -1e6, 1e6, msg::Unit::Mm);
        const bool ends = checkRange(out, "grid.end_mm", g.endMm, -1e6, 1e6, msg::Unit::Mm) && startOk;
        const std::size_t before = out.size();
        checkCount(out, "grid.count", g.count, 2, kIsoTargets, kMaxTargets, "accuracy.too_few_targets", "accuracy.fewer_targets_than_iso");
        const bool countOk = !hasErrors(msg::Problems(out.begin() + static_cast<std::ptrdiff_t>(before), out.end()));
        if (ends && !(g.endMm > g.startMm))
            out.push_back({"grid.end_mm", msg::make("accuracy.grid_end_not_after_start",
                                                    {msg::real("start", g.startMm, msg::Unit::Mm), msg::real("end", g.endMm, msg::Unit::Mm)})});
        else if (ends && countOk) {
            const double p = (g.endMm - g.startMm) / (g.count - 1);
            if (p < kMinSpacingMm)
                out.push_back({"grid.count", msg::make("accuracy.grid_spacing_too_small",
                                                       {msg::real("spacing", p, msg::Unit::Mm), msg::real("min", kMinSpacingMm, msg::Unit::Mm)})});
            else {
                targets = gridTargets(g);
                targetsUsable = true;
            }
        }
    } else if (t.targetsMm.empty()) {
        out.push_back({"targets_mm", msg::make("accuracy.no_targets")});
    } else {
        targets = t.targetsMm;
        const std::size_t before = out.size();
        checkCount(out, "targets_mm", static_cast<long long>(targets.size()), 2, kIsoTargets, kMaxTargets, "accuracy.too_few_targets",
                   "accuracy.fewer_targets_than_iso");
        bool finite = true;
        for (std::size_t i = 0; i < targets.size(); ++i) {
            const std::string path = indexPath("targets_mm", i);
            if (!std::isfinite(targets[i])) {
                out.push_back({path, msg::make("accuracy.value_not_finite")});
                finite = false;
            } else if (i > 0 && std::isfinite(targets[i - 1]) && !(targets[i] > targets[i - 1])) {
                out.push_back({path, msg::make("accuracy.targets_not_increasing",
                                               {msg::real("value", targets[i], msg::Unit::Mm), msg::real("previous", targets[i - 1], msg::Unit::Mm)})});
            }
        }
        targetsUsable = finite && !hasErrors(msg::Problems(out.begin() + static_cast<std::ptrdiff_t>(before), out.end()));
    }

    // Soft limits: every target, and the overrun points the standard cycle visits.
    if (targetsUsable) {
        for (std::size_t i = 0; i < targets.size(); ++i) {
            const std::string path = t.grid ? std::string("grid") : indexPath("targets_mm", i);
            if (limits.minMm && targets[i] < *limits.minMm)
                out.push_back({path, msg::make("accuracy.target_below_limit",
                                               {msg::real("value", targets[i], msg::Unit::Mm), msg::real("limit", *limits.minMm, msg::Unit::Mm)})});
            if (limits.maxMm && targets[i] > *limits.maxMm)
                out.push_back({path, msg::make("accuracy.target_above_limit",
                                               {msg::real("value", targets[i], msg::Unit::Mm), msg::real("limit", *limits.maxMm, msg::Unit::Mm)})});
        }
    }
    if (checkRange(out, "overrun_mm", t.overrunMm, 0, 1000, msg::Unit::Mm)) {
        if (t.overrunMm == 0)
            out.push_back({"overrun_mm", msg::make("accuracy.no_overrun"), msg::Severity::Warning});
        if (targetsUsable) {
            const double below = targets.front() - t.overrunMm, above = targets.back() + t.overrunMm;
            if (limits.minMm && below < *limits.minMm && targets.front() >= *limits.minMm)
                out.push_back({"overrun_mm", msg::make("accuracy.overrun_below_limit",
                                                       {msg::real("position", below, msg::Unit::Mm), msg::real("limit", *limits.minMm, msg::Unit::Mm)})});
            if (t.bidirectional && limits.maxMm && above > *limits.maxMm && targets.back() <= *limits.maxMm)
                out.push_back({"overrun_mm", msg::make("accuracy.overrun_above_limit",
                                                       {msg::real("position", above, msg::Unit::Mm), msg::real("limit", *limits.maxMm, msg::Unit::Mm)})});
        }
    }

    checkCount(out, "cycles", t.cycles, 2, kIsoCycles, kMaxCycles, "accuracy.too_few_cycles", "accuracy.fewer_cycles_than_iso");
    checkPositive(out, "feed_mm_s", t.feedMmS, std::min(kMaxFeedMmS, limits.maxFeedMmS.value_or(kMaxFeedMmS)), msg::Unit::MmPerS);
    checkRange(out, "dwell_s", t.dwellS, 0, 3600, msg::Unit::S);
    validateSettle(t.settle, out);
    validateTolerances(t.tolerances, "tolerances", out);
    return out;
}

} // namespace motion::metrology
