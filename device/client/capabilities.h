#pragma once
// What an instrument can do, the same words on every backend: screens, runners and
// the CLI gate features on these, never on a protocol's bits or a backend's class.
// When a capability is missing, the Instrument says why as a motion::msg::Message
// (Instrument::whyNot), which the GUI shows on the disabled control.
#include "motion/message.h"

#include <QFlags>

#include <array>
#include <string>

namespace dev {

enum class Capability : quint32 {
    Homing = 1u << 0,            ///< axes home on their switches
    SetZero = 1u << 1,           ///< the present position becomes an axis' zero
    MeasuredPosition = 1u << 2,  ///< an encoder or grating reading beside the commanded position
    ClosedLoop = 1u << 3,        ///< the position loop closes on that reading
    Telemetry = 1u << 4,         ///< a sample stream at a rate the host asks for (Instrument::subscribe)
    VelocityJog = 1u << 5,       ///< continuous jog and the joystick (startJog, setJogVelocities)
    StopsOnHostLoss = 1u << 6,   ///< the device itself stops a jog or a path when the host goes quiet
    PathQueue = 1u << 7,         ///< line and arc segments streamed to a device queue (Instrument::paths)
    PathZFollow = 1u << 8,       ///< a path segment may carry a Z target, run after its XY part
    CoupledXyThenZ = 1u << 9,    ///< Z moves only once X and Y have arrived (the analyzer)
    SoftLimits = 1u << 10,       ///< the device enforces soft limits the host sets
    PidGains = 1u << 11,         ///< Instrument::tuning(): the loop's gains, read and set
    TuningTests = 1u << 12,      ///< Instrument::tuning(): step and relay tests run on the device
    Pump = 1u << 13,             ///< an axis in µL (a plunger pump)
    TriggerOutput = 1u << 14,    ///< Instrument::pulseTrigger(): an output a camera is wired to
    MachineLimits = 1u << 15,    ///< the device reported its planner's acceleration and jerk
    Compensation = 1u << 16,     ///< Instrument::compensation(): axis error compensation kept and applied on the device
    ArchedMove = 1u << 17,       ///< Instrument::archMove(): Z up, XY across, Z down blended into one move
};
Q_DECLARE_FLAGS(Capabilities, Capability)

/// Every capability, in a fixed order (for listings).
const std::array<Capability, 18>& allCapabilities();
/// Stable lower-case key: "pid_gains". JSON output and message ids use it.
std::string capabilityKey(Capability c);

/// The reasons' message ids, a closed list for the wording layer:
///   capability.not_connected [{instrument}]              the link is not ready (instrument:
///                                                        once it has been identified)
///   capability.no_<key> {instrument, family[, because]}  the device has no such feature
/// `instrument` is the term "instrument.analyzer" or "instrument.stage", `family` the
/// firmware family as the device named it (verbatim), `because` an optional term
/// ("capability.because.open_loop").
inline constexpr const char* kNotConnectedId = "capability.not_connected";
std::string missingId(Capability c);  ///< "capability.no_pid_gains"

} // namespace dev

Q_DECLARE_OPERATORS_FOR_FLAGS(dev::Capabilities)
