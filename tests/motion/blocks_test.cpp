// Seed 004 blocks: validation, split at a direction change, the per-block plan, and the
// per-microstep delays (exact square root and the seed's Taylor recurrence).
#include "motion/message_print.h"
#include "motion/blocks.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace motion;

namespace {

/// Steps covered by a planned block: ramp at the mean speed plus cruise.
double coveredSteps(const BlockPlan& p)
{
    const double cruiseSpeed = p.rampFirst ? p.endSpeedStepsS : p.startSpeedStepsS;
    return 0.5 * (p.startSpeedStepsS + p.endSpeedStepsS) * p.rampTimeS + cruiseSpeed * p.cruiseTimeS;
}

BlockPlan planOne(double v1, Block b)
{
    std::vector<Block> blocks;
    if (v1 != 0.0)
        blocks.push_back({static_cast<std::int32_t>(v1), static_cast<std::int16_t>(v1), 1000});  // cruise 1 s at v1
    blocks.push_back(b);
    const auto plan = planJointBlocks(blocks, 30000, 1);
    EXPECT_TRUE(plan) << plan.error();
    return plan ? plan->blocks.back() : BlockPlan{};
}

}  // namespace

TEST(Blocks, EveryShapeOfTheSeed)
{
    // v1 = 1000 → v2 = 2000 in 0.5 s: s0 = 750 steps, reachable 500 … 1000.
    auto p = planOne(1000, {900, 2000, 500});
    EXPECT_EQ(p.shape, BlockShape::AccelThenCruise);
    EXPECT_NEAR(p.rampTimeS, 2 * (2000 * 0.5 - 900) / 1000.0, 1e-12);  // 0.2 s
    EXPECT_NEAR(p.accelStepsS2, 5000, 1e-9);
    EXPECT_NEAR(coveredSteps(p), 900, 1e-9);
    p = planOne(1000, {600, 2000, 500});
    EXPECT_EQ(p.shape, BlockShape::CruiseThenAccel);
    EXPECT_NEAR(p.rampTimeS, 2 * (600 - 1000 * 0.5) / 1000.0, 1e-12);
    EXPECT_NEAR(coveredSteps(p), 600, 1e-9);
    // v1 = 2000 → v2 = 1000.
    p = planOne(2000, {600, 1000, 500});
    EXPECT_EQ(p.shape, BlockShape::DecelThenCruise);
    EXPECT_LT(p.accelStepsS2, 0);
    EXPECT_NEAR(coveredSteps(p), 600, 1e-9);
    p = planOne(2000, {900, 1000, 500});
    EXPECT_EQ(p.shape, BlockShape::CruiseThenDecel);
    EXPECT_NEAR(coveredSteps(p), 900, 1e-9);
    p = planOne(1000, {500, 1000, 500});
    EXPECT_EQ(p.shape, BlockShape::Cruise);
    // Exactly s0: a ramp over the whole block.
    p = planOne(1000, {750, 2000, 500});
    EXPECT_NEAR(p.rampTimeS, 0.5, 1e-12);
    EXPECT_NEAR(p.cruiseTimeS, 0, 1e-12);
    // Negative direction works the same on magnitudes.
    p = planOne(-1000, {-900, -2000, 500});
    EXPECT_EQ(p.shape, BlockShape::AccelThenCruise);
    EXPECT_EQ(p.direction, -1);
}

TEST(Blocks, ValidationNamesJointBlockFieldAndValue)
{
    auto r = planJointBlocks({{10, 100, 0}}, 30000, 2);
    EXPECT_EQ(motion::msg::debugString(r.error()), "profile.block_zero_duration{joint=2, block=0}");
    r = planJointBlocks({{10, 100, 100}, {10, 32000, 100}}, 30000, 2);
    EXPECT_EQ(motion::msg::debugString(r.error()), "profile.block_too_fast{joint=2, block=1, v2=32000, max=30000}");
    r = planJointBlocks({{100, 0, 500}}, 30000, 0);  // rest to rest cannot move in the seed's plan
    EXPECT_FALSE(r);
    EXPECT_NE(motion::msg::debugString(r.error()).find("profile.block_unreachable{joint=0, block=0, steps=100,"), std::string::npos) << r.error();
    r = planJointBlocks({{-50, 1000, 500}}, 30000, 0);  // speed forward, S backward
    EXPECT_FALSE(r);
}

