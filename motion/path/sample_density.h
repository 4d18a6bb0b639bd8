#pragma once
// Whether a run's contour figure rests on enough samples to mean anything.
//
// The contour error is judged only where a telemetry sample lands: what the machine did
// between two samples is not seen. The rule: between two consecutive samples the path may
// bend away from the straight chord joining them by its sagitta, R·(1 − cos(Δ / 2R)) for an
// arc of radius R and a gap Δ along it. When the largest such sagitta is larger than the
// largest contour error the run reports, the sample spacing alone hides more than the figure
// claims to resolve: a bulge or a dip as large as the figure could lie between two samples
// unseen, and a line drawn through the samples cuts the path by more than the figure (a
// controller polled at 10 Hz gave 14 samples on a circle: chords 0.12 mm inside it, beside
// "max 2.2 µm"). A path of straight lines has no sagitta; there, and always, fewer than
// kMinSamples samples are too few to speak of a largest error at all.
#include "motion/path/path_geometry.h"

#include <cstddef>
#include <vector>

namespace motion::path {

struct SampleDensity {
    static constexpr std::size_t kMinSamples = 10;

    std::size_t samples = 0;
    double rateHz = 0;        ///< samples per second of device time; 0 with fewer than two
    double largestGapMm = 0;  ///< along the path, between two consecutive samples
    double largestSagMm = 0;  ///< how far the path can stray from the chord over a gap, at most
    bool tooSparse = false;   ///< the contour figure rests on too few samples (the rule above)
};

/// `alongMm[k]` and `timeS[k]`: where along the path sample k was judged and its device time
/// (both in the order taken); `maxContourMm`: the largest contour error reported.
SampleDensity judgeSampleDensity(const std::vector<Segment>& path, const std::vector<double>& alongMm,
                                 const std::vector<double>& timeS, double maxContourMm);

}  // namespace motion::path
