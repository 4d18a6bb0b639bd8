// When a run's contour figure rests on too few samples (motion/path/sample_density.h).
#include "motion/numbers.h"
#include "motion/path/sample_density.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace motion::path;

namespace {

std::vector<Segment> circle(double radiusMm)
{
    Segment s;
    s.kind = SegmentKind::ArcCcw;
    s.center = {0, 0};
    s.start = s.end = {radiusMm, 0};
    s.feedMmS = 5;
    return {s};
}

/// `n` samples spread evenly over the path's length, taken at `hz`.
void evenly(double lengthMm, std::size_t n, double hz, std::vector<double>* along, std::vector<double>* t)
{
    for (std::size_t k = 0; k < n; ++k) {
        along->push_back(lengthMm * static_cast<double>(k) / static_cast<double>(n - 1));
        t->push_back(static_cast<double>(k) / hz);
    }
}

}  // namespace

// What a GRBL controller polled at 10 Hz gave on a circle: 14 samples, a largest contour error
// of 2.2 µm at those samples, and chords that cut the circle by far more than that.
TEST(SampleDensity, FourteenSamplesOnACircleAreTooFewForAMicrometreFigure)
{
    const auto path = circle(3);
    const double length = 2 * motion::kPi * 3;
    std::vector<double> along, t;
    evenly(length, 14, 10, &along, &t);
    const SampleDensity d = judgeSampleDensity(path, along, t, 0.0022);
    EXPECT_EQ(d.samples, 14u);
    EXPECT_NEAR(d.rateHz, 10, 1e-9);
    EXPECT_NEAR(d.largestGapMm, length / 13, 1e-9);
    // Sagitta of a 1.45 mm gap on a 3 mm radius: R(1 − cos(Δ/2R)) = 0.0874 mm.
    EXPECT_NEAR(d.largestSagMm, 3 * (1 - std::cos(length / 13 / 6)), 1e-12);
    EXPECT_GT(d.largestSagMm, 0.08);
    EXPECT_TRUE(d.tooSparse);
}

TEST(SampleDensity, DenseTelemetryOnTheSameCircleIsEnough)
{
    const auto path = circle(3);
    const double length = 2 * motion::kPi * 3;
    std::vector<double> along, t;
    evenly(length, 1000, 250, &along, &t);  // the stage's 250 Hz
    const SampleDensity d = judgeSampleDensity(path, along, t, 0.0022);
    EXPECT_NEAR(d.rateHz, 250, 1e-9);
    EXPECT_LT(d.largestSagMm, 2e-5);  // a 0.019 mm gap on a 3 mm radius: 0.015 µm
    EXPECT_FALSE(d.tooSparse);
}

TEST(SampleDensity, AStraightLineHasNoSagButStillNeedsAFewSamples)
{
    Segment l;
    l.start = {0, 0};
    l.end = {20, 0};
    std::vector<double> along, t;
    evenly(20, 12, 10, &along, &t);
    SampleDensity d = judgeSampleDensity({l}, along, t, 0.001);
    EXPECT_EQ(d.largestSagMm, 0);
    EXPECT_FALSE(d.tooSparse);
    along.resize(5);
    t.resize(5);
    d = judgeSampleDensity({l}, along, t, 0.001);
    EXPECT_TRUE(d.tooSparse) << "five samples say nothing of a largest error";
}

TEST(SampleDensity, AGapAcrossALineAndAnArcCountsOnlyTheArcPiece)
{
    Segment l;
    l.start = {0, 0};
    l.end = {10, 0};
    Segment a;
    a.kind = SegmentKind::ArcCcw;
    a.start = {10, 0};
    a.center = {10, 5};
    a.end = {15, 5};  // a quarter of a 5 mm circle
    std::vector<double> along{0, 2, 4, 6, 8, 10.5, 12, 13, 14, 15, 16, 17};
    std::vector<double> t;
    for (std::size_t k = 0; k < along.size(); ++k)
        t.push_back(0.1 * static_cast<double>(k));
    const SampleDensity d = judgeSampleDensity({l, a}, along, t, 0.1);
    // The gap 8 → 10.5 has 0.5 mm on the arc; 10.5 → 12 has 1.5 mm, the arc's largest gap.
    EXPECT_NEAR(d.largestSagMm, 5 * (1 - std::cos(1.5 / 10)), 1e-12);
    EXPECT_FALSE(d.tooSparse);
}
