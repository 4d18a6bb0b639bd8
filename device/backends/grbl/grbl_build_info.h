#pragma once
// The answer to $I: which firmware, its build, and the two numbers the streamer and the
// jog planner rest on — usable planner blocks and the serial receive buffer size:
//
//   GRBL 1.1     [VER:1.1h.20190830:]            grblHAL   [VER:1.1f.20231210:my mill]
//                [OPT:V,15,128]                            [OPT:VNMZHSL,35,1024,3,0]
//                ok                                        [AXS:3:XYZ]
//                                                          [NEWOPT:ENUMS,RT+,HOME,…]
//                                                          [FIRMWARE:grblHAL]
//                                                          [DRIVER:…] [BOARD:…] … ok
//
// grblHAL's extra lines are kept as they came (tag and text) and the ones that matter read:
// AXS gives the axis count and letters, FIRMWARE confirms grblHAL even when its banner said
// "Grbl" (compatibility level 1 or 2).
#include "device/backends/grbl/grbl_lines.h"

#include <string>
#include <utility>
#include <vector>

namespace dev::grbl {

struct BuildInfo {
    std::string version;        ///< "1.1h.20190830"
    std::string userText;       ///< after the second ':' of VER (set with $I=…)
    std::string optionCodes;    ///< "VNMZHSL": the compile-time option letters
    int plannerBlocks = -1;     ///< usable blocks; -1 until [OPT:] was read
    int rxBufferBytes = -1;     ///< serial receive buffer size; -1 until [OPT:] was read
    int axisCount = -1;         ///< grblHAL [OPT:] fourth field or [AXS:]
    std::string axisLetters;    ///< grblHAL [AXS:3:XYZ]
    Firmware firmware = Firmware::Unknown;  ///< GrblHal once [FIRMWARE:grblHAL] or [AXS:] is seen
    std::vector<std::pair<std::string, std::string>> extra;  ///< other bracketed lines: tag, text

    bool hasOption(char code) const { return optionCodes.find(code) != std::string::npos; }
    /// Receive buffer the streamer may fill: the reported size, or the family's default.
    std::size_t rxBufferOrDefault(Firmware family) const;
    int plannerBlocksOrDefault() const { return plannerBlocks > 0 ? plannerBlocks : kGrblDefaultPlannerBlocks; }
};

/// Reads one line of a $I answer into `info`; false if the line is not part of one
/// (the caller then handles it as any other line).
bool addBuildInfoLine(BuildInfo& info, const Line& line);

} // namespace dev::grbl
