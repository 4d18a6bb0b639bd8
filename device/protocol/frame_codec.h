#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

namespace dev::proto {

/// Decoded frame body: type (1) + seq (2, LE) + payload + CRC (2, LE). The cap
/// keeps both ends' buffers bounded; anything longer is dropped as oversize.
constexpr std::size_t kMaxBodyBytes = 1024;
constexpr std::size_t kFrameHeaderBytes = 3;
constexpr std::size_t kFrameCrcBytes = 2;
constexpr std::size_t kMaxPayloadBytes = kMaxBodyBytes - kFrameHeaderBytes - kFrameCrcBytes;

struct Frame {
    std::uint8_t type = 0;
    std::uint16_t seq = 0;
    std::vector<std::uint8_t> payload;
};

/// Appends `0x00 COBS(body) 0x00` to `out`. The leading delimiter ends any
/// garbage the line carried before, so one noisy burst costs at most itself.
/// Returns false (and appends nothing) when the payload is over the cap.
bool encodeFrame(std::uint8_t type, std::uint16_t seq, const std::uint8_t* payload, std::size_t payloadSize,
                 std::vector<std::uint8_t>& out);
inline bool encodeFrame(const Frame& f, std::vector<std::uint8_t>& out)
{
    return encodeFrame(f.type, f.seq, f.payload.data(), f.payload.size(), out);
}

/// Bytes on the wire for a frame of `payloadSize` bytes (worst case of COBS).
constexpr std::size_t wireBytesForPayload(std::size_t payloadSize)
{
    const std::size_t body = payloadSize + kFrameHeaderBytes + kFrameCrcBytes;
    return 2 + body + body / 254 + 1;
}

struct DecoderStats {
    std::uint64_t frames = 0;        ///< good frames delivered
    std::uint64_t crcErrors = 0;     ///< well-formed COBS, wrong CRC
    std::uint64_t malformed = 0;     ///< bad COBS or shorter than header + CRC
    std::uint64_t oversize = 0;      ///< body longer than the cap: dropped up to the next delimiter
    /// Non-delimiter bytes that belonged to no good frame (garbage, damaged or
    /// oversize frames). 0x00 delimiters are framing and never counted, so
    /// garbage between two good frames adds exactly its non-zero byte count.
    std::uint64_t droppedBytes = 0;
};

/// Streaming decoder: feed bytes in any chunking, get whole frames. Its buffer is
/// bounded by the frame cap; overflow discards up to the next delimiter.
class FrameDecoder {
public:
    FrameDecoder();
    /// Appends every complete good frame found in `data` to `out`.
    void feed(const std::uint8_t* data, std::size_t size, std::vector<Frame>& out);
    const DecoderStats& stats() const { return m_stats; }
    void reset();

private:
    void finishBlock(std::vector<Frame>& out);

    std::vector<std::uint8_t> m_block;  ///< encoded bytes since the last delimiter
    bool m_discarding = false;          ///< true after an oversize block until the next 0x00
    DecoderStats m_stats;
};

} // namespace dev::proto
