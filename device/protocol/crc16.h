#pragma once
#include <cstddef>
#include <cstdint>

namespace dev::proto {

/// CRC-16/CCITT-FALSE: poly 0x1021, init 0xFFFF, no reflection, no final xor.
/// Check value for "123456789" is 0x29B1.
std::uint16_t crc16Ccitt(const std::uint8_t* data, std::size_t size, std::uint16_t crc = 0xFFFF);

} // namespace dev::proto
