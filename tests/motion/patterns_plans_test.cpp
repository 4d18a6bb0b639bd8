// Pattern shapes (motion/plans/pattern.h): parameters, validation, the segments they plan,
// limits and estimated time.
#include "motion/numbers.h"
#include "motion/chords.h"
#include "motion/plans/pattern.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace motion::plans;
using motion::path::Segment;

namespace {
using motion::kPi;

Pattern of(PatternShape s)
{
    Pattern p;
    p.shape = s;
    return p;
}

void expectContinuous(const std::vector<Segment>& path)
{
    for (std::size_t k = 1; k < path.size(); ++k) {
        EXPECT_NEAR(path[k].start.x, path[k - 1].end.x, 1e-9) << k;
        EXPECT_NEAR(path[k].start.y, path[k - 1].end.y, 1e-9) << k;
    }
}
double maxDeflectionDeg(const std::vector<Segment>& path)
{
    double worst = 0;
    for (std::size_t k = 1; k < path.size(); ++k)
        worst = std::max(worst, motion::path::deflectionRad(motion::path::endTangent(path[k - 1]),
                                                            motion::path::startTangent(path[k])) * 180 / kPi);
    return worst;
}
}  // namespace

TEST(PatternsPlans, EveryShapeNamesItselfAndPlansFromItsDefaults)
{
    for (PatternShape s : kAllShapes) {
        EXPECT_EQ(shapeFromName(shapeName(s)), s);
        const Pattern p = of(s);
        EXPECT_TRUE(validate(p).empty()) << shapeName(s);
        const auto path = plan(p);
        ASSERT_FALSE(path.empty()) << shapeName(s);
        expectContinuous(path);
        for (const auto& seg : path)
            EXPECT_EQ(seg.feedMmS, p.feedMmS);
    }
    EXPECT_FALSE(shapeFromName("square"));
}

TEST(PatternsPlans, DefaultLineIsSeed000sFiftyMillimetresAtTanFourThirds)
{
    const auto path = plan(of(PatternShape::Line));
    ASSERT_EQ(path.size(), 1u);
    EXPECT_NEAR(motion::path::lengthMm(path[0]), 50, 1e-12);
    EXPECT_NEAR((path[0].end.y - path[0].start.y) / (path[0].end.x - path[0].start.x), 4.0 / 3.0, 1e-12);
}

TEST(PatternsPlans, CircleIsFourTangentQuartersThatClose)
{
    Pattern p = of(PatternShape::Circle);
    p.circle.startDeg = 30;
    p.circle.clockwise = true;
    const auto path = plan(p);
    ASSERT_EQ(path.size(), 4u);
    EXPECT_NEAR(motion::path::pathLengthMm(path), 2 * kPi * 5, 1e-9);
    EXPECT_LT(maxDeflectionDeg(path), 1e-6);
    EXPECT_EQ(path.back().end.x, path.front().start.x);
    EXPECT_EQ(path.back().end.y, path.front().start.y);
    EXPECT_NEAR(path.front().start.x, 50 + 5 * std::cos(kPi / 6), 1e-12);
    EXPECT_EQ(path.front().kind, motion::path::SegmentKind::ArcCw);
}

TEST(PatternsPlans, ArcSweepIsSplitIntoQuarters)
{
    Pattern p = of(PatternShape::Arc);
    p.arc.sweepDeg = 200;
    const auto path = plan(p);
    ASSERT_EQ(path.size(), 3u);
    EXPECT_NEAR(motion::path::pathLengthMm(path), 10 * 200 * kPi / 180, 1e-9);
}

TEST(PatternsPlans, RectangleRunsItsPerimeterEitherWay)
{
    Pattern p = of(PatternShape::Rectangle);
    auto ccw = plan(p);
    ASSERT_EQ(ccw.size(), 4u);
    EXPECT_NEAR(motion::path::pathLengthMm(ccw), 2 * (40 + 30), 1e-12);
    EXPECT_GT(ccw[0].end.x, ccw[0].start.x);  // ccw leaves the lower-left corner along +X
    p.rectangle.clockwise = true;
    auto cw = plan(p);
    EXPECT_GT(cw[0].end.y, cw[0].start.y);    // cw leaves it along +Y
}

