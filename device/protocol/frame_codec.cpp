#include "device/protocol/frame_codec.h"

#include "device/protocol/cobs.h"
#include "device/protocol/crc16.h"

namespace dev::proto {
namespace {
constexpr std::size_t kMaxEncodedBlock = cobsMaxEncodedSize(kMaxBodyBytes);
}

bool encodeFrame(std::uint8_t type, std::uint16_t seq, const std::uint8_t* payload, std::size_t payloadSize,
                 std::vector<std::uint8_t>& out)
{
    if (payloadSize > kMaxPayloadBytes)
        return false;
    std::uint8_t body[kMaxBodyBytes];
    body[0] = type;
    body[1] = static_cast<std::uint8_t>(seq & 0xFF);
    body[2] = static_cast<std::uint8_t>(seq >> 8);
    for (std::size_t i = 0; i < payloadSize; ++i)
        body[kFrameHeaderBytes + i] = payload[i];
    const std::size_t crcAt = kFrameHeaderBytes + payloadSize;
    const std::uint16_t crc = crc16Ccitt(body, crcAt);
    body[crcAt] = static_cast<std::uint8_t>(crc & 0xFF);
    body[crcAt + 1] = static_cast<std::uint8_t>(crc >> 8);
    out.push_back(0);
    cobsEncode(body, crcAt + kFrameCrcBytes, out);
    out.push_back(0);
    return true;
}

FrameDecoder::FrameDecoder() { m_block.reserve(kMaxEncodedBlock); }

void FrameDecoder::reset()
{
    m_block.clear();
    m_discarding = false;
}

void FrameDecoder::feed(const std::uint8_t* data, std::size_t size, std::vector<Frame>& out)
{
    for (std::size_t i = 0; i < size; ++i) {
        const std::uint8_t b = data[i];
        if (b == 0) {
            if (m_discarding)
                m_discarding = false;  // the delimiter is framing, not a dropped byte
            else
                finishBlock(out);
            continue;
        }
        if (m_discarding) {
            ++m_stats.droppedBytes;
            continue;
        }
        if (m_block.size() >= kMaxEncodedBlock) {
            ++m_stats.oversize;
            m_stats.droppedBytes += m_block.size() + 1;
            m_block.clear();
            m_discarding = true;
            continue;
        }
        m_block.push_back(b);
    }
}

void FrameDecoder::finishBlock(std::vector<Frame>& out)
{
    if (m_block.empty())
        return;  // back-to-back delimiters are idle fill, not an error
    auto body = cobsDecode(m_block.data(), m_block.size());
    const std::size_t blockBytes = m_block.size();
    m_block.clear();
    if (body && body->size() > kMaxBodyBytes) {
        // A body with zeros in it encodes to size + 1, so up to 1028 bytes fit in
        // the block limit: the cap must be checked on the decoded body as well.
        ++m_stats.oversize;
        m_stats.droppedBytes += blockBytes;
        return;
    }
    if (!body || body->size() < kFrameHeaderBytes + kFrameCrcBytes) {
        ++m_stats.malformed;
        m_stats.droppedBytes += blockBytes;
        return;
    }
    const std::size_t crcAt = body->size() - kFrameCrcBytes;
    const std::uint16_t want = static_cast<std::uint16_t>((*body)[crcAt] | ((*body)[crcAt + 1] << 8));
    if (crc16Ccitt(body->data(), crcAt) != want) {
        ++m_stats.crcErrors;
        m_stats.droppedBytes += blockBytes;
        return;
    }
    Frame f;
    f.type = (*body)[0];
    f.seq = static_cast<std::uint16_t>((*body)[1] | ((*body)[2] << 8));
    f.payload.assign(body->begin() + kFrameHeaderBytes, body->begin() + static_cast<std::ptrdiff_t>(crcAt));
    ++m_stats.frames;
    out.push_back(std::move(f));
}

} // namespace dev::proto
