// Pairwise registration (imaging/registration.h) on synthetic tiles cut from a
// textured plane at known subpixel offsets, with noise.
#include "imaging/registration.h"
#include "synthetic.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

using imaging::PairStatus;
using imaging::registerPair;

TEST(Registration, FindsKnownSubpixelOffsetsWithinATenthOfAPixel)
{
    const imagingtest::Texture tex(7);
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> jitter(-6, 6);
    const int w = 192, h = 160;
    double sum2 = 0, worst = 0;
    int n = 0;
    for (int k = 0; k < 24; ++k) {
        // Alternate horizontal and vertical neighbours with ~15 % overlap, the stage
        // wrong by up to 6 px each way.
        const bool horizontal = k % 2 == 0;
        const Eigen::Vector2d expected = horizontal ? Eigen::Vector2d(0.85 * w, 0) : Eigen::Vector2d(0, 0.85 * h);
        const Eigen::Vector2d truth = expected + Eigen::Vector2d(jitter(rng), jitter(rng));
        const double ax = 200 + 37.3 * k, ay = 150 + 21.7 * k;
        const imaging::ImageU16 a = imagingtest::cutTile(tex, ax, ay, w, h, 60, 100 + k);
        const imaging::ImageU16 b = imagingtest::cutTile(tex, ax + truth.x(), ay + truth.y(), w, h, 60, 200 + k);
        const imaging::PairRegistration r = registerPair(a, b, expected, {});
        ASSERT_EQ(r.status, PairStatus::Accepted) << "pair " << k << " ncc " << r.ncc;
        const double err = (r.shiftPx - truth).norm();
        if (err > 0.3) std::printf("pair %d err %.3f truth %.3f %.3f got %.3f %.3f ncc %.3f\n", k, err, truth.x(), truth.y(), r.shiftPx.x(), r.shiftPx.y(), r.ncc);
        sum2 += err * err;
        worst = std::max(worst, err);
        ++n;
    }
    const double rms = std::sqrt(sum2 / n);
    EXPECT_LE(rms, 0.1);
    EXPECT_LE(worst, 0.5);
    std::printf("registration: rms %.3f px, worst %.3f px over %d pairs\n", rms, worst, n);
}

TEST(Registration, ABlankTileIsNotTrusted)
{
    const imagingtest::Texture tex(3);
    const imaging::ImageU16 a = imagingtest::cutTile(tex, 100, 100, 160, 160, 40, 1);
    const imaging::ImageU16 b = imagingtest::blankTile(160, 160, 20000, 40, 2);
    const imaging::PairRegistration r = registerPair(a, b, {136, 0}, {});
    EXPECT_EQ(r.status, PairStatus::LowScore) << r.ncc;
}

TEST(Registration, NeverAnswersBeyondTheBound)
{
    const imagingtest::Texture tex(5);
    const imaging::ImageU16 a = imagingtest::cutTile(tex, 300, 300, 160, 160, 30, 1);
    // Truly 12 px further right than expected, but the stage is trusted to 5 px.
    const imaging::ImageU16 b = imagingtest::cutTile(tex, 300 + 136 + 12, 300, 160, 160, 30, 2);
    imaging::RegistrationOptions o;
    o.maxShiftPx = 5;
    const imaging::PairRegistration r = registerPair(a, b, {136, 0}, o);
    EXPECT_LE(std::abs(r.shiftPx.x() - 136), 5.0);
    EXPECT_EQ(r.status, PairStatus::AtBound);
    o.maxShiftPx = 20;
    const imaging::PairRegistration wide = registerPair(a, b, {136, 0}, o);
    EXPECT_EQ(wide.status, PairStatus::Accepted);
    EXPECT_NEAR(wide.shiftPx.x(), 148, 0.1);
}

TEST(Registration, ARepetitivePatternWithinTheBoundIsAmbiguous)
{
    // Stripes every 8 px: offsets 8 px apart match equally well.
    imaging::ImageU16 a(160, 160), b(160, 160);
    for (int y = 0; y < 160; ++y)
        for (int x = 0; x < 160; ++x) {
            a.at(x, y) = static_cast<std::uint16_t>(1000 + 500 * std::sin(2 * M_PI * x / 8.0) + 3 * ((x * 7 + y * 13) % 5));
            b.at(x, y) = static_cast<std::uint16_t>(1000 + 500 * std::sin(2 * M_PI * (x + 136) / 8.0) + 3 * ((x * 11 + y * 3) % 5));
        }
    const imaging::PairRegistration r = registerPair(a, b, {136, 0}, {});
    EXPECT_EQ(r.status, PairStatus::Ambiguous) << r.ncc << " " << r.secondNcc;
}
