// Global placement (imaging/placement.h): a displaced row corrected, a blank tile
// flagged and left at its stage position, a tile never moved beyond the bound, one
// bad pair rejected without spoiling its row.
#include "grid.h"
#include "imaging/placement.h"

#include <gtest/gtest.h>

using imaging::PairStatus;

TEST(Placement, ARowDisplacedByBacklashIsCorrected)
{
    const imagingtest::Texture tex(21);
    imagingtest::Grid g = imagingtest::makeGrid(tex);
    // The stage says row 1 is where it was asked to be; it truly stopped 6 px short
    // (backlash on the return pass), so its stage positions are all 6 px wrong.
    for (int c = 0; c < g.cols; ++c)
        g.truePx[static_cast<std::size_t>(g.index(c, 1))].x() -= 6;
    g = [&] {
        imagingtest::Grid cut = g;
        cut.tiles.clear();
        for (std::size_t i = 0; i < g.truePx.size(); ++i)
            cut.tiles.push_back(imagingtest::cutTile(tex, 300 + g.truePx[i].x(), 200 + g.truePx[i].y(), g.tileW, g.tileH, 40, 77 + static_cast<unsigned>(i)));
        return cut;
    }();
    ASSERT_GT(imagingtest::worstRelativeError(g.stagePx, g.truePx), 6.0);
    std::vector<imaging::TilePair> pairs = imagingtest::registerGrid(g);
    const imaging::Placement p = imaging::placeTiles(g.stagePx, pairs, {});
    EXPECT_LT(imagingtest::rmsRelativeError(p.positionsPx, g.truePx), 0.3);
    EXPECT_LT(imagingtest::worstRelativeError(p.positionsPx, g.truePx), 0.5);
    for (bool byStage : p.placedByStage)
        EXPECT_FALSE(byStage);
    EXPECT_EQ(p.rejectedPairs, 0);
}

TEST(Placement, ABlankTileIsFlaggedAndPlacedByTheStage)
{
    const imagingtest::Texture tex(22);
    imagingtest::Grid g = imagingtest::makeGrid(tex);
    const int blank = g.index(1, 1);
    g.tiles[static_cast<std::size_t>(blank)] = imagingtest::blankTile(g.tileW, g.tileH, 20000, 40, 5);
    std::vector<imaging::TilePair> pairs = imagingtest::registerGrid(g);
    for (const imaging::TilePair& pr : pairs)
        if (pr.a == blank || pr.b == blank) {
            EXPECT_FALSE(pr.reg.accepted()) << pr.a << "-" << pr.b << " ncc " << pr.reg.ncc;
        }
    const imaging::Placement p = imaging::placeTiles(g.stagePx, pairs, {});
    for (std::size_t i = 0; i < p.placedByStage.size(); ++i)
        EXPECT_EQ(p.placedByStage[i], static_cast<int>(i) == blank) << i;
    EXPECT_EQ(p.positionsPx[static_cast<std::size_t>(blank)], g.stagePx[static_cast<std::size_t>(blank)]);
    // The others are placed by registration, to the truth.
    std::vector<Eigen::Vector2d> placed, truth;
    for (std::size_t i = 0; i < p.positionsPx.size(); ++i)
        if (static_cast<int>(i) != blank) {
            placed.push_back(p.positionsPx[i]);
            truth.push_back(g.truePx[i]);
        }
    EXPECT_LT(imagingtest::rmsRelativeError(placed, truth), 0.3);
    EXPECT_LT(imagingtest::worstRelativeError(placed, truth), 0.5);
}

namespace {

imaging::TilePair fakePair(int a, int b, Eigen::Vector2d shift, double ncc = 0.9)
{
    imaging::TilePair p{a, b, {}};
    p.reg.shiftPx = shift;
    p.reg.ncc = ncc;
    p.reg.status = PairStatus::Accepted;
    return p;
}

} // namespace

TEST(Placement, NoTileIsPulledFurtherThanTheBound)
{
    // 3 × 3 at 100 px; the centre tile's four pairs all agree it is 15 px off, as a
    // repetitive pattern one period away would say. The bound is 10 px.
    std::vector<Eigen::Vector2d> stage;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
            stage.emplace_back(100 * c, 100 * r);
    std::vector<imaging::TilePair> pairs;
    const Eigen::Vector2d off(15, 0);
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) {
            const int i = 3 * r + c;
            if (c < 2)
                pairs.push_back(fakePair(i, i + 1, Eigen::Vector2d(100, 0) + (i + 1 == 4 ? off : i == 4 ? -off : Eigen::Vector2d(0, 0))));
            if (r < 2)
                pairs.push_back(fakePair(i, i + 3, Eigen::Vector2d(0, 100) + (i + 3 == 4 ? off : i == 4 ? -off : Eigen::Vector2d(0, 0))));
        }
    imaging::PlacementOptions o;
    o.maxCorrectionPx = 10;
    const imaging::Placement p = imaging::placeTiles(stage, pairs, o);
    for (std::size_t i = 0; i < stage.size(); ++i)
        EXPECT_LE((p.positionsPx[i] - stage[i]).cwiseAbs().maxCoeff(), 10.0) << i;
    EXPECT_TRUE(p.placedByStage[4]);
    EXPECT_EQ(p.positionsPx[4], stage[4]);
    EXPECT_EQ(p.rejectedPairs, 4);
}

