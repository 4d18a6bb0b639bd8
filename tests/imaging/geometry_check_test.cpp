// The plan's camera checked against its images (imaging/geometry_check.h): tiles cut as a
// camera mirrored, turned or of another pixel size would take them, stitched with the
// plan's stage positions, are caught and measured; a right plan is left alone.
#include "grid.h"
#include "imaging/geometry_check.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

namespace {

/// The grid as a camera whose images move by `truth` × the plan's step would take it.
imagingtest::Grid geoCheckGrid(const imagingtest::Texture& tex, const Eigen::Matrix2d& truth)
{
    imagingtest::Grid g = imagingtest::makeGrid(tex);
    g.tiles.clear();
    for (std::size_t i = 0; i < g.stagePx.size(); ++i) {
        g.truePx[i] = truth * g.stagePx[i];
        g.tiles.push_back(imagingtest::cutTile(tex, 600 + g.truePx[i].x(), 600 + g.truePx[i].y(), g.tileW, g.tileH, 40, 500 + static_cast<unsigned>(i)));
    }
    return g;
}

imaging::GeometryCheck geoCheckRun(const imagingtest::Grid& g, const imaging::PlanCameraGeometry& plan)
{
    const auto pairs = imagingtest::registerGrid(g);
    const imaging::GeometryTileLoader load = [&g](int i) { return std::make_shared<const imaging::ImageU16>(g.tiles[static_cast<std::size_t>(i)]); };
    return imaging::checkGeometry(g.stagePx, pairs, g.tileW, g.tileH, plan, load, {});
}

} // namespace

TEST(GeometryCheck, ARightPlanIsLeftAlone)
{
    const imagingtest::Texture tex(31);
    const auto c = geoCheckRun(geoCheckGrid(tex, Eigen::Matrix2d::Identity()), {0.65, 0, false});
    ASSERT_TRUE(c.measured);
    EXPECT_FALSE(c.anythingOff());
    EXPECT_NEAR(c.measuredPixelUm(), 0.65, 0.65 * 0.005);
}

TEST(GeometryCheck, AMirroredCameraIsCaughtAndTheSettingNamed)
{
    const imagingtest::Texture tex(32);
    // Rows run up the image where the plan says down: every vertical pair fails the stitch.
    const auto c = geoCheckRun(geoCheckGrid(tex, Eigen::Vector2d(1, -1).asDiagonal()), {0.65, 0, false});
    ASSERT_TRUE(c.measured);
    EXPECT_TRUE(c.mirrorOff);
    EXPECT_TRUE(c.fit.imageYAlongPlusY);
    EXPECT_FALSE(c.rotationOff);
    EXPECT_FALSE(c.pixelOff);
}

TEST(GeometryCheck, ATurnedCameraIsMeasured)
{
    const imagingtest::Texture tex(33);
    const Eigen::Matrix2d turn = Eigen::Rotation2Dd(3.0 * M_PI / 180).toRotationMatrix();
    const auto c = geoCheckRun(geoCheckGrid(tex, turn), {0.65, 0, false});
    ASSERT_TRUE(c.measured);
    EXPECT_TRUE(c.rotationOff);
    EXPECT_FALSE(c.mirrorOff);
    EXPECT_NEAR(c.fit.rotationDeg, 3.0, 0.3);
}

TEST(GeometryCheck, AnotherPixelSizeIsMeasured)
{
    const imagingtest::Texture tex(34);
    // The images move 5 % further than the plan's pixel says: the true pixel is smaller.
    const auto c = geoCheckRun(geoCheckGrid(tex, Eigen::Matrix2d::Identity() * 1.05), {0.65, 0, false});
    ASSERT_TRUE(c.measured);
    EXPECT_TRUE(c.pixelOff);
    EXPECT_NEAR(c.measuredPixelUm(), 0.65 / 1.05, 0.005);
}
