// Seed 002 sine/cosine by chords.
#include "motion/numbers.h"
#include "motion/chords.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace motion;

namespace {
using motion::kPi;
}

TEST(Chords, ChordCountFollowsTheTolerance)
{
    // A = 10 mm, W = 40 mm: max|f''| = 10·(2π/40)² = 0.2467 mm⁻¹; tol 0.01 mm → h = 0.569 mm.
    const auto v = sineChords(10, 40, 40, 0.01);
    const double h = std::sqrt(8 * 0.01 / (10 * std::pow(2 * kPi / 40, 2)));
    EXPECT_EQ(v.size(), static_cast<std::size_t>(std::ceil(40 / h)) + 1);
    EXPECT_DOUBLE_EQ(v.front().x, 0);
    EXPECT_DOUBLE_EQ(v.back().x, 40);
    // Tighter tolerance, more chords: ×4 fewer error needs ×2 more chords.
    EXPECT_NEAR(double(sineChords(10, 40, 40, 0.0025).size() - 1) / double(v.size() - 1), 2.0, 0.05);
}

TEST(Chords, ChordErrorStaysWithinTolerance)
{
    for (bool cosine : {false, true}) {
        for (double tol : {0.1, 0.01, 0.001}) {
            const auto v = sineChords(5, 25, 60, tol, cosine);
            ASSERT_GE(v.size(), 2u);
            const auto f = [&](double x) { return 5 * (cosine ? std::cos(2 * kPi * x / 25) : std::sin(2 * kPi * x / 25)); };
            double worst = 0;
            for (std::size_t i = 1; i < v.size(); ++i)
                for (int k = 1; k < 50; ++k) {
                    const double x = v[i - 1].x + (v[i].x - v[i - 1].x) * k / 50;
                    const double y = v[i - 1].y + (v[i].y - v[i - 1].y) * k / 50;
                    worst = std::max(worst, std::fabs(f(x) - y));
                }
            EXPECT_LE(worst, tol) << tol;
            EXPECT_GT(worst, 0.5 * tol) << "chords no finer than needed";
        }
    }
}

TEST(Chords, SteppedSineStaysWithinToleranceAndOneStep)
{
    const double step = 0.001, tol = 0.005;  // 1 µm steps
    const auto v = sineChords(2, 10, 10, tol);
    const auto grid = interpolatePolyline(v, step);
    ASSERT_FALSE(grid.empty());
    EXPECT_EQ(grid.front(), (GridPoint{0, 0}));
    EXPECT_EQ(grid.back(), (GridPoint{10000, std::llround(2 * std::sin(2 * kPi) / step)}));
    std::vector<PointMm> mm;
    for (const auto& g : grid)
        mm.push_back({g.x * step, g.y * step});
    const auto f = [](double x) { return 2 * std::sin(2 * kPi * x / 10); };
    const double err = maxDistanceToGraphMm(mm, f, 0.05);
    // Chord error + one step from the line interpolation + half a step rounding each vertex.
    EXPECT_LE(err, tol + step * (1 + 0.71));
    EXPECT_GT(err, 0.5 * tol);
}

TEST(Chords, GenericFunctionAndBadInput)
{
    const auto parabola = functionChords([](double x) { return x * x; }, -1, 1, 2.0, 0.01);
    EXPECT_EQ(parabola.size(), static_cast<std::size_t>(std::ceil(2 / std::sqrt(0.04))) + 1);
    EXPECT_TRUE(functionChords([](double x) { return x; }, 0, 1, 0, 0.01).size() == 2);  // a line is one chord
    EXPECT_TRUE(sineChords(1, 0, 10, 0.01).empty());
    EXPECT_TRUE(sineChords(1, 10, 10, 0).empty());
}
