#include "motion/metrology/linear/iso230_2.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

namespace motion::metrology {

namespace {

constexpr int kMinTargets = 2;
constexpr int kMinCycles = 2;

struct Sample {
    std::vector<double> deviationsMm;
    std::size_t firstReading = 0;  ///< for problem paths, so a file names the line
};

struct Group {
    double targetMm = 0;
    Sample up, down;
};

/// Targets that round to the same nanometre are one target.
long long targetKey(double mm)
{
    return std::llround(mm * 1e6);
}

/// Mean and sample standard deviation (n − 1), two passes so that deviations of
/// a few µm on targets of hundreds of mm keep their digits.
std::pair<double, double> meanAndS(const std::vector<double>& v)
{
    double sum = 0;
    for (double x : v)
        sum += x;
    const double mean = sum / static_cast<double>(v.size());
    double ss = 0;
    for (double x : v)
        ss += (x - mean) * (x - mean);
    return {mean, std::sqrt(ss / static_cast<double>(v.size() - 1))};
}

motion::msg::Arg targetArg(double mm)
{
    return motion::msg::real("target", mm, motion::msg::Unit::Mm);
}

std::string readingPath(std::size_t k)
{
    return indexPath("readings", k);
}

} // namespace

Evaluation evaluate(const std::vector<Reading>& readings, const EvaluationOptions& options)
{
    Evaluation out;
    std::map<long long, Group> groups;
    std::map<std::tuple<long long, int, int>, std::size_t> seen;
    for (std::size_t k = 0; k < readings.size(); ++k) {
        const Reading& r = readings[k];
        bool good = true;
        if (!std::isfinite(r.targetMm)) {
            out.problems.push_back({fieldPath(readingPath(k), "target_mm"), motion::msg::make("accuracy.value_not_finite")});
            good = false;
        }
        if (!std::isfinite(r.measuredMm)) {
            out.problems.push_back({fieldPath(readingPath(k), "measured_mm"), motion::msg::make("accuracy.value_not_finite")});
            good = false;
        }
        if (r.cycle < 1) {
            out.problems.push_back({fieldPath(readingPath(k), "cycle"),
                                    motion::msg::make("accuracy.value_below", {motion::msg::integer("value", r.cycle), motion::msg::integer("min", 1)})});
            good = false;
        }
        if (!good)
            continue;
        const long long key = targetKey(r.targetMm);
        const auto id = std::make_tuple(key, static_cast<int>(r.direction), r.cycle);
        if (auto it = seen.find(id); it != seen.end()) {
            out.problems.push_back({readingPath(k),
                                    motion::msg::make("accuracy.duplicate_reading",
                                              {targetArg(r.targetMm), motion::msg::term("direction", directionTermId(r.direction)),
                                               motion::msg::integer("cycle", r.cycle), motion::msg::integer("first", static_cast<long long>(it->second))})});
            continue;
        }
        seen.emplace(id, k);
        Group& g = groups[key];
        if (g.up.deviationsMm.empty() && g.down.deviationsMm.empty())
            g.targetMm = r.targetMm;
        Sample& s = r.direction == Direction::Up ? g.up : g.down;
        if (s.deviationsMm.empty())
            s.firstReading = k;
        s.deviationsMm.push_back(r.deviationMm());
    }
    if (hasErrors(out.problems))
        return out;
    if (groups.size() < static_cast<std::size_t>(kMinTargets)) {
        out.problems.push_back({"readings", motion::msg::make("accuracy.too_few_targets",
                                                      {motion::msg::integer("count", static_cast<long long>(groups.size())), motion::msg::integer("min", kMinTargets)})});
        return out;
    }

    bool anyDown = false;
    for (const auto& [key, g] : groups)
        anyDown = anyDown || !g.down.deviationsMm.empty();

    std::size_t expected = 0;
    for (const auto& [key, g] : groups)
        expected = std::max({expected, g.up.deviationsMm.size(), g.down.deviationsMm.size()});

    auto checkSample = [&](const Group& g, const Sample& s, const Sample& other, Direction d) {
        if (s.deviationsMm.empty()) {
            out.problems.push_back({readingPath(other.firstReading),
                                    motion::msg::make("accuracy.direction_missing",
                                              {targetArg(g.targetMm), motion::msg::term("direction", directionTermId(d))})});
            return;
        }
        const auto n = static_cast<long long>(s.deviationsMm.size());
        if (n < kMinCycles) {
            out.problems.push_back({readingPath(s.firstReading),
                                    motion::msg::make("accuracy.too_few_cycles",
                                              {motion::msg::integer("count", n), motion::msg::integer("min", kMinCycles), targetArg(g.targetMm),
                                               motion::msg::term("direction", directionTermId(d))})});
            return;
        }
        if (s.deviationsMm.size() != expected)
            out.problems.push_back({readingPath(s.firstReading),
                                    motion::msg::make("accuracy.cycle_counts_differ",
                                              {targetArg(g.targetMm), motion::msg::term("direction", directionTermId(d)), motion::msg::integer("count", n),
                                               motion::msg::integer("expected", static_cast<long long>(expected))}),
                                    options.allowUnequalCycles ? motion::msg::Severity::Warning : motion::msg::Severity::Error});
    };
    for (const auto& [key, g] : groups) {
        checkSample(g, g.up, g.down, Direction::Up);
        if (anyDown)
            checkSample(g, g.down, g.up, Direction::Down);
    }
    if (hasErrors(out.problems))
        return out;

    std::vector<TargetStatistics> stats;
    for (const auto& [key, g] : groups) {
        TargetStatistics t;
        t.targetMm = g.targetMm;
        t.nUp = static_cast<int>(g.up.deviationsMm.size());
        std::tie(t.meanUpMm, t.sUpMm) = meanAndS(g.up.deviationsMm);
        if (anyDown) {
            t.nDown = static_cast<int>(g.down.deviationsMm.size());
            const auto [m, s] = meanAndS(g.down.deviationsMm);
            t.meanDownMm = m;
            t.sDownMm = s;
        }
        stats.push_back(t);
    }
    Evaluation summary = summarize(std::move(stats), anyDown);
    // Warnings found on the readings (unequal cycles in a live run) stay with the result.
    summary.problems.insert(summary.problems.begin(), out.problems.begin(), out.problems.end());
    return summary;
}

Evaluation summarize(std::vector<TargetStatistics> targets, bool bidirectional)
{
    Evaluation out;
    out.bidirectional = bidirectional;
    if (targets.size() < static_cast<std::size_t>(kMinTargets)) {
        out.problems.push_back({"targets", motion::msg::make("accuracy.too_few_targets",
                                                     {motion::msg::integer("count", static_cast<long long>(targets.size())), motion::msg::integer("min", kMinTargets)})});
        return out;
    }
    for (std::size_t i = 0; i < targets.size(); ++i) {
        const TargetStatistics& t = targets[i];
        const std::string path = indexPath("targets", i);
        if (i > 0 && !(t.targetMm > targets[i - 1].targetMm))
            out.problems.push_back({fieldPath(path, "target_mm"),
                                    motion::msg::make("accuracy.targets_not_increasing",
                                              {motion::msg::real("value", t.targetMm, motion::msg::Unit::Mm), motion::msg::real("previous", targets[i - 1].targetMm, motion::msg::Unit::Mm)})});
        const bool finite = std::isfinite(t.targetMm) && std::isfinite(t.meanUpMm) && std::isfinite(t.sUpMm) && t.sUpMm >= 0
            && (!bidirectional || (t.meanDownMm && t.sDownMm && std::isfinite(*t.meanDownMm) && std::isfinite(*t.sDownMm) && *t.sDownMm >= 0));
        if (!finite)
            out.problems.push_back({path, motion::msg::make("accuracy.statistics_incomplete", {targetArg(t.targetMm)})});
    }
    if (hasErrors(out.problems))
        return out;

    Figures& f = out.figures;
    double hiUp = -INFINITY, loUp = INFINITY, hiMeanUp = -INFINITY, loMeanUp = INFINITY;
    double hiDown = -INFINITY, loDown = INFINITY, hiMeanDown = -INFINITY, loMeanDown = INFINITY;
    double hiMean = -INFINITY, loMean = INFINITY, rUp = 0, rDown = 0, r = 0, b = 0, bSum = 0;
    for (TargetStatistics& t : targets) {
        out.cycles = std::max(out.cycles, t.nUp);
        t.rUpMm = 4 * t.sUpMm;
        hiUp = std::max(hiUp, t.meanUpMm + 2 * t.sUpMm);
        loUp = std::min(loUp, t.meanUpMm - 2 * t.sUpMm);
        hiMeanUp = std::max(hiMeanUp, t.meanUpMm);
        loMeanUp = std::min(loMeanUp, t.meanUpMm);
        rUp = std::max(rUp, t.rUpMm);
        if (!bidirectional) {
            t.meanMm = t.meanUpMm;
            t.meanDownMm.reset();
            t.sDownMm.reset();
            t.nDown = 0;
            t.reversalMm.reset();
            t.rDownMm.reset();
            t.rMm.reset();
            continue;
        }
        out.cycles = std::max(out.cycles, t.nDown);
        const double md = *t.meanDownMm, sd = *t.sDownMm;
        t.meanMm = (t.meanUpMm + md) / 2;
        t.reversalMm = t.meanUpMm - md;
        t.rDownMm = 4 * sd;
        t.rMm = std::max({2 * t.sUpMm + 2 * sd + std::fabs(*t.reversalMm), t.rUpMm, *t.rDownMm});
        hiDown = std::max(hiDown, md + 2 * sd);
        loDown = std::min(loDown, md - 2 * sd);
        hiMeanDown = std::max(hiMeanDown, md);
        loMeanDown = std::min(loMeanDown, md);
        hiMean = std::max(hiMean, t.meanMm);
        loMean = std::min(loMean, t.meanMm);
        rDown = std::max(rDown, *t.rDownMm);
        r = std::max(r, *t.rMm);
        b = std::max(b, std::fabs(*t.reversalMm));
        bSum += *t.reversalMm;
    }
    f.aUpMm = hiUp - loUp;
    f.eUpMm = hiMeanUp - loMeanUp;
    f.rUpMm = rUp;
    if (bidirectional) {
        f.aDownMm = hiDown - loDown;
        f.aMm = std::max(hiUp, hiDown) - std::min(loUp, loDown);
        f.eDownMm = hiMeanDown - loMeanDown;
        f.eMm = std::max(hiMeanUp, hiMeanDown) - std::min(loMeanUp, loMeanDown);
        f.mMm = hiMean - loMean;
        f.rDownMm = rDown;
        f.rMm = r;
        f.bMm = b;
        f.bMeanMm = bSum / static_cast<double>(targets.size());
    }
    out.targets = std::move(targets);
    return out;
}

} // namespace motion::metrology
