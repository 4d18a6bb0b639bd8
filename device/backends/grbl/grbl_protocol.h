#pragma once
// GRBL 1.1 / grblHAL line protocol: the constants both ends agree on (realtime bytes,
// buffer sizes, code numbers). Header only and dependency free, so the simulator's GRBL
// personality (device/sim/) can speak the same numbers without linking the client side.
//
// Source: the GRBL 1.1 interface, commands, jogging and settings documents, and grblHAL's
// errors.h / alarms.h / report.c for its additions. See docs/grbl.md.
#include <cstddef>
#include <cstdint>

namespace dev::grbl {

/// Which firmware family answered. grblHAL in its default compatibility level announces
/// itself as "GrblHAL"; built for level 1 or 2 it says "Grbl" and is told apart by $I.
enum class Firmware { Unknown, Grbl, GrblHal };

/// Realtime commands: single bytes the firmware picks off the serial stream as they arrive.
/// They never enter the receive buffer, need no line end, and are not counted by the streamer.
namespace rt {
constexpr std::uint8_t kStatusQuery = '?';
constexpr std::uint8_t kCycleStart = '~';
constexpr std::uint8_t kFeedHold = '!';
constexpr std::uint8_t kSoftReset = 0x18;  ///< ctrl-X
constexpr std::uint8_t kSafetyDoor = 0x84;
constexpr std::uint8_t kJogCancel = 0x85;
constexpr std::uint8_t kFeedOverrideReset = 0x90;
constexpr std::uint8_t kFeedOverridePlus10 = 0x91;
constexpr std::uint8_t kFeedOverrideMinus10 = 0x92;
constexpr std::uint8_t kFeedOverridePlus1 = 0x93;
constexpr std::uint8_t kFeedOverrideMinus1 = 0x94;
constexpr std::uint8_t kRapidOverride100 = 0x95;
constexpr std::uint8_t kRapidOverride50 = 0x96;
constexpr std::uint8_t kRapidOverride25 = 0x97;
constexpr std::uint8_t kSpindleOverrideReset = 0x99;
constexpr std::uint8_t kSpindleOverridePlus10 = 0x9A;
constexpr std::uint8_t kSpindleOverrideMinus10 = 0x9B;
constexpr std::uint8_t kSpindleOverridePlus1 = 0x9C;
constexpr std::uint8_t kSpindleOverrideMinus1 = 0x9D;
constexpr std::uint8_t kSpindleStopToggle = 0x9E;
constexpr std::uint8_t kFloodToggle = 0xA0;
constexpr std::uint8_t kMistToggle = 0xA1;

/// True for every byte GRBL 1.1 handles as a realtime command (the four typeable ones and
/// the extended-ASCII set 0x80–0xFF, which GRBL reserves for realtime use).
constexpr bool isRealtime(std::uint8_t b)
{
    return b == kStatusQuery || b == kCycleStart || b == kFeedHold || b == kSoftReset || b >= 0x80;
}
} // namespace rt

/// Receive buffer of a stock GRBL 1.1 (AVR): 128 bytes, a ring that keeps one slot empty,
/// so 127 bytes of unacknowledged lines at most.
constexpr std::size_t kGrblDefaultRxBufferBytes = 128;
/// grblHAL's usual receive buffer (RX_BUFFER_SIZE in its drivers); $I says the real one.
constexpr std::size_t kGrblHalDefaultRxBufferBytes = 1024;
/// Usable planner blocks of a stock GRBL 1.1 (16 slots, one kept empty), as [OPT:] reports.
constexpr int kGrblDefaultPlannerBlocks = 15;
/// GRBL's line buffer is 80 bytes with the terminator: a longer line is refused (error:11).
/// GRBL counts the line after removing spaces and comments; builders count every byte.
constexpr std::size_t kMaxLineChars = 79;
constexpr double kMmPerInch = 25.4;
/// Status queries per second the GRBL interface document recommends at most (5 Hz; 10 may work).
constexpr double kRecommendedStatusHz = 5.0;

/// error:N codes the client and the simulator act on. Meanings: grbl_codes.h.
namespace err {
constexpr int kExpectedCommandLetter = 1;
constexpr int kBadNumberFormat = 2;
constexpr int kInvalidStatement = 3;      ///< '$' command not recognized
constexpr int kNegativeValue = 4;
constexpr int kHomingDisabled = 5;
constexpr int kIdleError = 8;             ///< '$' command only when Idle
constexpr int kSystemGcLock = 9;          ///< G-code locked out in alarm or jog state
constexpr int kSoftLimitNeedsHoming = 10;
constexpr int kOverflow = 11;             ///< line too long
constexpr int kTravelExceeded = 15;       ///< jog target beyond the machine travel
constexpr int kInvalidJogCommand = 16;
constexpr int kUnsupportedCommand = 20;
constexpr int kModalGroupViolation = 21;
constexpr int kUndefinedFeedRate = 22;
constexpr int kCommandValueNotInteger = 23;
constexpr int kAxisCommandConflict = 24;
constexpr int kWordRepeated = 25;
constexpr int kNoAxisWords = 26;
constexpr int kValueWordMissing = 28;
constexpr int kInvalidTarget = 33;
constexpr int kArcRadiusError = 34;
constexpr int kNoOffsetsInPlane = 35;
constexpr int kUnusedWords = 36;
constexpr int kGrblHalValueOutOfRange = 39;
constexpr int kGrblHalSettingDisabled = 53;
} // namespace err

/// ALARM:N codes.
namespace alarm {
constexpr int kHardLimit = 1;
constexpr int kSoftLimit = 2;
constexpr int kAbortCycle = 3;        ///< reset while in motion: position lost
constexpr int kProbeFailInitial = 4;
constexpr int kProbeFailContact = 5;
constexpr int kHomingFailReset = 6;
constexpr int kHomingFailDoor = 7;
constexpr int kHomingFailPulloff = 8;
constexpr int kHomingFailApproach = 9;
constexpr int kGrblHalEStop = 10;
constexpr int kGrblHalHomingRequired = 11;
} // namespace alarm

/// Settings ($N=V) the client reads. Units as GRBL stores them: always millimetres, whatever $13 says.
namespace setting {
constexpr int kStatusReportMask = 10;  ///< bit 0: MPos (1) or WPos (0); bit 1: Bf field
constexpr int kJunctionDeviationMm = 11;
constexpr int kArcToleranceMm = 12;
constexpr int kReportInches = 13;
constexpr int kSoftLimits = 20;
constexpr int kHardLimits = 21;
constexpr int kHomingCycle = 22;       ///< grbl: boolean; grblHAL: flags, bit 0 = enabled
constexpr int kHomingDirInvertMask = 23;
constexpr int kHomingFeedMmMin = 24;
constexpr int kHomingSeekMmMin = 25;
constexpr int kHomingPulloffMm = 27;
constexpr int kDirInvertMask = 3;
constexpr int kStepsPerMmX = 100;      ///< +axis index
constexpr int kMaxRateMmMinX = 110;    ///< +axis index
constexpr int kAccelMmS2X = 120;       ///< +axis index
constexpr int kMaxTravelMmX = 130;     ///< +axis index
} // namespace setting

} // namespace dev::grbl
