// A grid map read both ways: the reverse pass visits the nodes in reverse order from
// +X +Y, the map and its figures are of the mean of the two directions (as ISO 230-2
// takes the mean bidirectional position), each node gets its reversal (forward −
// reverse), and the mean reversal along X and Y is the axes' lost motion, b = −B̄.
#include "motion/metrology/grid/compensation_table_2d.h"
#include "motion/metrology/grid/grid_map.h"
#include "motion/metrology/grid/grid_map_test.h"
#include "motion/metrology/grid/stage_errors.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace motion::metrology;

namespace {

/// 7 × 7 nodes every 10 mm; the stage's errors both ways, plus a reversal of X that
/// grows along X (a screw winding up more the farther it drives: −1 µm at 0, −2.2 µm
/// at 60 mm), split evenly between the directions.
GridMapInput bothWays(const StageErrors& s)
{
    GridMapInput in;
    for (int k = 0; k < 7; ++k) {
        in.xMm.push_back(10.0 * k);
        in.yMm.push_back(10.0 * k);
    }
    for (double y : in.yMm)
        for (double x : in.xMm) {
            const double windUpUm = -0.02 * x;
            const auto up = stageErrorUm(s, x, y, Direction::Up, Direction::Up);
            const auto down = stageErrorUm(s, x, y, Direction::Down, Direction::Down);
            in.exUm.push_back(up.xUm + 0.5 * windUpUm);
            in.eyUm.push_back(up.yUm);
            in.reverseExUm.push_back(down.xUm - 0.5 * windUpUm);
            in.reverseEyUm.push_back(down.yUm);
        }
    return in;
}

StageErrors stageWithBacklash()
{
    StageErrors s;
    s.x.pitchPolyUm = {0, 0.4};
    s.y.pitchPolyUm = {0, -0.2};
    s.squarenessUrad = 25;
    s.backlashXUm = 1.0;
    s.backlashYUm = 1.5;
    return s;
}

} // namespace

TEST(GridMapReversal, TheMapIsTheMeanOfBothDirectionsAndTheMeanReversalIsTheBacklash)
{
    const StageErrors s = stageWithBacklash();
    const auto r = analyseGridMap(bothWays(s));
    ASSERT_TRUE(r);
    // The wind-up moves the forward pass's slope along X by −10 ppm and the reverse's by
    // +10: their mean keeps the stage's own 400 ppm.
    EXPECT_NEAR(r->figures.scaleXPpm, 400, 1e-6);
    EXPECT_NEAR(r->figures.scaleYPpm, -200, 1e-6);
    EXPECT_NEAR(r->figures.squarenessUrad, 25, 1e-6);
    ASSERT_TRUE(r->figures.meanReversalXUm && r->figures.meanReversalYUm && r->figures.maxReversalUm);
    // B̄ = x̄↑ − x̄↓: arriving from below stops short by b/2, from above long by b/2.
    EXPECT_NEAR(*r->figures.meanReversalXUm, -1.0 - 0.02 * 30, 1e-9);
    EXPECT_NEAR(*r->figures.meanReversalYUm, -1.5, 1e-9);
    EXPECT_NEAR(*r->figures.maxReversalUm, std::hypot(1.0 + 0.02 * 60, 1.5), 1e-9);
    for (const auto& n : r->nodes) {
        ASSERT_TRUE(n.bidirectional());
        ASSERT_TRUE(n.forwardExUm && n.forwardEyUm && n.reverseExUm && n.reverseEyUm);
        EXPECT_NEAR(*n.reversalXUm, -1.0 - 0.02 * n.xMm, 1e-9);
        EXPECT_NEAR(*n.reversalXUm, *n.forwardExUm - *n.reverseExUm, 1e-12);
        EXPECT_NEAR(n.exUm, 0.5 * (*n.forwardExUm + *n.reverseExUm), 1e-12) << "the map is the mean";
        EXPECT_NEAR(n.reversalUm(), std::hypot(*n.reversalXUm, *n.reversalYUm), 1e-12);
    }
    // A one-way map has none of it.
    GridMapInput oneWay = bothWays(s);
    oneWay.reverseExUm.clear();
    oneWay.reverseEyUm.clear();
    const auto f = analyseGridMap(oneWay);
    ASSERT_TRUE(f);
    EXPECT_FALSE(f->figures.meanReversalXUm);
    EXPECT_FALSE(f->nodes.front().bidirectional());
    EXPECT_EQ(f->nodes.front().reversalUm(), 0.0);
    EXPECT_NEAR(f->figures.scaleXPpm, 390, 1e-6) << "forward only, the wind-up is in the scale";
}

