// Path geometry, look-ahead junction planning, point-by-point walking and the contour measure
// (motion/path/): what the device's path queue and the pattern screen are built on.
#include "motion/numbers.h"
#include "motion/path/contour_tracker.h"
#include "motion/path/grid_walker.h"
#include "motion/path/junction_planner.h"
#include "motion/path/path_geometry.h"
#include "motion/linear_move.h"
#include "motion/ring_buffer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace motion::path;

namespace {
using motion::kPi;

Segment line(Vec2 a, Vec2 b, double feed = 10)
{
    Segment s;
    s.kind = SegmentKind::Line;
    s.start = a;
    s.end = b;
    s.feedMmS = feed;
    return s;
}
Segment arc(Vec2 a, Vec2 b, Vec2 c, bool ccw, double feed = 10)
{
    Segment s;
    s.kind = ccw ? SegmentKind::ArcCcw : SegmentKind::ArcCw;
    s.start = a;
    s.end = b;
    s.center = c;
    s.feedMmS = feed;
    return s;
}
}  // namespace

TEST(PatternsPathGeometry, ArcLengthSweepAndTangents)
{
    const Segment quarter = arc({5, 0}, {0, 5}, {0, 0}, true);
    EXPECT_NEAR(sweepRad(quarter), kPi / 2, 1e-12);
    EXPECT_NEAR(lengthMm(quarter), 5 * kPi / 2, 1e-12);
    EXPECT_NEAR(startTangent(quarter).y, 1.0, 1e-12);   // ccw at (5,0) heads +y
    EXPECT_NEAR(endTangent(quarter).x, -1.0, 1e-12);
    const Segment cw = arc({5, 0}, {0, 5}, {0, 0}, false);  // the long way round
    EXPECT_NEAR(sweepRad(cw), 3 * kPi / 2, 1e-12);
    const Segment full = arc({5, 0}, {5, 0}, {0, 0}, true);
    EXPECT_NEAR(sweepRad(full), 2 * kPi, 1e-12);
    const Vec2 mid = pointAt(quarter, lengthMm(quarter) / 2);
    EXPECT_NEAR(mid.x, 5 / std::sqrt(2.0), 1e-12);
    EXPECT_NEAR(mid.y, 5 / std::sqrt(2.0), 1e-12);
}

TEST(PatternsPathGeometry, BoundingBoxIncludesTheArcsExtremes)
{
    // From (0,5) ccw to (0,-5) around the origin passes (-5, 0): x reaches -5, never +5.
    const Box b = boundingBox(arc({0, 5}, {0, -5}, {0, 0}, true));
    EXPECT_NEAR(b.minX, -5, 1e-12);
    EXPECT_NEAR(b.maxX, 0, 1e-12);
    EXPECT_NEAR(b.minY, -5, 1e-12);
    EXPECT_NEAR(b.maxY, 5, 1e-12);
    const Box f = boundingBox(arc({15, 10}, {15, 10}, {10, 10}, false));
    EXPECT_NEAR(f.minX, 5, 1e-12);
    EXPECT_NEAR(f.maxY, 15, 1e-12);
}

TEST(PatternsPathGeometry, NearestIsSignedLeftOfTravel)
{
    const Segment l = line({0, 0}, {10, 0});
    EXPECT_NEAR(nearestOn(l, {3, 0.2}).distanceMm, 0.2, 1e-12);
    EXPECT_NEAR(nearestOn(l, {3, -0.2}).distanceMm, -0.2, 1e-12);
    EXPECT_NEAR(nearestOn(l, {3, -0.2}).alongMm, 3, 1e-12);
    EXPECT_NEAR(std::fabs(nearestOn(l, {13, 4}).distanceMm), 5, 1e-12);  // beyond the end: to the end point
    const Segment c = arc({5, 0}, {-5, 0}, {0, 0}, true);
    EXPECT_NEAR(nearestOn(c, {0, 4.9}).distanceMm, 0.1, 1e-12);  // inside a ccw circle is left
    const Segment cw = arc({-5, 0}, {5, 0}, {0, 0}, false);
    EXPECT_NEAR(nearestOn(cw, {0, 4.9}).distanceMm, -0.1, 1e-12);
}

