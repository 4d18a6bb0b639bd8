#pragma once
// What a control engineer reads off a step response.
#include "motion/control/experiment.h"

namespace motion::control {

/// Whether the figures relative to the final value mean anything: a response
/// that tripped its envelope, or never stayed inside its band, has no final value.
/// LimitCycle (judgeStep, step_verdict.h): it keeps oscillating at rest around a centre.
enum class StepOutcome { Settled, DidNotSettle, Unstable, LimitCycle };

struct StepMetrics {
    StepOutcome outcome = StepOutcome::Settled;  ///< not Settled: rise, overshoot, settling and steady error are NaN
    double step = 0;            ///< setpoint − start (the size asked for)
    double finalValue = 0;      ///< mean of the last 5 % of the record, in the output unit
    double riseTimeS = 0;       ///< 10 % → 90 % of the way from start to the final value; NaN if never reached
    double overshootPct = 0;    ///< largest excursion past the final value, % of (final − start); 0 if none
    double settlingTimeS = 0;   ///< from the step until it stays within 2 % of (final − start) of the final value; NaN if it does not
    double steadyStateError = 0;///< setpoint − final value
    double iae = 0;             ///< ∫|e| dt, output unit·s
    double ise = 0;             ///< ∫e² dt, output unit²·s
    double peakOutput = 0;      ///< largest |u − u at start|, the controller output's unit
    double durationS = 0;
};

/// Metrics of a step record (setpoint constant after the start). bandFraction is the settling band (0.02 = 2 %).
/// A response that tripped its envelope is Unstable; one that never stays inside the
/// band around its final value DidNotSettle; either way with no figure read off a final value.
StepMetrics stepMetrics(const Record& r, double bandFraction = 0.02);
/// The figures as the record gives them, whatever the response did (outcome always Settled).
StepMetrics stepFigures(const Record& r, double bandFraction = 0.02);

/// When the response entered ±band (absolute, output unit) around the setpoint for
/// good, in s from the step; NaN if the last sample is outside it.
double settledInsideS(const Record& r, double band);

} // namespace motion::control
