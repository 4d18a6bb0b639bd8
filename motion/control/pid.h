#pragma once
// Seed 002 eq. 2, the incremental (velocity-form) PID, as the stage runs it.
//
// The controller keeps u_k itself and adds Δu_k each period. A gain change
// takes effect at the next period and only changes the size of the next
// increments: u_k stays where it was, so switching gains is bumpless by
// construction (a positional PID would jump by ΔKi·Σe at the switch).
#include "motion/control/gains.h"

namespace motion::control {

class IncrementalPid {
public:
    explicit IncrementalPid(const DiscreteGains& gains = {}) : m_gains(gains) {}

    /// One control period with error e_k; returns Δu_k and adds it to output().
    double step(double error);
    /// From the next period on. u and the error history are kept (bumpless).
    void setGains(const DiscreteGains& gains) { m_gains = gains; }
    const DiscreteGains& gains() const { return m_gains; }
    /// u_k, the sum of every increment since reset.
    double output() const { return m_u; }
    /// Forgets the error history; the output starts again from `u`.
    void reset(double u = 0);

private:
    DiscreteGains m_gains;
    double m_e1 = 0, m_e2 = 0;  ///< e_{k−1}, e_{k−2}
    double m_u = 0;
};

} // namespace motion::control
