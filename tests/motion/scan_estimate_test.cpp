// The scan's time estimate: each move timed as the stage's firmware plans it, plus
// settle and exposure per tile.
#include "motion/jerk_limited.h"
#include "motion/plans/scan/scan_estimate.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace motion::scan;

TEST(ScanEstimate, AMoveTakesTheFirmwaresJerkLimitedTime)
{
    const StageModel stage;
    // Along X only: the path limits are the axis' own, the speed the requested one.
    const auto alongX = motion::JerkLimitedProfile::plan(30, {10, 200, 4000});
    ASSERT_TRUE(alongX);
    EXPECT_NEAR(moveTimeS({10, 10}, {40, 10}, 10, stage), alongX->duration(), 1e-12);
    // 3-4-5 diagonal: each axis limits the path to its limit over its share; the
    // requested 15 mm/s is below 20/0.8 = 25 mm/s, the acceleration 200/0.8 = 250.
    const auto diagonal = motion::JerkLimitedProfile::plan(50, {15, 250, 5000});
    ASSERT_TRUE(diagonal);
    EXPECT_NEAR(moveTimeS({0, 0}, {30, 40}, 15, stage), diagonal->duration(), 1e-12);
    // A request above an axis' top speed over its share is capped: 20/0.8 = 25 mm/s.
    const auto capped = motion::JerkLimitedProfile::plan(50, {25, 250, 5000});
    EXPECT_NEAR(moveTimeS({0, 0}, {30, 40}, 40, stage), capped->duration(), 1e-12);
    EXPECT_EQ(moveTimeS({5, 5}, {5, 5}, 10, stage), 0.0);
}

TEST(ScanEstimate, TotalIsMovesPlusSettleAndExposurePerTile)
{
    ScanPlan p;
    p.camera.source = FieldSource::Direct;
    p.camera.fieldWidthMm = p.camera.fieldHeightMm = 1;
    p.region.cornerA = {20, 20};
    p.region.cornerB = {25.5, 24.6};  // 6 × 5 tiles at 0.9 mm
    p.settleS = 0.08;
    p.exposureS = 0.02;
    const StageModel stage;
    const ScanLayout l = layoutScan(p);
    ASSERT_EQ(l.tiles.size(), 30u);
    const ScanEstimate e = estimateScan(p, l, stage);
    double moves = 0;
    for (std::size_t k = 1; k < l.path.size(); ++k)
        moves += moveTimeS(l.path[k - 1].target, l.path[k].target, p.speedMmS, stage);
    EXPECT_NEAR(e.moveS, moves, 1e-9);
    EXPECT_NEAR(e.settleS, 30 * 0.08, 1e-12);
    EXPECT_NEAR(e.exposureS, 30 * 0.02, 1e-12);
    EXPECT_NEAR(e.totalS, e.moveS + e.settleS + e.exposureS, 1e-9);
    EXPECT_EQ(e.moves, 29);
    EXPECT_NEAR(e.travelMm, 29 * 0.9, 1e-9);
    ASSERT_EQ(e.tileDoneS.size(), 30u);
    EXPECT_TRUE(std::is_sorted(e.tileDoneS.begin(), e.tileDoneS.end()));
    EXPECT_NEAR(e.tileDoneS.back(), e.totalS, 1e-12);
    EXPECT_NEAR(e.tileDoneS.front(), 0.1, 1e-12) << "the first tile: settle and exposure, no move";
}

TEST(ScanEstimate, OvertravelMovesAreTimedToo)
{
    ScanPlan p;
    p.order = ScanOrder::Rows;
    const StageModel stage;
    const ScanEstimate direct = estimateScan(p, layoutScan(p), stage);
    p.approach.unidirectional = true;
    const ScanLayout l = layoutScan(p);
    const ScanEstimate uni = estimateScan(p, l, stage);
    EXPECT_EQ(uni.moves, static_cast<int>(l.path.size()) - 1);
    EXPECT_GT(uni.moves, direct.moves);
    EXPECT_GT(uni.totalS, direct.totalS);
}
