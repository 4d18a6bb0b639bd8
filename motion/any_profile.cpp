#include "motion/any_profile.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace motion {

namespace {

bool positive(double x) { return std::isfinite(x) && x > 0.0; }

/// "{field} = {value} must be finite and > 0 for {kind}": the field is the request's
/// member name, which the CLI maps back to its option.
motion::msg::Message fieldMessage(const char* field, double value, const char* id, const char* kind)
{
    return motion::msg::make(id, {motion::msg::verbatim("field", field), motion::msg::real("value", value), motion::msg::verbatim("kind", kind)});
}

}  // namespace

const char* profileKindName(ProfileKind kind)
{
    switch (kind) {
    case ProfileKind::SeedSCurve: return "seed-scurve";
    case ProfileKind::Trapezoid: return "trapezoid";
    case ProfileKind::Exponential: return "exponential";
    case ProfileKind::JerkLimited: return "jerk-limited";
    }
    return "?";
}

std::optional<ProfileKind> profileKindFromName(const std::string& name)
{
    for (ProfileKind k : {ProfileKind::SeedSCurve, ProfileKind::Trapezoid, ProfileKind::Exponential,
                          ProfileKind::JerkLimited})
        if (name == profileKindName(k))
            return k;
    return std::nullopt;
}

double AnyProfile::duration() const
{
    return std::visit([](const auto& p) { return p.duration(); }, m_profile);
}

double AnyProfile::distance() const
{
    return std::visit([](const auto& p) { return p.distance(); }, m_profile);
}

ProfileSample AnyProfile::at(double tS) const
{
    return std::visit([tS](const auto& p) { return p.at(tS); }, m_profile);
}

motion::msg::Checked<AnyProfile> planProfile(double distanceMm, const ProfileRequest& r)
{
    using Result = motion::msg::Checked<AnyProfile>;
    const char* kind = profileKindName(r.kind);
    if (!std::isfinite(distanceMm)) {
        return Result::fail(motion::msg::make("profile.not_finite", {motion::msg::verbatim("field", "distanceMm"), motion::msg::real("value", distanceMm)}));
    }
    if (!positive(r.vMaxMmS))
        return Result::fail(fieldMessage("vMaxMmS", r.vMaxMmS, "profile.not_positive", kind));
    switch (r.kind) {
    case ProfileKind::SeedSCurve: {
        if (!positive(r.accelTimeS))
            return Result::fail(fieldMessage("accelTimeS", r.accelTimeS, "profile.not_positive", kind));
        return Result::ok(AnyProfile(*SeedSCurve::plan(distanceMm, r.vMaxMmS, r.accelTimeS)));
    }
    case ProfileKind::Trapezoid: {
        if (!positive(r.aMaxMmS2))
            return Result::fail(fieldMessage("aMaxMmS2", r.aMaxMmS2, "profile.not_positive", kind));
        if (!std::isfinite(r.startSpeedMmS) || r.startSpeedMmS < 0.0 || r.startSpeedMmS > r.vMaxMmS)
            return Result::fail(fieldMessage("startSpeedMmS", r.startSpeedMmS, "profile.start_speed_above_max", kind));
        if (!std::isfinite(r.plateauMm) || r.plateauMm < 0.0)
            return Result::fail(fieldMessage("plateauMm", r.plateauMm, "profile.negative", kind));
        if (r.plateauMm > 0.0 && r.startSpeedMmS == 0.0)
            return Result::fail(fieldMessage("startSpeedMmS", r.startSpeedMmS, "profile.start_speed_for_plateau", kind));
        TrapezoidParams p;
        p.startSpeedMmS = r.startSpeedMmS;
        p.topSpeedMmS = r.vMaxMmS;
        p.accelMmS2 = r.aMaxMmS2;
        p.decelMmS2 = r.aMaxMmS2;
        p.plateauMm = r.plateauMm;
        return Result::ok(AnyProfile(*TrapezoidProfile::plan(distanceMm, p)));
    }
    case ProfileKind::Exponential: {
        if (!positive(r.accelTimeS))
            return Result::fail(fieldMessage("accelTimeS", r.accelTimeS, "profile.not_positive", kind));
        return Result::ok(AnyProfile(*ExponentialProfile::plan(distanceMm, r.vMaxMmS, r.accelTimeS / 3.0, r.accelTimeS)));
    }
    case ProfileKind::JerkLimited: {
        if (!positive(r.aMaxMmS2))
            return Result::fail(fieldMessage("aMaxMmS2", r.aMaxMmS2, "profile.not_positive", kind));
        if (!positive(r.jMaxMmS3))
            return Result::fail(fieldMessage("jMaxMmS3", r.jMaxMmS3, "profile.not_positive", kind));
        return Result::ok(AnyProfile(*JerkLimitedProfile::plan(distanceMm, {r.vMaxMmS, r.aMaxMmS2, r.jMaxMmS3})));
    }
    }
    return Result::fail(motion::msg::make("profile.unknown_kind"));
}

motion::msg::Checked<LinearMove<AnyProfile>> planSynchronized(const double* distancesMm, int axisCount, const ProfileRequest& r)
{
    using Result = motion::msg::Checked<LinearMove<AnyProfile>>;
    if (axisCount < 1 || axisCount > kMaxAxes) {
        return Result::fail(motion::msg::make("profile.axis_count", {motion::msg::integer("count", axisCount), motion::msg::integer("max", kMaxAxes)}));
    }
    double sumSq = 0.0, largest = 0.0;
    for (int i = 0; i < axisCount; ++i) {
        if (!std::isfinite(distancesMm[i]))
            return Result::fail(motion::msg::make("profile.axis_not_finite", {motion::msg::verbatim("field", "distanceMm"), motion::msg::real("value", distancesMm[i]),
                                                                      motion::msg::integer("axis", i, motion::msg::Unit::None)}));
        sumSq += distancesMm[i] * distancesMm[i];
        largest = std::max(largest, std::fabs(distancesMm[i]));
    }
    const double length = std::sqrt(sumSq);
    // The axis with the largest share limits the path: path limit = axis limit · L / max|d_i|.
    // Distance-like limits (the plateau) scale the same way so that axis sees exactly its own.
    const double k = largest > 0.0 ? length / largest : 1.0;
    ProfileRequest path = r;
    path.vMaxMmS *= k;
    path.aMaxMmS2 *= k;
    path.jMaxMmS3 *= k;
    path.startSpeedMmS *= k;
    path.plateauMm *= k;
    auto profile = planProfile(length, path);
    if (!profile)
        return Result::fail(profile.error());
    return Result::ok(LinearMove<AnyProfile>(*profile, distancesMm, axisCount));
}

std::vector<ProfileSample> sampleProfile(const Profile& profile, double dtS, std::size_t maxSamples)
{
    std::vector<ProfileSample> out;
    const double T = profile.duration();
    if (!positive(dtS) || !std::isfinite(T))
        return out;
    const double count = std::floor(T / dtS);
    if (count + 2.0 > static_cast<double>(maxSamples))
        return out;
    const auto n = static_cast<std::size_t>(count);
    out.reserve(n + 2);
    for (std::size_t i = 0; i <= n; ++i)
        out.push_back(profile.at(static_cast<double>(i) * dtS));
    if (out.back().t < T)
        out.push_back(profile.at(T));
    return out;
}

}  // namespace motion
