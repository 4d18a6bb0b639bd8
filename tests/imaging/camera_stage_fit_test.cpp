// The camera–stage fit (imaging/camera_stage_fit.h): known matrices come back as pixel
// sizes, rotation and mirror, with noisy shifts too; steps along one line are refused.
#include "imaging/camera_stage_fit.h"

#include <gtest/gtest.h>

#include <Eigen/LU>

#include <random>

namespace {

std::vector<imaging::CameraStageSample> camFitSamples(const Eigen::Matrix2d& m, double noisePx, unsigned seed)
{
    std::mt19937 rng(seed);
    std::normal_distribution<double> noise(0, noisePx);
    std::vector<imaging::CameraStageSample> out;
    const double stepUm = 65;
    for (int k = 1; k <= 2; ++k)
        for (const Eigen::Vector2d& dir : {Eigen::Vector2d(1, 0), Eigen::Vector2d(-1, 0), Eigen::Vector2d(0, 1), Eigen::Vector2d(0, -1)}) {
            imaging::CameraStageSample s;
            s.stageStepUm = dir * stepUm * k;
            s.imageShiftPx = m.inverse() * s.stageStepUm + Eigen::Vector2d(noise(rng), noise(rng));
            out.push_back(s);
        }
    return out;
}

} // namespace

TEST(CameraStageFit, TheUsualCameraComesBackExactly)
{
    const Eigen::Matrix2d m = imaging::cameraStageMatrix(0.65, 0.65, 0, false);
    const auto f = imaging::fitCameraStage(camFitSamples(m, 0, 1));
    ASSERT_TRUE(f);
    EXPECT_NEAR(f->pixelXUm, 0.65, 1e-9);
    EXPECT_NEAR(f->pixelYUm, 0.65, 1e-9);
    EXPECT_NEAR(f->rotationDeg, 0, 1e-9);
    EXPECT_FALSE(f->imageYAlongPlusY);
    EXPECT_NEAR(f->skewDeg, 0, 1e-9);
    EXPECT_LT(f->residualRmsPx, 1e-9);
}

TEST(CameraStageFit, ARotatedMirroredCameraWithOblongPixelsIsRecovered)
{
    const Eigen::Matrix2d m = imaging::cameraStageMatrix(0.71, 0.69, -2.5, true);
    const auto f = imaging::fitCameraStage(camFitSamples(m, 0, 2));
    ASSERT_TRUE(f);
    EXPECT_NEAR(f->pixelXUm, 0.71, 1e-9);
    EXPECT_NEAR(f->pixelYUm, 0.69, 1e-9);
    EXPECT_NEAR(f->rotationDeg, -2.5, 1e-9);
    EXPECT_TRUE(f->imageYAlongPlusY);
    EXPECT_TRUE(f->stageUmPerPx.isApprox(m, 1e-12));
}

TEST(CameraStageFit, ACameraTurnedAQuarterIsNotMistakenForAMirror)
{
    const auto f = imaging::fitCameraStage(camFitSamples(imaging::cameraStageMatrix(1.3, 1.3, 90, false), 0, 3));
    ASSERT_TRUE(f);
    EXPECT_NEAR(f->rotationDeg, 90, 1e-9);
    EXPECT_FALSE(f->imageYAlongPlusY);
    const auto g = imaging::fitCameraStage(camFitSamples(imaging::cameraStageMatrix(1.3, 1.3, 180, true), 0, 3));
    ASSERT_TRUE(g);
    EXPECT_NEAR(std::fabs(g->rotationDeg), 180, 1e-9);
    EXPECT_TRUE(g->imageYAlongPlusY);
}

TEST(CameraStageFit, NoisyShiftsGiveTheGeometryWithinTheirNoise)
{
    const Eigen::Matrix2d m = imaging::cameraStageMatrix(0.65, 0.65, 1.2, false);
    // 0.1 px of registration noise on 100–200 px shifts.
    const auto f = imaging::fitCameraStage(camFitSamples(m, 0.1, 4));
    ASSERT_TRUE(f);
    EXPECT_NEAR(f->pixelXUm, 0.65, 0.65 * 0.002);
    EXPECT_NEAR(f->pixelYUm, 0.65, 0.65 * 0.002);
    EXPECT_NEAR(f->rotationDeg, 1.2, 0.1);
    EXPECT_FALSE(f->imageYAlongPlusY);
    // The residual says how noisy the shifts were.
    EXPECT_GT(f->residualRmsPx, 0.03);
    EXPECT_LT(f->residualRmsPx, 0.3);
}

TEST(CameraStageFit, StepsAlongOneLineAreRefused)
{
    std::vector<imaging::CameraStageSample> s(3);
    for (int i = 0; i < 3; ++i) {
        s[static_cast<std::size_t>(i)].stageStepUm = {10.0 * (i + 1), 0};
        s[static_cast<std::size_t>(i)].imageShiftPx = {15.0 * (i + 1), 0};
    }
    EXPECT_FALSE(imaging::fitCameraStage(s));
    EXPECT_FALSE(imaging::fitCameraStage({}));
}

TEST(CameraStageFit, AnglesWrapIntoOneTurn)
{
    EXPECT_DOUBLE_EQ(imaging::wrapDegrees(190), -170);
    EXPECT_DOUBLE_EQ(imaging::wrapDegrees(-180), 180);
    EXPECT_DOUBLE_EQ(imaging::wrapDegrees(720.5), 0.5);
}
