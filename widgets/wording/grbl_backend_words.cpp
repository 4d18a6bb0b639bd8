// Words for the GRBL backend's own messages (ids grbl.*, docs/grbl.md "Messages") that the
// table in grbl_words.cpp does not word, and the reasons it gives for what GRBL cannot do
// (capability.because.grbl_*). Context words::GrblBackendWords (its Chinese is pending). An error:N or ALARM:N is worded with
// its documented meaning (device/backends/grbl/grbl_codes.cpp, translated in the "grbl" context)
// and, for an error, the line it answers.
#include "widgets/wording/areas.h"
#include "widgets/wording/wording.h"

#include "device/backends/grbl/grbl_codes.h"

#include <QCoreApplication>

namespace words::areas {
namespace {

class GrblBackendWords {
    Q_DECLARE_TR_FUNCTIONS(words::GrblBackendWords)
public:
    static QString text(const msg::Message& m);
    static QString term(const std::string& id);

private:
    static QString meaning(const grbl::CodeMeaning* c);
};

QString GrblBackendWords::meaning(const grbl::CodeMeaning* c)
{
    return c ? QCoreApplication::translate("grbl", c->text) : tr("a code this version of BenchPilot does not know");
}

QString GrblBackendWords::text(const msg::Message& m)
{
    const std::string& id = m.id;
    auto a = [&m](const char* name) { return words::arg(m, name); };
    if (id == "grbl.error") {
        const int code = static_cast<int>(m.integer("code"));
        const QString what = meaning(grbl::errorMeaning(code));
        if (m.text("line").empty())
            return tr("error:%1 — %2").arg(code).arg(what);
        return tr("error:%1 — %2 (the controller's answer to \"%3\")").arg(code).arg(what, a("line"));
    }
    if (id == "grbl.alarm") {
        const int code = static_cast<int>(m.integer("code"));
        return tr("ALARM:%1 — %2").arg(code).arg(meaning(grbl::alarmMeaning(code)));
    }
    if (id == "grbl.status.malformed")
        return tr("A status report could not be read (%1): %2").arg(a("reason"), a("line"));
    if (id == "grbl.settings.missing")
        return tr("The controller's setting $%1 (axis %2) is missing.").arg(a("setting"), a("axis"));
    if (id == "grbl.settings.invalid")
        return tr("The controller's setting $%1 (axis %2) is %3; it must be above 0.").arg(a("setting"), a("axis"), a("value"));
    if (id == "grbl.settings.report_inches")
        return tr("The controller reports positions in inches ($13=1); BenchPilot converts them to millimetres.");
    if (id == "grbl.settings.soft_limits_without_homing")
        return tr("Soft limits are on ($20=1) but homing is off ($22=0): GRBL cannot enforce them.");
    if (id == "grbl.jog.budget_too_small")
        return tr("Even a creeping jog could not stop within %1: the link latency %2 and the refresh period %3 leave no room.")
            .arg(a("budget"), a("latency"), a("refresh"));
    if (id == "grbl.jog.speed_limited")
        return tr("The jog runs at %1 instead of %2, so that it stops within %3 of a release, and of a lost link.")
            .arg(a("speed"), a("asked"), a("budget"));
    if (id == "grbl.gcode.not_finite")
        return tr("The %1 word of a G-code line is not a number GRBL can take.").arg(a("word"));
    if (id == "grbl.gcode.bad_feed")
        return tr("A feed of %1 is not one GRBL can run.").arg(a("feed"));
    if (id == "grbl.gcode.bad_dwell")
        return tr("A dwell of %1 is not one GRBL can wait.").arg(a("seconds"));
    if (id == "grbl.gcode.bad_axis")
        return tr("%1 is not a GRBL axis.").arg(a("axis"));
    if (id == "grbl.gcode.no_axes")
        return tr("A G-code move names no axis.");
    if (id == "grbl.gcode.bad_port")
        return tr("Output %1 is not a digital output number (0–255).").arg(a("port"));
    if (id == "grbl.gcode.bad_setting")
        return tr("$%1 is not a setting number.").arg(a("setting"));
    if (id == "grbl.gcode.too_long")
        return tr("The G-code line \"%1\" is longer than the %2 GRBL reads.").arg(a("line"), a("limit"));
    if (id == "grbl.device_message")
        return tr("The controller says: %1").arg(a("text"));
    if (id == "grbl.device_line")
        return tr("The controller sent: %1").arg(a("line"));
    if (id == "grbl.unknown_line")
        return tr("A line from the controller was not understood and was ignored (%1 so far): %2").arg(a("count"), a("line"));
    if (id == "grbl.line_too_long")
        return tr("The controller sent a line longer than %1; the rest of it was dropped (noise, or a wrong baud rate?).").arg(a("limit"));
    if (id == "grbl.controller_reset") {
        if (m.integer("lost") == 0)
            return tr("The controller reset by itself; its position is no longer trusted.");
        return tr("The controller reset by itself: %1 lines were lost (the first \"%2\"); its position is no longer trusted.")
            .arg(a("lost"), a("first"));
    }
    return {};
}

QString GrblBackendWords::term(const std::string& id)
{
    if (id == "capability.because.grbl_homing_disabled")
        return tr("homing is disabled on the controller ($22=0): take the present position as home instead (Set home here)");
    if (id == "capability.because.grbl_open_loop")
        return tr("GRBL drives its steppers open loop, with no encoder to read and no loop to tune");
    if (id == "capability.because.grbl_no_watchdog")
        return tr("GRBL cannot notice that BenchPilot went away; what is queued ahead of a jog runs out within the machine "
                  "profile's stop budget (250 ms unless it says otherwise)");
    if (id == "capability.because.grbl_machine_travel")
        return tr("GRBL enforces only its machine travel ($130–$132)");
    if (id == "capability.because.grbl_xy_plane")
        return tr("its X and Y are not GRBL's X and Y, and GRBL draws arcs only in its XY plane");
    if (id == "capability.because.no_pump_in_profile")
        return tr("the machine profile names no pump axis");
    if (id == "capability.because.no_trigger_in_profile")
        return tr("the machine profile names no trigger output");
    if (id == "grbl.status.unknown_state")
        return tr("an unknown state");
    if (id == "grbl.status.bad_substate")
        return tr("a bad sub-state");
    if (id == "grbl.status.bad_position")
        return tr("a bad position");
    if (id == "grbl.status.bad_offset")
        return tr("a bad work offset");
    if (id == "grbl.status.bad_buffer")
        return tr("a bad buffer state");
    if (id == "grbl.status.bad_line_number")
        return tr("a bad line number");
    if (id == "grbl.status.bad_feed")
        return tr("a bad feed");
    if (id == "grbl.status.bad_pins")
        return tr("bad pin states");
    if (id == "grbl.status.bad_overrides")
        return tr("bad override values");
    if (id == "grbl.status.bad_accessories")
        return tr("bad accessory states");
    if (id == "grbl.status.no_position")
        return tr("no position");
    return {};
}

} // namespace

QString grblBackend(const msg::Message& m) { return GrblBackendWords::text(m); }
QString grblBackendTerm(const std::string& id) { return GrblBackendWords::term(id); }

} // namespace words::areas
