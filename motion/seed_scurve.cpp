#include "motion/seed_scurve.h"

#include <cmath>

namespace motion {

// Decel phase, derived (seed 000 eq. 2 and 3 as printed are wrong there):
// with T = t3 and τ = t - T, eq. 1 reads a(t) = A·τ² - B·τ = -a_acc(τ). Integrating from t3:
//   v(t) = vPeak + A·τ³/3 - B·τ²/2
//   s(t) = s(t3) + vPeak·τ + A·τ⁴/12 - B·τ³/6
// Expanded in global t this is v(t) = A/3·t³ - (2TA+B)/2·t² + (T²A+TB)·t + vPeak + c1 with
// c1 = -A·T³/3 - B·T²/2. The printed eq. 2 has -A/3·t³ and (T²A - TB)·t (two sign errors) and
// evaluates c1 at t2 instead of T = t3; the printed eq. 3 subtracts (v(t2) + c1)·t instead of
// adding it and starts from s(t2) instead of s(t3). With those errors the velocity jumps at t3
// (tests/motion/seed_scurve_test.cpp: PrintedDecelVelocityIsDiscontinuous). We evaluate in
// local time τ, which is both correct and better conditioned than the expanded polynomial.

std::optional<SeedSCurve> SeedSCurve::plan(double distanceMm, double vMaxMmS, double accelTimeS)
{
    if (!std::isfinite(distanceMm) || !std::isfinite(vMaxMmS) || !std::isfinite(accelTimeS) || vMaxMmS <= 0.0
        || accelTimeS <= 0.0)
        return std::nullopt;
    SeedSCurve p;
    const double lengthMm = std::fabs(distanceMm);
    p.m_distanceMm = distanceMm;
    p.m_direction = distanceMm < 0.0 ? -1.0 : 1.0;
    // Both ramps together cover vPeak·t2. A shorter move keeps the seed's acceleration time (it is
    // the machine's tuned parameter) and lowers the peak speed instead; no cruise then.
    const double rampsMm = vMaxMmS * accelTimeS;
    if (lengthMm >= rampsMm) {
        p.m_peakVelocityMmS = vMaxMmS;
        p.m_cruiseTimeS = (lengthMm - rampsMm) / vMaxMmS;
    } else {
        p.m_peakVelocityMmS = lengthMm / accelTimeS;
        p.m_cruiseTimeS = 0.0;
    }
    if (lengthMm == 0.0) {
        p.m_accelTimeS = 0.0;  // nothing to do: a zero-length move takes no time
        return p;
    }
    p.m_accelTimeS = accelTimeS;
    p.m_coeffAMmS4 = 6.0 * p.m_peakVelocityMmS / (accelTimeS * accelTimeS * accelTimeS);
    p.m_coeffBMmS3 = p.m_coeffAMmS4 * accelTimeS;
    return p;
}

std::optional<SeedSCurve> SeedSCurve::fromSeedParameters(double accelTimeS, double cruiseTimeS,
                                                         double accelDistanceMm, int direction)
{
    if (!std::isfinite(accelTimeS) || !std::isfinite(cruiseTimeS) || !std::isfinite(accelDistanceMm)
        || accelTimeS <= 0.0 || cruiseTimeS < 0.0 || accelDistanceMm <= 0.0 || (direction != 1 && direction != -1))
        return std::nullopt;
    SeedSCurve p;
    p.m_direction = direction;
    p.m_accelTimeS = accelTimeS;
    p.m_cruiseTimeS = cruiseTimeS;
    p.m_peakVelocityMmS = 2.0 * accelDistanceMm / accelTimeS;  // s1 = vPeak·t2/2
    p.m_coeffAMmS4 = 12.0 * accelDistanceMm / (accelTimeS * accelTimeS * accelTimeS * accelTimeS);
    p.m_coeffBMmS3 = p.m_coeffAMmS4 * accelTimeS;
    p.m_distanceMm = direction * (2.0 * accelDistanceMm + p.m_peakVelocityMmS * cruiseTimeS);
    return p;
}

ProfileSample SeedSCurve::at(double tS) const
{
    ProfileSample out;
    const double total = duration();
    if (!(tS > 0.0)) {  // also catches NaN: treat as "not started"
        out.t = 0.0;
        return out;
    }
    if (tS >= total) {
        out.t = total;
        out.s = m_distanceMm;
        return out;
    }
    out.t = tS;
    const double A = m_coeffAMmS4, B = m_coeffBMmS3, t2 = m_accelTimeS, vp = m_peakVelocityMmS;
    const double t3 = t2 + m_cruiseTimeS;
    double s, v, a, j;
    if (tS <= t2) {
        const double tau = tS;
        j = B - 2.0 * A * tau;
        a = tau * (B - A * tau);
        v = tau * tau * (B / 2.0 - A * tau / 3.0);
        s = tau * tau * tau * (B / 6.0 - A * tau / 12.0);
    } else if (tS <= t3) {
        j = 0.0;
        a = 0.0;
        v = vp;
        s = 0.5 * vp * t2 + vp * (tS - t2);
    } else {
        // Evaluate from the end (mirror of the ramp) so the last sample lands on the distance
        // without cancellation: s(t) = D - s_acc(t5 - t).
        const double tau = total - tS;
        j = B - 2.0 * A * tau;
        a = -tau * (B - A * tau);
        v = tau * tau * (B / 2.0 - A * tau / 3.0);
        s = std::fabs(m_distanceMm) - tau * tau * tau * (B / 6.0 - A * tau / 12.0);
    }
    out.s = m_direction * s;
    out.v = m_direction * v;
    out.a = m_direction * a;
    out.j = m_direction * j;
    return out;
}

}  // namespace motion
