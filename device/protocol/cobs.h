#pragma once
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace dev::proto {

/// Consistent Overhead Byte Stuffing: removes every 0x00 from a block so 0x00 can
/// delimit frames. Overhead is one byte per started 254 bytes of input.
void cobsEncode(const std::uint8_t* data, std::size_t size, std::vector<std::uint8_t>& out);

/// Decodes one COBS block (without its 0x00 delimiter). nullopt when the block is
/// malformed (a zero inside, or a code byte pointing past the end).
std::optional<std::vector<std::uint8_t>> cobsDecode(const std::uint8_t* data, std::size_t size);

/// Worst-case encoded size of `size` input bytes, delimiter not included.
constexpr std::size_t cobsMaxEncodedSize(std::size_t size) { return size + size / 254 + 1; }

} // namespace dev::proto
