#include "motion/metrology/contour/circular_test.h"
#include "motion/numbers.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace motion::metrology {

namespace {

constexpr std::size_t kMinSamples = 8;

double wrap(double a)
{
    a = std::fmod(a, 2 * kPi);
    return a < 0 ? a + 2 * kPi : a;
}

/// A path as radius against angle about a centre, sorted by angle, for
/// interpolation at another path's angles.
struct PolarPath {
    std::vector<double> angle;
    std::vector<double> radius;

    PolarPath(const std::vector<XyPoint>& pts, const XyPoint& c)
    {
        std::vector<std::pair<double, double>> v;
        for (const XyPoint& p : pts)
            v.push_back({wrap(std::atan2(p.yMm - c.yMm, p.xMm - c.xMm)), std::hypot(p.xMm - c.xMm, p.yMm - c.yMm)});
        std::sort(v.begin(), v.end());
        for (const auto& [a, r] : v) {
            angle.push_back(a);
            radius.push_back(r);
        }
    }

    /// Linear in angle, across 2π between the last and the first sample.
    double at(double a) const
    {
        const std::size_t n = angle.size();
        const auto i = static_cast<std::size_t>(std::upper_bound(angle.begin(), angle.end(), a) - angle.begin());
        const std::size_t lo = i == 0 ? n - 1 : i - 1, hi = i == n ? 0 : i;
        double a0 = angle[lo], a1 = angle[hi];
        if (i == 0)
            a0 -= 2 * kPi;
        if (i == n)
            a1 += 2 * kPi;
        if (!(a1 > a0))
            return radius[lo];
        return radius[lo] + (a - a0) / (a1 - a0) * (radius[hi] - radius[lo]);
    }

    double largestGapRad() const
    {
        double gap = angle.front() + 2 * kPi - angle.back();
        for (std::size_t i = 1; i < angle.size(); ++i)
            gap = std::max(gap, angle[i] - angle[i - 1]);
        return gap;
    }
};

void checkPlane(motion::msg::Problems& out, double centre, double radius, const AxisLimits& l, const std::string& axis)
{
    if (l.minMm && centre - radius < *l.minMm)
        out.push_back({"radius_mm", motion::msg::make("accuracy.circle.below_limit", {motion::msg::verbatim("axis", axis), motion::msg::real("value", centre - radius, motion::msg::Unit::Mm),
                                                                              motion::msg::real("limit", *l.minMm, motion::msg::Unit::Mm)})});
    if (l.maxMm && centre + radius > *l.maxMm)
        out.push_back({"radius_mm", motion::msg::make("accuracy.circle.above_limit", {motion::msg::verbatim("axis", axis), motion::msg::real("value", centre + radius, motion::msg::Unit::Mm),
                                                                              motion::msg::real("limit", *l.maxMm, motion::msg::Unit::Mm)})});
}

} // namespace

const char* rotationName(Rotation r)
{
    return r == Rotation::Cw ? "cw" : "ccw";
}

const char* rotationTermId(Rotation r)
{
    return r == Rotation::Cw ? "rotation.cw" : "rotation.ccw";
}

motion::msg::Problems validate(const CircularTest& t, const XyLimits& limits)
{
    motion::msg::Problems out;
    auto letter = [](char c) { return c >= 'A' && c <= 'Z'; };
    if (t.axes.size() != 2 || !letter(t.axes[0]) || !letter(t.axes[1]) || t.axes[0] == t.axes[1])
        out.push_back({"axes", motion::msg::make("accuracy.circle.axes_invalid", {motion::msg::verbatim("axes", t.axes)})});
    const bool cx = checkRange(out, "centre_mm.x_mm", t.centreMm.xMm, -1e6, 1e6, motion::msg::Unit::Mm);
    const bool cy = checkRange(out, "centre_mm.y_mm", t.centreMm.yMm, -1e6, 1e6, motion::msg::Unit::Mm);
    if (checkRange(out, "radius_mm", t.radiusMm, -INFINITY, 10000, motion::msg::Unit::Mm)) {
        if (!(t.radiusMm > 0))
            out.push_back({"radius_mm", motion::msg::make("accuracy.value_not_positive", {motion::msg::real("value", t.radiusMm, motion::msg::Unit::Mm)})});
        else if (cx && cy) {
            checkPlane(out, t.centreMm.xMm, t.radiusMm, limits.x, t.axes.substr(0, 1));
            checkPlane(out, t.centreMm.yMm, t.radiusMm, limits.y, t.axes.size() > 1 ? t.axes.substr(1, 1) : t.axes);
        }
    }
    const double maxFeed = std::min(kMaxFeedMmS, limits.maxFeedMmS.value_or(kMaxFeedMmS));
    if (checkRange(out, "feed_mm_s", t.feedMmS, -INFINITY, maxFeed, motion::msg::Unit::MmPerS) && !(t.feedMmS > 0))
        out.push_back({"feed_mm_s", motion::msg::make("accuracy.value_not_positive", {motion::msg::real("value", t.feedMmS, motion::msg::Unit::MmPerS)})});
    if (!t.clockwise && !t.counterClockwise)
        out.push_back({"directions", motion::msg::make("accuracy.circle.no_direction")});
    checkRange(out, "lead_arc_deg", t.leadArcDeg, 0, 180, motion::msg::Unit::Deg);
    if (t.samplesPerRevolution < static_cast<int>(kMinSamples) || t.samplesPerRevolution > 100000)
        out.push_back({"samples_per_revolution",
                       motion::msg::make(t.samplesPerRevolution < static_cast<int>(kMinSamples) ? "accuracy.value_below" : "accuracy.value_above",
                                 {motion::msg::integer("value", t.samplesPerRevolution),
                                  t.samplesPerRevolution < static_cast<int>(kMinSamples) ? motion::msg::integer("min", static_cast<long long>(kMinSamples))
                                                                                         : motion::msg::integer("max", 100000)})});
    for (const auto& [key, v] : {std::pair{"max_g_mm", t.maxGMm}, std::pair{"max_h_mm", t.maxHMm}})
        if (v && checkRange(out, key, *v, -INFINITY, 1000, motion::msg::Unit::Mm) && !(*v > 0))
            out.push_back({key, motion::msg::make("accuracy.value_not_positive", {motion::msg::real("value", *v, motion::msg::Unit::Mm)})});
    return out;
}