TEST(PatternsPlans, SineAndCosineAreSeed002sChordsWithinTolerance)
{
    for (PatternShape s : {PatternShape::Sine, PatternShape::Cosine}) {
        Pattern p = of(s);
        p.wave.originMm = {0, 0};
        const auto path = plan(p);
        ASSERT_GT(path.size(), 50u);
        // Equal-x chords (seed 002: equal angle parts), every vertex on the curve, every chord
        // within the tolerance of it.
        const double k = 2 * kPi / p.wave.wavelengthMm;
        auto f = [&](double x) { return p.wave.amplitudeMm * (s == PatternShape::Cosine ? std::cos(k * x) : std::sin(k * x)); };
        std::vector<motion::PointMm> mids;
        for (const auto& seg : path) {
            EXPECT_NEAR(seg.end.y, f(seg.end.x), 1e-9);
            EXPECT_NEAR(seg.end.x - seg.start.x, path[0].end.x - path[0].start.x, 1e-9);
            mids.push_back({(seg.start.x + seg.end.x) / 2, (seg.start.y + seg.end.y) / 2});
        }
        EXPECT_LE(motion::maxDistanceToGraphMm(mids, f, 0.5), p.wave.toleranceMm + 1e-9);
        EXPECT_LT(maxDeflectionDeg(path), 10);  // shallow junctions: run without stopping
    }
}

TEST(PatternsPlans, WaveIsTurnedAndPlacedByItsFrame)
{
    Pattern p = of(PatternShape::Sine);
    p.wave.originMm = {10, 20};
    p.wave.angleDeg = 90;
    const auto path = plan(p);
    EXPECT_NEAR(path.front().start.x, 10, 1e-12);
    EXPECT_NEAR(path.front().start.y, 20, 1e-12);
    EXPECT_NEAR(path.back().end.y, 20 + p.wave.lengthMm, 1e-9);  // the wave's axis runs along +Y
}

TEST(PatternsPlans, SpiralGrowsByItsPitchPerTurnWithoutCorners)
{
    Pattern p = of(PatternShape::Spiral);
    const auto path = plan(p);
    ASSERT_EQ(path.size(), 8u * 2);  // 4 turns = 8 half circles, each two quarter pieces
    EXPECT_LT(maxDeflectionDeg(path), 1e-6);
    // After each whole turn the spiral is back on its start ray, one pitch further out.
    for (int turn = 1; turn <= 4; ++turn) {
        const auto& end = path[static_cast<std::size_t>(turn * 4 - 1)].end;
        EXPECT_NEAR(end.x - 50, 1 + 2 * turn, 1e-9) << turn;
        EXPECT_NEAR(end.y, 50, 1e-9) << turn;
    }
    double len = 0;
    for (int k = 0; k < 8; ++k)
        len += kPi * (1 + k * 1.0);  // half circle k has radius r0 + k·pitch/2
    EXPECT_NEAR(motion::path::pathLengthMm(path), len, 1e-9);
}

TEST(PatternsPlans, RasterIsASerpentineCoveringItsRectangle)
{
    Pattern p = of(PatternShape::Raster);
    const auto path = plan(p);
    ASSERT_EQ(path.size(), 11u + 10u);  // 20 mm / 2 mm → 11 passes, 10 steps between
    EXPECT_NEAR(motion::path::pathLengthMm(path), 11 * 40 + 10 * 2, 1e-9);
    const auto b = boundsOf(path);
    EXPECT_NEAR(b.minX, 30, 1e-12);
    EXPECT_NEAR(b.maxX, 70, 1e-12);
    EXPECT_NEAR(b.maxY, 50, 1e-12);
    p.raster.alongY = true;
    const auto y = plan(p);
    EXPECT_EQ(y.size(), 2u * 21 - 1);  // 40 mm / 2 mm → 21 passes along Y
    EXPECT_NEAR(y[0].end.y - y[0].start.y, 20, 1e-12);
}