TEST(GridMapReversal, TheTableFromABidirectionalMapCorrectsTheMeanOfBothDirections)
{
    const GridMapInput in = bothWays(stageWithBacklash());
    const auto both = analyseGridMap(in);
    ASSERT_TRUE(both);
    GridMapInput mean = in;
    for (std::size_t k = 0; k < mean.exUm.size(); ++k) {
        mean.exUm[k] = 0.5 * (in.exUm[k] + in.reverseExUm[k]);
        mean.eyUm[k] = 0.5 * (in.eyUm[k] + in.reverseEyUm[k]);
    }
    mean.reverseExUm.clear();
    mean.reverseEyUm.clear();
    const auto a = compensationFromMap(*both);
    const auto b = compensationFromMap(*analyseGridMap(mean));
    ASSERT_TRUE(a && b);
    ASSERT_EQ(a->correctionXUm.size(), b->correctionXUm.size());
    for (std::size_t k = 0; k < a->correctionXUm.size(); ++k) {
        EXPECT_NEAR(a->correctionXUm[k], b->correctionXUm[k], 1e-9);
        EXPECT_NEAR(a->correctionYUm[k], b->correctionYUm[k], 1e-9);
    }
}

TEST(GridMapReversal, TheReversePassReadsEveryNodeAgainBackwardsFromAbove)
{
    GridMapTest t;
    t.columns = 3;
    t.rows = 3;
    t.pitchXMm = t.pitchYMm = 5;
    t.bidirectional = true;
    const auto plan = planGridMap(t, 10, 20);
    ASSERT_EQ(plan.size(), 18u);
    // Forward: row by row along +X, each row led in from below.
    EXPECT_FALSE(plan[0].reverse);
    EXPECT_TRUE(plan[0].leadIn);
    EXPECT_EQ(plan[0].approachSide(), -1.0);
    EXPECT_EQ(plan[8].node(3), 8);
    // Reverse: from the last node back, along −X, each row led in from above.
    for (std::size_t k = 9; k < 18; ++k) {
        EXPECT_TRUE(plan[k].reverse);
        EXPECT_EQ(plan[k].node(3), static_cast<int>(17 - k));
        EXPECT_EQ(plan[k].leadIn, plan[k].column == 2) << k;
        EXPECT_EQ(plan[k].approachSide(), 1.0);
    }
    EXPECT_NEAR(plan[9].xMm, 20, 1e-12);
    EXPECT_NEAR(plan[9].yMm, 30, 1e-12);
    t.bidirectional = false;
    EXPECT_EQ(planGridMap(t, 10, 20).size(), 9u);
}

TEST(GridMapReversal, TheReversePassesLeadInAboveTheLastNodeMustBeInTheTravel)
{
    GridMapTest t;
    t.columns = t.rows = 3;
    t.pitchXMm = t.pitchYMm = 10;
    t.approachMm = 0.05;
    // The last node at 100 mm, the end of the travel: one way it fits.
    EXPECT_TRUE(validateTravel(t, 80, 0.1, 0, 100, 0, 100).empty());
    t.bidirectional = true;
    const auto p = validateTravel(t, 80, 0.1, 0, 100, 0, 100);
    ASSERT_EQ(p.size(), 1u) << motion::msg::debugFormat(p);
    EXPECT_EQ(p[0].message.id, "grid.leaves_travel");
    EXPECT_EQ(p[0].path, "nodes.columns");
    EXPECT_NEAR(p[0].message.number("end"), 100.05, 1e-9);
}
