#pragma once
// What a job measured at one target: where it was asked to go, what was
// commanded, what the scale read at the moment that mattered (the camera trigger
// for a scan; the reading for a calibration run), and when on the device's clock.
// Plain data, one record per visit, so the stitching scan and the calibration
// bench (roadmap) share one model and one CSV writer.
#include <cstdint>
#include <string>
#include <vector>

namespace motion {

struct PositionRecord {
    int target = 0;                  ///< index of the target in its job (tile number, target × repeat)
    std::string label;               ///< how the job names it ("tile_007.tif")
    std::vector<double> plannedMm;   ///< per axis: the position asked for
    std::vector<double> commandedMm; ///< per axis: what was sent (after compensation)
    std::vector<double> measuredMm;  ///< per axis: the scale's reading; empty until measured
    std::uint64_t deviceTimeUs = 0;  ///< device clock at the reading
    double settleS = 0;              ///< from the device's motion-done to the reading
    bool measured() const { return !measuredMm.empty(); }
};

} // namespace motion
