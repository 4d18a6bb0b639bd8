#pragma once
// Relay autotuning (Åström & Hägglund 1984) with a phase-crossover refinement.
//
// Run 1, the relay: u = u0 ± d switched on the error with hysteresis ε. The
// loop settles into a limit cycle; from the last stable cycles come Tu (zero
// crossings) and the amplitude a, hence the classic describing-function
// estimate Ku = 4d / (π·sqrt(a² − ε²)). That estimate assumes the output is a
// sine and the oscillation sits at −180°; neither holds in general (a delay
// plant's output is a square-ish wave, and hysteresis and the relay's own
// switching move the cycle to where the plant lags less than 180°): the
// classic Ku is up to ~27 % off on delay-dominant plants.
//
// Refinement: the first Fourier harmonics of u and y over whole cycles give
// G(jω) exactly at the relay's frequency (and at 3ω from the square wave's
// third harmonic). Then short forced square-wave runs (the same relay, switched
// on a timer at a chosen period) measure G at frequencies picked by the secant
// method on the phase until two points bracket −180° closely; Ku = 1/|G| and
// Tu = 2π/ω are interpolated there. See docs/tuning.md for the measured error.
#include "motion/control/experiment.h"
#include "motion/control/tuning/oscillation.h"

#include <optional>
#include <string>
#include <vector>

namespace motion::control {

struct RelayAutotuneOptions {
    double amplitude = 1;       ///< d
    double hysteresis = 0;      ///< ε
    double periodS = 1e-3;      ///< the loop's control period (forced periods are whole multiples of it)
    int relayCycles = 12;
    bool refine = true;
    int forcedCycles = 6;       ///< per forced run, of which the first skipCycles settle
    int skipCycles = 2;
    int maxForcedRuns = 8;
    double phaseToleranceRad = 0.003;  ///< a point this close to −180° ends the refinement
    InputModel input = InputModel::Held;
};

struct RelayResult {
    double kuDescribing = 0;    ///< classic: 4d/(π·sqrt(a²−ε²))
    double tuRelayS = 0;        ///< classic: the relay's own period
    double amplitude = 0;       ///< a
    double relayPhaseDeg = 0;   ///< arg G at the relay's frequency: how far from −180° the cycle sat
    double ku = 0;              ///< refined (the classic values when not refined)
    double tuS = 0;
    bool refined = false;
    int runs = 0;               ///< relay + forced runs
    std::vector<FrequencyPoint> points;  ///< every measured G(jω), relay first
};

class RelayAutotune {
public:
    explicit RelayAutotune(const RelayAutotuneOptions& options);

    /// The next run (without its envelope, which the caller adds); nullopt once finished.
    std::optional<RelaySpec> next() const { return m_next; }
    void report(const Record& run);
    bool finished() const { return !m_next.has_value(); }
    const std::optional<RelayResult>& result() const { return m_result; }
    /// Why it failed; may be set beside a result (classic values only, refinement failed).
    const motion::msg::Message& failure() const { return m_failure; }  ///< tuning.relay.*
    const RelayAutotuneOptions& options() const { return m_options; }
    /// A forced run's period in control periods (0 for the relay run).
    long forcedPeriodSamples() const { return m_forcedSamples; }

private:
    /// A measured point with its phase unwrapped (continuous in ω, in rad).
    struct Point {
        FrequencyPoint fp;
        double phase = 0;
    };
    void addForced(const FrequencyPoint& p);
    void planForced();
    void finishWith(const Point& a, const Point* b);
    RelaySpec forcedSpec(long samples) const;

    RelayAutotuneOptions m_options;
    std::optional<RelaySpec> m_next;
    std::optional<RelayResult> m_result;
    motion::msg::Message m_failure;
    RelayResult m_work;
    Point m_relayPoint;
    std::vector<Point> m_forced;           ///< forced-run points
    std::vector<long> m_triedSamples;
    long m_forcedSamples = 0;
    double m_minOmega = 0, m_maxOmega = 0;
};

} // namespace motion::control
