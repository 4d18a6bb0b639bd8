#pragma once
// How long a scan takes and how far the stage travels: every move timed with the
// stage's own planner (the time-optimal jerk-limited straight-line move the
// firmware runs, under the same per-axis limits), plus settle and exposure per tile.
#include "motion/plans/scan/scan_layout.h"

#include <vector>

namespace motion::scan {

struct ScanEstimate {
    double totalS = 0;     ///< from arriving at the first waypoint to the last tile's exposure end
    double moveS = 0;      ///< moving between waypoints (overtravel points included)
    double settleS = 0;    ///< tiles × settle
    double exposureS = 0;  ///< tiles × exposure
    double travelMm = 0;   ///< straight-line path length, overtravel included
    int moves = 0;         ///< moves between waypoints
    /// Per tile (by index): time from the start at which its exposure has ended;
    /// total − tileDoneS[k] is what remains after tile k.
    std::vector<double> tileDoneS;
};

/// Duration of one straight move between two commanded positions at the plan's speed
/// on `stage`, as the firmware plans it (path limits from each axis' share, seed
/// 002's stage: device/sim/sim_machine.cpp planSegment).
double moveTimeS(Point2 from, Point2 to, double speedMmS, const StageModel& stage);

ScanEstimate estimateScan(const ScanPlan& plan, const ScanLayout& layout, const StageModel& stage);

} // namespace motion::scan
