#include "motion/control/tuning/ultimate_gain.h"
#include "motion/control/tuning/short_number.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace motion::control {
namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();

} // namespace

UltimateGainSearch::UltimateGainSearch(const UltimateGainOptions& options) : m_options(options)
{
    if (std::isfinite(options.startKp) && options.startKp > 0 && options.startKp <= options.kpMax)
        m_next = options.startKp;
    else
        m_failure = motion::msg::make("tuning.ultimate.bad_start_kp", {motion::msg::real("value", options.startKp), motion::msg::real("max", options.kpMax)});
}

UltimateTrial UltimateGainSearch::analyzeTrial(double kp, const Record& trial, double swing)
{
    UltimateTrial t;
    t.kp = kp;
    t.reason = trial.reason;
    t.oscillation = analyzeOscillation(trial.measured, trial.periodS, 0, swing);
    const bool hitEnvelope = trial.reason == EndReason::Excursion || trial.reason == EndReason::FollowingError;
    if (t.oscillation.oscillating)
        t.logRatio = std::log(t.oscillation.ratio);  // what the cycles said, even if the envelope ended it
    else
        t.logRatio = hitEnvelope ? kInf : -kInf;
    return t;
}

void UltimateGainSearch::report(double kp, const Record& trial)
{
    if (!m_next)
        return;
    UltimateTrial t = analyzeTrial(kp, trial, m_options.swing * m_stepScale);
    t.stepScale = m_stepScale;
    t.sustained = std::isfinite(t.logRatio) && t.oscillation.ratio >= m_options.sustainedLow
        && t.oscillation.ratio <= m_options.sustainedHigh;
    if (t.logRatio == kInf && m_stepScale > 1.0 / 16) {
        // Stopped by the envelope before one cycle could be compared: a big first
        // overshoot, or real growth. A smaller step tells them apart.
        t.inconclusive = true;
        m_trials.push_back(t);
        if (static_cast<int>(m_trials.size()) >= m_options.maxTrials) {
            m_failure = motion::msg::make("tuning.ultimate.envelope_hits");
            m_next.reset();
            return;
        }
        m_stepScale *= 0.5;
        return;  // same Kp again
    }
    m_trials.push_back(t);
    decide();
}

void UltimateGainSearch::finish(double ku, double tuS, double ratio)
{
    UltimateResult r;
    r.ku = ku;
    r.tuS = tuS;
    r.ratio = ratio;
    r.trials = static_cast<int>(m_trials.size());
    for (const auto& t : m_trials)
        if (t.sustained) {
            r.firstSustainedKp = t.kp;
            break;
        }
    m_result = r;
    m_next.reset();
}

void UltimateGainSearch::decide()
{
    // The closest trial below (decaying) and above (growing) Ku.
    const UltimateTrial* below = nullptr;
    const UltimateTrial* above = nullptr;
    const UltimateTrial* nearest = nullptr;
    for (const auto& t : m_trials) {
        if (t.inconclusive)
            continue;
        if (t.logRatio < 0 && (!below || t.kp > below->kp))
            below = &t;
        if (t.logRatio >= 0 && (!above || t.kp < above->kp))
            above = &t;
        if (std::isfinite(t.logRatio) && (!nearest || std::abs(t.logRatio) < std::abs(nearest->logRatio)))
            nearest = &t;
    }
    const double tol = m_options.refineTolerance;
    const bool bracketFinite = below && above && std::isfinite(below->logRatio) && std::isfinite(above->logRatio);
    auto interpolate = [&](double ln1, double v1, double ln2, double v2) { return v1 + (v2 - v1) * (0 - ln1) / (ln2 - ln1); };
    if (bracketFinite && (std::abs(below->logRatio) < tol || std::abs(above->logRatio) < tol
                          || std::log(above->kp / below->kp) < 0.005)) {
        // Ku where ln ratio = 0, interpolated in ln Kp; Tu likewise.
        const double lnKu = interpolate(below->logRatio, std::log(below->kp), above->logRatio, std::log(above->kp));
        const double tu = interpolate(below->logRatio, below->oscillation.periodS, above->logRatio, above->oscillation.periodS);
        finish(std::exp(lnKu), tu, nearest->oscillation.ratio);
        return;
    }
    if (nearest && std::abs(nearest->logRatio) < 0.25 * tol) {
        finish(nearest->kp, nearest->oscillation.periodS, nearest->oscillation.ratio);
        return;
    }
    if (below && above && !bracketFinite && std::log(above->kp / below->kp) < 0.01 && std::isfinite(below->logRatio)
        && below->oscillation.ratio >= m_options.sustainedLow) {
        // It grows out of the envelope right above a trial that barely decays:
        // Ku sits in between, closer than the trials can resolve.
        finish(std::sqrt(below->kp * above->kp), below->oscillation.periodS, below->oscillation.ratio);
        return;
    }
    if (static_cast<int>(m_trials.size()) >= m_options.maxTrials) {
        const motion::msg::Arg trials = motion::msg::integer("trials", static_cast<long long>(m_trials.size()));
        m_failure = nearest ? motion::msg::make("tuning.ultimate.no_sustained_nearest",
                                        {trials, motion::msg::real("kp", nearest->kp), motion::msg::real("ratio", nearest->oscillation.ratio)})
                            : motion::msg::make("tuning.ultimate.no_sustained", {trials});
        m_next.reset();
        return;
    }
    double next;
    const UltimateTrial& last = m_trials.back();
    if (below && above) {
        const double lo = std::log(below->kp), hi = std::log(above->kp);
        double x = 0.5 * (lo + hi);
        if (bracketFinite)
            x = interpolate(below->logRatio, lo, above->logRatio, hi);
        x = std::clamp(x, lo + 0.1 * (hi - lo), hi - 0.1 * (hi - lo));
        next = std::exp(x);
    } else if (above) {
        // Everything tried so far grows: come down.
        next = above->kp / m_options.growth;
    } else {
        // Everything decays. With two measured ratios, extrapolate the secant;
        // with one, assume the flattest slope a delay loop has (ln r = 2·ln(K/Ku)).
        next = below->kp * m_options.growth;
        std::vector<const UltimateTrial*> finite;
        for (const auto& t : m_trials)
            if (std::isfinite(t.logRatio) && !t.inconclusive)
                finite.push_back(&t);
        std::sort(finite.begin(), finite.end(), [](auto* a, auto* b) { return a->kp > b->kp; });
        if (finite.size() >= 2 && finite[0]->kp != finite[1]->kp) {
            const double s = (finite[0]->logRatio - finite[1]->logRatio) / std::log(finite[0]->kp / finite[1]->kp);
            if (s > 0)
                next = finite[0]->kp * std::exp(-finite[0]->logRatio / s);
        } else if (finite.size() == 1) {
            next = finite[0]->kp * std::exp(-finite[0]->logRatio / 2);
        }
        const double from = below->kp;
        next = std::clamp(next * 1.02, from * 1.05, from * m_options.growth);
    }
    (void)last;
    if (next > m_options.kpMax) {
        if (!above) {
            m_failure = motion::msg::make("tuning.ultimate.decays_up_to", {motion::msg::real("kp", m_options.kpMax)});
            m_next.reset();
            return;
        }
        next = m_options.kpMax;
    }
    for (const auto& t : m_trials)
        if (!t.inconclusive && std::abs(t.kp - next) <= 1e-9 * next) {
            m_failure = motion::msg::make("tuning.ultimate.stalled", {motion::msg::real("kp", next)});
            m_next.reset();
            return;
        }
    m_next = next;
}

} // namespace motion::control
