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
    double pumpStartS = 0;  ///< the plunger (with ArchPumpParts)
    double leaveStartS = 0; ///< Z's way back up after the plunger (with ArchPumpParts)
    double durationS = 0;   ///< until every part has ended
};

/// A plunger move inside the target well, and the rise after it. The plunger starts once
/// the way down has covered `liquidMm` (down to the height below which liquid lands in the
/// well: its rim); the rise starts when Z is down and late enough that it covers
/// `leaveLiquidMm` (back up to that height) no earlier than the plunger stops. So the
/// plunger moves only while the tip is below that height, and as much of it as can
/// overlaps Z's way down and back up.
struct ArchPumpParts {
    const Profile* plunger = nullptr;  ///< nullptr: no plunger move
    double liquidMm = 0;
    const Profile* leave = nullptr;    ///< nullptr: Z stays down
    double leaveLiquidMm = 0;
};

/// `rise`, `xy`, `down`: the three rest-to-rest profiles, nullptr for a part of no length.
ArchTiming archTiming(const Profile* rise, const Profile* xy, const Profile* down, double departMm, double approachMm,
                      const ArchPumpParts& pump = {});

} // namespace motion
