#pragma once
// Seed 004 claim 7–8: blocks travel to the joints' executors as classic CAN data frames.
//   ID   = 0xA0 + joint digit ("0xA followed by one digit of joint number": 0xA0 … 0xA9)
//   data = int32 S (bytes 0–3), int16 V2 (bytes 4–5), uint16 t0 (bytes 6–7), DLC 8.
// The seed does not give the byte order; we use little-endian, which is what the seed's ARM
// executor gets by copying the fields out of the frame buffer.
// Claim 8: frames are sent joint-interleaved — every joint's first block, then every joint's
// second block, and so on — so no joint starves while another's queue is filled.

#include "motion/blocks.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace motion {

struct CanFrame {
    std::uint16_t id = 0;                ///< 11-bit standard identifier
    std::uint8_t dlc = 8;
    std::array<std::uint8_t, 8> data{};
};

constexpr int kMaxCanJoints = 10;  ///< one decimal digit in the ID

/// nullopt for a joint outside 0…9.
std::optional<CanFrame> packBlockFrame(int joint, const Block& block);

/// Inverse of packBlockFrame: joint and block, or nullopt for a frame that is not a block frame.
std::optional<std::pair<int, Block>> unpackBlockFrame(const CanFrame& frame);

/// All joints' blocks as frames, joint-interleaved (claim 8). Joints with fewer blocks drop out
/// when they run out. blocksPerJoint[j] belongs to joint j; at most kMaxCanJoints joints.
std::vector<CanFrame> interleaveBlockFrames(const std::vector<std::vector<Block>>& blocksPerJoint);

/// candump-style text: "0A1#E8030000F401F401".
std::string canFrameToHex(const CanFrame& frame);

}  // namespace motion
