#pragma once
// Model plants for practice and for testing the tuners against closed forms:
//   fopdt:K=..,tau=..,L=..      K·e^{−sL}/(1 + s·tau)          (first order plus dead time)
//   lag:K=..,tau=..,n=..        K/(1 + s·tau)^n                 (n equal lags)
// Both accept Ts=.. (the loop's control period, s; default 1e-4, i.e. 10 kHz).
// Times in seconds; K in output units per input unit.
#include "motion/checked.h"

#include <complex>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace motion::control {

struct PlantSpec {
    enum class Kind { Fopdt, Lag };
    Kind kind = Kind::Fopdt;
    double gain = 1;         ///< K
    double tauS = 1;         ///< time constant of each lag
    double delayS = 0;       ///< L (fopdt only)
    int order = 1;           ///< n (1 for fopdt)
    double periodS = 1e-4;   ///< Ts: the loop runs at this period, the plant is integrated exactly over it

    /// The spec back as text, fields in their canonical order ("fopdt:K=2,tau=0.5,L=0.1").
    std::string text() const;
};

/// Parses a plant spec. Errors name the field at fault: "lag: n must be a whole
/// number from 1 to 12 (got 2.5)", "fopdt: unknown field 'Tau' (fields: K, tau, L, Ts)".
motion::msg::Checked<PlantSpec> parsePlant(std::string_view text);

/// G(jω).
std::complex<double> frequencyResponse(const PlantSpec& p, double omegaRadS);

/// The phase crossover of the continuous plant: ω where arg G(jω) = −π, Ku = 1/|G(jωu)|.
struct UltimatePoint {
    double ku = 0;
    double tuS = 0;
    double omegaRadS = 0;
};
/// nullopt when the phase never reaches −180° (fopdt with L = 0, lag with n ≤ 2):
/// such a loop has no finite ultimate gain.
std::optional<UltimatePoint> ultimatePoint(const PlantSpec& p);
/// A sentence saying why a plant has no finite ultimate gain (empty if it has one).
motion::msg::Message whyNoUltimateGain(const PlantSpec& p);

/// Fixed-step, exact simulation of the plant for an input held constant over
/// each control period (zero-order hold). Sample convention: y_k is the output
/// at t_k; the controller reads it, and u_k is held over [t_k, t_k + Ts). The
/// lags are integrated with their exact transition (no integration error), the
/// dead time shifts the held input by L, split inside a period when L is not a
/// whole number of periods.
class PlantSim {
public:
    explicit PlantSim(const PlantSpec& spec);
    const PlantSpec& spec() const { return m_spec; }
    double periodS() const { return m_spec.periodS; }
    /// y_k.
    double output() const { return m_order ? m_x[m_order - 1] : m_spec.gain * m_lastDelayedInput; }
    /// Holds u over one period and moves to t_{k+1}.
    void step(double u);
    /// At rest with every state at the equilibrium of a constant input u (and y = K·u).
    void settleAt(double u);

private:
    static constexpr int kMaxOrder = 12;
    void advance(const double* phi, const double* gamma, double u);

    PlantSpec m_spec;
    int m_order;
    double m_x[kMaxOrder] = {};
    // Transition over the two parts of a period (before and after the delayed
    // input changes): phi[d] multiplies x_{i−d} into x_i, gamma[i] the input.
    double m_phi1[kMaxOrder] = {}, m_gamma1[kMaxOrder] = {};
    double m_phi2[kMaxOrder] = {}, m_gamma2[kMaxOrder] = {};
    bool m_split = false;
    // Dead time: the last m+2 inputs (ring; m_head is the slot of the newest).
    std::vector<double> m_history;
    std::size_t m_head = 0;
    std::size_t m_wholeDelay = 0;  ///< m = floor(L / Ts)
    double m_lastDelayedInput = 0;
};

} // namespace motion::control
