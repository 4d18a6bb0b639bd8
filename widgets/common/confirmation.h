#pragma once
// One rule for what asks first, on every screen: a long move
// (further than kLongMoveShare of an axis's travel) and a destructive action
// (Abort a run, Disconnect during one, quitting with unsaved edits or a running
// job) are confirmed. Screens raise the question through their Confirm hook;
// app/ shows it (long moves may offer "don't ask again for this session").
#include <cmath>

namespace ui::confirmation {

/// A move longer than this share of the axis's travel asks first (Jog, Patterns, Scan).
constexpr double kLongMoveShare = 0.25;

inline bool isLongMove(double fromMm, double toMm, double travelMm)
{
    return travelMm > 0 && std::abs(toMm - fromMm) > kLongMoveShare * travelMm;
}

} // namespace ui::confirmation
