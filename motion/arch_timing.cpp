#include "motion/arch_timing.h"

#include <algorithm>
#include <cmath>

namespace motion {

double timeToCoverS(const Profile& p, double s)
{
    const double total = std::abs(p.distance());
    if (s <= 0)
        return 0;
    if (s >= total)
        return p.duration();
    // A rest-to-rest profile never turns back: |s(t)| grows monotonically, so bisection
    // finds the first instant to well under the simulator's 100 µs tick.
    double lo = 0, hi = p.duration();
    for (int i = 0; i < 60 && hi - lo > 1e-9; ++i) {
        const double mid = 0.5 * (lo + hi);
        (std::abs(p.at(mid).s) >= s ? hi : lo) = mid;
    }
    return hi;
}

ArchTiming archTiming(const Profile* rise, const Profile* xy, const Profile* down, double departMm, double approachMm,
                      const ArchPumpParts& pump)
{
    ArchTiming t;
    const double riseS = rise ? rise->duration() : 0.0;
    const double xyS = xy ? xy->duration() : 0.0;
    const double d = xy ? std::abs(xy->distance()) : 0.0;
    // XY reaches the edge of the depart circle no earlier than Z reaches the clearance.
    t.xyStartS = xy ? std::max(0.0, riseS - timeToCoverS(*xy, std::max(0.0, departMm))) : riseS;
    // Z leaves the clearance no earlier than XY enters the approach circle, nor before it got there.
    t.downStartS = std::max(riseS, xy ? t.xyStartS + timeToCoverS(*xy, d - std::max(0.0, approachMm)) : riseS);
    const double downEndS = t.downStartS + (down ? down->duration() : 0.0);
    t.durationS = std::max({riseS, t.xyStartS + xyS, downEndS});
    t.pumpStartS = t.leaveStartS = downEndS;
    if (pump.plunger) {
        t.pumpStartS = t.downStartS + (down ? timeToCoverS(*down, pump.liquidMm) : 0.0);
        const double pumpEndS = t.pumpStartS + pump.plunger->duration();
        t.leaveStartS = std::max(downEndS, pumpEndS - (pump.leave ? timeToCoverS(*pump.leave, pump.leaveLiquidMm) : 0.0));
        t.durationS = std::max(t.durationS, pumpEndS);
    }
    if (pump.leave)
        t.durationS = std::max(t.durationS, t.leaveStartS + pump.leave->duration());
    return t;
}

} // namespace motion