TEST(PatternsPathGeometry, LineCrossTrackIsSeed000sTable5Form)
{
    // The line of seed 000 §4.1 (tan θ = 4/3): the contour error of a measured end point against
    // the line equals motion::contourErrorMm, the cross-track form Table 5 uses. Run 1, (30, 40):
    // measured (29.98, 39.95) gives -0.014 mm in the table.
    const Segment l = line({0, 0}, {30, 40});
    const double theta = std::atan2(4.0, 3.0);
    const Nearest n = nearestOn(l, {29.98 - 1e-9, 39.95});
    EXPECT_NEAR(n.distanceMm, motion::contourErrorMm(theta, -0.02, -0.05), 1e-6);
    EXPECT_NEAR(n.distanceMm, -0.014, 0.0005);
}

TEST(PatternsJunctionPlanner, JunctionSpeedFollowsTheDeviationCircle)
{
    const double a = 100, d = 0.01;
    EXPECT_TRUE(std::isinf(junctionSpeedMmS({1, 0}, {1, 0}, a, d)));
    EXPECT_EQ(junctionSpeedMmS({1, 0}, {-1, 0}, a, d), 0.0);
    // 90°: c = cos 45° = 0.7071, R = 0.01·0.7071/0.2929 = 0.02414 mm, v = √(100·R) = 1.554 mm/s.
    EXPECT_NEAR(junctionSpeedMmS({1, 0}, {0, 1}, a, d), 1.5538, 1e-3);
    // 10°: R = 0.01·cos5°/(1 − cos5°) = 2.618 mm, v = 16.18 mm/s.
    const double ten = 10 * kPi / 180;
    EXPECT_NEAR(junctionSpeedMmS({1, 0}, {std::cos(ten), std::sin(ten)}, a, d), 16.18, 0.005);
    // Shallower corners are taken faster.
    double last = 0;
    for (int deg = 170; deg >= 1; deg -= 13) {
        const double r = deg * kPi / 180;
        const double v = junctionSpeedMmS({1, 0}, {std::cos(r), std::sin(r)}, a, d);
        EXPECT_GT(v, last) << deg;
        last = v;
    }
}

TEST(PatternsJunctionPlanner, ShallowChainNeverStopsAndEveryChangeFitsTheAcceleration)
{
    // Twenty 2 mm chords turning 4° each: every junction keeps speed, only the ends are at rest.
    std::vector<Segment> path;
    Vec2 p{0, 0};
    for (int k = 0; k < 20; ++k) {
        const double ang = k * 4.0 * kPi / 180;
        const Vec2 q = p + 2.0 * Vec2{std::cos(ang), std::sin(ang)};
        path.push_back(line(p, q, 20));
        p = q;
    }
    PathLimits lim;
    lim.accelMmS2 = 100;
    const PathEstimate e = estimatePath(path, lim);
    ASSERT_EQ(e.blocks.size(), 20u);
    EXPECT_EQ(e.blocks.front().entryMmS, 0.0);
    EXPECT_EQ(e.blocks.back().exitMmS, 0.0);
    for (std::size_t k = 0; k + 1 < e.blocks.size(); ++k) {
        EXPECT_GT(e.blocks[k].exitMmS, 5.0) << "junction " << k;
        EXPECT_EQ(e.blocks[k].exitMmS, e.blocks[k + 1].entryMmS);
    }
    for (const PlanBlock& b : e.blocks) {
        EXPECT_LE(std::fabs(b.exitMmS * b.exitMmS - b.entryMmS * b.entryMmS), 2 * lim.accelMmS2 * b.lengthMm + 1e-9);
        EXPECT_LE(b.entryMmS, b.nominalMmS + 1e-12);
    }
    // 40 mm at up to 20 mm/s, two 0.2 s ramps: 2 s of cruise plus 0.2 s.
    EXPECT_NEAR(e.durationS, 40.0 / 20 + 20.0 / 100, 0.02);
}

