#pragma once
// Time-optimal, jerk-limited ("7-segment" / double-S) rest-to-rest move along one coordinate.
//
// Segments: jerk +J, 0, -J (accelerate to the peak speed), cruise, jerk -J, 0, +J (brake).
// Durations Tj, Ta, Tj, Tv, Tj, Ta, Tj. With |v| ≤ vMax, |a| ≤ aMax, |j| ≤ jMax the shortest
// rest-to-rest move is bang-bang in jerk, and only three shapes exist:
//   1. vMax reached (Tv ≥ 0), with or without an aMax plateau (Ta ≥ 0),
//   2. vMax not reached but aMax reached: Ta solves A(Ta+Tj)(Ta+2Tj) = D (a quadratic),
//   3. neither reached: Ta = Tv = 0, Tj = ∛(D / 2J).
// All three are closed forms: planning does no iteration and no allocation.

#include "motion/profile.h"

#include "motion/message.h"

#include <optional>
#include <string>

namespace motion {

struct JerkLimits {
    double vMaxMmS, aMaxMmS2, jMaxMmS3;
};

/// nullopt when every limit is finite and > 0, else a message naming the field, the axis (when
/// axis >= 0) and the value, e.g. "axis 1: aMaxMmS2 = -3 must be finite and > 0".
std::optional<motion::msg::Message> validateJerkLimits(const JerkLimits& limits, int axis = -1);

class JerkLimitedProfile final : public Profile {
public:
    static std::optional<JerkLimitedProfile> plan(double distanceMm, const JerkLimits& limits);  ///< time-optimal rest-to-rest 7-segment, signed distance

    double duration() const override { return 4.0 * m_jerkTimeS + 2.0 * m_constAccelTimeS + m_cruiseTimeS; }
    double distance() const override { return m_direction * m_lengthMm; }
    ProfileSample at(double tS) const override;

    double jerkTimeS() const { return m_jerkTimeS; }              ///< Tj: each of the four jerk segments
    double constAccelTimeS() const { return m_constAccelTimeS; }  ///< Ta: each of the two constant-acceleration segments
    double cruiseTimeS() const { return m_cruiseTimeS; }          ///< Tv
    double peakAccelerationMmS2() const { return m_jerkMmS3 * m_jerkTimeS; }  ///< magnitude
    double peakVelocityMmS() const;                               ///< magnitude
    double jerkMmS3() const { return m_jerkMmS3; }                ///< magnitude of jerk in the jerk segments

private:
    JerkLimitedProfile() = default;

    double m_lengthMm = 0;         ///< |distance|
    double m_direction = 1;        ///< +1 or -1
    double m_jerkMmS3 = 0;         ///< J
    double m_jerkTimeS = 0;        ///< Tj
    double m_constAccelTimeS = 0;  ///< Ta
    double m_cruiseTimeS = 0;      ///< Tv
};

}  // namespace motion
