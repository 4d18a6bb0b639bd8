#pragma once
// One judgement of a step response, the same for an operator's step test and the
// Ziegler–Nichols verification: the metrics with their outcome (unstable, a limit
// cycle, did not settle, settled), the residual oscillation at rest if there is
// one, and when the response entered an absolute band around the target for good.
#include "motion/control/experiment.h"
#include "motion/control/tuning/step_metrics.h"

#include <limits>

namespace motion::control {

/// What the judgement needs to know of the measurement and what to report.
struct StepJudging {
    double bandFraction = 0.02;  ///< the settling band, a fraction of the step's span
    double resolution = 0;       ///< the measurement's quantum (a grating count, output unit); 0: none (a model)
    double targetBand = 0;       ///< ±band around the setpoint whose entry is timed (0.005 mm: seed 002's ±5 µm); 0: none
};

/// An oscillation that goes on to the end of the record with an amplitude that does
/// not die out: the loop hunts instead of coming to rest.
struct LimitCycle {
    bool found = false;
    double amplitude = 0;      ///< half the mean peak-to-peak of the last cycles, output unit
    double periodS = 0;
    int cycles = 0;            ///< full cycles measured
    double threshold = 0;      ///< peak-to-peak a swing must exceed to count (output unit)
};

/// The oscillation left in the last part of `r` (the second half of the record),
/// against `resolution` (see the threshold's reason in the .cpp).
LimitCycle findLimitCycle(const Record& r, double resolution);

struct StepVerdict {
    StepMetrics metrics;  ///< outcome Unstable, LimitCycle, DidNotSettle or Settled
    LimitCycle limitCycle;
    double insideTargetBandS = std::numeric_limits<double>::quiet_NaN();  ///< NaN: never, or no band asked
};

/// The judgement: a tripped envelope is Unstable; a residual oscillation a LimitCycle
/// (its figures kept: it has a centre to read them from); a response that never stays in
/// its band DidNotSettle; else Settled.
StepVerdict judgeStep(const Record& r, const StepJudging& how);

/// The key in files and JSON: "settled", "did not settle", "unstable", "limit cycle".
const char* stepOutcomeName(StepOutcome o);
/// The outcome from its key; nullopt-like: false when the key is unknown.
bool stepOutcomeFromName(const std::string& name, StepOutcome* out);

} // namespace motion::control
