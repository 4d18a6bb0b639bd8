#pragma once
// Seed 001 (multi-stepper synchronous pulse output, chemiluminescence analyzer): trapezoidal move
// with "plateau steps" (平稳步数). The motor starts at a start speed v0 it can jump to without
// losing steps, runs `plateau` at v0, accelerates to the top speed vH, cruises, decelerates and
// runs `plateau` at v0 again before stopping. The plateau is also the minimum cruise at vH.
//
// The seed's short-move rules, for total length N, ramp lengths nA = (vH² - v0²)/2a and
// nD = (vH² - v0²)/2d and plateau P:
//   * nA + nD + 3P > N  → lower the top speed so that nA' + nD' = N - 3P (cruise = P),
//                         split in the ratio nA'/nD' = d/a (both ramps end at the same speed);
//   * 3P ≥ N            → the whole move runs at v0.
// Speed jumps 0 → v0 at the start and v0 → 0 at the end (that is what a start speed means for a
// stepper); acceleration jumps at every corner, so jerk is reported as 0 (it is a Dirac there).

#include "motion/profile.h"

#include <optional>

namespace motion {

struct TrapezoidParams {
    double startSpeedMmS = 0;  ///< v0 ≥ 0, also the stop speed and the plateau speed; > 0 if plateauMm > 0
    double topSpeedMmS = 0;    ///< vH > 0
    double accelMmS2 = 0;      ///< a > 0
    double decelMmS2 = 0;      ///< d > 0 (magnitude)
    double plateauMm = 0;      ///< P ≥ 0: seed's plateau steps × step length
};

class TrapezoidProfile final : public Profile {
public:
    /// nullopt for non-finite or out-of-range parameters (see TrapezoidParams).
    static std::optional<TrapezoidProfile> plan(double distanceMm, const TrapezoidParams& params);

    double duration() const override { return m_phaseEndS[4]; }
    double distance() const override { return m_direction * m_lengthMm; }
    ProfileSample at(double tS) const override;

    double reachedTopSpeedMmS() const { return m_topMmS; }  ///< vH, or the lowered vH' of a short move
    double accelLengthMm() const { return m_accelMm; }
    double decelLengthMm() const { return m_decelMm; }
    double cruiseLengthMm() const { return m_cruiseMm; }
    double plateauLengthMm() const { return m_plateauMm; }
    bool constantSpeed() const { return m_constantSpeed; }  ///< the 3P ≥ N rule applied

private:
    TrapezoidProfile() = default;

    double m_lengthMm = 0, m_direction = 1;
    double m_startMmS = 0, m_topMmS = 0, m_accelMmS2 = 0, m_decelMmS2 = 0;
    double m_plateauMm = 0, m_accelMm = 0, m_cruiseMm = 0, m_decelMm = 0;
    bool m_constantSpeed = false;
    double m_phaseEndS[5] = {0, 0, 0, 0, 0};  ///< ends of plateau, accel, cruise, decel, plateau
};

}  // namespace motion
