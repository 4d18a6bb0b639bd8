#pragma once
// When the three parts of an arched move start (docs/protocol.md, "ARCH_MOVE"): Z up
// to a clearance, XY across, Z down. XY may start before Z has reached the clearance
// as long as it is still within `departMm` of where it started when Z gets there; Z may
// start down once XY is within `approachMm` of its target (and Z has risen). The
// simulated firmware runs a move so and the recipe planner times it so: one function,
// so the two cannot drift.
#include "motion/profile.h"

namespace motion {

/// The first time at which `p` has covered |s| (its distance's sign ignored); its
/// duration when |s| is not less than its whole distance, 0 for s <= 0.
double timeToCoverS(const Profile& p, double s);

struct ArchTiming {
    double xyStartS = 0;    ///< from the move's start
    double downStartS = 0;  ///< Z's way down from the clearance
    double durationS = 0;   ///< until every part has ended
};

/// `rise`, `xy`, `down`: the three rest-to-rest profiles, nullptr for a part of no length.
ArchTiming archTiming(const Profile* rise, const Profile* xy, const Profile* down, double departMm, double approachMm);

} // namespace motion
