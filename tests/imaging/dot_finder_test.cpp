// The grid-plate dot finder (imaging/dot_finder.h) on synthetic plates rendered at
// known sub-pixel positions, blurred and with noise.
#include "imaging/dot_finder.h"
#include "marks.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

using imaging::findDot;
using imagingtest::DotMark;
using imagingtest::renderDots;

TEST(DotFinder, FindsTheNearestDotCentreWithinFiveHundredthsOfAPixelRms)
{
    std::mt19937 rng(8);
    std::uniform_real_distribution<double> where(-15, 15);
    std::uniform_real_distribution<double> blur(0.8, 2.5);
    std::uniform_real_distribution<double> radius(5, 14);
    const int w = 256, h = 224;
    const double cx = 0.5 * (w - 1), cy = 0.5 * (h - 1);
    double sum2 = 0, worst = 0;
    int n = 0;
    for (int k = 0; k < 30; ++k) {
        const double tx = where(rng), ty = where(rng), r = radius(rng);
        // A plate: the nearest dot and its neighbours at a pitch of 70 px.
        std::vector<DotMark> dots;
        for (int j = -1; j <= 1; ++j)
            for (int i = -1; i <= 1; ++i)
                dots.push_back({cx + tx + 70 * i, cy + ty + 70 * j, r});
        const auto found = findDot(renderDots(w, h, dots, blur(rng), 200, 40 + k));
        ASSERT_TRUE(found.ok()) << k << ": " << found.error().id;
        const double e2 = (found->xPx - tx) * (found->xPx - tx) + (found->yPx - ty) * (found->yPx - ty);
        sum2 += e2;
        worst = std::max(worst, std::sqrt(e2));
        ++n;
        EXPECT_TRUE(found->dark);
        EXPECT_NEAR(found->diameterPx, 2 * r, 0.15 * 2 * r);
    }
    const double rms = std::sqrt(sum2 / n);
    std::printf("dot centre error: %.4f px RMS, worst %.4f px over %d images\n", rms, worst, n);
    EXPECT_LE(rms, 0.05);
}

TEST(DotFinder, BlankGlassIsNotFound)
{
    const auto found = findDot(renderDots(200, 200, {}, 1.0, 200, 2));
    ASSERT_FALSE(found.ok());
    EXPECT_EQ(found.error().id, "imaging.dot.not_found");
}

TEST(DotFinder, ADotBlurredToNothingIsNotFound)
{
    ASSERT_TRUE(findDot(renderDots(200, 200, {{104.2, 97.9, 4}}, 1.0, 200, 3)).ok());
    // The same dot 30 px out of focus keeps about 1 % of its depth.
    const auto found = findDot(imagingtest::defocus(renderDots(200, 200, {{104.2, 97.9, 4}}, 0.5, 0, 3), 30, 200, 3));
    ASSERT_FALSE(found.ok());
    EXPECT_EQ(found.error().id, "imaging.dot.not_found");
}

TEST(DotFinder, TwoDotsEquallyNearTheCentreAreAmbiguous)
{
    const double cx = 99.5, cy = 99.5;
    const auto found = findDot(renderDots(200, 200, {{cx - 25, cy + 3, 8}, {cx + 25, cy - 3, 8}}, 1.2, 200, 5));
    ASSERT_FALSE(found.ok());
    EXPECT_EQ(found.error().id, "imaging.dot.ambiguous");
    const auto near = findDot(renderDots(200, 200, {{cx - 22, cy + 3, 8}, {cx + 28, cy - 3, 8}}, 1.2, 200, 5));
    ASSERT_TRUE(near.ok());
    EXPECT_NEAR(near->xPx, -22, 0.05);
    EXPECT_NEAR(near->yPx, 3, 0.05);
}

TEST(DotFinder, TheNearestDotCutByTheFrameIsRefused)
{
    // The only dot lies half outside the image: its centroid would be wrong.
    const auto found = findDot(renderDots(160, 160, {{3, 80, 10}}, 1.0, 200, 7));
    ASSERT_FALSE(found.ok());
    EXPECT_EQ(found.error().id, "imaging.dot.at_edge");
}
