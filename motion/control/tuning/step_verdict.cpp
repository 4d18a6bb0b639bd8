#include "motion/control/tuning/step_verdict.h"

#include "motion/control/tuning/oscillation.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace motion::control {

namespace {
/// The share of the record, at its end, read for an oscillation at rest: the step's
/// transient is over by then on any loop that settles at all.
constexpr double kTailShare = 0.5;
/// At least this many full cycles make an oscillation a cycle rather than one overshoot.
constexpr int kMinCycles = 2;
/// Cycles averaged for the amplitude and the period.
constexpr int kMaxCycles = 4;
/// A decaying transient halves or more every half cycle on a loop that settles; a limit
/// cycle's half cycles keep their size. Peak-to-peaks spread wider than this are a decay.
constexpr double kSteadySpread = 2.5;
/// On a measurement without a quantum (a model plant), swings under this share of the
/// step are too small to see on the plot and are not called a cycle.
constexpr double kModelShareOfStep = 0.005;
} // namespace

LimitCycle findLimitCycle(const Record& r, double resolution)
{
    LimitCycle c;
    const std::size_t n = r.size();
    if (n < 16)
        return c;
    const double step = r.setpoint.empty() ? 0 : std::abs(r.setpoint.back() - r.startPosition);
    // The grating reads whole counts and the loop's deadband is one count: an axis at rest
    // may sit anywhere inside ±1 count and its reading may toggle between two neighbouring
    // counts. Swings of up to two counts peak-to-peak are therefore what a still axis can
    // show; a swing larger than that is motion the grating resolves beyond doubt.
    c.threshold = resolution > 0 ? 2 * resolution : kModelShareOfStep * step;
    if (!(c.threshold > 0))
        return c;
    const auto from = static_cast<std::size_t>(std::floor(static_cast<double>(n) * (1 - kTailShare)));
    // A quarter count above it, so that rounding in readings of whole counts never makes
    // exactly two counts a larger swing.
    const std::vector<Extremum> ex = findExtrema(r.measured, r.periodS, from, c.threshold + 0.25 * resolution);
    if (ex.size() < static_cast<std::size_t>(2 * kMinCycles + 1))
        return c;
    const std::size_t use = std::min<std::size_t>(ex.size(), 2 * kMaxCycles + 1);
    const std::size_t first = ex.size() - use;
    double lo = 1e300, hi = 0, sum = 0;
    for (std::size_t i = first; i + 1 < ex.size(); ++i) {
        const double pp = std::abs(ex[i + 1].value - ex[i].value);
        lo = std::min(lo, pp);
        hi = std::max(hi, pp);
        sum += pp;
    }
    if (!(lo > 0) || hi / lo > kSteadySpread)
        return c;  // dying out: the end of a transient, not a cycle
    const double halfPeriodS = (ex.back().timeS - ex[first].timeS) / static_cast<double>(use - 1);
    // Still going at the end: the last turn is no further back than a period and a half.
    const double endS = static_cast<double>(n - 1) * r.periodS;
    if (endS - ex.back().timeS > 3 * halfPeriodS)
        return c;
    c.found = true;
    c.amplitude = sum / static_cast<double>(use - 1) / 2;
    c.periodS = 2 * halfPeriodS;
    c.cycles = static_cast<int>((use - 1) / 2);
    return c;
}

StepVerdict judgeStep(const Record& r, const StepJudging& how)
{
    StepVerdict v;
    v.metrics = stepMetrics(r, how.bandFraction);
    if (how.targetBand > 0)
        v.insideTargetBandS = settledInsideS(r, how.targetBand);
    if (v.metrics.outcome == StepOutcome::Unstable)
        return v;
    v.limitCycle = findLimitCycle(r, how.resolution);
    if (v.limitCycle.found) {
        // The cycle has a centre, so the figures read off it mean something; the outcome
        // says it never came to rest.
        const StepMetrics figures = stepFigures(r, how.bandFraction);
        v.metrics = figures;
        v.metrics.outcome = StepOutcome::LimitCycle;
    }
    return v;
}

const char* stepOutcomeName(StepOutcome o)
{
    switch (o) {
    case StepOutcome::Settled: return "settled";
    case StepOutcome::DidNotSettle: return "did not settle";
    case StepOutcome::Unstable: return "unstable";
    case StepOutcome::LimitCycle: return "limit cycle";
    }
    return "settled";
}

bool stepOutcomeFromName(const std::string& name, StepOutcome* out)
{
    for (StepOutcome o : {StepOutcome::Settled, StepOutcome::DidNotSettle, StepOutcome::Unstable, StepOutcome::LimitCycle})
        if (name == stepOutcomeName(o)) {
            *out = o;
            return true;
        }
    return false;
}

} // namespace motion::control
