#include "motion/path/junction_planner.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace motion::path {

double junctionSpeedMmS(Vec2 in, Vec2 out, double accelMmS2, double deviationMm)
{
    const double phi = deflectionRad(in, out);
    if (phi < 1e-9)
        return std::numeric_limits<double>::infinity();  // straight on: only the blocks' own speeds limit it
    const double c = std::cos(0.5 * phi);                // sine of half the interior angle
    if (c <= 1e-12)
        return 0.0;                                       // a reversal: stop there
    const double radius = deviationMm * c / (1.0 - c);
    return std::sqrt(std::max(0.0, accelMmS2 * radius));
}

double arcSpeedLimitMmS(double radiusMm, double accelMmS2) { return std::sqrt(std::max(0.0, 0.5 * accelMmS2 * radiusMm)); }

void planSpeeds(std::vector<PlanBlock>& blocks, double accelMmS2, PathState start, PathState end)
{
    if (blocks.empty())
        return;
    const std::size_t n = blocks.size();
    const double a2 = 2.0 * accelMmS2;
    // Backward: from the end state, the fastest each block may be entered so that everything
    // after it can still slow down in time.
    for (std::size_t k = n; k-- > 0;) {
        PlanBlock& b = blocks[k];
        double exit = k + 1 == n ? std::min(end.speedMmS, b.nominalMmS) : blocks[k + 1].entryMmS;
        if (b.stopAfter)
            exit = 0;
        b.exitMmS = exit;
        double entryCap = std::min(b.maxEntryMmS, b.nominalMmS);
        if (k > 0)
            entryCap = std::min(entryCap, blocks[k - 1].nominalMmS);
        if (k > 0 && blocks[k - 1].stopAfter)
            entryCap = 0;
        b.entryMmS = std::min(entryCap, std::sqrt(exit * exit + a2 * b.lengthMm));
    }
    // Forward: from the start state, the fastest each block can actually be reached.
    blocks[0].entryMmS = std::min(std::max(0.0, start.speedMmS), blocks[0].nominalMmS);
    for (std::size_t k = 0; k < n; ++k) {
        PlanBlock& b = blocks[k];
        if (k > 0)
            b.entryMmS = std::min(b.entryMmS, blocks[k - 1].exitMmS);
        b.exitMmS = std::min(b.exitMmS, std::sqrt(b.entryMmS * b.entryMmS + a2 * b.lengthMm));
        if (k + 1 < n)
            b.exitMmS = std::min(b.exitMmS, blocks[k + 1].entryMmS);
    }
}

double blockPeakSpeedMmS(const PlanBlock& b, double accelMmS2)
{
    const double e = b.entryMmS, x = b.exitMmS;
    const double peak = std::sqrt(std::max(0.0, (2.0 * accelMmS2 * b.lengthMm + e * e + x * x) / 2.0));
    return std::max({std::min(peak, b.nominalMmS), e, x});
}

double blockDurationS(const PlanBlock& b, double accelMmS2)
{
    if (b.lengthMm <= 0)
        return 0.0;
    const double e = b.entryMmS, x = b.exitMmS;
    const double peak = blockPeakSpeedMmS(b, accelMmS2);
    if (peak <= 0)
        return 0.0;
    const double up = std::max(0.0, peak - e) / accelMmS2, down = std::max(0.0, peak - x) / accelMmS2;
    const double rampMm = (peak * peak - e * e) / (2 * accelMmS2) + (peak * peak - x * x) / (2 * accelMmS2);
    const double cruiseMm = std::max(0.0, b.lengthMm - rampMm);
    return up + down + cruiseMm / peak;
}

std::vector<PlanBlock> blocksFor(const std::vector<Segment>& path, const PathLimits& limits)
{
    std::vector<PlanBlock> blocks;
    blocks.reserve(path.size());
    for (std::size_t k = 0; k < path.size(); ++k) {
        const Segment& s = path[k];
        PlanBlock b;
        b.lengthMm = lengthMm(s);
        b.nominalMmS = std::min(s.feedMmS, limits.maxSpeedMmS);
        if (s.isArc())
            b.nominalMmS = std::min(b.nominalMmS, arcSpeedLimitMmS(radiusMm(s), limits.accelMmS2));
        b.stopAfter = s.zMm.has_value();
        b.maxEntryMmS = k == 0 ? 0.0
                               : junctionSpeedMmS(endTangent(path[k - 1]), startTangent(s), limits.accelMmS2,
                                                  limits.junctionDeviationMm);
        blocks.push_back(b);
    }
    return blocks;
}

PathEstimate estimatePath(const std::vector<Segment>& path, const PathLimits& limits)
{
    PathEstimate e;
    e.blocks = blocksFor(path, limits);
    planSpeeds(e.blocks, limits.accelMmS2, PathState{0}, PathState{0});
    for (const PlanBlock& b : e.blocks) {
        e.durationS += blockDurationS(b, limits.accelMmS2);
        e.lengthMm += b.lengthMm;
    }
    return e;
}

}  // namespace motion::path
