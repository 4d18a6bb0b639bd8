#include "motion/can_frame.h"

#include <algorithm>
#include <cstdio>

namespace motion {

namespace {
void putLe(std::uint8_t* out, std::uint32_t value, int bytes)
{
    for (int i = 0; i < bytes; ++i)
        out[i] = static_cast<std::uint8_t>((value >> (8 * i)) & 0xFFu);
}
std::uint32_t getLe(const std::uint8_t* in, int bytes)
{
    std::uint32_t v = 0;
    for (int i = 0; i < bytes; ++i)
        v |= static_cast<std::uint32_t>(in[i]) << (8 * i);
    return v;
}
}  // namespace

std::optional<CanFrame> packBlockFrame(int joint, const Block& block)
{
    if (joint < 0 || joint >= kMaxCanJoints)
        return std::nullopt;
    CanFrame f;
    f.id = static_cast<std::uint16_t>(0xA0 + joint);
    putLe(&f.data[0], static_cast<std::uint32_t>(block.steps), 4);
    putLe(&f.data[4], static_cast<std::uint16_t>(block.endSpeed), 2);
    putLe(&f.data[6], block.durationMs, 2);
    return f;
}

std::optional<std::pair<int, Block>> unpackBlockFrame(const CanFrame& frame)
{
    if (frame.dlc != 8 || frame.id < 0xA0 || frame.id >= 0xA0 + kMaxCanJoints)
        return std::nullopt;
    Block b;
    b.steps = static_cast<std::int32_t>(getLe(&frame.data[0], 4));
    b.endSpeed = static_cast<std::int16_t>(static_cast<std::uint16_t>(getLe(&frame.data[4], 2)));
    b.durationMs = static_cast<std::uint16_t>(getLe(&frame.data[6], 2));
    return std::make_pair(frame.id - 0xA0, b);
}

std::vector<CanFrame> interleaveBlockFrames(const std::vector<std::vector<Block>>& blocksPerJoint)
{
    std::vector<CanFrame> out;
    std::size_t rounds = 0;
    const std::size_t joints = std::min<std::size_t>(blocksPerJoint.size(), kMaxCanJoints);
    for (std::size_t j = 0; j < joints; ++j)
        rounds = std::max(rounds, blocksPerJoint[j].size());
    for (std::size_t r = 0; r < rounds; ++r)
        for (std::size_t j = 0; j < joints; ++j)
            if (r < blocksPerJoint[j].size())
                out.push_back(*packBlockFrame(static_cast<int>(j), blocksPerJoint[j][r]));
    return out;
}

std::string canFrameToHex(const CanFrame& frame)
{
    char buf[3 + 1 + 16 + 1];
    int n = std::snprintf(buf, sizeof buf, "%03X#", frame.id & 0x7FFu);
    for (int i = 0; i < frame.dlc && i < 8; ++i)
        n += std::snprintf(buf + n, sizeof buf - static_cast<std::size_t>(n), "%02X", frame.data[static_cast<std::size_t>(i)]);
    return std::string(buf, static_cast<std::size_t>(n));
}

}  // namespace motion
