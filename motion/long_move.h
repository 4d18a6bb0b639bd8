#pragma once
// The house rule for which moves ask first: one threshold for every screen and for the
// jobs that describe a run before it starts (device/jobs/scan_launch.h), so a screen and
// a script cannot disagree about what a long move is. widgets/common/confirmation.h says
// what else asks.
#include <cmath>

namespace motion {

/// A move longer than this share of the axis's travel asks first (Jog, Patterns, Scan).
constexpr double kLongMoveShare = 0.25;

inline bool isLongMove(double fromMm, double toMm, double travelMm)
{
    return travelMm > 0 && std::abs(toMm - fromMm) > kLongMoveShare * travelMm;
}

} // namespace motion
