// The error and alarm tables. Meanings follow GRBL 1.1's interface document (codes 1–38,
// alarms 1–9) and grblHAL's errors and alarms lists (its additions), worded for an operator.
// lupdate reads the QT_TRANSLATE_NOOP marks; without Qt they are the plain strings.
#include "device/backends/grbl/grbl_codes.h"

#include <algorithm>
#include <iterator>
#include <string>

#ifndef QT_TRANSLATE_NOOP
#define QT_TRANSLATE_NOOP(scope, x) x
#endif

namespace dev::grbl {
namespace {

const CodeMeaning kErrors[] = {
    {1, QT_TRANSLATE_NOOP("grbl", "A G-code word has no letter: every word is a letter followed by a value."), false},
    {2, QT_TRANSLATE_NOOP("grbl", "A number is missing or is not written as a valid number."), false},
    {3, QT_TRANSLATE_NOOP("grbl", "The '$' system command is not recognized or not supported."), false},
    {4, QT_TRANSLATE_NOOP("grbl", "A negative value was given where only a positive one is allowed."), false},
    {5, QT_TRANSLATE_NOOP("grbl", "Homing is not enabled in the controller's settings."), false},
    {6, QT_TRANSLATE_NOOP("grbl", "The step pulse time is shorter than the controller allows."), false},
    {7, QT_TRANSLATE_NOOP("grbl", "Reading the stored settings failed; the controller restored its defaults."), false},
    {8, QT_TRANSLATE_NOOP("grbl", "This '$' command is only accepted while the controller is idle."), false},
    {9, QT_TRANSLATE_NOOP("grbl", "G-code is locked out while the controller is in alarm or jogging."), false},
    {10, QT_TRANSLATE_NOOP("grbl", "Soft limits cannot be enabled unless homing is enabled too."), false},
    {11, QT_TRANSLATE_NOOP("grbl", "The line is longer than the controller accepts; it was not executed."), false},
    {12, QT_TRANSLATE_NOOP("grbl", "This setting would make the step rate exceed what the controller supports."), false},
    {13, QT_TRANSLATE_NOOP("grbl", "The safety door is open; the controller entered its door state."), false},
    {14, QT_TRANSLATE_NOOP("grbl", "The build info or startup line is too long to be stored."), false},
    {15, QT_TRANSLATE_NOOP("grbl", "The jog target lies beyond the machine travel; the jog was ignored."), false},
    {16, QT_TRANSLATE_NOOP("grbl", "The jog command has no '=' or contains G-code that jogging does not allow."), false},
    {17, QT_TRANSLATE_NOOP("grbl", "Laser mode needs a PWM spindle output."), false},
    {18, QT_TRANSLATE_NOOP("grbl", "The controller is being reset."), true},
    {19, QT_TRANSLATE_NOOP("grbl", "A value that must be above zero was zero or negative."), true},
    {20, QT_TRANSLATE_NOOP("grbl", "The block contains a G-code command that is not supported or not valid."), false},
    {21, QT_TRANSLATE_NOOP("grbl", "The block contains two commands of the same modal group."), false},
    {22, QT_TRANSLATE_NOOP("grbl", "No feed rate has been set for this move."), false},
    {23, QT_TRANSLATE_NOOP("grbl", "This G-code command needs a whole-number value."), false},
    {24, QT_TRANSLATE_NOOP("grbl", "Two commands in the block both need the axis words."), false},
    {25, QT_TRANSLATE_NOOP("grbl", "A G-code word appears twice in the block."), false},
    {26, QT_TRANSLATE_NOOP("grbl", "The command needs axis words, and the block has none."), false},
    {27, QT_TRANSLATE_NOOP("grbl", "The line number (N) is outside the valid range."), false},
    {28, QT_TRANSLATE_NOOP("grbl", "The command is missing a required P or L value."), false},
    {29, QT_TRANSLATE_NOOP("grbl", "The work coordinate systems G59.1, G59.2 and G59.3 are not supported."), false},
    {30, QT_TRANSLATE_NOOP("grbl", "G53 is only allowed with G0 or G1 motion."), false},
    {31, QT_TRANSLATE_NOOP("grbl", "The block has axis words that no command uses."), false},
    {32, QT_TRANSLATE_NOOP("grbl", "The arc has no axis words in the selected plane."), false},
    {33, QT_TRANSLATE_NOOP("grbl", "The motion target is invalid (an impossible arc, or a probe target equal to the current position)."), false},
    {34, QT_TRANSLATE_NOOP("grbl", "The arc's radius form gives no valid geometry; use the centre (I J) form or split the arc."), false},
    {35, QT_TRANSLATE_NOOP("grbl", "The arc in centre form has no I/J/K offset in the selected plane."), false},
    {36, QT_TRANSLATE_NOOP("grbl", "The block has value words that no command uses."), false},
    {37, QT_TRANSLATE_NOOP("grbl", "G43.1 dynamic tool length offset was given for an axis other than the configured one."), false},
    {38, QT_TRANSLATE_NOOP("grbl", "The tool number is above the largest supported."), false},
    {39, QT_TRANSLATE_NOOP("grbl", "A value is out of range."), true},
    {40, QT_TRANSLATE_NOOP("grbl", "This G-code command is not allowed while a tool change is pending."), true},
    {41, QT_TRANSLATE_NOOP("grbl", "The spindle is not running, but the motion needs it (constant surface speed or spindle sync)."), true},
    {42, QT_TRANSLATE_NOOP("grbl", "Threading needs the ZX plane."), true},
    {43, QT_TRANSLATE_NOOP("grbl", "The maximum feed rate is exceeded."), true},
    {44, QT_TRANSLATE_NOOP("grbl", "The spindle speed is out of range."), true},
    {45, QT_TRANSLATE_NOOP("grbl", "A limit switch is engaged: only homing is allowed."), true},
    {46, QT_TRANSLATE_NOOP("grbl", "The machine must be homed before it can continue."), true},
    {47, QT_TRANSLATE_NOOP("grbl", "The current tool is not set (tool changer)."), true},
    {48, QT_TRANSLATE_NOOP("grbl", "Two value words conflict."), true},
    {49, QT_TRANSLATE_NOOP("grbl", "The power-on self test failed; a hard reset is needed."), true},
    {50, QT_TRANSLATE_NOOP("grbl", "The emergency stop is active."), true},
    {51, QT_TRANSLATE_NOOP("grbl", "A motor driver reports a fault."), true},
    {52, QT_TRANSLATE_NOOP("grbl", "The setting value is out of range."), true},
    {53, QT_TRANSLATE_NOOP("grbl", "This setting is not available on this controller."), true},
    {54, QT_TRANSLATE_NOOP("grbl", "The retract position is below the drilling depth."), true},
    {55, QT_TRANSLATE_NOOP("grbl", "Two auto-squared axes cannot be homed at the same time."), true},
    {56, QT_TRANSLATE_NOOP("grbl", "The coordinate system is locked."), true},
    {57, QT_TRANSLATE_NOOP("grbl", "An unexpected file demarcation was found."), true},
    {58, QT_TRANSLATE_NOOP("grbl", "The auxiliary port is not available."), true},
    {60, QT_TRANSLATE_NOOP("grbl", "The SD card could not be mounted."), true},
    {61, QT_TRANSLATE_NOOP("grbl", "Reading a file failed."), true},
    {62, QT_TRANSLATE_NOOP("grbl", "A directory could not be opened."), true},
    {63, QT_TRANSLATE_NOOP("grbl", "The directory was not found."), true},
    {64, QT_TRANSLATE_NOOP("grbl", "The SD card is not mounted."), true},
    {65, QT_TRANSLATE_NOOP("grbl", "The file system is not mounted."), true},
    {66, QT_TRANSLATE_NOOP("grbl", "The file system is read-only."), true},
    {70, QT_TRANSLATE_NOOP("grbl", "Bluetooth could not be started."), true},
    {71, QT_TRANSLATE_NOOP("grbl", "An expression contains an unknown operation."), true},
    {72, QT_TRANSLATE_NOOP("grbl", "An expression divides by zero."), true},
    {73, QT_TRANSLATE_NOOP("grbl", "An expression argument is too large or too small."), true},
    {74, QT_TRANSLATE_NOOP("grbl", "An expression argument is not valid for its operation."), true},
    {75, QT_TRANSLATE_NOOP("grbl", "An expression is not valid."), true},
    {76, QT_TRANSLATE_NOOP("grbl", "An expression gave no number (NaN or infinity)."), true},
    {77, QT_TRANSLATE_NOOP("grbl", "Authentication is required."), true},
    {78, QT_TRANSLATE_NOOP("grbl", "Access is denied."), true},
    {79, QT_TRANSLATE_NOOP("grbl", "Not allowed while a critical event is active."), true},
    {80, QT_TRANSLATE_NOOP("grbl", "Flow statements are only allowed in a macro from the file system."), true},
    {81, QT_TRANSLATE_NOOP("grbl", "The flow statement is unknown."), true},
    {82, QT_TRANSLATE_NOOP("grbl", "A flow statement overflowed the stack."), true},
    {83, QT_TRANSLATE_NOOP("grbl", "A flow statement ran out of memory."), true},
    {84, QT_TRANSLATE_NOOP("grbl", "The file could not be opened."), true},
    {253, QT_TRANSLATE_NOOP("grbl", "A user-defined error occurred."), true},
};

const CodeMeaning kAlarms[] = {
    {1, QT_TRANSLATE_NOOP("grbl", "A hard limit switch was hit. The sudden halt has probably lost the position: home again."), false},
    {2, QT_TRANSLATE_NOOP("grbl", "A motion target lies beyond the machine travel (soft limit). The position was kept; the alarm may be unlocked."), false},
    {3, QT_TRANSLATE_NOOP("grbl", "Reset while moving. The position is probably lost: home again."), false},
    {4, QT_TRANSLATE_NOOP("grbl", "Probe failed: the probe was not in the expected state before the probing cycle began."), false},
    {5, QT_TRANSLATE_NOOP("grbl", "Probe failed: the probe did not touch within the programmed travel."), false},
    {6, QT_TRANSLATE_NOOP("grbl", "Homing failed: the homing cycle was reset."), false},
    {7, QT_TRANSLATE_NOOP("grbl", "Homing failed: the safety door was opened during homing."), false},
    {8, QT_TRANSLATE_NOOP("grbl", "Homing failed: pulling off did not clear the limit switch. Increase the pull-off distance or check the wiring."), false},
    {9, QT_TRANSLATE_NOOP("grbl", "Homing failed: no limit switch was found within the search distance. Check the maximum travel, the pull-off and the wiring."), false},
    {10, QT_TRANSLATE_NOOP("grbl", "The emergency stop is asserted: clear it and reset."), true},
    {11, QT_TRANSLATE_NOOP("grbl", "Homing is required: run homing ($H) to continue."), true},
    {12, QT_TRANSLATE_NOOP("grbl", "A limit switch is engaged: clear it before continuing."), true},
    {13, QT_TRANSLATE_NOOP("grbl", "The probe protection was triggered: clear it before continuing."), true},
    {14, QT_TRANSLATE_NOOP("grbl", "The spindle did not reach its speed in time: clear before continuing."), true},
    {15, QT_TRANSLATE_NOOP("grbl", "Homing failed: the second switch of an auto-squared axis was not found within the search distance."), true},
    {16, QT_TRANSLATE_NOOP("grbl", "The power-on self test failed."), true},
    {17, QT_TRANSLATE_NOOP("grbl", "A motor driver reports a fault."), true},
    {18, QT_TRANSLATE_NOOP("grbl", "Homing failed: the homing configuration is not valid."), true},
};

const CodeMeaning* find(const CodeMeaning* begin, const CodeMeaning* end, int code)
{
    const CodeMeaning* it = std::lower_bound(begin, end, code, [](const CodeMeaning& m, int c) { return m.code < c; });
    return it != end && it->code == code ? it : nullptr;
}

} // namespace

const CodeMeaning* errorMeaning(int code) { return find(std::begin(kErrors), std::end(kErrors), code); }
const CodeMeaning* alarmMeaning(int code) { return find(std::begin(kAlarms), std::end(kAlarms), code); }

const CodeMeaning* errorTable(std::size_t* count)
{
    if (count)
        *count = std::size(kErrors);
    return kErrors;
}

const CodeMeaning* alarmTable(std::size_t* count)
{
    if (count)
        *count = std::size(kAlarms);
    return kAlarms;
}

motion::msg::Message errorMessage(int code, std::string_view line)
{
    return motion::msg::make("grbl.error", {motion::msg::integer("code", code, motion::msg::Unit::None), motion::msg::verbatim("line", std::string(line))});
}

motion::msg::Message alarmMessage(int code) { return motion::msg::make("grbl.alarm", {motion::msg::integer("code", code, motion::msg::Unit::None)}); }

} // namespace dev::grbl
