#include "motion/trapezoid.h"

#include <cmath>

namespace motion {

namespace {
bool finiteNonNegative(double x) { return std::isfinite(x) && x >= 0.0; }
bool finitePositive(double x) { return std::isfinite(x) && x > 0.0; }
}  // namespace

std::optional<TrapezoidProfile> TrapezoidProfile::plan(double distanceMm, const TrapezoidParams& params)
{
    if (!std::isfinite(distanceMm) || !finiteNonNegative(params.startSpeedMmS) || !finitePositive(params.topSpeedMmS)
        || !finitePositive(params.accelMmS2) || !finitePositive(params.decelMmS2)
        || !finiteNonNegative(params.plateauMm) || params.startSpeedMmS > params.topSpeedMmS
        || (params.plateauMm > 0.0 && params.startSpeedMmS == 0.0))
        return std::nullopt;
    TrapezoidProfile p;
    const double N = std::fabs(distanceMm);
    const double v0 = params.startSpeedMmS, a = params.accelMmS2, d = params.decelMmS2;
    double P = params.plateauMm;
    p.m_lengthMm = N;
    p.m_direction = distanceMm < 0.0 ? -1.0 : 1.0;
    p.m_startMmS = v0;
    p.m_accelMmS2 = a;
    p.m_decelMmS2 = d;
    if (N == 0.0)
        return p;

    if (3.0 * P >= N && v0 > 0.0) {
        // Seed rule: too short for any ramp — the whole move runs at the start speed.
        p.m_constantSpeed = true;
        p.m_topMmS = v0;
        p.m_plateauMm = 0.0;
        p.m_cruiseMm = N;
    } else {
        if (v0 == 0.0)
            P = 0.0;
        const double vH = params.topSpeedMmS;
        double nA = (vH * vH - v0 * v0) / (2.0 * a);
        double nD = (vH * vH - v0 * v0) / (2.0 * d);
        double top = vH;
        double cruise = N - 2.0 * P - nA - nD;
        if (nA + nD + 3.0 * P > N) {
            // Both ramps must meet at the same speed: a·nA' = d·nD' and nA' + nD' = N - 3P.
            const double ramps = N - 3.0 * P;
            nA = ramps * d / (a + d);
            nD = ramps - nA;
            top = std::sqrt(v0 * v0 + 2.0 * a * nA);
            cruise = P;
        }
        p.m_topMmS = top;
        p.m_plateauMm = P;
        p.m_accelMm = nA;
        p.m_decelMm = nD;
        p.m_cruiseMm = cruise;
    }
    const double plateauS = p.m_plateauMm > 0.0 ? p.m_plateauMm / v0 : 0.0;
    p.m_phaseEndS[0] = plateauS;
    p.m_phaseEndS[1] = p.m_phaseEndS[0] + (p.m_topMmS - v0) / a;
    p.m_phaseEndS[2] = p.m_phaseEndS[1] + (p.m_cruiseMm > 0.0 ? p.m_cruiseMm / p.m_topMmS : 0.0);
    p.m_phaseEndS[3] = p.m_phaseEndS[2] + (p.m_topMmS - v0) / d;
    p.m_phaseEndS[4] = p.m_phaseEndS[3] + plateauS;
    return p;
}

ProfileSample TrapezoidProfile::at(double tS) const
{
    ProfileSample out;
    if (!(tS > 0.0))
        return out;
    const double total = duration();
    if (tS >= total) {
        out.t = total;
        out.s = distance();
        return out;
    }
    out.t = tS;
    const double v0 = m_startMmS, vH = m_topMmS;
    double s, v, a = 0.0;
    if (tS < m_phaseEndS[0]) {
        v = v0;
        s = v0 * tS;
    } else if (tS < m_phaseEndS[1]) {
        const double u = tS - m_phaseEndS[0];
        a = m_accelMmS2;
        v = v0 + a * u;
        s = m_plateauMm + v0 * u + 0.5 * a * u * u;
    } else if (tS < m_phaseEndS[2]) {
        v = vH;
        s = m_plateauMm + m_accelMm + vH * (tS - m_phaseEndS[1]);
    } else {
        // Decel and final plateau are evaluated from the end so the move lands on its length exactly.
        const double fromEnd = total - tS;
        const double plateauS = m_phaseEndS[4] - m_phaseEndS[3];
        if (fromEnd < plateauS) {
            v = v0;
            s = m_lengthMm - v0 * fromEnd;
        } else {
            const double u = fromEnd - plateauS;  // time before the decel ends
            a = -m_decelMmS2;
            v = v0 + m_decelMmS2 * u;
            s = m_lengthMm - m_plateauMm - (v0 * u + 0.5 * m_decelMmS2 * u * u);
        }
    }
    out.s = m_direction * s;
    out.v = m_direction * v;
    out.a = m_direction * a;
    return out;
}

}  // namespace motion