TEST(Placement, OneBadPairIsRejectedAndTheRowHolds)
{
    // 3 rows of 5 whose true step is 101 px across and 100 px down; in the middle
    // row, pair 2–3 claims 109 px with a good score. (The stage's 100 px step pulls
    // the answer by a few hundredths: its prior is weak, not absent.)
    std::vector<Eigen::Vector2d> stage;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 5; ++c)
            stage.emplace_back(100 * c, 100 * r);
    std::vector<imaging::TilePair> pairs;
    std::size_t bad = 0;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 5; ++c) {
            const int i = 5 * r + c;
            if (c < 4) {
                if (r == 1 && c == 2)
                    bad = pairs.size();
                pairs.push_back(fakePair(i, i + 1, {r == 1 && c == 2 ? 109.0 : 101.0, 0.0}));
            }
            if (r < 2)
                pairs.push_back(fakePair(i, i + 5, {0.0, 100.0}));
        }
    const imaging::Placement p = imaging::placeTiles(stage, pairs, {});
    EXPECT_EQ(p.rejectedPairs, 1);
    EXPECT_EQ(pairs[bad].reg.status, PairStatus::Outlier);
    for (int c = 5; c < 9; ++c)
        EXPECT_NEAR(p.positionsPx[static_cast<std::size_t>(c + 1)].x() - p.positionsPx[static_cast<std::size_t>(c)].x(), 101.0, 0.1);
}

namespace {

// A 6 × 4 scan whose grating reads 1.5 % long in x, 1 % short in y and leans 4 mrad:
// the pairs see the true steps, the stage's positions drift from them across the mosaic.
imagingtest::Grid scaledStageGrid(const imagingtest::Texture& tex, Eigen::Matrix2d* stageOfTrue)
{
    imagingtest::Grid g;
    g.cols = 6;
    g.rows = 4;
    *stageOfTrue << 1.015, 0.004, 0.0, 0.99;
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> jitter(-0.3, 0.3);
    for (int r = 0; r < g.rows; ++r)
        for (int c = 0; c < g.cols; ++c) {
            const Eigen::Vector2d truth(c * g.stepX + jitter(rng), r * g.stepY + jitter(rng));
            g.truePx.push_back(truth);
            g.stagePx.push_back(*stageOfTrue * truth);
        }
    for (std::size_t i = 0; i < g.truePx.size(); ++i)
        g.tiles.push_back(imagingtest::cutTile(tex, 300 + g.truePx[i].x(), 200 + g.truePx[i].y(), g.tileW, g.tileH, 40, 500 + static_cast<unsigned>(i)));
    return g;
}

} // namespace

TEST(Placement, AStageScaleErrorIsFittedAndNeitherPullsTheTilesNorTripsTheBound)
{
    const imagingtest::Texture tex(31);
    Eigen::Matrix2d stageOfTrue;
    const imagingtest::Grid g = scaledStageGrid(tex, &stageOfTrue);
    // Across 550 px the drift reaches ±4 px from the centre: more than this bound.
    imaging::PlacementOptions o;
    o.maxCorrectionPx = 3;

    std::vector<imaging::TilePair> pairs = imagingtest::registerGrid(g);
    const imaging::Placement p = imaging::placeTiles(g.stagePx, pairs, o);
    ASSERT_TRUE(p.stageModel.used);
    // The model maps the stage's positions back onto the camera's: M = stageOfTrue⁻¹.
    EXPECT_LT((p.stageModel.m * stageOfTrue - Eigen::Matrix2d::Identity()).cwiseAbs().maxCoeff(), 1e-3) << p.stageModel.m;
    EXPECT_NEAR(p.stageModel.scaleXPpm(), (1 / 1.015 - 1) * 1e6, 1000);
    EXPECT_NEAR(p.stageModel.scaleYPpm(), (1 / 0.99 - 1) * 1e6, 1000);
    EXPECT_EQ(p.rejectedPairs, 0);
    EXPECT_LT(imagingtest::rmsRelativeError(p.positionsPx, g.truePx), 0.3);
    EXPECT_LT(p.rmsBeyondModelPx, 0.5);
    EXPECT_GT(p.rmsCorrectionPx, 2.0);  // against the stage as it read

    // The stage's positions taken as they are: the bound rejects good pairs.
    o.fitStageModel = false;
    std::vector<imaging::TilePair> again = imagingtest::registerGrid(g);
    const imaging::Placement raw = imaging::placeTiles(g.stagePx, again, o);
    EXPECT_FALSE(raw.stageModel.used);
    EXPECT_GT(raw.rejectedPairs, 0);
}

TEST(Placement, AStagesRandomErrorsAreNotMistakenForAStageModel)
{
    const imagingtest::Texture tex(32);
    for (unsigned seed = 1; seed <= 4; ++seed) {
        const imagingtest::Grid g = imagingtest::makeGrid(tex, 40, seed);
        std::vector<imaging::TilePair> pairs = imagingtest::registerGrid(g);
        const imaging::Placement p = imaging::placeTiles(g.stagePx, pairs, {});
        EXPECT_FALSE(p.stageModel.used) << "seed " << seed << ": " << p.stageModel.m;
        EXPECT_LT(imagingtest::rmsRelativeError(p.positionsPx, g.truePx), 0.3) << "seed " << seed;
    }
}
