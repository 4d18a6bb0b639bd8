#include "motion/path/sample_density.h"

#include "motion/numbers.h"

#include <algorithm>
#include <cmath>

namespace motion::path {

namespace {

/// The most the path between `fromMm` and `toMm` (along it) strays from a straight chord:
/// the largest sagitta of any arc piece in the gap (an arc piece longer than half its circle
/// strays by its diameter at most).
double sagOver(const std::vector<Segment>& path, double fromMm, double toMm)
{
    double start = 0, worst = 0;
    for (const Segment& s : path) {
        const double len = lengthMm(s);
        const double a = std::max(fromMm, start), b = std::min(toMm, start + len);
        start += len;
        if (!s.isArc() || b <= a)
            continue;
        const double r = radiusMm(s);
        if (r <= 0)
            continue;
        worst = std::max(worst, r * (1 - std::cos(std::min((b - a) / (2 * r), motion::kPi))));
    }
    return worst;
}

}  // namespace

SampleDensity judgeSampleDensity(const std::vector<Segment>& path, const std::vector<double>& alongMm,
                                 const std::vector<double>& timeS, double maxContourMm)
{
    SampleDensity d;
    d.samples = alongMm.size();
    if (timeS.size() >= 2 && timeS.back() > timeS.front())
        d.rateHz = static_cast<double>(timeS.size() - 1) / (timeS.back() - timeS.front());
    for (std::size_t k = 1; k < alongMm.size(); ++k) {
        const double a = std::min(alongMm[k - 1], alongMm[k]), b = std::max(alongMm[k - 1], alongMm[k]);
        if (b - a > d.largestGapMm)
            d.largestGapMm = b - a;
        d.largestSagMm = std::max(d.largestSagMm, sagOver(path, a, b));
    }
    d.tooSparse = d.samples < SampleDensity::kMinSamples || d.largestSagMm > std::fabs(maxContourMm);
    return d;
}

}  // namespace motion::path
