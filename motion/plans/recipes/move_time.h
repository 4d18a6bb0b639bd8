#pragma once
// How long the analyzer takes for one MOVE, planned the way its firmware plans
// it (device/sim/sim_machine.cpp, planSegment): one straight segment for the
// axes named, the path speed capped so every axis stays under its own maximum
// speed and acceleration, and seed 000's simplified S-curve
// (motion/seed_scurve.h) with its acceleration phase stretched until the
// curve's peak (1.5·v/t2) is within the path's acceleration limit.
#include "motion/plans/plates/deck.h"
#include "motion/seed_scurve.h"

#include <optional>

#include <vector>

namespace motion::plates {

struct AxisDelta {
    const AxisMotion* axis = nullptr;
    double delta = 0;  ///< axis units, signed
};

/// Seconds for a straight move of these axes together. `speed` in axis units
/// per second; 0 = the slowest default speed among the axes (the firmware's
/// rule for a MOVE without a speed). 0 for a move of zero length.
double moveTimeS(const std::vector<AxisDelta>& axes, double speed);
/// The profile behind moveTimeS(); nullopt for a move of zero length.
std::optional<motion::SeedSCurve> moveProfile(const std::vector<AxisDelta>& axes, double speed);

} // namespace motion::plates
