#include "motion/control/tuning/relay_autotune.h"

#include "motion/control/tuning/short_number.h"
#include "motion/numbers.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace motion::control {

RelayAutotune::RelayAutotune(const RelayAutotuneOptions& o) : m_options(o)
{
    RelaySpec s;
    s.amplitude = o.amplitude;
    s.hysteresis = o.hysteresis;
    s.cycles = o.relayCycles;
    m_next = s;
}

RelaySpec RelayAutotune::forcedSpec(long samples) const
{
    RelaySpec s;
    s.amplitude = m_options.amplitude;
    s.hysteresis = m_options.hysteresis;
    s.forcedPeriodS = static_cast<double>(samples) * m_options.periodS;
    s.cycles = m_options.forcedCycles;
    return s;
}

void RelayAutotune::report(const Record& run)
{
    if (!m_next)
        return;
    ++m_work.runs;
    if (m_forcedSamples == 0) {
        const RelayAnalysis a = analyzeRelay(run, m_options.amplitude, m_options.hysteresis, m_options.input);
        if (!a.ok) {
            m_failure = endedNormally(run.reason)
                ? a.problem
                : motion::msg::make("tuning.relay.failed_run_ended", {motion::msg::nested("cause", a.problem), motion::msg::term("reason", endReasonTerm(run.reason))});
            m_next.reset();
            return;
        }
        m_work.kuDescribing = a.kuDescribing;
        m_work.tuRelayS = a.periodS;
        m_work.amplitude = a.amplitude;
        m_work.relayPhaseDeg = a.fundamental.phaseRad() * 180 / kPi;
        m_work.ku = a.kuDescribing;
        m_work.tuS = a.periodS;
        m_work.points.push_back(a.fundamental);
        m_relayPoint = {a.fundamental, a.fundamental.phaseRad()};
        m_minOmega = m_maxOmega = a.fundamental.omegaRadS;
        if (!m_options.refine) {
            m_result = m_work;
            m_next.reset();
            return;
        }
        if (std::abs(m_relayPoint.phase + kPi) < m_options.phaseToleranceRad) {
            finishWith(m_relayPoint, nullptr);
            return;
        }
        planForced();
        return;
    }
    if (!endedNormally(run.reason)) {
        m_failure = motion::msg::make("tuning.relay.refinement_ended", {motion::msg::term("reason", endReasonTerm(run.reason))});
        m_result = m_work;
        m_next.reset();
        return;
    }
    const FrequencyPoint p = analyzeForced(run, m_forcedSamples, m_options.skipCycles, m_options.input);
    m_work.points.push_back(p);
    addForced(p);
    m_minOmega = std::min(m_minOmega, p.omegaRadS);
    m_maxOmega = std::max(m_maxOmega, p.omegaRadS);
    if (std::abs(m_forced.back().phase + kPi) < m_options.phaseToleranceRad) {
        finishWith(m_forced.back(), nullptr);
        return;
    }
    planForced();
}

void RelayAutotune::addForced(const FrequencyPoint& p)
{
    // A phase is only known modulo 2π: take the branch nearest to what the
    // measured points predict at this ω (the lag grows with ω; steps between
    // measured frequencies are kept small enough for this to be unambiguous).
    std::vector<Point> known = m_forced;
    known.push_back(m_relayPoint);
    std::sort(known.begin(), known.end(), [&](const Point& a, const Point& b) {
        return std::abs(a.fp.omegaRadS - p.omegaRadS) < std::abs(b.fp.omegaRadS - p.omegaRadS);
    });
    const Point& ref = known[0];
    double slope = ref.phase / ref.fp.omegaRadS;  // as a pure delay would
    if (known.size() >= 2 && std::abs(known[1].fp.omegaRadS - ref.fp.omegaRadS) > 1e-12) {
        const double s = (known[1].phase - ref.phase) / (known[1].fp.omegaRadS - ref.fp.omegaRadS);
        if (s < 0)
            slope = s;
    }
    const double predicted = ref.phase + slope * (p.omegaRadS - ref.fp.omegaRadS);
    const double raw = std::arg(p.g);
    const double phase = raw + 2 * kPi * std::round((predicted - raw) / (2 * kPi));
    m_forced.push_back({p, phase});
}

