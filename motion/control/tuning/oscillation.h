#pragma once
// Reading an oscillation off sampled data: its growth per cycle, its period,
// and the plant's frequency response at its frequency.
#include "motion/control/experiment.h"

#include "motion/message.h"

#include <complex>
#include <cstddef>
#include <string>
#include <vector>

namespace motion::control {

struct Extremum {
    std::size_t index = 0;
    double timeS = 0;   ///< parabola through the three samples around it
    double value = 0;
    bool maximum = false;
};

/// Alternating maxima and minima of y[from…]: an extremum counts once the signal
/// has moved `swing` away from it (so quantisation noise makes none).
std::vector<Extremum> findExtrema(const std::vector<double>& y, double periodS, std::size_t from, double swing);

struct OscillationAnalysis {
    enum class Method { None, Extrema, DampedSineFit };
    Method method = Method::None;
    bool oscillating = false;
    /// Peak-to-peak amplitude of a cycle over that of the cycle before (geometric
    /// mean of the last few cycles): < 1 decays, 1 sustained, > 1 grows.
    double ratio = 0;
    std::vector<double> ratios;  ///< every cycle-over-cycle ratio measured, oldest first
    double periodS = 0;
    double lastPeakToPeak = 0;   ///< of the last full cycle
    int extrema = 0;
};

/// Growth and period of the oscillation in y[from…]. With 12 or more samples a
/// cycle it compares successive peak-to-peak amplitudes (extrema); below that the
/// extrema are sampled at a different phase each cycle and would make a steady
/// oscillation look modulated, so it fits a damped sinusoid (an AR(2) model with
/// a constant) and reports the same ratio, ρ^(samples per cycle).
OscillationAnalysis analyzeOscillation(const std::vector<double>& y, double periodS, std::size_t from, double swing);

/// How the controller output reached the plant.
enum class InputModel {
    Held,     ///< held over each period (a model plant's zero-order hold): continuous G(jω)
    Sampled,  ///< only the samples matter (the device's discrete loop): G(e^{jωT})
};

struct FrequencyPoint {
    double omegaRadS = 0;
    std::complex<double> g;
    double gain() const { return std::abs(g); }
    /// In (−2π, 0]: a lag, as the plants here have.
    double phaseRad() const;
};

/// First harmonics of y over u across `samples` samples from `first`, at ω
/// (choose whole cycles: the window should hold a whole number of periods).
FrequencyPoint fourierPoint(const Record& r, std::size_t first, std::size_t samples, double omegaRadS, InputModel input);

/// A relay oscillation: period from zero crossings of the output around its
/// mean, amplitude, both averaged over the last stable cycles, the classic
/// describing-function estimate and the exact first (and third) harmonic point.
struct RelayAnalysis {
    bool ok = false;
    motion::msg::Message problem;       ///< why not, when !ok (tuning.relay.*)
    double periodS = 0;         ///< Tu estimate
    double amplitude = 0;       ///< a: half the output's peak-to-peak
    double kuDescribing = 0;    ///< 4d / (π·sqrt(a² − ε²))
    FrequencyPoint fundamental;
    FrequencyPoint third;       ///< at 3ω (the relay's square wave carries a third of d there)
    bool thirdUsable = false;   ///< its output is well above the noise
    int cycles = 0;             ///< stable cycles used
    std::size_t first = 0, samples = 0;  ///< the window used
};
RelayAnalysis analyzeRelay(const Record& r, double amplitude, double hysteresis, InputModel input);

/// A forced square wave of `periodSamples` control periods: G at its fundamental,
/// over the whole periods after `skipCycles`.
FrequencyPoint analyzeForced(const Record& r, long periodSamples, int skipCycles, InputModel input);

} // namespace motion::control
