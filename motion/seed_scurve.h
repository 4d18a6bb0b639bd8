#pragma once
// Seed 000 (automatic sampling analyzer manipulator), §2.1: the "simplified S-curve".
//
// Acceleration is a parabola a(t) = -A·t² + B·t on [0, t2], zero while cruising on [t2, t3], and
// the mirror image a(t) = A·t² - (2TA + B)·t + T²A + TB on [t3, t5] (eq. 1). Velocity and position
// follow by integration (eq. 2, 3). Reading eq. 1 back:
//   * a(0) = a(t2) = 0           ⇒ B = A·t2,
//   * v(t2) = A·t2³/6 = vPeak    ⇒ A = 6·vPeak / t2³,
//   * s(t2) = A·t2⁴/12 = vPeak·t2/2 = s1 (the seed's "acceleration distance"),
//   * the decel expression is the accel one negated and shifted by T, so T = t3 (the instant
//     deceleration starts), and t5 = t3 + t2.
// The printed decel-phase velocity and position (eq. 2, 3, t3 ≤ t ≤ t5) are garbled; see
// seed_scurve.cpp for the derivation and tests/motion/seed_scurve_test.cpp for the proof.
//
// Peak acceleration is A·t2²/4 = 1.5·vPeak/t2 at t2/2; peak |jerk| is B = 6·vPeak/t2² at the
// start and end of each ramp (jerk steps there, acceleration and velocity never do).
// Seed Table 2's "maximum acceleration" (1500 / 2000 mm/s² for 37.5 / 50 mm/s in 0.1 s) equals
// 4·vMax/t2, which eq. 1 never reaches (562.5 / 750 mm/s²): eq. 1 is right, the column is a
// machine limit the curve stays under (test Table2PeakAccelerationStaysUnderTheTablesMaximum).

#include "motion/profile.h"

#include <optional>

namespace motion {

class SeedSCurve final : public Profile {
public:
    /// Rest-to-rest move of signed `distanceMm` with peak speed at most vMaxMmS and acceleration phase lasting accelTimeS.
    /// Short moves lower the peak speed so the move still ends exactly at distance. nullopt for non-finite/non-positive limits.
    static std::optional<SeedSCurve> plan(double distanceMm, double vMaxMmS, double accelTimeS);

    /// The seed's own parametrisation (§2.1 end): acceleration time t2, cruise time t3 - t2 and
    /// acceleration distance s1 (all >= 0, t2 > 0, s1 > 0) fix A, B and T. `direction` is +1 or -1.
    static std::optional<SeedSCurve> fromSeedParameters(double accelTimeS, double cruiseTimeS,
                                                        double accelDistanceMm, int direction = +1);

    double duration() const override { return 2.0 * m_accelTimeS + m_cruiseTimeS; }
    double distance() const override { return m_distanceMm; }
    ProfileSample at(double tS) const override;

    double accelTimeS() const { return m_accelTimeS; }        ///< t2 (= t5 - t3)
    double cruiseTimeS() const { return m_cruiseTimeS; }      ///< t3 - t2
    double peakVelocityMmS() const { return m_peakVelocityMmS; }  ///< magnitude, reached at t2
    double accelDistanceMm() const { return 0.5 * m_peakVelocityMmS * m_accelTimeS; }  ///< s1 = s(t2), magnitude
    double peakAccelerationMmS2() const { return 1.5 * m_peakVelocityMmS / m_accelTimeS; }  ///< A·t2²/4 at t2/2
    double peakJerkMmS3() const { return m_coeffBMmS3; }      ///< |j| at the ramp ends (= B)
    double coefficientA() const { return m_coeffAMmS4; }      ///< eq. 1's A (mm/s⁴), magnitude
    double coefficientB() const { return m_coeffBMmS3; }      ///< eq. 1's B (mm/s³), magnitude
    double decelStartS() const { return m_accelTimeS + m_cruiseTimeS; }  ///< eq. 1's T = t3

private:
    SeedSCurve() = default;

    double m_distanceMm = 0;       ///< signed
    double m_direction = 1;        ///< +1 or -1
    double m_accelTimeS = 0;       ///< t2
    double m_cruiseTimeS = 0;      ///< t3 - t2
    double m_peakVelocityMmS = 0;  ///< magnitude
    double m_coeffAMmS4 = 0;       ///< A = 6·vPeak/t2³
    double m_coeffBMmS3 = 0;       ///< B = A·t2
};

}  // namespace motion