TEST(Blocks, DirectionChangeIsSplitAtZeroSpeed)
{
    // +1000 → -500 in 300 ms: zero speed after 200 ms (constant deceleration through zero),
    // 100 steps forward braking, then 25 steps back speeding up: S = 75.
    const auto r = planJointBlocks({{1000, 1000, 1000}, {75, -500, 300}}, 30000, 0);
    ASSERT_TRUE(r) << r.error();
    EXPECT_EQ(r->splitCount, 1);
    ASSERT_EQ(r->blocks.size(), 3u);
    const BlockPlan& a = r->blocks[1];
    const BlockPlan& b = r->blocks[2];
    EXPECT_EQ(a.sourceIndex, 1);
    EXPECT_EQ(b.sourceIndex, 1);
    EXPECT_EQ(a.direction, 1);
    EXPECT_EQ(b.direction, -1);
    EXPECT_EQ(a.steps, 100);
    EXPECT_EQ(b.steps, 25);
    EXPECT_EQ(a.endSpeedStepsS, 0);
    EXPECT_EQ(b.startSpeedStepsS, 0);
    EXPECT_NEAR(a.durationS + b.durationS, 0.3, 1e-12);
    EXPECT_NEAR(a.accelStepsS2, -5000, 1e-9);
    EXPECT_NEAR(b.accelStepsS2, 5000, 1e-9);
}

TEST(Blocks, PropertyRandomReachableBlocksArePlannedExactly)
{
    std::mt19937_64 rng(4004);
    std::uniform_int_distribution<int> speed(0, 20000), duration(1, 2000);
    std::uniform_real_distribution<double> frac(0, 1);
    for (int trial = 0; trial < 2000; ++trial) {
        std::vector<Block> blocks;
        double v1 = 0;
        for (int k = 0; k < 8; ++k) {
            const int v2 = speed(rng);
            const int t0 = duration(rng);
            const double lo = std::min(v1, double(v2)) * t0 / 1000.0, hi = std::max(v1, double(v2)) * t0 / 1000.0;
            const double s = std::round(lo + frac(rng) * (hi - lo));
            blocks.push_back({static_cast<std::int32_t>(s), static_cast<std::int16_t>(v2), static_cast<std::uint16_t>(t0)});
            v1 = v2;
        }
        const auto r = planJointBlocks(blocks, 20000, 0);
        ASSERT_TRUE(r) << r.error();
        for (const auto& p : r->blocks) {
            ASSERT_NEAR(coveredSteps(p), p.steps, 0.5 + 1e-9);
            ASSERT_NEAR(p.rampTimeS + p.cruiseTimeS, p.durationS, 1e-12);
            ASSERT_GE(p.rampTimeS, 0);
            ASSERT_GE(p.cruiseTimeS, 0);
        }
    }
}

TEST(Blocks, ExactDelaysAddUpToTheBlockDuration)
{
    const double F = 1e6;  // 1 MHz timer
    const auto p = planOne(1000, {900, 2000, 500});
    const auto delays = exactDelaysTicks(p, F);
    ASSERT_EQ(delays.size(), 900u);
    double total = 0;
    for (double d : delays)
        total += d / F;
    // End-speed delays run each ramp step at the speed it ends with: a hair short of t0.
    EXPECT_NEAR(total, 0.5, 0.5 * 1e-3);
    EXPECT_NEAR(delays.back(), F / 2000, 1e-9);
    EXPECT_NEAR(delays.front(), F / std::sqrt(1000.0 * 1000 + 2 * 5000), 1e-9);
}

