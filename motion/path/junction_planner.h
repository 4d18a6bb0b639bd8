#pragma once
// Look-ahead speed planning over a queue of path segments, after grbl's planner: every segment
// has a nominal (cruise) speed and a largest speed it may be entered with; the planner finds the
// entry and exit speed of each so that the path speeds up and slows down at no more than the
// path acceleration and never has to stop between two segments unless their junction demands it.
//
// Junction speed ("junction deviation"): a corner of deflection φ (0 = straight on) is passed as
// if it were rounded by a circle tangent to both segments whose closest point stays δ from the
// corner. That circle's radius is R = δ·c/(1 − c) with c = cos(φ/2) (the sine of half the
// interior angle), and the speed whose centripetal acceleration on it is the path acceleration a
// is v = √(a·R). Straight on (φ = 0) gives no limit, a reversal (φ = π) gives 0, a shallow
// 10° bend with δ = 0.01 mm and a = 100 mm/s² allows 16 mm/s. The path itself is still followed
// exactly through the corner (point by point); δ only sets how hard the corner may be taken.
//
// Planning takes a START state (the speed the first segment is entered with — a machine already
// moving, or 0) and an END state (the speed the last one may leave with: 0 when nothing follows),
// so the same call plans a path from rest and re-plans a queue while it runs.

#include "motion/path/path_geometry.h"

#include <vector>

namespace motion::path {

struct PathLimits {
    double accelMmS2 = 100;          ///< tangential acceleration and deceleration along the path
    double junctionDeviationMm = 0.01;
    double maxSpeedMmS = 1e300;      ///< no segment runs faster, whatever its feed
};

/// Largest speed at a junction from direction `in` to direction `out` (unit vectors).
double junctionSpeedMmS(Vec2 in, Vec2 out, double accelMmS2, double deviationMm);
/// Largest steady speed on an arc of this radius: half the path acceleration is left for the
/// centripetal part (v²/R ≤ a/2), so speeding up on the arc still keeps |a| ≤ a·√(5/4).
double arcSpeedLimitMmS(double radiusMm, double accelMmS2);

struct PlanBlock {
    double lengthMm = 0;
    double nominalMmS = 0;           ///< cruise speed: feed, capped by the limits and the arc limit
    double maxEntryMmS = 0;          ///< junction limit with the block before (0 for a stop)
    bool stopAfter = false;          ///< must be at rest at its end (e.g. Z follows XY there)
    // Results of planSpeeds():
    double entryMmS = 0;
    double exitMmS = 0;
};

struct PathState {
    double speedMmS = 0;
};

/// Fills entryMmS / exitMmS: block 0 is entered at min(start.speed, its limits), the last is left
/// at most at end.speed, each block's exit is the next one's entry, and every change of speed
/// fits a·length (a backward pass from the end, then a forward pass from the start).
void planSpeeds(std::vector<PlanBlock>& blocks, double accelMmS2, PathState start, PathState end);

/// Time a block takes with its planned entry/exit speeds: accelerate towards the nominal speed,
/// cruise, slow down to the exit speed (a triangle when the block is too short to cruise).
double blockDurationS(const PlanBlock& block, double accelMmS2);
/// Highest speed a block reaches with its planned entry/exit speeds.
double blockPeakSpeedMmS(const PlanBlock& block, double accelMmS2);

/// Blocks of a whole path (lengths, nominal speeds, junction limits), ready for planSpeeds().
std::vector<PlanBlock> blocksFor(const std::vector<Segment>& path, const PathLimits& limits);

struct PathEstimate {
    double durationS = 0;
    double lengthMm = 0;
    std::vector<PlanBlock> blocks;   ///< planned, one per segment
};
/// Plans a whole path from rest to rest and times it. Z moves (seed 000's "Z following") are not
/// included: the caller adds them (they depend on the Z axis' own profile).
PathEstimate estimatePath(const std::vector<Segment>& path, const PathLimits& limits);

}  // namespace motion::path
