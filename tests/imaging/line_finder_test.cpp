// The graduation-line finder (imaging/line_finder.h) on synthetic scales rendered at
// known sub-pixel positions, blurred and with noise.
#include "imaging/line_finder.h"
#include "marks.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

using imaging::findLine;
using imaging::LineDirection;
using imaging::LineFinderOptions;
using imagingtest::LineMark;
using imagingtest::renderLines;

namespace {

LineFinderOptions along(LineDirection d)
{
    LineFinderOptions o;
    o.direction = d;
    return o;
}

} // namespace

TEST(LineFinder, FindsTheNearestLineWithinFiveHundredthsOfAPixelRms)
{
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> where(-12, 12);
    std::uniform_real_distribution<double> blur(0.8, 2.5);
    const int w = 256, h = 192;
    double sum2 = 0, worst = 0;
    int n = 0;
    for (int k = 0; k < 40; ++k) {
        const bool vertical = k % 2 == 0;
        const double centre = 0.5 * ((vertical ? w : h) - 1);
        const double truth = where(rng);
        // A scale: the nearest line and its neighbours 40 px away each side.
        const imaging::ImageU16 im = renderLines(w, h, vertical, {{centre + truth - 40}, {centre + truth}, {centre + truth + 40}}, blur(rng), 200, 100 + k);
        const auto found = findLine(im, along(vertical ? LineDirection::Vertical : LineDirection::Horizontal));
        ASSERT_TRUE(found.ok()) << k << ": " << found.error().id;
        const double e = found->offsetPx - truth;
        sum2 += e * e;
        worst = std::max(worst, std::abs(e));
        ++n;
        EXPECT_TRUE(found->dark);
        // The depth of the blurred line at its centre, not the chrome's.
        EXPECT_GT(found->contrast, 0.4);
        EXPECT_LT(found->contrast, 1.0);
    }
    const double rms = std::sqrt(sum2 / n);
    std::printf("line offset error: %.4f px RMS, worst %.4f px over %d images\n", rms, worst, n);
    EXPECT_LE(rms, 0.05);
}

TEST(LineFinder, FindsABrightLineOnADarkField)
{
    const double truth = 3.37;
    const imaging::ImageU16 im = renderLines(160, 120, true, {{79.5 + truth, 3}}, 1.2, 150, 3, true);
    const auto found = findLine(im, along(LineDirection::Vertical));
    ASSERT_TRUE(found.ok()) << found.error().id;
    EXPECT_FALSE(found->dark);
    EXPECT_NEAR(found->offsetPx, truth, 0.05);
}

TEST(LineFinder, BlankGlassIsNotFound)
{
    const imaging::ImageU16 im = renderLines(200, 200, true, {}, 1.0, 200, 9);
    const auto found = findLine(im, along(LineDirection::Vertical));
    ASSERT_FALSE(found.ok());
    EXPECT_EQ(found.error().id, "imaging.line.not_found");
}

TEST(LineFinder, ALineBlurredToNothingIsNotFound)
{
    // In focus the same line is found; 40 px of blur leaves a few per cent of contrast.
    ASSERT_TRUE(findLine(renderLines(256, 128, true, {{130}}, 1.5, 200, 4), along(LineDirection::Vertical)).ok());
    const auto found = findLine(renderLines(256, 128, true, {{130}}, 40, 200, 4), along(LineDirection::Vertical));
    ASSERT_FALSE(found.ok());
    EXPECT_EQ(found.error().id, "imaging.line.not_found");
}

TEST(LineFinder, TwoLinesEquallyNearTheCentreAreAmbiguous)
{
    const double c = 0.5 * (200 - 1);
    const auto found = findLine(renderLines(120, 200, false, {{c - 20.3}, {c + 20.3}}, 1.2, 200, 6), along(LineDirection::Horizontal));
    ASSERT_FALSE(found.ok());
    EXPECT_EQ(found.error().id, "imaging.line.ambiguous");
    // A few pixels off the middle, the nearer one is read.
    const auto near = findLine(renderLines(120, 200, false, {{c - 17.5}, {c + 23.1}}, 1.2, 200, 6), along(LineDirection::Horizontal));
    ASSERT_TRUE(near.ok());
    EXPECT_NEAR(near->offsetPx, -17.5, 0.05);
}

TEST(LineFinder, AnImageTooSmallIsRefused)
{
    const auto found = findLine(imaging::ImageU16(8, 100, 1000), along(LineDirection::Vertical));
    ASSERT_FALSE(found.ok());
    EXPECT_EQ(found.error().id, "imaging.line.image_too_small");
}
