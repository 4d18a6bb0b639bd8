// Quadrature decoding (seed 003 handle encoder, seed 002 grating ×4).
#include "motion/quadrature.h"

#include <gtest/gtest.h>

#include <random>

using namespace motion;

namespace {
// AB states in the order A leading B (the seed's clockwise) passes them: 00, 10, 11, 01.
constexpr bool kA[4] = {false, true, true, false};
constexpr bool kB[4] = {false, false, true, true};

void run(QuadratureDecoder& d, int cycles, bool forward)
{
    for (int c = 0; c < cycles; ++c)
        for (int i = 1; i <= 4; ++i) {
            const int k = forward ? i % 4 : 4 - i;  // forward 10 11 01 00, backward 01 11 10 00
            d.update(kA[k], kB[k]);
        }
}
}  // namespace

TEST(Quadrature, CountsPerCycleInEachMode)
{
    for (auto [mode, perCycle] : {std::pair{QuadratureMode::X1, 1}, std::pair{QuadratureMode::X2, 2},
                                  std::pair{QuadratureMode::X4, 4}}) {
        QuadratureDecoder d(mode);
        run(d, 10, true);
        EXPECT_EQ(d.count(), 10 * perCycle);
        EXPECT_EQ(d.direction(), +1);  // A leads B
        run(d, 3, false);
        EXPECT_EQ(d.count(), 7 * perCycle);
        EXPECT_EQ(d.direction(), -1);
        EXPECT_EQ(d.illegalTransitions(), 0u);
    }
}

TEST(Quadrature, DitherOnOneEdgeDoesNotDrift)
{
    // Vibration on A while B is low: 00 ↔ 10 forever must not walk the count away in any mode.
    for (auto mode : {QuadratureMode::X1, QuadratureMode::X2, QuadratureMode::X4}) {
        QuadratureDecoder d(mode);
        for (int i = 0; i < 1001; ++i)
            d.update(i % 2 == 0, false);
        EXPECT_EQ(d.count(), 1);  // ended on 10: one edge forward of 00 in every mode
        d.update(false, false);
        EXPECT_EQ(d.count(), 0);
    }
}

TEST(Quadrature, BothLinesChangingIsIllegalAndNotCounted)
{
    QuadratureDecoder d(QuadratureMode::X4);
    d.update(true, false);  // +1
    d.update(false, true);  // 10 → 01: skipped a state
    EXPECT_EQ(d.count(), 1);
    EXPECT_EQ(d.illegalTransitions(), 1u);
    d.update(false, true);  // no change
    EXPECT_EQ(d.illegalTransitions(), 1u);
}

TEST(Quadrature, PropertyRandomWalkMatchesPositionInX4AndX1)
{
    std::mt19937_64 rng(303);
    QuadratureDecoder x4(QuadratureMode::X4), x2(QuadratureMode::X2), x1(QuadratureMode::X1);
    long position = 0;  // in quarter cycles
    for (int i = 0; i < 100000; ++i) {
        position += (rng() % 2) ? 1 : -1;
        const int k = static_cast<int>(((position % 4) + 4) % 4);
        x4.update(kA[k], kB[k]);
        x2.update(kA[k], kB[k]);
        x1.update(kA[k], kB[k]);
        ASSERT_EQ(x4.count(), position);
        // ×1 counts the 00↔10 edge (positions 4k ↔ 4k+1): floor((position + 3) / 4).
        const long num = position + 3;
        const long expectedX1 = num >= 0 ? num / 4 : -((-num + 3) / 4);
        ASSERT_EQ(x1.count(), expectedX1) << position;
        ASSERT_LE(std::abs(x2.count() * 2 - position), 2);
    }
}
