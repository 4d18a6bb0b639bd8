#include "device/backends/grbl/grbl_build_info.h"

namespace dev::grbl {

std::size_t BuildInfo::rxBufferOrDefault(Firmware family) const
{
    if (rxBufferBytes > 0)
        return static_cast<std::size_t>(rxBufferBytes);
    return family == Firmware::GrblHal ? kGrblHalDefaultRxBufferBytes : kGrblDefaultRxBufferBytes;
}

namespace {

/// A small non-negative integer field; -1 if it is not one.
int smallInt(std::string_view s)
{
    if (s.empty() || s.size() > 6)
        return -1;
    int v = 0;
    for (const char c : s) {
        if (c < '0' || c > '9')
            return -1;
        v = v * 10 + (c - '0');
    }
    return v;
}

std::vector<std::string_view> split(std::string_view s, char sep)
{
    std::vector<std::string_view> out;
    while (true) {
        const std::size_t at = s.find(sep);
        out.push_back(s.substr(0, at));
        if (at == std::string_view::npos)
            return out;
        s.remove_prefix(at + 1);
    }
}

} // namespace

bool addBuildInfoLine(BuildInfo& info, const Line& line)
{
    switch (line.kind) {
    case LineKind::Version: {
        const std::size_t colon = line.payload.find(':');
        info.version = std::string(line.payload.substr(0, colon));
        info.userText = colon == std::string_view::npos ? std::string() : std::string(line.payload.substr(colon + 1));
        return true;
    }
    case LineKind::Options: {
        // OPT:codes,blocks,rxbytes[,axes,tools]. Codes may be empty ("[OPT:,15,128]").
        const auto f = split(line.payload, ',');
        info.optionCodes = std::string(f[0]);
        if (f.size() > 1)
            info.plannerBlocks = smallInt(f[1]);
        if (f.size() > 2)
            info.rxBufferBytes = smallInt(f[2]);
        if (f.size() > 3)
            info.axisCount = smallInt(f[3]);
        // A zero or absurd buffer would stall the streamer or overrun the device: distrust it.
        if (info.rxBufferBytes == 0 || info.rxBufferBytes > 65536)
            info.rxBufferBytes = -1;
        if (info.plannerBlocks == 0 || info.plannerBlocks > 1024)
            info.plannerBlocks = -1;
        return true;
    }
    case LineKind::Bracketed: {
        if (line.tag == "AXS") {
            const auto f = split(line.payload, ':');
            info.axisCount = smallInt(f[0]);
            if (f.size() > 1)
                info.axisLetters = std::string(f[1]);
            info.firmware = Firmware::GrblHal;
        } else if (line.tag == "FIRMWARE") {
            if (line.payload == "grblHAL")
                info.firmware = Firmware::GrblHal;
        }
        // $# parameter lines ([G54:…], [TLO:…]) are not build info.
        static constexpr std::string_view kParams[] = {"G54", "G55", "G56", "G57", "G58", "G59", "G28", "G30", "G92", "TLO", "HOME"};
        for (const auto p : kParams)
            if (line.tag == p)
                return false;
        if (info.extra.size() < 64)
            info.extra.emplace_back(std::string(line.tag), std::string(line.payload));
        return true;
    }
    default:
        return false;
    }
}

} // namespace dev::grbl
