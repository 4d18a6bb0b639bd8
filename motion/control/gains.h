#pragma once
// PID gains in the two forms BenchPilot uses, and the checks a device applies
// before it takes a set.
//
// Discrete (on the wire, on the device): seed 002 eq. 2 per control period T,
//   Δu_k = kp·(e_k − e_{k−1}) + ki·e_k + kd·(e_k − 2e_{k−1} + e_{k−2}),
// kp, ki, kd dimensionless (u and e in the same unit).
// Continuous (on screens, in CLI JSON): u(t) = Kp·e + Ki·∫e dt + Kd·de/dt with
// Ki in 1/s and Kd in s. Eq. 2 is the backward-difference discretisation of it:
//   ki = Ki·T, kd = Kd/T  ⇔  Ki = ki/T, Kd = kd·T;  Ti = Kp/Ki, Td = Kd/Kp.
#include "motion/message.h"

#include <string>
#include <vector>

namespace motion::control {

/// Per control period, as eq. 2 runs them.
struct DiscreteGains {
    double kp = 0;
    double ki = 0;  ///< per period
    double kd = 0;  ///< per period
    bool operator==(const DiscreteGains& o) const { return kp == o.kp && ki == o.ki && kd == o.kd; }
    bool operator!=(const DiscreteGains& o) const { return !(*this == o); }
};

/// Continuous-time parallel form.
struct ContinuousGains {
    double kp = 0;
    double kiPerS = 0;  ///< Ki, 1/s
    double kdS = 0;     ///< Kd, s
    /// Ti = Kp/Ki in s; +inf without integral action.
    double tiS() const;
    /// Td = Kd/Kp in s; 0 without derivative action (or without Kp).
    double tdS() const;
};

DiscreteGains toDiscrete(const ContinuousGains& g, double periodS);
ContinuousGains toContinuous(const DiscreteGains& g, double periodS);

/// The largest discrete gains a device accepts. A number above these is a typo
/// or a unit mix-up (Ki in 1/s sent as a per-period gain), not a tuning: with
/// kp = 1000 a 1 µm error asks for a 1 mm correction in one period.
struct GainLimits {
    double kpMax = 100;
    double kiMax = 100;
    double kdMax = 100;
};

struct GainProblem {
    int index = 0;           ///< 0 kp, 1 ki, 2 kd
    std::string field;       ///< "kp", "ki", "kd"
    double value = 0;
    double limit = 0;        ///< the largest accepted, for gain_above_limit
    motion::msg::Message message;    ///< tuning.gain_not_finite / gain_negative / gain_above_limit {gain, value, max}
};

/// The refusal as the reference firmware words it on the wire ("kd = -0.1 must not be
/// negative"): device/sim's text. The host words `message` in the operator's language.
std::string wireText(const GainProblem& p);

/// Every gain that is not finite, negative or above its limit; empty when the set is fine.
std::vector<GainProblem> checkGains(const DiscreteGains& g, const GainLimits& limits = {});

} // namespace motion::control
