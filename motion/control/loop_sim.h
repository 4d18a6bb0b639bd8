#pragma once
// An experiment on a model plant: the controller at the plant's control period,
// the plant integrated exactly between periods (plant.h). What the device does
// on the stage, done in-process on a model.
#include "motion/control/experiment.h"
#include "motion/control/plant.h"

#include <functional>

namespace motion::control {

/// Called after every period with the record so far; returning true ends the
/// experiment there (EndReason::Completed: it ran what it needed): how a tuner
/// stops a trial that has shown enough.
using EarlyStop = std::function<bool(const Record& soFar)>;

/// Runs `experiment` on `plant` (which starts wherever it is) until it ends;
/// `maxPeriods` is a last-resort cap (the envelope's duration normally ends it first).
Record runExperiment(PlantSim& plant, Experiment experiment, const EarlyStop& earlyStop = {},
                     long maxPeriods = 50'000'000);

/// Closed loop with a plain incremental PID from rest at 0 towards setpoint
/// `step` for `durationS`: the workhorse of bench_tuning and of quick checks.
Record simulatePid(const PlantSpec& spec, const DiscreteGains& gains, double step, double durationS);

} // namespace motion::control
