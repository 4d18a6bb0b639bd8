#include "device/protocol/cobs.h"

namespace dev::proto {

void cobsEncode(const std::uint8_t* data, std::size_t size, std::vector<std::uint8_t>& out)
{
    std::size_t codeIndex = out.size();
    out.push_back(0);  // placeholder for the first code byte
    std::uint8_t code = 1;
    for (std::size_t i = 0; i < size; ++i) {
        if (data[i] == 0) {
            out[codeIndex] = code;
            codeIndex = out.size();
            out.push_back(0);
            code = 1;
            continue;
        }
        out.push_back(data[i]);
        if (++code == 0xFF) {
            out[codeIndex] = code;
            codeIndex = out.size();
            out.push_back(0);
            code = 1;
        }
    }
    out[codeIndex] = code;
}

std::optional<std::vector<std::uint8_t>> cobsDecode(const std::uint8_t* data, std::size_t size)
{
    std::vector<std::uint8_t> out;
    out.reserve(size);
    std::size_t i = 0;
    while (i < size) {
        const std::uint8_t code = data[i++];
        if (code == 0)
            return std::nullopt;
        for (std::uint8_t k = 1; k < code; ++k) {
            if (i >= size || data[i] == 0)
                return std::nullopt;
            out.push_back(data[i++]);
        }
        // A code below 0xFF marks a zero that was removed, except at the very end.
        if (code != 0xFF && i < size)
            out.push_back(0);
    }
    return out;
}

} // namespace dev::proto
