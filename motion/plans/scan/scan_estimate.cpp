#include "motion/plans/scan/scan_estimate.h"

#include "motion/linear_move.h"

#include <algorithm>
#include <cmath>

namespace motion::scan {

double moveTimeS(Point2 from, Point2 to, double speedMmS, const StageModel& stage)
{
    const double d[2] = {to.xMm - from.xMm, to.yMm - from.yMm};
    const double length = std::hypot(d[0], d[1]);
    if (length <= 0)
        return 0;
    // The firmware caps the path speed at the requested one and at each axis' top
    // speed over its share; giving each axis min(top, requested·share) as its own
    // limit makes planLinearJerkLimited arrive at exactly that path speed.
    JerkLimits limits[2];
    for (int i = 0; i < 2; ++i) {
        const double share = std::fabs(d[i]) / length;
        const double requested = share > 0 ? speedMmS * share : speedMmS;
        limits[i] = {std::min(stage.maxSpeedMmS[i], requested), stage.maxAccelMmS2[i], stage.maxJerkMmS3[i]};
    }
    const auto move = planLinearJerkLimited(d, limits, 2);
    return move ? move->duration() : 0.0;
}

ScanEstimate estimateScan(const ScanPlan& plan, const ScanLayout& layout, const StageModel& stage)
{
    ScanEstimate e;
    e.tileDoneS.assign(layout.tiles.size(), 0.0);
    double t = 0;
    Point2 at{};
    for (std::size_t k = 0; k < layout.path.size(); ++k) {
        const Waypoint& w = layout.path[k];
        const Point2 target = commandedTarget(plan, w.target);
        if (k > 0) {
            const double m = moveTimeS(at, target, plan.speedMmS, stage);
            e.moveS += m;
            e.travelMm += std::hypot(target.xMm - at.xMm, target.yMm - at.yMm);
            ++e.moves;
            t += m;
        }
        at = target;
        if (w.tile >= 0) {
            t += plan.settleS + plan.exposureS;
            e.tileDoneS[static_cast<std::size_t>(w.tile)] = t;
        }
    }
    const double tiles = static_cast<double>(layout.tiles.size());
    e.settleS = tiles * plan.settleS;
    e.exposureS = tiles * plan.exposureS;
    e.totalS = t;
    return e;
}

} // namespace motion::scan