TEST(Blocks, TaylorRecurrenceErrorIsBoundedPerStepAndOverTheRamp)
{
    const double F = 1e6;
    std::mt19937_64 rng(1234);
    std::uniform_real_distribution<double> v(200, 20000), acc(1000, 200000);
    for (int trial = 0; trial < 500; ++trial) {
        const double v0 = v(rng), a = acc(rng) * (trial % 2 ? 1 : -1);
        // One step from the exact previous delay: error within the Lagrange bound, always short.
        const double p0 = F / v0;
        const double n = 2 * a * p0 * p0 / (F * F);
        if (std::fabs(n) > 0.5)
            continue;
        const double exact = F / std::sqrt(v0 * v0 + 2 * a);
        double taylor;
        taylorRecurrence(p0, -a / (F * F), 1, &taylor);
        ASSERT_LE(taylor, exact * (1 + 1e-15));
        ASSERT_LE((exact - taylor) / exact, taylorStepErrorBound(n) + 1e-15) << "n=" << n;
    }
    // Over a whole ramp: a relative error δ in p_{i-1} leaves the step as δ·g with
    // g = (1 + 3mp²)/(1 + mp²) (< 1 accelerating, > 1 braking), so E_i ≤ max(g,1)·E_{i-1} + bound_i.
    for (double a : {20000.0, -20000.0}) {
        const double w1 = a > 0 ? 1000 : 5000, w2 = a > 0 ? 5000 : 1000;
        const double t0 = (w2 - w1) / a;
        const auto plan = planOne(w1, {static_cast<std::int32_t>(std::round(0.5 * (w1 + w2) * t0)),
                                       static_cast<std::int16_t>(w2), static_cast<std::uint16_t>(std::lround(t0 * 1000))});
        const auto exact = exactDelaysTicks(plan, F);
        const auto taylor = taylorDelaysTicks(plan, F);
        ASSERT_EQ(exact.size(), taylor.size());
        double boundSum = 0, worst = 0;
        for (std::size_t i = 0; i < exact.size(); ++i) {
            worst = std::max(worst, std::fabs(taylor[i] - exact[i]) / exact[i]);
            const double prev = i == 0 ? F / w1 : exact[i - 1];
            const double mp2 = -plan.accelStepsS2 / (F * F) * prev * prev;
            boundSum = std::max(1.0, (1 + 3 * mp2) / (1 + mp2)) * boundSum
                       + taylorStepErrorBound(2 * plan.accelStepsS2 * prev * prev / (F * F));
            ASSERT_LE(std::fabs(taylor[i] - exact[i]) / exact[i], boundSum * 1.01 + 1e-12) << "a=" << a << " i=" << i;
        }
        // 1000 ↔ 5000 microsteps/s at 20 000 microsteps/s² (600 microsteps): accelerating the
        // recurrence stays within 0.6 % (bound 1.5 %); braking, its error compounds to 4.4 %
        // (bound 4.7 %) — a user would see the joint arrive late.
        EXPECT_LT(worst, a > 0 ? 0.006 : 0.045) << "a=" << a;
        EXPECT_LT(boundSum, a > 0 ? 0.015 : 0.047) << "a=" << a;
        // Re-anchoring on the closed form every 32 microsteps stops the braking error compounding
        // (4.4 % → < 1 %); what is left is the error of one 32-step stretch at the highest n.
        const auto anchored = taylorDelaysTicks(plan, F, 0.25, 32);
        double worstAnchored = 0;
        for (std::size_t i = 0; i < exact.size(); ++i)
            worstAnchored = std::max(worstAnchored, std::fabs(anchored[i] - exact[i]) / exact[i]);
        EXPECT_LT(worstAnchored, 0.01) << "a=" << a;
        EXPECT_LE(worstAnchored, worst * (1 + 1e-9)) << "a=" << a;
    }
}

TEST(Blocks, TaylorFallsBackToTheSquareRootNearZeroSpeed)
{
    const double F = 1e6;
    // From rest: 0 → 2000 microsteps/s in 1 s, 1000 steps.
    const auto r = planJointBlocks({{1000, 2000, 1000}}, 30000, 0);
    ASSERT_TRUE(r) << r.error();
    const auto exact = exactDelaysTicks(r->blocks[0], F);
    const auto taylor = taylorDelaysTicks(r->blocks[0], F);
    ASSERT_EQ(taylor.size(), 1000u);
    EXPECT_DOUBLE_EQ(taylor.front(), exact.front());  // √(2a) for the first microstep
    for (std::size_t i = 0; i < taylor.size(); ++i)
        ASSERT_TRUE(std::isfinite(taylor[i]) && taylor[i] > 0);
    EXPECT_NEAR(taylor.back(), exact.back(), 0.01 * exact.back());
}
