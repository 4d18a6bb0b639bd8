#include "device/backends/grbl/grbl_jog.h"

#include "device/backends/grbl/grbl_gcode.h"

#include <algorithm>
#include <cmath>

namespace dev::grbl {

namespace {

/// Segment time for speed v: ≥ the minimum, and long enough that aheadMax fits the planner
/// with one block to spare: (blocks − 1) segments cover aheadMin + dt ⇔ dt ≥ aheadMin/(blocks − 2).
double segmentTimeS(const JogPlanInput& in, double v)
{
    const double aheadMin = v / (2 * in.accelMmS2) + in.linkLatencyS + in.refreshPeriodS;
    const int spare = std::max(1, in.plannerBlocks - 2);
    return std::max(in.minSegmentS, aheadMin / spare);
}

double overrunS(const JogPlanInput& in, double v)
{
    return v / in.accelMmS2 + in.linkLatencyS + in.refreshPeriodS + segmentTimeS(in, v);
}

} // namespace

JogPlan planContinuousJog(const JogPlanInput& in)
{
    JogPlan p;
    p.accelMmS2 = in.accelMmS2;
    p.linkLatencyS = in.linkLatencyS;
    const double wanted = std::min(in.speedMmS, in.maxRateMmS);
    const bool sane = std::isfinite(wanted) && wanted > 0 && std::isfinite(in.accelMmS2) && in.accelMmS2 > 0
                      && in.plannerBlocks >= 3 && in.refreshPeriodS >= 0 && in.linkLatencyS >= 0 && in.stopBudgetS > 0;
    // Even a creeping jog needs L + C + dt: a host that refreshes too rarely cannot promise the budget.
    if (!sane || overrunS(in, 0) >= in.stopBudgetS) {
        p.problem = motion::msg::make("grbl.jog.budget_too_small", {motion::msg::real("budget", in.stopBudgetS, motion::msg::Unit::S),
                                                             motion::msg::real("latency", in.linkLatencyS, motion::msg::Unit::S),
                                                             motion::msg::real("refresh", in.refreshPeriodS, motion::msg::Unit::S)});
        return p;
    }
    double v = wanted;
    if (overrunS(in, v) > in.stopBudgetS) {
        // overrunS grows with v: bisect for the largest speed that keeps the budget.
        double lo = 0, hi = v;
        for (int k = 0; k < 60; ++k) {
            const double mid = 0.5 * (lo + hi);
            (overrunS(in, mid) <= in.stopBudgetS ? lo : hi) = mid;
        }
        v = lo;
        p.speedLimited = true;
    }
    const double a = in.accelMmS2;
    p.feasible = true;
    p.speedMmS = v;
    p.feedMmMin = v * 60;
    p.segmentS = segmentTimeS(in, v);
    p.segmentMm = v * p.segmentS;
    p.aheadMinS = v / (2 * a) + in.linkLatencyS + in.refreshPeriodS;
    p.aheadMaxS = p.aheadMinS + p.segmentS;
    p.segmentsAhead = static_cast<int>(std::ceil(p.aheadMaxS / p.segmentS - 1e-9));
    p.releaseStopS = in.linkLatencyS + v / a;
    p.releaseStopMm = v * in.linkLatencyS + v * v / (2 * a);
    p.lostLinkOverrunS = p.aheadMaxS + v / (2 * a);
    p.lostLinkOverrunMm = v * p.aheadMaxS;
    return p;
}

std::pair<double, double> jogLimitsAlong(const std::vector<double>& unit, const std::vector<double>& maxRateMmS,
                                         const std::vector<double>& accelMmS2)
{
    double norm = 0;
    for (const double u : unit)
        norm += u * u;
    norm = std::sqrt(norm);
    double v = 1e300, acc = 1e300;
    for (std::size_t i = 0; i < unit.size() && norm > 0; ++i) {
        const double u = std::fabs(unit[i]) / norm;
        if (u < 1e-12)
            continue;
        if (i < maxRateMmS.size())
            v = std::min(v, maxRateMmS[i] / u);
        if (i < accelMmS2.size())
            acc = std::min(acc, accelMmS2[i] / u);
    }
    return {v, acc};
}

namespace {
std::string segmentLineOf(const JogPlan& plan, const std::string& axes, const std::vector<double>& unit)
{
    double norm = 0;
    for (const double u : unit)
        norm += u * u;
    norm = std::sqrt(norm);
    std::vector<AxisValue> deltas;
    for (std::size_t i = 0; i < axes.size() && i < unit.size() && norm > 0; ++i)
        if (std::fabs(unit[i]) > 1e-12)
            deltas.push_back({axes[i], unit[i] / norm * plan.segmentMm});
    return plan.feasible ? jogLine(deltas, plan.feedMmMin).text : std::string();  // empty when refused: nothing is sent
}
} // namespace

ContinuousJog::ContinuousJog(const JogPlan& plan, std::string axes, std::vector<double> unit)
    : m_plan(plan), m_line(segmentLineOf(plan, axes, unit))
{
}

void ContinuousJog::retarget(const JogPlan& plan, const std::string& axes, const std::vector<double>& unit)
{
    m_plan = plan;
    m_line = segmentLineOf(plan, axes, unit);
    if (m_line.empty())
        m_active = false;
}

std::vector<std::string> ContinuousJog::start(double nowS)
{
    m_active = !m_line.empty();
    // The machine accelerates from rest and so lags a constant-speed start by v/(2a), plus the
    // latency of the first line: counting that lag keeps the estimate of what is ahead honest.
    m_queuedUntilS = nowS + m_plan.linkLatencyS + m_plan.speedMmS / (2 * m_plan.accelMmS2);
    return tick(nowS);
}

std::vector<std::string> ContinuousJog::tick(double nowS)
{
    std::vector<std::string> out;
    if (!m_active)
        return out;
    // A host that stalled (the queue ran dry) starts over from where the machine now is.
    m_queuedUntilS = std::max(m_queuedUntilS, nowS);
    while (m_queuedUntilS - nowS < m_plan.aheadMinS && static_cast<int>(out.size()) < m_plan.segmentsAhead) {
        out.push_back(m_line);
        m_queuedUntilS += m_plan.segmentS;
        ++m_sent;
    }
    return out;
}

std::uint8_t ContinuousJog::stop()
{
    m_active = false;
    return rt::kJogCancel;
}

} // namespace dev::grbl