TEST(PatternsPlans, ValidationReportsEveryProblemByField)
{
    Pattern p = of(PatternShape::Spiral);
    p.feedMmS = 0;
    p.spiral.pitchMm = -1;
    p.spiral.turns = 2.3;
    p.spiral.startRadiusMm = std::nan("");
    const auto problems = validate(p);
    std::vector<std::string> fields;
    for (const auto& q : problems)
        fields.push_back(q.path);
    EXPECT_EQ(fields, (std::vector<std::string>{"feed_mm_s", "start_radius_mm", "pitch_mm", "turns"}));
    EXPECT_EQ(motion::msg::debugString(problems[2].message), "pattern.not_above{value=-1 mm, min=0 mm}");
    EXPECT_TRUE(plan(p).empty());

    Pattern w = of(PatternShape::Sine);
    w.wave.toleranceMm = 1e-5;
    w.wave.lengthMm = 1e6;
    ASSERT_EQ(validate(w).size(), 1u);
    EXPECT_EQ(validate(w)[0].path, "tolerance_mm");

    Pattern l = of(PatternShape::Line);
    l.line.endMm = l.line.startMm;
    ASSERT_EQ(validate(l).size(), 1u);
    EXPECT_EQ(validate(l)[0].path, "end_mm");
}

TEST(PatternsPlans, APatternLeavingTheSoftLimitsNamesTheSegment)
{
    Pattern p = of(PatternShape::Raster);
    p.raster.cornerMm = {70, 30};  // 40 mm wide from x = 70: the first pass ends at 110
    const auto path = plan(p);
    const auto v = outsideLimits(path, {0, 0, 100, 100});
    ASSERT_TRUE(v);
    EXPECT_EQ(v->segment, 0u);
    EXPECT_EQ(v->axis, 0);
    EXPECT_TRUE(v->upper);
    EXPECT_EQ(motion::msg::debugString(v->message),
              "pattern.segment_above_limit{segment=0, kind=term:segment.line, axis=\"X\", value=110 mm, limit=100 mm}");
    // A circle touching nothing with its ends, only with its bulge.
    Pattern c = of(PatternShape::Circle);
    c.circle.centerMm = {50, 3};
    c.circle.startDeg = 90;
    const auto cv = outsideLimits(plan(c), {0, 0, 100, 100});
    ASSERT_TRUE(cv);
    EXPECT_EQ(cv->segment, 1u);  // the second quarter (ccw from the top: left, then down) reaches y = -2
    EXPECT_NEAR(cv->reachesMm, -2, 1e-9);
    EXPECT_FALSE(outsideLimits(plan(of(PatternShape::Circle)), {0, 0, 100, 100}));
}

TEST(PatternsPlans, EstimatedTimeFollowsFeedAndAcceleration)
{
    motion::path::PathLimits lim;
    lim.accelMmS2 = 100;
    // The 10 mm circle at 2 mm/s: 31.4 mm / 2 mm/s plus 0.02 s of ramps, no stops on the way.
    const double t = estimatedTimeS(plan(of(PatternShape::Circle)), lim);
    EXPECT_NEAR(t, 2 * kPi * 5 / 2 + 2.0 / 100, 1e-6);
    // A rectangle's three inner 90° corners cost nearly a stop each (v/a = 0.2 s of extra time
    // per stop at 20 mm/s), on top of the stop-to-stop ramps a circle pays too.
    Pattern r = of(PatternShape::Rectangle);
    r.feedMmS = 20;
    const double tr = estimatedTimeS(plan(r), lim);
    EXPECT_GT(tr, 140.0 / 20 + 0.2 + 3 * 0.15);
    EXPECT_LT(tr, 140.0 / 20 + 0.2 + 3 * 0.2);
}
