// Seed 002 point-by-point interpolation: lines in all octants, arcs across quadrants.
#include "motion/interpolation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace motion;

namespace {

double distanceToLine(const GridPoint& p, double xe, double ye)
{
    return std::fabs(p.x * ye - p.y * xe) / std::hypot(xe, ye);
}

void expectUnitSteps(const std::vector<GridPoint>& pts)
{
    for (std::size_t i = 1; i < pts.size(); ++i)
        ASSERT_EQ(std::llabs(pts[i].x - pts[i - 1].x) + std::llabs(pts[i].y - pts[i - 1].y), 1) << "step " << i;
}

}  // namespace

TEST(LineInterpolation, TextbookExampleFirstQuadrant)
{
    // (0,0) → (5,3), F = 5y - 3x: 0 → x, -3 → y, 2 → x, -1 → y, 4 → x, 1 → x, -2 → y, 3 → x.
    const auto pts = interpolateLinePoints(5, 3);
    const std::vector<GridPoint> expected = {{0, 0}, {1, 0}, {1, 1}, {2, 1}, {2, 2}, {3, 2}, {4, 2}, {4, 3}, {5, 3}};
    EXPECT_EQ(pts, expected);
}

TEST(LineInterpolation, AxisAlignedLinesStayOnTheAxis)
{
    for (auto [xe, ye] : {std::pair{0, 7}, std::pair{0, -7}, std::pair{9, 0}, std::pair{-9, 0}}) {
        const auto pts = interpolateLinePoints(xe, ye);
        ASSERT_EQ(pts.size(), static_cast<std::size_t>(std::abs(xe) + std::abs(ye) + 1));
        for (const auto& p : pts)
            EXPECT_EQ(distanceToLine(p, xe, ye), 0.0) << xe << "," << ye;
        EXPECT_EQ(pts.back(), (GridPoint{xe, ye}));
    }
    EXPECT_EQ(interpolateLinePoints(0, 0).size(), 1u);
}

TEST(LineInterpolation, PropertyEveryOctantEveryStepWithinOneStep)
{
    std::mt19937_64 rng(2002);
    std::uniform_int_distribution<int> coord(-3000, 3000);
    std::vector<std::uint8_t> codes;
    for (int trial = 0; trial < 5000; ++trial) {
        const int xe = trial < 8 ? (trial & 1 ? -1 : 1) * (3 + trial) : coord(rng);
        const int ye = trial < 8 ? (trial & 2 ? -1 : 1) * (7 - trial % 4) : coord(rng);
        const auto pts = interpolateLinePoints(xe, ye);
        ASSERT_EQ(pts.size(), static_cast<std::size_t>(std::abs(xe) + std::abs(ye) + 1));
        ASSERT_EQ(pts.back(), (GridPoint{xe, ye}));
        expectUnitSteps(pts);
        if (xe != 0 || ye != 0) {
            for (const auto& p : pts)
                ASSERT_LE(distanceToLine(p, xe, ye), 1.0) << xe << "," << ye;
        }
        // The branch-free code loop produces the same path.
        codes.assign(pts.size(), 0);
        const auto n = interpolateLineCodes(xe, ye, codes.data());
        ASSERT_EQ(n + 1, static_cast<std::int64_t>(pts.size()));
        GridPoint at;
        for (std::int64_t i = 0; i < n; ++i) {
            const int sign = codes[i] & 2 ? -1 : 1;
            (codes[i] & 1 ? at.y : at.x) += sign;
            ASSERT_EQ(at, pts[static_cast<std::size_t>(i + 1)]);
        }
    }
}

TEST(ArcInterpolation, QuarterCircleCcwFromXAxis)
{
    const auto pts = interpolateArcPoints({5, 0}, {0, 5}, true);
    ASSERT_TRUE(pts);
    EXPECT_EQ(pts->front(), (GridPoint{5, 0}));
    EXPECT_EQ(pts->back(), (GridPoint{0, 5}));
    expectUnitSteps(*pts);
    EXPECT_EQ(pts->size(), 11u);  // 5 steps in x, 5 in y
    for (const auto& p : *pts) {
        EXPECT_GE(p.x, 0);
        EXPECT_GE(p.y, 0);
    }
}

TEST(ArcInterpolation, FullCircleAndDirections)
{
    const auto ccw = interpolateArcPoints({10, 0}, {10, 0}, true);
    const auto cw = interpolateArcPoints({10, 0}, {10, 0}, false);
    ASSERT_TRUE(ccw && cw);
    EXPECT_EQ(ccw->size(), 81u);  // 4 quadrants × 20 steps
    EXPECT_EQ(cw->size(), 81u);
    EXPECT_GT((*ccw)[3].y, 0);  // CCW goes up first
    EXPECT_LT((*cw)[3].y, 0);   // CW goes down first
    // Half circle CW from (0,10) through (10,0) to (0,-10) crosses two quadrant boundaries.
    const auto half = interpolateArcPoints({0, 10}, {0, -10}, false);
    ASSERT_TRUE(half);
    EXPECT_EQ(half->back(), (GridPoint{0, -10}));
    for (const auto& p : *half)
        EXPECT_GE(p.x, 0);
}

TEST(ArcInterpolation, RejectsEndOffTheCircle)
{
    EXPECT_FALSE(interpolateArcPoints({10, 0}, {0, 12}, true));
    EXPECT_FALSE(interpolateArcPoints({1, 0}, {0, 1}, true));  // radius 1 would pass the centre
}

TEST(ArcInterpolation, PropertyRandomArcsStayWithinOneStepAndSweepTheRightAngle)
{
    std::mt19937_64 rng(3003);
    std::uniform_real_distribution<double> radius(2, 2000), angle(-M_PI, M_PI);
    int tested = 0;
    while (tested < 3000) {
        const double r = radius(rng), a0 = angle(rng), a1 = angle(rng);
        const GridPoint s{std::llround(r * std::cos(a0)), std::llround(r * std::sin(a0))};
        const GridPoint e{std::llround(r * std::cos(a1)), std::llround(r * std::sin(a1))};
        const double rs = std::hypot(double(s.x), double(s.y));
        if (rs < 2 || std::fabs(std::hypot(double(e.x), double(e.y)) - rs) > 0.5 || s == e)
            continue;
        ++tested;
        const bool ccw = tested % 2 == 0;
        const auto pts = interpolateArcPoints(s, e, ccw);
        ASSERT_TRUE(pts) << s.x << "," << s.y << " → " << e.x << "," << e.y;
        ASSERT_EQ(pts->back(), e);
        expectUnitSteps(*pts);
        double swept = 0;
        for (std::size_t i = 0; i < pts->size(); ++i) {
            const auto& p = (*pts)[i];
            ASSERT_LE(std::fabs(std::hypot(double(p.x), double(p.y)) - rs), 1.0)
                << "point " << i << " of arc r=" << rs << (ccw ? " ccw" : " cw");
            if (i > 0) {
                const auto& q = (*pts)[i - 1];
                swept += std::atan2(double(q.x) * p.y - double(q.y) * p.x, double(q.x) * p.x + double(q.y) * p.y);
            }
        }
        double expected = std::atan2(double(e.y), double(e.x)) - std::atan2(double(s.y), double(s.x));
        if (ccw && expected <= 0)
            expected += 2 * M_PI;
        if (!ccw && expected >= 0)
            expected -= 2 * M_PI;
        ASSERT_NEAR(swept, expected, 1e-9 + 2.0 / rs) << (ccw ? "ccw" : "cw");
    }
}