TEST(PatternsJunctionPlanner, StartAndEndStatesAreHonoured)
{
    std::vector<PlanBlock> blocks(3);
    for (auto& b : blocks) {
        b.lengthMm = 1;
        b.nominalMmS = 20;
        b.maxEntryMmS = 1e9;
    }
    planSpeeds(blocks, 100, PathState{8}, PathState{4});
    EXPECT_EQ(blocks[0].entryMmS, 8.0);
    EXPECT_EQ(blocks[2].exitMmS, 4.0);
    planSpeeds(blocks, 100, PathState{0}, PathState{0});
    EXPECT_EQ(blocks[0].entryMmS, 0.0);
    EXPECT_NEAR(blocks[0].exitMmS, std::sqrt(200.0), 1e-9);
    EXPECT_EQ(blocks[2].exitMmS, 0.0);
    // A Z move after block 1 (seed 000's "Z following") brings XY to rest there.
    blocks[1].stopAfter = true;
    planSpeeds(blocks, 100, PathState{0}, PathState{0});
    EXPECT_EQ(blocks[1].exitMmS, 0.0);
    EXPECT_EQ(blocks[2].entryMmS, 0.0);
}

TEST(PatternsJunctionPlanner, ArcsAreCappedByTheirCentripetalLimit)
{
    PathLimits lim;
    lim.accelMmS2 = 100;
    const auto blocks = blocksFor({arc({1, 0}, {-1, 0}, {0, 0}, true, 50)}, lim);
    EXPECT_NEAR(blocks[0].nominalMmS, std::sqrt(0.5 * 100 * 1), 1e-12);
}

TEST(PatternsGridWalker, LineWalkLeadsItsTargetByLessThanAStep)
{
    GridWalker w = GridWalker::line({10, 20}, {10 + 300, 20 - 170});
    const double len = std::hypot(300.0, 170.0);
    for (int k = 1; k <= 100; ++k) {
        const double f = k / 100.0;
        w.advanceTo(f);
        const double px = static_cast<double>(w.position().x - 10), py = static_cast<double>(w.position().y - 20);
        const double along = (px * 300 - py * 170) / len;
        EXPECT_GE(along, f * len - 1e-9) << k;
        EXPECT_LE(along, f * len + 1.0 + 1e-9) << k;
        EXPECT_LE(std::fabs(px * -170 - py * 300) / len, 1.0) << k;  // within a step of the line
    }
    EXPECT_TRUE(w.done());
    EXPECT_EQ(w.position(), (motion::GridPoint{310, -150}));
}

TEST(PatternsGridWalker, ArcWalkStaysOnTheCircleAndEndsExactlyWhereAsked)
{
    std::mt19937 rng(9);
    std::uniform_int_distribution<int> r(20, 4000);
    std::uniform_real_distribution<double> ang(0, 2 * kPi);
    for (int trial = 0; trial < 300; ++trial) {
        const int radius = r(rng);
        const double a0 = ang(rng), a1 = ang(rng);
        const motion::GridPoint c{1000, -2000};
        const motion::GridPoint from{c.x + std::llround(radius * std::cos(a0)), c.y + std::llround(radius * std::sin(a0))};
        const motion::GridPoint to{c.x + std::llround(radius * std::cos(a1)), c.y + std::llround(radius * std::sin(a1))};
        const bool ccw = trial % 2 == 0;
        auto w = GridWalker::arc(from, to, c, ccw);
        ASSERT_TRUE(w) << trial;
        const double r0 = std::hypot(double(from.x - c.x), double(from.y - c.y));
        for (int k = 1; k <= 50 && !w->done(); ++k) {
            w->advanceTo(k / 50.0);
            const double rr = std::hypot(double(w->position().x - c.x), double(w->position().y - c.y));
            EXPECT_LE(std::fabs(rr - r0), 2.0) << trial;  // on the circle, or finishing onto the end
        }
        EXPECT_TRUE(w->done()) << trial;
        EXPECT_EQ(w->position(), to) << trial;
    }
}

TEST(PatternsGridWalker, ArcProgressIsUniformInAngleNotInSteps)
{
    // Half the sweep of a quarter circle is 45°, however many steps the walk needed to get there.
    auto w = GridWalker::arc({1000, 0}, {0, 1000}, {0, 0}, true);
    ASSERT_TRUE(w);
    w->advanceTo(0.5);
    const double a = std::atan2(double(w->position().y), double(w->position().x));
    EXPECT_NEAR(a, kPi / 4, 1.5 / 1000);
    EXPECT_FALSE(GridWalker::arc({1000, 0}, {0, 1010}, {0, 0}, true));  // 10 steps off the circle
    EXPECT_FALSE(GridWalker::arc({1, 0}, {0, 1}, {0, 0}, true));        // radius under 2 steps
}

