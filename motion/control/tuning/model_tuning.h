#pragma once
// Tuning a model plant end to end, in-process: the same planners and the same
// experiments the device runs, on PlantSim. Used by the CLI (--plant), the
// tuning screen's model plants and the accuracy tests.
#include "motion/control/loop_sim.h"
#include "motion/control/tuning/relay_autotune.h"
#include "motion/control/tuning/ultimate_gain.h"

#include <functional>
#include <optional>
#include <string>

namespace motion::control {

enum class TuningMethod { UltimateGain, Relay };

struct ModelTuningOptions {
    TuningMethod method = TuningMethod::UltimateGain;
    double step = 1;               ///< ultimate gain: the setpoint step of each trial
    /// The operator's envelope; trials run inside trialShare of it, so a trial
    /// that grows is stopped before the real limits.
    Envelope envelope{3, 3, 600};
    double trialShare = 0.6;
    double startKp = 0.1;
    double kpMax = 1000;
    double relayAmplitude = 1;     ///< d
    double hysteresis = 0;         ///< ε
    bool refine = true;
};

struct ModelTuning {
    bool ok = false;
    motion::msg::Message error;            ///< why not (or a note beside a classic-only relay result): tuning.*
    double ku = 0, tuS = 0;
    std::optional<UltimateResult> ultimate;
    std::optional<RelayResult> relay;
    std::vector<UltimateTrial> trials;  ///< ultimate gain: every trial
    std::vector<Record> runs;      ///< every experiment's record, in order
    double simulatedS = 0;
};

/// Progress: (runs done, a short description of the last one).
using TuningProgress = std::function<void(int runs, const motion::msg::Message& what)>;

/// Tunes `plant` with `options`. A plant with no finite ultimate gain is
/// refused up front, with the reason.
ModelTuning tuneModel(const PlantSpec& plant, const ModelTuningOptions& options, const TuningProgress& progress = {});

/// Stops a P-only trial once it has shown enough cycles, or has gone quiet:
/// what the model tuner uses so a trial costs what it needs and no more.
EarlyStop trialEarlyStop(double swing);

/// The envelope a trial runs in: `share` of the operator's limits, same duration.
Envelope trialEnvelope(const Envelope& operatorEnvelope, double share);

} // namespace motion::control
