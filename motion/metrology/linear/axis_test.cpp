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

void checkPositive(motion::msg::Problems& out, const std::string& path, double v, double max, motion::msg::Unit unit)
{
    if (!checkRange(out, path, v, -INFINITY, max, unit))
        return;
    if (!(v > 0))
        out.push_back({path, motion::msg::make("accuracy.value_not_positive", {motion::msg::real("value", v, unit)})});
}

void checkCount(motion::msg::Problems& out, const std::string& path, long long count, int min, int recommended, int max, const char* tooFew,
                const char* fewerThanIso)
{
    if (count < min)
        out.push_back({path, motion::msg::make(tooFew, {motion::msg::integer("count", count), motion::msg::integer("min", min)})});
    else if (count > max)
        out.push_back({path, motion::msg::make("accuracy.value_above", {motion::msg::integer("value", count), motion::msg::integer("max", max)})});
    else if (count < recommended)
        out.push_back({path, motion::msg::make(fewerThanIso, {motion::msg::integer("count", count), motion::msg::integer("recommended", recommended)}), motion::msg::Severity::Warning});
}

} // namespace

void validateSettle(const SettleRule& s, motion::msg::Problems& out)
{
    checkPositive(out, "settle.tolerance_um", s.toleranceUm, 1000, motion::msg::Unit::Um);
    const bool window = checkRange(out, "settle.window_s", s.windowS, 0, 600, motion::msg::Unit::S);
    const bool timeout = checkRange(out, "settle.timeout_s", s.timeoutS, 0, 3600, motion::msg::Unit::S);
    if (window && timeout && s.timeoutS < s.windowS)
        out.push_back({"settle.timeout_s", motion::msg::make("accuracy.settle_timeout_below_window",
                                                     {motion::msg::real("timeout", s.timeoutS, motion::msg::Unit::S), motion::msg::real("window", s.windowS, motion::msg::Unit::S)})});
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

motion::msg::Problems validate(const AxisTest& t, const AxisLimits& limits)
{
    motion::msg::Problems out;
    if (t.axis.size() != 1 || t.axis[0] < 'A' || t.axis[0] > 'Z')
        out.push_back({"axis", motion::msg::make("accuracy.axis_name_invalid", {motion::msg::verbatim("axis", t.axis)})});

    // Targets: exactly one of the list and the grid.
    std::vector<double> targets;
    bool targetsUsable = false;
    if (!t.targetsMm.empty() && t.grid) {
        out.push_back({"grid", motion::msg::make("accuracy.targets_and_grid")});
    } else if (t.grid) {
        const TargetGrid& g = *t.grid;
        const bool startOk = checkRange(out, "grid.start_mm", g.startMm, -1e6, 1e6, motion::msg::Unit::Mm);
        const bool ends = checkRange(out, "grid.end_mm", g.endMm, -1e6, 1e6, motion::msg::Unit::Mm) && startOk;
        const std::size_t before = out.size();
        checkCount(out, "grid.count", g.count, 2, kIsoTargets, kMaxTargets, "accuracy.too_few_targets", "accuracy.fewer_targets_than_iso");
        const bool countOk = !hasErrors(motion::msg::Problems(out.begin() + static_cast<std::ptrdiff_t>(before), out.end()));
        if (ends && !(g.endMm > g.startMm))
            out.push_back({"grid.end_mm", motion::msg::make("accuracy.grid_end_not_after_start",
                                                    {motion::msg::real("start", g.startMm, motion::msg::Unit::Mm), motion::msg::real("end", g.endMm, motion::msg::Unit::Mm)})});
        else if (ends && countOk) {
            const double p = (g.endMm - g.startMm) / (g.count - 1);
            if (p < kMinSpacingMm)
                out.push_back({"grid.count", motion::msg::make("accuracy.grid_spacing_too_small",
                                                       {motion::msg::real("spacing", p, motion::msg::Unit::Mm), motion::msg::real("min", kMinSpacingMm, motion::msg::Unit::Mm)})});
            else {
                targets = gridTargets(g);
                targetsUsable = true;
            }
        }
    } else if (t.targetsMm.empty()) {
        out.push_back({"targets_mm", motion::msg::make("accuracy.no_targets")});
    } else {
        targets = t.targetsMm;
        const std::size_t before = out.size();
        checkCount(out, "targets_mm", static_cast<long long>(targets.size()), 2, kIsoTargets, kMaxTargets, "accuracy.too_few_targets",
                   "accuracy.fewer_targets_than_iso");
        bool finite = true;
        for (std::size_t i = 0; i < targets.size(); ++i) {
            const std::string path = indexPath("targets_mm", i);
            if (!std::isfinite(targets[i])) {
                out.push_back({path, motion::msg::make("accuracy.value_not_finite")});
                finite = false;
            } else if (i > 0 && std::isfinite(targets[i - 1]) && !(targets[i] > targets[i - 1])) {
                out.push_back({path, motion::msg::make("accuracy.targets_not_increasing",
                                               {motion::msg::real("value", targets[i], motion::msg::Unit::Mm), motion::msg::real("previous", targets[i - 1], motion::msg::Unit::Mm)})});
            }
        }
        targetsUsable = finite && !hasErrors(motion::msg::Problems(out.begin() + static_cast<std::ptrdiff_t>(before), out.end()));
    }

    // Soft limits: every target, and the overrun points the standard cycle visits.
    if (targetsUsable) {
        for (std::size_t i = 0; i < targets.size(); ++i) {
            const std::string path = t.grid ? std::string("grid") : indexPath("targets_mm", i);
            if (limits.minMm && targets[i] < *limits.minMm)
                out.push_back({path, motion::msg::make("accuracy.target_below_limit",
                                               {motion::msg::real("value", targets[i], motion::msg::Unit::Mm), motion::msg::real("limit", *limits.minMm, motion::msg::Unit::Mm)})});
            if (limits.maxMm && targets[i] > *limits.maxMm)
                out.push_back({path, motion::msg::make("accuracy.target_above_limit",
                                               {motion::msg::real("value", targets[i], motion::msg::Unit::Mm), motion::msg::real("limit", *limits.maxMm, motion::msg::Unit::Mm)})});
        }
    }
    if (checkRange(out, "overrun_mm", t.overrunMm, 0, 1000, motion::msg::Unit::Mm)) {
        if (t.overrunMm == 0)
            out.push_back({"overrun_mm", motion::msg::make("accuracy.no_overrun"), motion::msg::Severity::Warning});
        if (targetsUsable) {
            const double below = targets.front() - t.overrunMm, above = targets.back() + t.overrunMm;
            if (limits.minMm && below < *limits.minMm && targets.front() >= *limits.minMm)
                out.push_back({"overrun_mm", motion::msg::make("accuracy.overrun_below_limit",
                                                       {motion::msg::real("position", below, motion::msg::Unit::Mm), motion::msg::real("limit", *limits.minMm, motion::msg::Unit::Mm)})});
            if (t.bidirectional && limits.maxMm && above > *limits.maxMm && targets.back() <= *limits.maxMm)
                out.push_back({"overrun_mm", motion::msg::make("accuracy.overrun_above_limit",
                                                       {motion::msg::real("position", above, motion::msg::Unit::Mm), motion::msg::real("limit", *limits.maxMm, motion::msg::Unit::Mm)})});
        }
    }

    checkCount(out, "cycles", t.cycles, 2, kIsoCycles, kMaxCycles, "accuracy.too_few_cycles", "accuracy.fewer_cycles_than_iso");
    checkPositive(out, "feed_mm_s", t.feedMmS, std::min(kMaxFeedMmS, limits.maxFeedMmS.value_or(kMaxFeedMmS)), motion::msg::Unit::MmPerS);
    checkRange(out, "dwell_s", t.dwellS, 0, 3600, motion::msg::Unit::S);
    validateSettle(t.settle, out);
    validateTolerances(t.tolerances, "tolerances", out);
    return out;
}

} // namespace motion::metrology
