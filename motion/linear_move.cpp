#include "motion/linear_move.h"

#include <limits>

namespace motion {

namespace {

motion::msg::Message axisMessage(int axis, const char* field, double value, const char* id)
{
    return motion::msg::make(id, {motion::msg::verbatim("field", field), motion::msg::real("value", value), motion::msg::integer("axis", axis, motion::msg::Unit::None)});
}

/// Length of the line, or a message when the input is unusable.
bool lineLength(const double* distancesMm, int axisCount, double& lengthMm, motion::msg::Message& error)
{
    if (axisCount < 1 || axisCount > kMaxAxes) {
        error = motion::msg::make("profile.axis_count", {motion::msg::integer("count", axisCount), motion::msg::integer("max", kMaxAxes)});
        return false;
    }
    double sumSq = 0.0;
    for (int i = 0; i < axisCount; ++i) {
        if (!std::isfinite(distancesMm[i])) {
            error = axisMessage(i, "distanceMm", distancesMm[i], "profile.axis_not_finite");
            return false;
        }
        sumSq += distancesMm[i] * distancesMm[i];
    }
    lengthMm = std::sqrt(sumSq);
    return true;
}

}  // namespace

motion::msg::Checked<LinearMove<JerkLimitedProfile>> planLinearJerkLimited(const double* distancesMm,
                                                                 const JerkLimits* limitsPerAxis, int axisCount)
{
    using Result = motion::msg::Checked<LinearMove<JerkLimitedProfile>>;
    double lengthMm = 0.0;
    motion::msg::Message error;
    if (!lineLength(distancesMm, axisCount, lengthMm, error))
        return Result::fail(error);
    constexpr double inf = std::numeric_limits<double>::infinity();
    JerkLimits path{inf, inf, inf};
    for (int i = 0; i < axisCount; ++i) {
        const JerkLimits& lim = limitsPerAxis[i];
        // Validated inline (not via validateJerkLimits) so the success path builds no message.
        if (!(std::isfinite(lim.vMaxMmS) && lim.vMaxMmS > 0.0))
            return Result::fail(axisMessage(i, "vMaxMmS", lim.vMaxMmS, "profile.axis_not_positive"));
        if (!(std::isfinite(lim.aMaxMmS2) && lim.aMaxMmS2 > 0.0))
            return Result::fail(axisMessage(i, "aMaxMmS2", lim.aMaxMmS2, "profile.axis_not_positive"));
        if (!(std::isfinite(lim.jMaxMmS3) && lim.jMaxMmS3 > 0.0))
            return Result::fail(axisMessage(i, "jMaxMmS3", lim.jMaxMmS3, "profile.axis_not_positive"));
        const double share = std::fabs(distancesMm[i]);
        if (share == 0.0)
            continue;  // an axis that does not move does not limit the path
        // lim / (share / L) written as lim·L / share: one division per limit.
        path.vMaxMmS = std::fmin(path.vMaxMmS, lim.vMaxMmS * lengthMm / share);
        path.aMaxMmS2 = std::fmin(path.aMaxMmS2, lim.aMaxMmS2 * lengthMm / share);
        path.jMaxMmS3 = std::fmin(path.jMaxMmS3, lim.jMaxMmS3 * lengthMm / share);
    }
    if (lengthMm == 0.0)
        path = limitsPerAxis[0];  // zero-length move: any valid limits give the empty profile
    const auto profile = JerkLimitedProfile::plan(lengthMm, path);
    if (!profile)
        return Result::fail(motion::msg::make("profile.path_limits_not_finite"));
    return Result::ok(LinearMove<JerkLimitedProfile>(*profile, distancesMm, axisCount));
}

motion::msg::Checked<LinearMove<SeedSCurve>> planLinearSeedSCurve(const double* distancesMm, const double* vMaxMmSPerAxis,
                                                        double accelTimeS, int axisCount)
{
    using Result = motion::msg::Checked<LinearMove<SeedSCurve>>;
    double lengthMm = 0.0;
    motion::msg::Message error;
    if (!lineLength(distancesMm, axisCount, lengthMm, error))
        return Result::fail(error);
    if (!(std::isfinite(accelTimeS) && accelTimeS > 0.0))
        return Result::fail(motion::msg::make("profile.not_positive_plain", {motion::msg::verbatim("field", "accelTimeS"), motion::msg::real("value", accelTimeS)}));
    double pathVMaxMmS = std::numeric_limits<double>::infinity();
    for (int i = 0; i < axisCount; ++i) {
        const double v = vMaxMmSPerAxis[i];
        if (!(std::isfinite(v) && v > 0.0))
            return Result::fail(axisMessage(i, "vMaxMmS", v, "profile.axis_not_positive"));
        const double share = std::fabs(distancesMm[i]);
        if (share > 0.0)
            pathVMaxMmS = std::fmin(pathVMaxMmS, v * lengthMm / share);
    }
    if (lengthMm == 0.0)
        pathVMaxMmS = vMaxMmSPerAxis[0];
    const auto profile = SeedSCurve::plan(lengthMm, pathVMaxMmS, accelTimeS);
    if (!profile)
        return Result::fail(motion::msg::make("profile.path_speed_not_finite"));
    return Result::ok(LinearMove<SeedSCurve>(*profile, distancesMm, axisCount));
}

double contourErrorMm(double thetaRad, double errorXMm, double errorYMm)
{
    return -std::sin(thetaRad) * errorXMm + std::cos(thetaRad) * errorYMm;
}

}  // namespace motion