TEST(PatternsGridWalker, FullCircleComesBackToItsStart)
{
    auto w = GridWalker::arc({500, 0}, {500, 0}, {0, 0}, false);
    ASSERT_TRUE(w);
    w->advanceTo(0.75);
    EXPECT_NEAR(double(w->position().x), 0, 2);  // three quarters clockwise from (500,0): (0, 500)
    EXPECT_NEAR(double(w->position().y), 500, 2);
    EXPECT_NEAR(w->progress(), 0.75, 0.01);
    w->advanceTo(1.0);
    EXPECT_EQ(w->position(), (motion::GridPoint{500, 0}));
    EXPECT_GT(w->stepsTaken(), 3900);  // about 8·R
}

TEST(PatternsContourTracker, JudgesAgainstThePathNotTheLastLine)
{
    // An L-shaped path; a point that lags at the corner is judged against the first leg.
    const std::vector<Segment> path = {line({0, 0}, {10, 0}), line({10, 0}, {10, 10})};
    ContourTracker t(path);
    EXPECT_NEAR(t.add({5, 0.002}).errorMm, 0.002, 1e-12);
    const ContourSample s = t.add({9.999, -0.001});
    EXPECT_EQ(s.segment, 0u);
    EXPECT_NEAR(s.errorMm, -0.001, 1e-12);
    const ContourSample u = t.add({10.003, 4});
    EXPECT_EQ(u.segment, 1u);
    EXPECT_NEAR(u.errorMm, -0.003, 1e-12);  // right of travel going +y
    EXPECT_NEAR(u.pathMm, 14, 1e-12);
    EXPECT_NEAR(t.summary().maxAbsMm, 0.003, 1e-12);
    EXPECT_NEAR(t.summary().rmsMm, std::sqrt((4e-6 + 1e-6 + 9e-6) / 3), 1e-12);
}

TEST(PatternsContourTracker, ARasterIsNeverJudgedAgainstALaterPass)
{
    // Serpentine lines 0.1 mm apart: a point 0.06 mm off its own line is nearer the next pass,
    // but the tracker only looks a little way ahead of where the walk is.
    const std::vector<Segment> path = {line({0, 0}, {10, 0}), line({10, 0}, {10, 0.1}), line({10, 0.1}, {0, 0.1})};
    ContourTracker t(path, 0);
    t.add({1, 0});
    const ContourSample s = t.add({2, 0.06});
    EXPECT_EQ(s.segment, 0u);
    EXPECT_NEAR(s.errorMm, 0.06, 1e-12);
    EXPECT_NEAR(t.add({8, 0.06}).errorMm, 0.06, 1e-12);   // the turn is in reach now, the pass back is not
    EXPECT_EQ(t.add({10.003, 0.05}).segment, 1u);
    EXPECT_EQ(t.add({5, 0.1}).segment, 2u);
}

TEST(PatternsContourTracker, LeadInIsTrackedButNotCounted)
{
    const std::vector<Segment> path = {line({0, 0}, {5, 0}), line({5, 0}, {5, 5})};
    ContourTracker t(path, 1);
    t.add({2, 0.5});  // a big miss on the lead-in
    t.add({5.001, 2});
    EXPECT_EQ(t.summary().samples, 1u);
    EXPECT_NEAR(t.summary().maxAbsMm, 0.001, 1e-12);
}

TEST(PatternsRingBuffer, PeekSeesWhatIsQueuedOldestFirst)
{
    motion::RingBuffer<int, 5> rb;
    EXPECT_EQ(rb.peek(0), nullptr);
    for (int i = 1; i <= 4; ++i)
        ASSERT_TRUE(rb.tryPush(i));
    rb.tryPop();
    ASSERT_TRUE(rb.tryPush(5));  // wrapped
    for (int i = 0; i < 4; ++i)
        EXPECT_EQ(*rb.peek(static_cast<std::size_t>(i)), i + 2);
    EXPECT_EQ(rb.peek(4), nullptr);
    rb.clear();
    EXPECT_TRUE(rb.empty());
    EXPECT_TRUE(rb.tryPush(7));
    EXPECT_EQ(*rb.peek(0), 7);
}
