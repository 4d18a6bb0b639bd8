#include "motion/control/tuning/step_metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace motion::control {
namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// First time the response (in fractions of the way from y0 to yf) reaches `level`, interpolated.
double firstCrossing(const Record& r, double y0, double yf, double level)
{
    const double span = yf - y0;
    double prev = 0;
    for (std::size_t k = 0; k < r.size(); ++k) {
        const double f = (r.measured[k] - y0) / span;
        if (f >= level) {
            if (k == 0)
                return 0;
            return (static_cast<double>(k - 1) + (level - prev) / (f - prev)) * r.periodS;
        }
        prev = f;
    }
    return kNaN;
}
} // namespace

namespace {
StepMetrics unsettled(StepMetrics m, StepOutcome why)
{
    m.outcome = why;
    m.riseTimeS = m.overshootPct = m.settlingTimeS = m.steadyStateError = kNaN;
    return m;
}
} // namespace

StepMetrics stepMetrics(const Record& r, double bandFraction)
{
    StepMetrics m = stepFigures(r, bandFraction);
    // A tripped envelope ends a response that was running away: its last samples
    // are no final value, and "overshoot 0 %, settled in 6 ms" read off them would lie.
    if (r.reason == EndReason::Excursion || r.reason == EndReason::FollowingError)
        return unsettled(m, StepOutcome::Unstable);
    if (r.size() >= 2 && !std::isfinite(m.settlingTimeS))
        return unsettled(m, StepOutcome::DidNotSettle);
    return m;
}

StepMetrics stepFigures(const Record& r, double bandFraction)
{
    StepMetrics m;
    if (r.size() < 2)
        return m;
    const std::size_t n = r.size();
    const double y0 = r.startPosition;
    const double sp = r.setpoint.back();
    m.step = sp - y0;
    m.durationS = static_cast<double>(n) * r.periodS;
    const std::size_t tail = std::max<std::size_t>(1, n / 20);
    double sum = 0;
    for (std::size_t k = n - tail; k < n; ++k)
        sum += r.measured[k];
    m.finalValue = sum / static_cast<double>(tail);
    m.steadyStateError = sp - m.finalValue;
    for (std::size_t k = 0; k < n; ++k) {
        const double e = r.setpoint[k] - r.measured[k];
        m.iae += std::abs(e) * r.periodS;
        m.ise += e * e * r.periodS;
        m.peakOutput = std::max(m.peakOutput, std::abs(r.output[k] - r.startOutput));
    }
    const double span = m.finalValue - y0;
    if (std::abs(span) < 1e-12 * std::max(1.0, std::abs(m.step))) {
        m.riseTimeS = m.settlingTimeS = kNaN;
        return m;
    }
    const double t10 = firstCrossing(r, y0, m.finalValue, 0.1), t90 = firstCrossing(r, y0, m.finalValue, 0.9);
    m.riseTimeS = t90 - t10;
    double peak = 0;
    for (std::size_t k = 0; k < n; ++k)
        peak = std::max(peak, (r.measured[k] - m.finalValue) / span);
    m.overshootPct = 100 * peak;
    const double band = bandFraction * std::abs(span);
    m.settlingTimeS = kNaN;
    for (std::size_t k = n; k-- > 0;) {
        if (std::abs(r.measured[k] - m.finalValue) > band) {
            if (k + 1 < n)
                m.settlingTimeS = static_cast<double>(k + 1) * r.periodS;
            return m;
        }
    }
    m.settlingTimeS = 0;
    return m;
}

double settledInsideS(const Record& r, double band)
{
    const std::size_t n = r.size();
    for (std::size_t k = n; k-- > 0;) {
        if (std::abs(r.measured[k] - r.setpoint[k]) > band)
            return k + 1 < n ? static_cast<double>(k + 1) * r.periodS : kNaN;
    }
    return n ? 0.0 : kNaN;
}

} // namespace motion::control
