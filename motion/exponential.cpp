#include "motion/exponential.h"

#include <algorithm>
#include <cmath>

namespace motion {

namespace {

bool positive(double x) { return std::isfinite(x) && x > 0.0; }

/// Distance of the ramp v = vm(1 - e^(-t/τ)) after time t.
double rampDistance(double vm, double tau, double t) { return vm * (t - tau * (-std::expm1(-t / tau))); }

}  // namespace

std::optional<ExponentialProfile> ExponentialProfile::plan(double distanceMm, double vMaxMmS, double timeConstantS,
                                                           double accelTimeS)
{
    if (!std::isfinite(distanceMm) || !positive(vMaxMmS) || !positive(timeConstantS) || !positive(accelTimeS))
        return std::nullopt;
    ExponentialProfile p;
    p.m_lengthMm = std::fabs(distanceMm);
    p.m_direction = distanceMm < 0.0 ? -1.0 : 1.0;
    p.m_vMaxMmS = vMaxMmS;
    p.m_tauS = timeConstantS;
    if (p.m_lengthMm == 0.0)
        return p;
    const double half = 0.5 * p.m_lengthMm;
    if (rampDistance(vMaxMmS, timeConstantS, accelTimeS) <= half) {
        p.m_accelTimeS = accelTimeS;
        p.m_cruiseTimeS = (p.m_lengthMm - 2.0 * rampDistance(vMaxMmS, timeConstantS, accelTimeS)) / p.cruiseSpeedMmS();
        return p;
    }
    // Short move: find Ta' < accelTimeS with rampDistance(Ta') = D/2. The function is convex and
    // increasing, so Newton from the right end (where it overshoots) converges monotonically.
    double t = accelTimeS;
    for (int it = 0; it < 60; ++it) {
        const double f = rampDistance(vMaxMmS, timeConstantS, t) - half;
        const double v = vMaxMmS * -std::expm1(-t / timeConstantS);
        const double next = t - f / v;
        if (!(next < t) || next <= 0.0)
            break;
        t = next;
        if (std::fabs(f) <= 1e-14 * p.m_lengthMm)
            break;
    }
    p.m_accelTimeS = t;
    p.m_cruiseTimeS = 0.0;
    return p;
}

double ExponentialProfile::cruiseSpeedMmS() const { return m_vMaxMmS * -std::expm1(-m_accelTimeS / m_tauS); }

ProfileSample ExponentialProfile::at(double tS) const
{
    ProfileSample out;
    if (!(tS > 0.0))
        return out;
    const double total = duration();
    if (tS >= total) {
        out.t = total;
        out.s = distance();
        return out;
    }
    out.t = tS;
    const double vm = m_vMaxMmS, tau = m_tauS;
    double s, v, a, j;
    const bool decel = tS > m_accelTimeS + m_cruiseTimeS;
    const double u = decel ? total - tS : tS;  // decel is the time-mirror: evaluate from the end
    if (u <= m_accelTimeS) {
        const double e = std::exp(-u / tau);
        s = rampDistance(vm, tau, u);
        v = vm * (1.0 - e);
        a = vm / tau * e;
        j = -a / tau;
    } else {
        s = rampDistance(vm, tau, m_accelTimeS) + cruiseSpeedMmS() * (u - m_accelTimeS);
        v = cruiseSpeedMmS();
        a = 0.0;
        j = 0.0;
    }
    if (decel) {
        s = m_lengthMm - s;
        a = -a;
    }
    out.s = m_direction * s;
    out.v = m_direction * v;
    out.a = m_direction * a;
    out.j = m_direction * j;
    return out;
}

std::optional<ExponentialStair> buildExponentialStair(const ExponentialStairConfig& c)
{
    if (!positive(c.maxRateHz) || !positive(c.timeConstantS) || !positive(c.accelTimeS) || !positive(c.startRateHz)
        || !positive(c.timerClockHz) || !(c.interruptLatencyS >= 0.0) || c.stages < 2 || c.timerModulus == 0)
        return std::nullopt;
    ExponentialStair out;
    const double fm = c.maxRateHz, tau = c.timeConstantS;
    const int climbing = c.stages - 1;  // stairs below the top
    const double dt = c.accelTimeS / climbing;
    const double latencyTicks = c.interruptLatencyS * c.timerClockHz;
    const auto makeStage = [&](double rate) -> std::optional<StairStage> {
        StairStage st;
        st.rateHz = rate;
        const double ticks = c.timerClockHz / rate;
        st.periodTicks = static_cast<std::uint32_t>(std::llround(ticks));
        const long long reload = std::llround(ticks - latencyTicks);
        if (reload <= 0 || reload > static_cast<long long>(c.timerModulus))
            return std::nullopt;
        st.reloadTicks = static_cast<std::uint32_t>(reload);
        st.reloadValue = c.timerModulus - st.reloadTicks;
        return st;
    };
    // Each stair runs at the MEAN rate of the ideal curve over its slot, so a stair covers the
    // same number of steps as the curve does in that slot: position stays on the curve at every
    // stair edge; only the rate is stepped. The first stair never goes below the jump rate.
    double stairTime = 0.0;
    for (int i = 0; i < climbing; ++i) {
        const double t0 = i * dt, t1 = (i + 1) * dt;
        const double idealSteps = rampDistance(fm, tau, t1) - rampDistance(fm, tau, t0);
        const double rate = std::max(c.startRateHz, idealSteps / dt);
        auto st = makeStage(rate);
        if (!st)
            return std::nullopt;
        st->steps = static_cast<std::uint32_t>(std::max(1LL, std::llround(rate * dt)));
        stairTime += st->steps / rate;
        out.accelSteps += st->steps;
        out.stages.push_back(*st);
    }
    auto top = makeStage(std::max(c.startRateHz, fm * -std::expm1(-c.accelTimeS / tau)));
    if (!top)
        return std::nullopt;
    top->steps = 0;  // seed: the top stair's step count 0x00 marks the end of acceleration
    top->last = true;
    out.stages.push_back(*top);
    out.idealAccelSteps = rampDistance(fm, tau, c.accelTimeS);
    out.stairAccelTimeS = stairTime;
    out.timeErrorS = stairTime - c.accelTimeS;
    // Rate error of the stair against the curve, sampled densely over the stair's own time line.
    double maxErr = 0.0, sumSq = 0.0;
    const int samples = 2000;
    std::size_t stage = 0;
    double stageEnd = out.stages[0].steps / out.stages[0].rateHz;
    for (int k = 0; k <= samples; ++k) {
        const double t = stairTime * k / samples;
        while (stage + 1 < out.stages.size() - 1 && t > stageEnd) {
            ++stage;
            stageEnd += out.stages[stage].steps / out.stages[stage].rateHz;
        }
        const double err = out.stages[stage].rateHz - fm * -std::expm1(-t / tau);
        maxErr = std::max(maxErr, std::fabs(err));
        sumSq += err * err;
    }
    out.maxRateErrorHz = maxErr;
    out.rmsRateErrorHz = std::sqrt(sumSq / (samples + 1));
    return out;
}

std::vector<double> stairStepPeriodsS(const ExponentialStair& stair, const ExponentialStairConfig& config,
                                      std::int64_t totalSteps)
{
    std::vector<double> periods;
    if (totalSteps <= 0 || stair.stages.empty())
        return periods;
    const double latencyTicks = config.interruptLatencyS * config.timerClockHz;
    const auto periodOf = [&](const StairStage& st) { return (st.reloadTicks + latencyTicks) / config.timerClockHz; };
    // The acceleration as a list of per-step periods, cut at half the move for short moves.
    std::vector<double> up;
    const std::int64_t halfSteps = totalSteps / 2;
    for (const auto& st : stair.stages) {
        if (st.last)
            break;
        for (std::uint32_t k = 0; k < st.steps && static_cast<std::int64_t>(up.size()) < halfSteps; ++k)
            up.push_back(periodOf(st));
    }
    const bool reachedTop = static_cast<std::int64_t>(up.size()) < halfSteps
                            || static_cast<std::int64_t>(up.size()) == static_cast<std::int64_t>(stair.accelSteps);
    periods.reserve(static_cast<std::size_t>(totalSteps));
    periods.insert(periods.end(), up.begin(), up.end());
    const std::int64_t cruise = totalSteps - 2 * static_cast<std::int64_t>(up.size());
    const double cruisePeriod = reachedTop ? periodOf(stair.stages.back()) : (up.empty() ? periodOf(stair.stages.front()) : up.back());
    for (std::int64_t k = 0; k < cruise; ++k)
        periods.push_back(cruisePeriod);
    periods.insert(periods.end(), up.rbegin(), up.rend());  // deceleration walks the table back
    return periods;
}

}  // namespace motion
