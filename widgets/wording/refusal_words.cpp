// Words for device.refused: what the device refused, worded from its error code, the
// axis at fault and the code's value (device/backends/benchpilot/refusal_value.h), in
// the operator's language. Where the firmware's own words add specifics the code cannot
// (which value was out of range), the English quotes them; a translation words the
// sentence alone, since the device speaks English.
#include "widgets/wording/areas.h"
#include "widgets/wording/word_table.h"

#include <QCoreApplication>

#include <cstring>

namespace ui::words::areas {
namespace {

constexpr const char* kContext = "ui::words::RefusalWords";

// clang-format off
const Row kRows[] = {
    {"device.refused.unknown_command", QT_TRANSLATE_NOOP3("ui::words::RefusalWords", "the device does not know this request (type %1)", "device.refused.unknown_command"), "value"},
    {"device.refused.bad_payload", QT_TRANSLATE_NOOP3("ui::words::RefusalWords", "the device could not read this request", "device.refused.bad_payload")},
    {"device.refused.bad_axis", QT_TRANSLATE_NOOP3("ui::words::RefusalWords", "the instrument has no axis or channel %1", "device.refused.bad_axis"), "value"},
    {"device.refused.not_homed", QT_TRANSLATE_NOOP3("ui::words::RefusalWords", "not homed: home it first", "device.refused.not_homed")},
    {"device.refused.soft_limit", QT_TRANSLATE_NOOP3("ui::words::RefusalWords", "it would cross the soft limit at %1", "device.refused.soft_limit"), "value"},
    {"device.refused.busy", QT_TRANSLATE_NOOP3("ui::words::RefusalWords", "still moving or homing", "device.refused.busy")},
    {"device.refused.estop_active", QT_TRANSLATE_NOOP3("ui::words::RefusalWords", "the E-stop is latched: reset it first", "device.refused.estop_active")},
    {"device.refused.over_capacity", QT_TRANSLATE_NOOP3("ui::words::RefusalWords", "the telemetry would not fit the link: at most %1 fits", "device.refused.over_capacity"), "value"},
    {"device.refused.out_of_range", QT_TRANSLATE_NOOP3("ui::words::RefusalWords", "a speed, limit, rate or count in the request is out of the device's range", "device.refused.out_of_range")},
    {"device.refused.fault", QT_TRANSLATE_NOOP3("ui::words::RefusalWords", "the device is in a fault state: reset it first", "device.refused.fault")},
    {"device.refused.bad_gains", QT_TRANSLATE_NOOP3("ui::words::RefusalWords", "gain %1 is not finite, is negative or is above the device's limit; nothing changed", "device.refused.bad_gains"), "value"},
    {"device.refused.test_active", QT_TRANSLATE_NOOP3("ui::words::RefusalWords", "a tuning test runs on it", "device.refused.test_active")},
    {"device.refused.not_closed_loop", QT_TRANSLATE_NOOP3("ui::words::RefusalWords", "it has no closed loop (PID) to tune", "device.refused.not_closed_loop")},
    {"device.refused.no_capture", QT_TRANSLATE_NOOP3("ui::words::RefusalWords", "no test capture to read there (%1 samples captured)", "device.refused.no_capture"), "value"},
    {"device.refused.path_queue_full", QT_TRANSLATE_NOOP3("ui::words::RefusalWords", "the path queue has room for only %1 more segments", "device.refused.path_queue_full"), "value"},
    {"device.refused.path_sequence", QT_TRANSLATE_NOOP3("ui::words::RefusalWords", "the device expected path segment %1 next", "device.refused.path_sequence"), "value"},
    {"device.refused.path_geometry", QT_TRANSLATE_NOOP3("ui::words::RefusalWords", "path segment %1 cannot be run: an arc's end is off its circle, or its radius is under two steps", "device.refused.path_geometry"), "value"},
    {"device.refused.path_state", QT_TRANSLATE_NOOP3("ui::words::RefusalWords", "no path is open to add to: none was begun, its last segment is queued, or it was aborted", "device.refused.path_state")},
    {"device.refused.comp_invalid", QT_TRANSLATE_NOOP3("ui::words::RefusalWords", "the device cannot apply this compensation; nothing changed", "device.refused.comp_invalid")},
    {"device.refused.comp_sequence", QT_TRANSLATE_NOOP3("ui::words::RefusalWords", "the compensation upload is out of order: the device expects entry %1", "device.refused.comp_sequence"), "value"},
    {"device.refused.comp_missing", QT_TRANSLATE_NOOP3("ui::words::RefusalWords", "no compensation to enable", "device.refused.comp_missing")},
    // Around the sentence: the axis it is about, and the device's own words where they add to it.
    {"device.refused.on_axis", QT_TRANSLATE_NOOP3("ui::words::RefusalWords", "axis %1: %2", "device.refused.on_axis"), "axis,sentence"},
    {"device.refused.device_says", QT_TRANSLATE_NOOP3("ui::words::RefusalWords", "%1 (the device says: %2)", "device.refused.device_says"), "sentence,detail"},
};
// clang-format on

/// Codes whose value cannot say what the firmware's words do.
bool firmwareAddsTo(const std::string& name)
{
    return name == "out_of_range" || name == "bad_payload" || name == "fault" || name == "comp_invalid" || name == "unknown_command"
           || name == "bad_gains";  // which value it was (NaN, 1e9) and the set kept
}

} // namespace

QString refusal(const motion::msg::Message& m)
{
    constexpr const char* kTermPrefix = "device.error.";
    const std::string code = m.text("code");
    if (m.id != "device.refused" || code.rfind(kTermPrefix, 0) != 0)
        return {};
    const std::string name = code.substr(std::strlen(kTermPrefix));
    motion::msg::Message s = m;
    s.id = "device.refused." + name;
    QString sentence = fromRows(kContext, kRows, s);
    if (sentence.isNull())
        return {};  // a code this host does not know: its term and the device's words (device_words.cpp)
    if (const motion::msg::Arg* axis = m.arg("axis"))
        sentence = fromRows(kContext, kRows, motion::msg::make("device.refused.on_axis", {*axis, motion::msg::verbatim("sentence", sentence.toStdString())}));
    if (firmwareAddsTo(name) && !m.text("detail").empty())
        sentence = fromRows(kContext, kRows, motion::msg::make("device.refused.device_says", {motion::msg::verbatim("sentence", sentence.toStdString()), *m.arg("detail")}));
    return sentence;
}

} // namespace ui::words::areas
