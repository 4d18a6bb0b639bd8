#include "motion/control/tuning/model_tuning.h"
#include "motion/control/tuning/short_number.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

namespace motion::control {
namespace {
constexpr int kEnoughExtrema = 14;  ///< about six cycle-over-cycle ratios


/// Streaming version of findExtrema's rule, plus the checkpoints of the quiet test.
struct Monitor {
    double swing;
    int dir = 0;
    double hi = 0, lo = 0, cand = 0;
    bool started = false;
    int extrema = 0;
    std::size_t nextCheck = 2000;

    bool operator()(const Record& r)
    {
        const std::size_t n = r.size();
        const double y = r.measured.back();
        if (!started) {
            hi = lo = cand = y;
            started = true;
        }
        if (dir == 0) {
            hi = std::max(hi, y);
            lo = std::min(lo, y);
            if (hi - lo > swing) {
                dir = y >= hi ? 1 : -1;
                cand = y;
            }
        } else if (dir > 0) {
            if (y > cand)
                cand = y;
            else if (y < cand - swing) {
                ++extrema;
                dir = -1;
                cand = y;
            }
        } else {
            if (y < cand)
                cand = y;
            else if (y > cand + swing) {
                ++extrema;
                dir = 1;
                cand = y;
            }
        }
        if (extrema >= kEnoughExtrema)
            return true;
        if (n >= nextCheck) {
            // Quiet: the second half of the run so far moved by next to nothing
            // compared with how far the output has come.
            nextCheck = 2 * n;
            const auto [mn, mx] = std::minmax_element(r.measured.begin() + static_cast<std::ptrdiff_t>(n / 2), r.measured.end());
            double reach = 0;
            for (double v : r.measured)
                reach = std::max(reach, std::abs(v - r.startPosition));
            // (A dead time has not even let the output move yet: not quiet, waiting.)
            if (reach > 100 * swing && *mx - *mn <= std::max(swing, 2e-3 * reach))
                return true;
        }
        return false;
    }
};
} // namespace

EarlyStop trialEarlyStop(double swing)
{
    auto m = std::make_shared<Monitor>();
    m->swing = swing;
    return [m](const Record& r) { return (*m)(r); };
}

Envelope trialEnvelope(const Envelope& e, double share)
{
    return {e.maxExcursion * share, e.maxFollowingError * share, e.maxDurationS};
}

ModelTuning tuneModel(const PlantSpec& plant, const ModelTuningOptions& o, const TuningProgress& progress)
{
    ModelTuning out;
    const motion::msg::Message why = whyNoUltimateGain(plant);
    if (!why.empty()) {
        out.error = motion::msg::make("tuning.model.no_ultimate_gain", {motion::msg::verbatim("plant", plant.text()), motion::msg::nested("cause", why)});
        return out;
    }
    const Envelope trialEnv = trialEnvelope(o.envelope, o.trialShare);
    if (o.method == TuningMethod::UltimateGain) {
        UltimateGainOptions uo;
        uo.startKp = o.startKp;
        uo.kpMax = o.kpMax;
        uo.swing = 1e-6 * std::abs(o.step);
        UltimateGainSearch search(uo);
        while (auto kp = search.nextKp()) {
            PlantSim sim(plant);
            StepSpec s;
            s.step = o.step * search.stepScale();
            s.gains = {*kp, 0, 0};
            s.runS = o.envelope.maxDurationS;
            s.envelope = trialEnv;
            s.envelope.maxDurationS = o.envelope.maxDurationS * 1.01;  // runS ends it first, normally
            Record r = runExperiment(sim, Experiment::stepTest(s, sim.output(), 0, plant.periodS), trialEarlyStop(uo.swing * search.stepScale()));
            out.simulatedS += static_cast<double>(r.size()) * r.periodS;
            search.report(*kp, r);
            out.runs.push_back(std::move(r));
            if (progress) {
                const auto& t = search.trials().back();
                progress(static_cast<int>(out.runs.size()),
                         t.oscillation.oscillating ? motion::msg::make("tuning.progress.trial", {motion::msg::real("kp", *kp), motion::msg::real("ratio", t.oscillation.ratio)})
                                                   : motion::msg::make("tuning.progress.trial_no_oscillation", {motion::msg::real("kp", *kp)}));
            }
        }
        out.trials = search.trials();
        if (!search.result()) {
            out.error = search.failure();
            return out;
        }
        out.ultimate = search.result();
        out.ku = out.ultimate->ku;
        out.tuS = out.ultimate->tuS;
        out.ok = true;
        return out;
    }
    RelayAutotuneOptions ro;
    ro.amplitude = o.relayAmplitude;
    ro.hysteresis = o.hysteresis;
    ro.periodS = plant.periodS;
    ro.refine = o.refine;
    ro.input = InputModel::Held;
    RelayAutotune tuner(ro);
    PlantSim sim(plant);  // one plant: the forced runs start from the relay's cycle, as on a device
    while (auto spec = tuner.next()) {
        RelaySpec s = *spec;
        s.envelope = trialEnv;
        Record r = runExperiment(sim, Experiment::relay(s, 0, 0, plant.periodS));
        out.simulatedS += static_cast<double>(r.size()) * r.periodS;
        tuner.report(r);
        out.runs.push_back(std::move(r));
        if (progress)
            progress(static_cast<int>(out.runs.size()), s.forcedPeriodS > 0
                                                            ? motion::msg::make("tuning.progress.forced_run", {motion::msg::real("period", s.forcedPeriodS, motion::msg::Unit::S)})
                                                            : motion::msg::make("tuning.progress.relay_run"));
    }
    if (!tuner.result()) {
        out.error = tuner.failure();
        return out;
    }
    out.relay = tuner.result();
    out.error = tuner.failure();
    out.ku = out.relay->ku;
    out.tuS = out.relay->tuS;
    out.ok = true;
    return out;
}

} // namespace motion::control
