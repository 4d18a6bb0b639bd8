#include "motion/metrology/contour/xy_line_test.h"

#include <cmath>

namespace motion::metrology {

namespace {

double along(const XyPoint& origin, double theta, const XyPoint& p)
{
    return std::cos(theta) * (p.xMm - origin.xMm) + std::sin(theta) * (p.yMm - origin.yMm);
}

double across(const XyPoint& origin, double theta, const XyPoint& p)
{
    return -std::sin(theta) * (p.xMm - origin.xMm) + std::cos(theta) * (p.yMm - origin.yMm);
}

bool finite(const XyPoint& p)
{
    return std::isfinite(p.xMm) && std::isfinite(p.yMm);
}

/// `what` names the number as the axis test's messages do: "value" for a target,
/// "position" for an overrun point.
void checkInside(motion::msg::Problems& out, const std::string& path, double v, const AxisLimits& l, const char* axis, const char* below, const char* above,
                 const char* what)
{
    if (l.minMm && v < *l.minMm)
        out.push_back({path, motion::msg::make(below, {motion::msg::real(what, v, motion::msg::Unit::Mm), motion::msg::real("limit", *l.minMm, motion::msg::Unit::Mm), motion::msg::verbatim("axis", axis)})});
    if (l.maxMm && v > *l.maxMm)
        out.push_back({path, motion::msg::make(above, {motion::msg::real(what, v, motion::msg::Unit::Mm), motion::msg::real("limit", *l.maxMm, motion::msg::Unit::Mm), motion::msg::verbatim("axis", axis)})});
}

} // namespace

double contourErrorMm(double thetaRad, double exMm, double eyMm)
{
    return -std::sin(thetaRad) * exMm + std::cos(thetaRad) * eyMm;
}

double alongLineErrorMm(double thetaRad, double exMm, double eyMm)
{
    return std::cos(thetaRad) * exMm + std::sin(thetaRad) * eyMm;
}

std::vector<XyPoint> pointsOf(const XyLineTest& t)
{
    if (!t.pointsMm.empty() || !t.fromMm || !t.toMm || t.count < 2 || t.count > kMaxTargets)
        return t.pointsMm;
    std::vector<XyPoint> out;
    for (int i = 0; i < t.count; ++i) {
        const double w = static_cast<double>(i) / (t.count - 1);
        auto at = [&](double a, double b) { return std::round((a + w * (b - a)) * 1e6) / 1e6; };
        out.push_back({at(t.fromMm->xMm, t.toMm->xMm), at(t.fromMm->yMm, t.toMm->yMm)});
    }
    return out;
}

double lineAngleRad(const std::vector<XyPoint>& p)
{
    if (p.size() < 2)
        return 0;
    return std::atan2(p.back().yMm - p.front().yMm, p.back().xMm - p.front().xMm);
}

motion::msg::Problems validate(const XyLineTest& t, const XyLimits& limits)
{
    motion::msg::Problems out;
    const bool line = t.fromMm || t.toMm;
    if (!t.pointsMm.empty() && line)
        out.push_back({"points_mm", motion::msg::make("accuracy.targets_and_grid")});
    else if (t.pointsMm.empty() && !line)
        out.push_back({"points_mm", motion::msg::make("accuracy.no_targets")});
    else if (line && !(t.fromMm && t.toMm))
        out.push_back({t.fromMm ? "to_mm" : "from_mm", motion::msg::make("accuracy.no_targets")});

    const std::vector<XyPoint> points = pointsOf(t);
    const std::string listPath = t.pointsMm.empty() ? "count" : "points_mm";
    const auto n = static_cast<long long>(line ? t.count : static_cast<int>(points.size()));
    if (!hasErrors(out)) {
        if (n < 2)
            out.push_back({listPath, motion::msg::make("accuracy.too_few_targets", {motion::msg::integer("count", n), motion::msg::integer("min", 2)})});
        else if (n > kMaxTargets)
            out.push_back({listPath, motion::msg::make("accuracy.value_above", {motion::msg::integer("value", n), motion::msg::integer("max", kMaxTargets)})});
        else if (n < kIsoTargets)
            out.push_back({listPath, motion::msg::make("accuracy.fewer_targets_than_iso", {motion::msg::integer("count", n), motion::msg::integer("recommended", kIsoTargets)}),
                           motion::msg::Severity::Warning});
    }
    bool allFinite = !points.empty();
    for (std::size_t i = 0; i < points.size(); ++i)
        if (!finite(points[i])) {
            out.push_back({line ? std::string("from_mm") : indexPath("points_mm", i), motion::msg::make("accuracy.value_not_finite")});
            allFinite = false;
        }
    if (allFinite && points.size() >= 2 && !hasErrors(out)) {
        const double theta = lineAngleRad(points);
        const XyPoint& o = points.front();
        for (std::size_t i = 0; i < points.size(); ++i) {
            const std::string path = line ? std::string("count") : indexPath("points_mm", i);
            const double off = std::fabs(across(o, theta, points[i]));
            if (off > kMaxOffLineMm)
                out.push_back({path, motion::msg::make("accuracy.xy.point_off_line",
                                               {motion::msg::real("distance", off, motion::msg::Unit::Mm), motion::msg::real("max", kMaxOffLineMm, motion::msg::Unit::Mm)})});
            if (i > 0 && !(along(o, theta, points[i]) > along(o, theta, points[i - 1]) + 1e-6))
                out.push_back({path, motion::msg::make("accuracy.targets_not_increasing",
                                               {motion::msg::real("value", along(o, theta, points[i]), motion::msg::Unit::Mm),
                                                motion::msg::real("previous", along(o, theta, points[i - 1]), motion::msg::Unit::Mm)})});
            checkInside(out, fieldPath(path, "x_mm"), points[i].xMm, limits.x, "X", "accuracy.target_below_limit", "accuracy.target_above_limit", "value");
            checkInside(out, fieldPath(path, "y_mm"), points[i].yMm, limits.y, "Y", "accuracy.target_below_limit", "accuracy.target_above_limit", "value");
        }
        if (checkRange(out, "overrun_mm", t.overrunMm, 0, 1000, motion::msg::Unit::Mm)) {
            const XyPoint before{o.xMm - t.overrunMm * std::cos(theta), o.yMm - t.overrunMm * std::sin(theta)};
            checkInside(out, "overrun_mm", before.xMm, limits.x, "X", "accuracy.overrun_below_limit", "accuracy.overrun_above_limit", "position");
            checkInside(out, "overrun_mm", before.yMm, limits.y, "Y", "accuracy.overrun_below_limit", "accuracy.overrun_above_limit", "position");
        }
    }

    if (t.cycles < 2)
        out.push_back({"cycles", motion::msg::make("accuracy.too_few_cycles", {motion::msg::integer("count", t.cycles), motion::msg::integer("min", 2)})});
    else if (t.cycles > kMaxCycles)
        out.push_back({"cycles", motion::msg::make("accuracy.value_above", {motion::msg::integer("value", t.cycles), motion::msg::integer("max", kMaxCycles)})});
    else if (t.cycles < kIsoCycles)
        out.push_back({"cycles", motion::msg::make("accuracy.fewer_cycles_than_iso", {motion::msg::integer("count", t.cycles), motion::msg::integer("recommended", kIsoCycles)}),
                       motion::msg::Severity::Warning});
    const double maxFeed = std::min(kMaxFeedMmS, limits.maxFeedMmS.value_or(kMaxFeedMmS));
    if (checkRange(out, "feed_mm_s", t.feedMmS, -INFINITY, maxFeed, motion::msg::Unit::MmPerS) && !(t.feedMmS > 0))
        out.push_back({"feed_mm_s", motion::msg::make("accuracy.value_not_positive", {motion::msg::real("value", t.feedMmS, motion::msg::Unit::MmPerS)})});
    checkRange(out, "dwell_s", t.dwellS, 0, 3600, motion::msg::Unit::S);
    validateSettle(t.settle, out);
    validateTolerances(t.contourTolerances, "contour_tolerances", out);
    return out;
}

std::vector<XyStop> runSequence(const XyLineTest& t)
{
    std::vector<XyStop> out;
    if (hasErrors(validate(t)))
        return out;
    const auto points = pointsOf(t);
    const double theta = lineAngleRad(points);
    const XyPoint before{points.front().xMm - t.overrunMm * std::cos(theta), points.front().yMm - t.overrunMm * std::sin(theta)};
    for (int cycle = 1; cycle <= t.cycles; ++cycle)
        for (std::size_t i = 0; i < points.size(); ++i) {
            XyStop s{cycle, i, points[i], std::nullopt};
            if (i == 0)
                s.overrunMm = before;
            out.push_back(s);
        }
    return out;
}

XyEvaluation evaluate(const std::vector<XyPoint>& targets, const std::vector<XyReading>& readings)
{
    XyEvaluation out;
    out.thetaRad = lineAngleRad(targets);
    std::vector<Reading> x, y, contour;
    for (std::size_t k = 0; k < readings.size(); ++k) {
        const XyReading& r = readings[k];
        if (r.pointIndex >= targets.size()) {
            out.problems.push_back({indexPath("readings", k),
                                    motion::msg::make("accuracy.xy.no_such_point", {motion::msg::integer("index", static_cast<long long>(r.pointIndex)),
                                                                            motion::msg::integer("count", static_cast<long long>(targets.size()))})});
            continue;
        }
        const XyPoint& p = targets[r.pointIndex];
        const double ex = r.xMm - p.xMm, ey = r.yMm - p.yMm;
        const double s = along(targets.front(), out.thetaRad, p);
        const double eps = contourErrorMm(out.thetaRad, ex, ey);
        // A single direction per axis is reported as ↑, whichever way the line runs.
        x.push_back({p.xMm, Direction::Up, r.cycle, r.xMm});
        y.push_back({p.yMm, Direction::Up, r.cycle, r.yMm});
        contour.push_back({s, Direction::Up, r.cycle, s + eps});
        out.contourMm.push_back(eps);
    }
    if (hasErrors(out.problems))
        return out;
    // An axis that does not move along the line (a line parallel to the other axis)
    // has one target, not a positioning test: left empty, with a warning.
    auto axisMoves = [&](bool isX) {
        for (std::size_t i = 1; i < targets.size(); ++i)
            if (std::fabs(isX ? targets[i].xMm - targets[0].xMm : targets[i].yMm - targets[0].yMm) > kMaxOffLineMm)
                return true;
        return false;
    };
    if (axisMoves(true))
        out.x = evaluate(x);
    else
        out.problems.push_back({"", motion::msg::make("accuracy.xy.axis_does_not_move", {motion::msg::verbatim("axis", "X")}), motion::msg::Severity::Warning});
    if (axisMoves(false))
        out.y = evaluate(y);
    else
        out.problems.push_back({"", motion::msg::make("accuracy.xy.axis_does_not_move", {motion::msg::verbatim("axis", "Y")}), motion::msg::Severity::Warning});
    out.contour = evaluate(contour);
    return out;
}

} // namespace motion::metrology