std::optional<CircleFit> fitCircle(const std::vector<XyPoint>& pts)
{
    const auto n = static_cast<Eigen::Index>(pts.size());
    if (n < 3)
        return std::nullopt;
    // Algebraic start: x² + y² + D·x + E·y + F = 0, linear in D, E, F, about the
    // mean so the numbers stay small.
    double mx = 0, my = 0;
    for (const XyPoint& p : pts) {
        mx += p.xMm;
        my += p.yMm;
    }
    mx /= static_cast<double>(n);
    my /= static_cast<double>(n);
    Eigen::MatrixXd a(n, 3);
    Eigen::VectorXd b(n);
    for (Eigen::Index i = 0; i < n; ++i) {
        const double x = pts[static_cast<std::size_t>(i)].xMm - mx, y = pts[static_cast<std::size_t>(i)].yMm - my;
        a.row(i) << x, y, 1;
        b(i) = -(x * x + y * y);
    }
    const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(a);
    if (qr.rank() < 3)
        return std::nullopt;
    const Eigen::Vector3d def = qr.solve(b);
    double cx = -def(0) / 2, cy = -def(1) / 2;
    const double r2 = cx * cx + cy * cy - def(2);
    if (!(r2 > 0))
        return std::nullopt;
    double r = std::sqrt(r2);
    // Gauss–Newton on the geometric residuals d_i − r.
    for (int iter = 0; iter < 30; ++iter) {
        Eigen::MatrixXd j(n, 3);
        Eigen::VectorXd res(n);
        for (Eigen::Index i = 0; i < n; ++i) {
            const double dx = pts[static_cast<std::size_t>(i)].xMm - mx - cx, dy = pts[static_cast<std::size_t>(i)].yMm - my - cy;
            const double d = std::hypot(dx, dy);
            if (!(d > 0))
                return std::nullopt;
            j.row(i) << -dx / d, -dy / d, -1;
            res(i) = d - r;
        }
        const Eigen::Vector3d step = j.colPivHouseholderQr().solve(-res);
        cx += step(0);
        cy += step(1);
        r += step(2);
        if (step.norm() < 1e-13 * std::max(1.0, r))
            break;
    }
    if (!std::isfinite(cx) || !std::isfinite(cy) || !(r > 0))
        return std::nullopt;
    return CircleFit{{cx + mx, cy + my}, r};
}

