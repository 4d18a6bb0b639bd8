#pragma once
// The reason codes of EVENT (docs/protocol.md, "Event reasons"): why the device raised
// an event, and the numbers a host needs to say so in its operator's language. Codes
// are per event kind; a host that meets a code it does not know shows the event's text.
// Values: positions and lengths in the axis unit (mm or µL), times in seconds.
#include <cstdint>

namespace dev::proto::reason {

// Test kinds, a tuning event's first value.
constexpr double kStepTest = 1, kRelayTest = 2;

// MotionDone, HomeDone
constexpr std::uint8_t kAlreadyThere = 1;       ///< the axis was at the target: nothing moved
constexpr std::uint8_t kOutsideWindow = 2;      ///< arrived, but outside the in-position window
// LimitHit
constexpr std::uint8_t kHomeSwitch = 1;
constexpr std::uint8_t kLimitSwitch = 2;
// Fault
constexpr std::uint8_t kHomeSwitchNotFound = 1; ///< over the whole travel
// EStop
constexpr std::uint8_t kAllHalted = 1;
// JogExpired
constexpr std::uint8_t kNotRefreshed = 1;       ///< values: the watchdog (s)
// Stopped
constexpr std::uint8_t kStopRequest = 1;        ///< a STOP brought it to rest
constexpr std::uint8_t kWithCoupledAxis = 2;    ///< its coupled axis stopped, so it did
constexpr std::uint8_t kHomingOtherFailed = 3;  ///< homing cancelled: another axis found no switch
constexpr std::uint8_t kHomingEarlierFailed = 4;///< homing cancelled: an axis homed before it did not reach home
constexpr std::uint8_t kHomingStopped = 5;      ///< homing stopped before this axis' turn
constexpr std::uint8_t kWaitedMoveStopped = 6;  ///< cancelled: the move it waited for was stopped
constexpr std::uint8_t kWaitedMoveHitSwitch = 7;///< cancelled: a switch stopped the move it waited for
// LostSteps
constexpr std::uint8_t kOffCommand = 1;         ///< values: the encoder's distance from the command
// Reset
constexpr std::uint8_t kCleared = 1;
// TestEnded — values: test kind, seconds
constexpr std::uint8_t kSettled = 1;
constexpr std::uint8_t kCompleted = 2;
// TestTripped — values: test kind, limit, value, seconds, stopped at (kDuration: test kind, limit (s), stopped at)
constexpr std::uint8_t kExcursion = 1;
constexpr std::uint8_t kFollowingError = 2;
constexpr std::uint8_t kDuration = 3;
// TestAborted — values: test kind (kHostSilent: test kind, silence (s))
constexpr std::uint8_t kOnRequest = 1;
constexpr std::uint8_t kByEStop = 2;
constexpr std::uint8_t kHostSilent = 3;
constexpr std::uint8_t kByFault = 4;
// GainsChanged — values: kp, ki, kd per control period
constexpr std::uint8_t kGainsSet = 1;
constexpr std::uint8_t kGainsFellBack = 2;      ///< the set before the one that tripped a test
// PathStarted, PathDone, PathHeld, PathAborted: the code is the PathReason (messages_path.h)
// of a held or ended path, kPathRan for one that started or finished as planned.
constexpr std::uint8_t kPathRan = 255;
// CompChanged — values: for kInstalled the model (1 table, 2 polynomial); else kept for power-up (0 or 1)
constexpr std::uint8_t kInstalled = 1;
constexpr std::uint8_t kEnabled = 2;
constexpr std::uint8_t kDisabled = 3;

} // namespace dev::proto::reason