void RelayAutotune::finishWith(const Point& a, const Point* b)
{
    double w = a.fp.omegaRadS, lnG = std::log(a.fp.gain());
    if (b) {
        const double t = (-kPi - a.phase) / (b->phase - a.phase);
        w = a.fp.omegaRadS + t * (b->fp.omegaRadS - a.fp.omegaRadS);
        lnG = lnG + t * (std::log(b->fp.gain()) - lnG);
    }
    m_work.ku = std::exp(-lnG);
    m_work.tuS = 2 * kPi / w;
    m_work.refined = true;
    m_result = m_work;
    m_next.reset();
}

void RelayAutotune::planForced()
{
    // Forced points are exact; the relay's own point is slightly off (its cycle
    // is not a whole number of samples), so it only guides until two forced points exist.
    std::vector<Point> pts = m_forced;
    if (pts.size() < 2)
        pts.push_back(m_relayPoint);
    const Point* less = nullptr;  // lags less than 180°, the one nearest −180°
    const Point* more = nullptr;  // lags more than 180°, the one nearest −180°
    for (const auto& p : pts) {
        if (p.phase > -kPi && (!less || p.phase < less->phase))
            less = &p;
        if (p.phase <= -kPi && (!more || p.phase > more->phase))
            more = &p;
    }
    const int forcedRuns = m_work.runs - 1;
    auto samplesOf = [&](double w) { return std::max(2L, std::lround(2 * kPi / (w * m_options.periodS))); };
    if (less && more) {
        const double gap = std::abs(less->fp.omegaRadS - more->fp.omegaRadS) / std::min(less->fp.omegaRadS, more->fp.omegaRadS);
        const bool adjacent = std::abs(samplesOf(less->fp.omegaRadS) - samplesOf(more->fp.omegaRadS)) <= 1;
        if (gap < 0.002 || forcedRuns >= m_options.maxForcedRuns || adjacent) {
            finishWith(*less, more);
            return;
        }
    }
    if (forcedRuns >= m_options.maxForcedRuns) {
        m_failure = motion::msg::make(less ? "tuning.relay.no_point_lagging_more" : "tuning.relay.no_point_lagging_less",
                              {motion::msg::real("from", m_minOmega), motion::msg::real("to", m_maxOmega)});
        m_result = m_work;
        m_next.reset();
        return;
    }
    // The secant on phase through the two points nearest −180°.
    std::vector<const Point*> near;
    for (const auto& p : pts)
        near.push_back(&p);
    std::sort(near.begin(), near.end(), [](auto* a, auto* b) { return std::abs(a->phase + kPi) < std::abs(b->phase + kPi); });
    const Point* a = less && more ? less : near[0];
    const Point* b = less && more ? more : (near.size() > 1 ? near[1] : nullptr);
    double w;
    if (b && std::abs(b->fp.omegaRadS - a->fp.omegaRadS) > 1e-12 && (b->phase - a->phase) / (b->fp.omegaRadS - a->fp.omegaRadS) < 0) {
        w = a->fp.omegaRadS + (-kPi - a->phase) * (b->fp.omegaRadS - a->fp.omegaRadS) / (b->phase - a->phase);
    } else {
        w = a->fp.omegaRadS * kPi / std::max(0.1, -a->phase);  // one point: scale as a pure delay would (phase ∝ ω)
    }
    const double nearest = near[0]->fp.omegaRadS;
    if (less && more) {
        const double lo = std::min(less->fp.omegaRadS, more->fp.omegaRadS), hi = std::max(less->fp.omegaRadS, more->fp.omegaRadS);
        w = std::clamp(w, lo + 0.05 * (hi - lo), hi - 0.05 * (hi - lo));
    } else {
        // Not bracketed yet: aim a little past the estimate so the next point
        // lands on the other side, never closer than 0.2 % to the nearest point
        // and never more than 1.5× away from it (the phase must stay unambiguous).
        w += 0.3 * (w - nearest);
        if (std::abs(w - nearest) < 0.002 * nearest)
            w = nearest * (w >= nearest ? 1.002 : 0.998);
        w = std::clamp(w, nearest / 1.5, nearest * 1.5);
    }
    long samples = samplesOf(w);
    while (std::find(m_triedSamples.begin(), m_triedSamples.end(), samples) != m_triedSamples.end()) {
        samples += w > a->fp.omegaRadS ? -1 : 1;  // already measured there: one period further towards the target
        if (samples < 2) {
            if (less && more)
                finishWith(*less, more);
            else {
                m_failure = motion::msg::make("tuning.relay.nyquist");
                m_result = m_work;
                m_next.reset();
            }
            return;
        }
    }
    m_triedSamples.push_back(samples);
    m_forcedSamples = samples;
    m_next = forcedSpec(samples);
}

} // namespace motion::control