CircularEvaluation evaluate(const CircularTest& t, const std::vector<CircularRun>& runs)
{
    CircularEvaluation out;
    bool seen[2] = {false, false};
    for (std::size_t k = 0; k < runs.size(); ++k) {
        const CircularRun& run = runs[k];
        const std::string path = indexPath("runs", k);
        auto& already = seen[run.rotation == Rotation::Cw ? 0 : 1];
        if (already)
            out.problems.push_back({path, motion::msg::make("accuracy.circle.direction_twice", {motion::msg::term("rotation", rotationTermId(run.rotation))})});
        already = true;
        if (run.samplesMm.size() < kMinSamples) {
            out.problems.push_back({path, motion::msg::make("accuracy.circle.too_few_samples",
                                                    {motion::msg::integer("count", static_cast<long long>(run.samplesMm.size())),
                                                     motion::msg::integer("min", static_cast<long long>(kMinSamples))})});
            continue;
        }
        bool finite = true;
        for (std::size_t i = 0; i < run.samplesMm.size() && finite; ++i)
            if (!std::isfinite(run.samplesMm[i].xMm) || !std::isfinite(run.samplesMm[i].yMm)) {
                out.problems.push_back({indexPath(path + ".samples", i), motion::msg::make("accuracy.value_not_finite")});
                finite = false;
            }
        if (!finite)
            continue;
        const double gapDeg = PolarPath(run.samplesMm, t.centreMm).largestGapRad() * 180 / kPi;
        if (gapDeg > kMaxSampleGapDeg)
            out.problems.push_back({path, motion::msg::make("accuracy.circle.incomplete_revolution",
                                                    {motion::msg::real("gap", gapDeg, motion::msg::Unit::Deg), motion::msg::real("max", kMaxSampleGapDeg, motion::msg::Unit::Deg)})});
    }
    if (runs.empty())
        out.problems.push_back({"runs", motion::msg::make("accuracy.circle.no_runs")});
    if (hasErrors(out.problems))
        return out;

    std::vector<XyPoint> all;
    for (const CircularRun& run : runs) {
        const auto fit = fitCircle(run.samplesMm);
        if (!fit) {
            out.problems.push_back({"runs", motion::msg::make("accuracy.circle.no_circle", {motion::msg::term("rotation", rotationTermId(run.rotation))})});
            return out;
        }
        RunResult r;
        r.rotation = run.rotation;
        r.lsq = *fit;
        double lo = INFINITY, hi = -INFINITY;
        r.radialDeviationMinMm = INFINITY;
        r.radialDeviationMaxMm = -INFINITY;
        for (const XyPoint& p : run.samplesMm) {
            RadialSample s;
            s.angleRad = wrap(std::atan2(p.yMm - t.centreMm.yMm, p.xMm - t.centreMm.xMm));
            s.radialDeviationMm = std::hypot(p.xMm - t.centreMm.xMm, p.yMm - t.centreMm.yMm) - t.radiusMm;
            s.lsqAngleRad = wrap(std::atan2(p.yMm - fit->centreMm.yMm, p.xMm - fit->centreMm.xMm));
            s.lsqDeviationMm = std::hypot(p.xMm - fit->centreMm.xMm, p.yMm - fit->centreMm.yMm) - fit->radiusMm;
            lo = std::min(lo, s.lsqDeviationMm);
            hi = std::max(hi, s.lsqDeviationMm);
            r.radialDeviationMinMm = std::min(r.radialDeviationMinMm, s.radialDeviationMm);
            r.radialDeviationMaxMm = std::max(r.radialDeviationMaxMm, s.radialDeviationMm);
            r.samples.push_back(s);
            all.push_back(p);
        }
        r.circularDeviationMm = hi - lo;
        out.runs.push_back(r);
    }
    if (runs.size() == 2) {
        const auto common = fitCircle(all);
        if (!common) {
            out.problems.push_back({"runs", motion::msg::make("accuracy.circle.no_circle", {motion::msg::term("rotation", rotationTermId(runs[0].rotation))})});
            return out;
        }
        double lo = INFINITY, hi = -INFINITY;
        for (const XyPoint& p : all) {
            const double d = std::hypot(p.xMm - common->centreMm.xMm, p.yMm - common->centreMm.yMm);
            lo = std::min(lo, d);
            hi = std::max(hi, d);
        }
        out.bidirectionalDeviationMm = hi - lo;
        const PolarPath a(runs[0].samplesMm, common->centreMm), b(runs[1].samplesMm, common->centreMm);
        double h = 0;
        for (std::size_t i = 0; i < a.angle.size(); ++i)
            h = std::max(h, std::fabs(a.radius[i] - b.at(a.angle[i])));
        for (std::size_t i = 0; i < b.angle.size(); ++i)
            h = std::max(h, std::fabs(b.radius[i] - a.at(b.angle[i])));
        out.hysteresisMm = h;
    }
    return out;
}

std::vector<PolarPoint> polarPlot(const RunResult& run, double nominalRadiusMm, double magnification)
{
    std::vector<PolarPoint> out;
    for (const RadialSample& s : run.samples)
        out.push_back({s.lsqAngleRad, nominalRadiusMm + magnification * s.lsqDeviationMm});
    return out;
}

double autoMagnification(const CircularEvaluation& e, double nominalRadiusMm)
{
    double big = 0;
    for (const RunResult& r : e.runs)
        for (const RadialSample& s : r.samples)
            big = std::max(big, std::fabs(s.lsqDeviationMm));
    if (!(big > 0) || !(nominalRadiusMm > 0))
        return 1;
    const double want = nominalRadiusMm / 4 / big;
    // The largest 1-2-5 step not above `want`, so the plot stays inside 1.25 R.
    const double decade = std::pow(10.0, std::floor(std::log10(want)));
    for (double m : {5.0, 2.0, 1.0})
        if (m * decade <= want)
            return m * decade;
    return decade;
}

} // namespace motion::metrology
