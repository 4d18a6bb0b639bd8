// Seed 004 CAN frames.
#include "motion/can_frame.h"

#include <gtest/gtest.h>

using namespace motion;

TEST(CanFrame, PacksIdAndFieldsAsTheSeedGives)
{
    // Joint 1: S = 1000 (0x3E8), V2 = -500 (0xFE0C), t0 = 500 ms (0x1F4).
    const auto f = packBlockFrame(1, {1000, -500, 500});
    ASSERT_TRUE(f);
    EXPECT_EQ(f->id, 0xA1);
    EXPECT_EQ(f->dlc, 8);
    const std::array<std::uint8_t, 8> expected{0xE8, 0x03, 0x00, 0x00, 0x0C, 0xFE, 0xF4, 0x01};
    EXPECT_EQ(f->data, expected);
    EXPECT_EQ(canFrameToHex(*f), "0A1#E80300000CFEF401");
    const auto back = unpackBlockFrame(*f);
    ASSERT_TRUE(back);
    EXPECT_EQ(back->first, 1);
    EXPECT_EQ(back->second.steps, 1000);
    EXPECT_EQ(back->second.endSpeed, -500);
    EXPECT_EQ(back->second.durationMs, 500);
    EXPECT_FALSE(packBlockFrame(10, {}));  // one digit of joint number
    EXPECT_FALSE(packBlockFrame(-1, {}));
    CanFrame other;
    other.id = 0x123;
    EXPECT_FALSE(unpackBlockFrame(other));
}

TEST(CanFrame, ExtremesRoundTrip)
{
    const Block b{-2147483647 - 1, -32768, 65535};
    const auto back = unpackBlockFrame(*packBlockFrame(9, b));
    ASSERT_TRUE(back);
    EXPECT_EQ(back->first, 9);
    EXPECT_EQ(back->second.steps, b.steps);
    EXPECT_EQ(back->second.endSpeed, b.endSpeed);
    EXPECT_EQ(back->second.durationMs, b.durationMs);
}

TEST(CanFrame, FramesAreSentJointInterleaved)
{
    // Claim 8: first block of each joint, then second block of each joint, …
    const std::vector<std::vector<Block>> blocks = {
        {{1, 0, 1}, {2, 0, 1}, {3, 0, 1}},
        {{11, 0, 1}},
        {{21, 0, 1}, {22, 0, 1}},
    };
    const auto frames = interleaveBlockFrames(blocks);
    ASSERT_EQ(frames.size(), 6u);
    const int expectedJoint[] = {0, 1, 2, 0, 2, 0};
    const int expectedSteps[] = {1, 11, 21, 2, 22, 3};
    for (std::size_t i = 0; i < frames.size(); ++i) {
        const auto u = unpackBlockFrame(frames[i]);
        ASSERT_TRUE(u);
        EXPECT_EQ(u->first, expectedJoint[i]);
        EXPECT_EQ(u->second.steps, expectedSteps[i]);
    }
}
