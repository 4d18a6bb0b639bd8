#pragma once
// From a joystick's deflection to a velocity: a dead-band around the centre (a knob at rest,
// or a thumb resting on it, never creeps), then an expo curve (fine control near the centre,
// full speed at the rim), scaled to the maximum speed. The two-axis version shapes the length
// of the deflection and keeps its direction, so the dead-band is round and a diagonal push
// moves diagonally at the speed the same push along an axis would give.
#include "motion/path/path_geometry.h"

namespace motion::jog {

struct StickShaping {
    double deadband = 0.08;  ///< share of full deflection (0…0.9) that gives nothing
    double expo = 0.4;       ///< 0 linear … 1 cubic: out = (1−e)·u + e·u³ of the deflection u past the dead-band
};

/// One axis: deflection −1…1 → −1…1.
double shapeAxis(double deflection, const StickShaping& s);
/// Two axes: deflection inside the unit circle (longer ones are cut to it) → a vector no longer than 1.
motion::path::Vec2 shapeStick(motion::path::Vec2 deflection, const StickShaping& s);

} // namespace motion::jog
