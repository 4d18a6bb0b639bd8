#pragma once
// One door to every profile kind, for the places that let a person pick the kind (the CLI's
// `profile` command, the Profiles screen): a request with the union of the kinds' limits, a
// value-type AnyProfile (std::variant, no heap), synchronised multi-axis moves and a sampler.

#include "motion/exponential.h"
#include "motion/jerk_limited.h"
#include "motion/linear_move.h"
#include "motion/checked.h"
#include "motion/profile.h"
#include "motion/seed_scurve.h"
#include "motion/trapezoid.h"

#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace motion {

enum class ProfileKind { SeedSCurve, Trapezoid, Exponential, JerkLimited };

const char* profileKindName(ProfileKind kind);  ///< "seed-scurve", "trapezoid", "exponential", "jerk-limited"
std::optional<ProfileKind> profileKindFromName(const std::string& name);

/// Limits of a move. Each kind reads the fields it needs (and says which one is missing):
///   seed-scurve:  vMaxMmS, accelTimeS
///   trapezoid:    vMaxMmS, aMaxMmS2 (accel and decel), startSpeedMmS, plateauMm
///   exponential:  vMaxMmS (fm), accelTimeS (τ = accelTimeS / 3, so 95 % of fm is reached)
///   jerk-limited: vMaxMmS, aMaxMmS2, jMaxMmS3
struct ProfileRequest {
    ProfileKind kind = ProfileKind::JerkLimited;
    double vMaxMmS = 0;
    double aMaxMmS2 = 0;
    double jMaxMmS3 = 0;
    double accelTimeS = 0;
    double startSpeedMmS = 0;
    double plateauMm = 0;
};

class AnyProfile final : public Profile {
public:
    using Variant = std::variant<SeedSCurve, TrapezoidProfile, ExponentialProfile, JerkLimitedProfile>;
    explicit AnyProfile(Variant v) : m_profile(std::move(v)) {}

    double duration() const override;
    double distance() const override;
    ProfileSample at(double tS) const override;
    ProfileKind kind() const { return static_cast<ProfileKind>(m_profile.index()); }
    const Variant& variant() const { return m_profile; }

private:
    Variant m_profile;
};

/// One axis. Errors name the field and value ("vMaxMmS = 0 must be finite and > 0").
motion::msg::Checked<AnyProfile> planProfile(double distanceMm, const ProfileRequest& request);

/// Several axes on a straight line, all with the request's limits: the axis that moves furthest
/// runs at the limits, the others in proportion (see linear_move.h).
motion::msg::Checked<LinearMove<AnyProfile>> planSynchronized(const double* distancesMm, int axisCount,
                                                    const ProfileRequest& request);

/// Samples at t = 0, dt, 2dt, … and always at the end. Empty when dt ≤ 0 or the count would pass
/// maxSamples (a runaway request from a person typing a tiny dt).
std::vector<ProfileSample> sampleProfile(const Profile& profile, double dtS, std::size_t maxSamples = 1000000);

}  // namespace motion
