#pragma once
// Multi-axis synchronisation on a straight line.
//
// All axes start and stop together and stay on the line from the origin to the target, as the
// analyzer's XY move along tan θ = 4/3 in seed 000 §4.1. We plan ONE profile along the path length
// L = |d| and give axis i the share u_i = d_i / L of every sample. Per-axis limits become path
// limits through |u_i|: axis i sees |u_i|·vPath, so vPath = min_i vMax_i / |u_i| (same for a, j).
// Because the axes are rigidly proportional, the time-optimal path profile under those limits is
// the time-optimal straight-line move: no axis could go faster without leaving the line.

#include "motion/jerk_limited.h"
#include "motion/checked.h"
#include "motion/profile.h"
#include "motion/seed_scurve.h"

#include <array>
#include <cmath>

namespace motion {

constexpr int kMaxAxes = 6;  ///< enough for XYZ + pump or a 6-joint arm; fixed so moves stay off the heap

template <class PathProfile>
class LinearMove {
public:
    /// `pathProfile` runs from 0 to the line length; distancesMm[0..axisCount) is the target.
    LinearMove(const PathProfile& pathProfile, const double* distancesMm, int axisCount)
        : m_path(pathProfile), m_axisCount(axisCount)
    {
        const double length = std::fabs(pathProfile.distance());
        for (int i = 0; i < axisCount; ++i) {
            m_distanceMm[static_cast<std::size_t>(i)] = distancesMm[i];
            m_unit[static_cast<std::size_t>(i)] = length > 0.0 ? distancesMm[i] / length : 0.0;
        }
    }

    double duration() const { return m_path.duration(); }
    int axisCount() const { return m_axisCount; }
    double distanceMm(int axis) const { return m_distanceMm[static_cast<std::size_t>(axis)]; }
    double directionCosine(int axis) const { return m_unit[static_cast<std::size_t>(axis)]; }  ///< u_i
    const PathProfile& path() const { return m_path; }

    /// Sample of one axis at time t; clamps like Profile::at and ends exactly on the axis target.
    ProfileSample axisAt(int axis, double tS) const
    {
        const auto i = static_cast<std::size_t>(axis);
        const ProfileSample p = m_path.at(tS);
        if (tS >= m_path.duration())
            return {p.t, m_distanceMm[i], 0.0, 0.0, 0.0};
        const double u = m_unit[i];
        return {p.t, u * p.s, u * p.v, u * p.a, u * p.j};
    }

private:
    PathProfile m_path;
    int m_axisCount;
    std::array<double, kMaxAxes> m_distanceMm{};
    std::array<double, kMaxAxes> m_unit{};
};

/// Straight-line, time-optimal jerk-limited move of axisCount (1..kMaxAxes) axes.
motion::msg::Checked<LinearMove<JerkLimitedProfile>> planLinearJerkLimited(const double* distancesMm,
                                                                 const JerkLimits* limitsPerAxis, int axisCount);

/// Seed 000's way: every axis uses the same acceleration time; the slowest axis (relative to its
/// share of the line) sets the path speed.
motion::msg::Checked<LinearMove<SeedSCurve>> planLinearSeedSCurve(const double* distancesMm, const double* vMaxMmSPerAxis,
                                                        double accelTimeS, int axisCount);

/// Contour (cross-track) error of an XY point that should lie on the line at angle θ to the x axis:
/// ε = -sin θ·e_x + cos θ·e_y, with e = actual - commanded.
/// Seed 000 §4.1 prints ε = cos θ·e_x + sin θ·e_y, which is the ALONG-track error; its own Table 5
/// is computed with the cross-track form above (tests/motion/linear_move_test.cpp reproduces it).
double contourErrorMm(double thetaRad, double errorXMm, double errorYMm);

}  // namespace motion
