#include "motion/jerk_limited.h"

#include <cmath>
#include <vector>

namespace motion {

namespace {

bool positiveFinite(double x) { return std::isfinite(x) && x > 0.0; }

/// Position, velocity, acceleration, jerk (magnitudes, direction +) on the acceleration half at
/// local time tau in [0, 2Tj + Ta] and on the cruise that follows.
struct HalfState {
    double s, v, a, j;
};

HalfState accelHalf(double tau, double J, double Tj, double Ta)
{
    if (tau <= Tj) {
        return {J * tau * tau * tau / 6.0, 0.5 * J * tau * tau, J * tau, J};
    }
    const double ap = J * Tj;
    const double v1 = 0.5 * ap * Tj;
    const double s1 = v1 * Tj / 3.0;
    if (tau <= Tj + Ta) {
        const double u = tau - Tj;
        return {s1 + v1 * u + 0.5 * ap * u * u, v1 + ap * u, ap, 0.0};
    }
    const double v2 = v1 + ap * Ta;
    const double s2 = s1 + v1 * Ta + 0.5 * ap * Ta * Ta;
    const double u = tau - Tj - Ta;
    if (u <= Tj) {
        return {s2 + u * (v2 + u * (0.5 * ap - J * u / 6.0)), v2 + u * (ap - 0.5 * J * u), ap - J * u, -J};
    }
    const double vp = v2 + 0.5 * ap * Tj;
    const double s3 = s2 + v2 * Tj + ap * Tj * Tj / 3.0;
    return {s3 + vp * (u - Tj), vp, 0.0, 0.0};
}

}  // namespace

std::optional<motion::msg::Message> validateJerkLimits(const JerkLimits& limits, int axis)
{
    const struct {
        const char* name;
        double value;
    } fields[] = {{"vMaxMmS", limits.vMaxMmS}, {"aMaxMmS2", limits.aMaxMmS2}, {"jMaxMmS3", limits.jMaxMmS3}};
    for (const auto& f : fields) {
        if (!positiveFinite(f.value)) {
            if (axis < 0)
                return motion::msg::make("profile.not_positive_plain", {motion::msg::verbatim("field", f.name), motion::msg::real("value", f.value)});
            return motion::msg::make("profile.axis_not_positive", {motion::msg::verbatim("field", f.name), motion::msg::real("value", f.value),
                                                           motion::msg::integer("axis", axis, motion::msg::Unit::None)});
        }
    }
    return std::nullopt;
}

std::optional<JerkLimitedProfile> JerkLimitedProfile::plan(double distanceMm, const JerkLimits& limits)
{
    const double V = limits.vMaxMmS, A = limits.aMaxMmS2, J = limits.jMaxMmS3;
    if (!std::isfinite(distanceMm) || !positiveFinite(V) || !positiveFinite(A) || !positiveFinite(J))
        return std::nullopt;
    JerkLimitedProfile p;
    const double D = std::fabs(distanceMm);
    p.m_lengthMm = D;
    p.m_direction = distanceMm < 0.0 ? -1.0 : 1.0;
    p.m_jerkMmS3 = J;
    if (D == 0.0)
        return p;

    // Ramp 0 → vMax: aMax is reached only if vMax > aMax²/J (else the ramp is a pure jerk triangle).
    double Tj, Ta;
    if (V * J >= A * A) {
        Tj = A / J;
        Ta = V / A - Tj;
    } else {
        Tj = std::sqrt(V / J);
        Ta = 0.0;
    }
    // Rest-to-rest with vMax: both ramps cover vMax·(2Tj + Ta) (each ramp's mean speed is vMax/2).
    const double rampsMm = V * (2.0 * Tj + Ta);
    if (D >= rampsMm) {
        p.m_jerkTimeS = Tj;
        p.m_constAccelTimeS = Ta;
        p.m_cruiseTimeS = (D - rampsMm) / V;
        return p;
    }
    // vMax not reached. With aMax reached, distance = A(Ta+Tj)(Ta+2Tj), Tj = A/J; that needs
    // D ≥ 2A³/J² (Ta = 0). Root in the cancellation-free form 2c/(b + √(b² - 4c')).
    Tj = A / J;
    const double minMmForAMax = 2.0 * A * Tj * Tj;
    if (D >= minMmForAMax) {
        const double c = D / A - 2.0 * Tj * Tj;
        p.m_jerkTimeS = Tj;
        p.m_constAccelTimeS = 2.0 * c / (3.0 * Tj + std::sqrt(Tj * Tj + 4.0 * D / A));
    } else {
        p.m_jerkTimeS = std::cbrt(D / (2.0 * J));  // D = 2·J·Tj³
        p.m_constAccelTimeS = 0.0;
    }
    p.m_cruiseTimeS = 0.0;
    return p;
}

double JerkLimitedProfile::peakVelocityMmS() const
{
    return m_jerkMmS3 * m_jerkTimeS * (m_jerkTimeS + m_constAccelTimeS);
}

ProfileSample JerkLimitedProfile::at(double tS) const
{
    ProfileSample out;
    const double total = duration();
    if (!(tS > 0.0))
        return out;
    if (tS >= total) {
        out.t = total;
        out.s = distance();
        return out;
    }
    out.t = tS;
    // The move is point-symmetric about its midpoint: s(t) = D - s(T - t), v(t) = v(T - t),
    // a(t) = -a(T - t), j(t) = j(T - t). Evaluating the second half from the end makes the last
    // sample land on D exactly and halves the code.
    const bool secondHalf = tS > 0.5 * total;
    const double tau = secondHalf ? total - tS : tS;
    const HalfState h = accelHalf(tau, m_jerkMmS3, m_jerkTimeS, m_constAccelTimeS);
    out.s = m_direction * (secondHalf ? m_lengthMm - h.s : h.s);
    out.v = m_direction * h.v;
    out.a = m_direction * (secondHalf ? -h.a : h.a);
    out.j = m_direction * h.j;
    return out;
}

}  // namespace motion
