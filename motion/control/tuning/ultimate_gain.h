#pragma once
// The ultimate-gain method (Ziegler–Nichols, seed 002 §2.2): P-only control,
// Kp raised trial by trial until the loop oscillates without growing or
// decaying. A trial is a setpoint step with gains (Kp, 0, 0); its oscillation
// is judged by the ratio of successive cycles' peak-to-peak amplitudes
// (sustained within 0.9–1.1). Then the search refines by the secant method on
// ln(ratio) against ln(Kp), so Ku lands where the ratio is 1, not merely inside
// the window, and Tu is interpolated there too.
//
// A planner without a plant: nextKp() says what to try, report() takes the
// trial's record. The model-plant tuner and the device runner both drive it.
#include "motion/control/experiment.h"
#include "motion/control/tuning/oscillation.h"

#include <optional>
#include <string>
#include <vector>

namespace motion::control {

struct UltimateGainOptions {
    double startKp = 0.1;
    double growth = 2.0;            ///< factor between trials while nothing oscillates
    double kpMax = 100;             ///< give up above this
    int maxTrials = 30;
    double sustainedLow = 0.9;      ///< ratio window that counts as sustained
    double sustainedHigh = 1.1;
    double refineTolerance = 0.01;  ///< |ln ratio| below this ends the refinement
    double swing = 0;               ///< extrema closer than this are noise (output unit)
};

struct UltimateTrial {
    double kp = 0;
    OscillationAnalysis oscillation;
    EndReason reason = EndReason::Running;
    /// ln(ratio): −inf when nothing oscillated, +inf when it grew into the
    /// trial's envelope before a cycle could be compared.
    double logRatio = 0;
    bool sustained = false;  ///< ratio inside the sustained window
    double stepScale = 1;    ///< the step it ran with, as a share of the step asked for
    bool inconclusive = false;  ///< hit the envelope before a cycle could be compared: repeated with a smaller step
};

struct UltimateResult {
    double ku = 0;
    double tuS = 0;
    double ratio = 0;        ///< at the trial nearest to Ku
    double firstSustainedKp = 0;  ///< the first trial whose ratio fell inside the window (0: none did)
    int trials = 0;
};

class UltimateGainSearch {
public:
    explicit UltimateGainSearch(const UltimateGainOptions& options);

    /// Kp of the next trial; nullopt once finished (see result() / failure()).
    std::optional<double> nextKp() const { return m_next; }
    /// The next trial's step as a share of the step asked for. A trial that hits
    /// the envelope on its first overshoot, before one cycle could be compared,
    /// says nothing about growth: it is repeated with half the step (the loop is
    /// linear, its ratio does not depend on the step), down to 1/16.
    double stepScale() const { return m_stepScale; }
    /// The record of the trial run at `kp` (a P-only step test).
    void report(double kp, const Record& trial);
    bool finished() const { return !m_next.has_value(); }
    const std::optional<UltimateResult>& result() const { return m_result; }
    const motion::msg::Message& failure() const { return m_failure; }  ///< tuning.ultimate.*
    const std::vector<UltimateTrial>& trials() const { return m_trials; }
    const UltimateGainOptions& options() const { return m_options; }

    static UltimateTrial analyzeTrial(double kp, const Record& trial, double swing);

private:
    void decide();
    void finish(double ku, double tuS, double ratio);

    UltimateGainOptions m_options;
    std::vector<UltimateTrial> m_trials;
    std::optional<double> m_next;
    double m_stepScale = 1;
    std::optional<UltimateResult> m_result;
    motion::msg::Message m_failure;
};

} // namespace motion::control
