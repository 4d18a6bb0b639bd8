// Words for the GRBL backend's own messages (ids grbl.*, docs/grbl.md "Messages") that the
// table in grbl_words.cpp does not word — the GRBL client's refusals, link and path messages,
// the protocol probe's and the machine profile reader's — and the reasons it gives for what
// GRBL cannot do (capability.because.grbl_*). Context ui::words::GrblBackendWords (its Chinese is
// pending). A code (error:N in grbl.identify.refused) is worded with its documented meaning
// (device/backends/grbl/grbl_codes.cpp, translated in the "grbl" context).
#include "widgets/wording/areas.h"
#include "widgets/wording/word_table.h"
#include "widgets/wording/wording.h"

#include "device/backends/grbl/grbl_codes.h"

#include <QCoreApplication>

namespace ui::words::areas {
namespace {

// What the GRBL client, the protocol probe and the machine profile reader say (docs/grbl.md,
// "Messages"): one row per id, the English with %1, %2 … for the arguments named beside it.
// grbl.error, grbl.alarm, grbl.status.*, grbl.settings.*, grbl.gcode.* and grbl.jog.budget_too_small
// are worded by grbl_words.cpp's table, which comes first.
// clang-format off
const Row kRows[] = {
    {"grbl.connect.no_answer", QT_TRANSLATE_NOOP3("ui::words::GrblBackendWords", "no answer from %1 within %2: check power, cable and baud rate (GRBL boards usually run at 115200 Bd)", "grbl.connect.no_answer"), "link,seconds"},
    {"grbl.connect.no_grbl_line", QT_TRANSLATE_NOOP3("ui::words::GrblBackendWords", "%1 sent %2 bytes but no GRBL line within %3: a wrong baud rate, or not a GRBL controller", "grbl.connect.no_grbl_line"), "link,bytes,seconds"},
    {"grbl.connect.never_acknowledged", QT_TRANSLATE_NOOP3("ui::words::GrblBackendWords", "%1 answers like GRBL but never acknowledged a line within %2: it may be busy (in a critical alarm it hears nothing but a reset)", "grbl.connect.never_acknowledged"), "link,seconds"},
    {"grbl.connect.identify_silent", QT_TRANSLATE_NOOP3("ui::words::GrblBackendWords", "%1 stopped answering while it was being identified ($I, $$, $#)", "grbl.connect.identify_silent"), "link"},
    {"grbl.identify.not_answered", QT_TRANSLATE_NOOP3("ui::words::GrblBackendWords", "%1 was not answered: %2", "grbl.identify.not_answered"), "command,cause"},
    {"grbl.identify.refused", QT_TRANSLATE_NOOP3("ui::words::GrblBackendWords", "the controller refused %1 with error:%2 (%3)", "grbl.identify.refused"), "command,code,meaning"},
    {"grbl.identify.no_limits", QT_TRANSLATE_NOOP3("ui::words::GrblBackendWords", "the controller's settings ($$) do not give its limits: %1 (%2 problems in all)", "grbl.identify.no_limits"), "problem,count"},
    {"grbl.identify.inches_refused", QT_TRANSLATE_NOOP3("ui::words::GrblBackendWords", "the controller reports positions in inches ($13=1) and the machine profile refuses inch reports: set $13=0 on the controller, or \"inch_reports\": \"convert\" in the profile", "grbl.identify.inches_refused")},
    {"grbl.identify.axis_missing", QT_TRANSLATE_NOOP3("ui::words::GrblBackendWords", "the machine profile drives axis %1 with GRBL axis %2, but this controller has axes %3", "grbl.identify.axis_missing"), "axis,grbl_axis,axes"},
    {"grbl.identify.pump_axis_missing", QT_TRANSLATE_NOOP3("ui::words::GrblBackendWords", "the machine profile drives the pump with GRBL axis %1, but this controller has axes %2", "grbl.identify.pump_axis_missing"), "grbl_axis,axes"},
    {"grbl.silent", QT_TRANSLATE_NOOP3("ui::words::GrblBackendWords", "the controller stopped answering: no status report for %1", "grbl.silent"), "seconds"},
    {"grbl.silent_with_noise", QT_TRANSLATE_NOOP3("ui::words::GrblBackendWords", "no status report for %1 (%2 unreadable lines: a wrong baud rate or noise?)", "grbl.silent_with_noise"), "seconds,count"},
    {"grbl.reset_by_itself", QT_TRANSLATE_NOOP3("ui::words::GrblBackendWords", "the controller reset by itself", "grbl.reset_by_itself")},
    {"grbl.reset_flushed", QT_TRANSLATE_NOOP3("ui::words::GrblBackendWords", "a reset flushed it", "grbl.reset_flushed")},
    {"grbl.stop_timeout", QT_TRANSLATE_NOOP3("ui::words::GrblBackendWords", "stop: the controller did not come to rest and reset within %1", "grbl.stop_timeout"), "seconds"},
    {"grbl.stop_overtaken_by_estop", QT_TRANSLATE_NOOP3("ui::words::GrblBackendWords", "stop overtaken by the E-stop", "grbl.stop_overtaken_by_estop")},
    {"grbl.beyond_travel", QT_TRANSLATE_NOOP3("ui::words::GrblBackendWords", "%1 %2 is beyond the machine travel %3 … %4 (work coordinates, G54; the controller's $%5): refused before sending, since GRBL would stop with ALARM:2 and need a reset", "grbl.beyond_travel"), "axis,target,min,max,setting"},
    {"grbl.line_not_sent", QT_TRANSLATE_NOOP3("ui::words::GrblBackendWords", "%1: the line \"%2\" cannot be sent", "grbl.line_not_sent"), "request,line"},
    {"grbl.estop_latched", QT_TRANSLATE_NOOP3("ui::words::GrblBackendWords", "%1: the E-stop is latched: reset it first", "grbl.estop_latched"), "request"},
    {"grbl.home_one_or_all", QT_TRANSLATE_NOOP3("ui::words::GrblBackendWords", "home: GRBL homes one axis or all of them, not %1", "grbl.home_one_or_all"), "axes"},
    {"grbl.set_zero_while_moving", QT_TRANSLATE_NOOP3("ui::words::GrblBackendWords", "set zero: wait until the instrument is still", "grbl.set_zero_while_moving")},
    {"grbl.set_zero_no_axis", QT_TRANSLATE_NOOP3("ui::words::GrblBackendWords", "set zero: no such axis", "grbl.set_zero_no_axis")},
    {"grbl.soft_limits_fixed", QT_TRANSLATE_NOOP3("ui::words::GrblBackendWords", "GRBL enforces its machine travel ($130–$132) as its soft limits; other limits cannot be set from here", "grbl.soft_limits_fixed")},
    {"grbl.move_in_alarm", QT_TRANSLATE_NOOP3("ui::words::GrblBackendWords", "move: the controller is in alarm (its position is not trusted): home it, or unlock it on your word", "grbl.move_in_alarm")},
    {"grbl.move_not_established", QT_TRANSLATE_NOOP3("ui::words::GrblBackendWords", "move: axis %1 has no established position: home it, or take the present position as home (Set home here, `zero`) first", "grbl.move_not_established"), "axis"},
    {"grbl.no_trigger_output", QT_TRANSLATE_NOOP3("ui::words::GrblBackendWords", "this instrument has no trigger output: the machine profile names none", "grbl.no_trigger_output")},
    {"grbl.trigger_bad_width", QT_TRANSLATE_NOOP3("ui::words::GrblBackendWords", "trigger: %1 is not a pulse width", "grbl.trigger_bad_width"), "width"},
    {"grbl.event.estop", QT_TRANSLATE_NOOP3("ui::words::GrblBackendWords", "E-stop: feed hold and soft reset; if it was moving, the controller lost its position", "grbl.event.estop")},
    {"grbl.event.estop_cleared", QT_TRANSLATE_NOOP3("ui::words::GrblBackendWords", "E-stop latch cleared", "grbl.event.estop_cleared")},
    {"grbl.event.position", QT_TRANSLATE_NOOP3("ui::words::GrblBackendWords", "work position (G54) %1, machine position %2", "grbl.event.position"), "work,machine"},
    {"grbl.home_kept", QT_TRANSLATE_NOOP3("ui::words::GrblBackendWords", "the controller has not restarted since home was set here: %1 keep their established positions", "grbl.home_kept"), "axes"},
    {"grbl.home_lost_restart", QT_TRANSLATE_NOOP3("ui::words::GrblBackendWords", "the controller restarted as the port opened (its start-up message came): %1 have no established position until home is set again", "grbl.home_lost_restart"), "axes"},
    {"grbl.home_lost_changed", QT_TRANSLATE_NOOP3("ui::words::GrblBackendWords", "the controller's work offset or machine position is not what it was when home was set here (it restarted, or another program moved it): %1 have no established position until home is set again", "grbl.home_lost_changed"), "axes"},
    {"grbl.home_not_saved", QT_TRANSLATE_NOOP3("ui::words::GrblBackendWords", "the home set here cannot be remembered in %1: the next connection will not keep it", "grbl.home_not_saved"), "file"},
    {"grbl.path.already_running", QT_TRANSLATE_NOOP3("ui::words::GrblBackendWords", "a path is already running", "grbl.path.already_running")},
    {"grbl.path.not_begun", QT_TRANSLATE_NOOP3("ui::words::GrblBackendWords", "no path begun, or it has ended", "grbl.path.not_begun")},
    {"grbl.path.out_of_sequence", QT_TRANSLATE_NOOP3("ui::words::GrblBackendWords", "segment %1 expected, %2 sent", "grbl.path.out_of_sequence"), "expected,sent"},
    {"grbl.path.window_full", QT_TRANSLATE_NOOP3("ui::words::GrblBackendWords", "the path window is full (room for %1 more segments)", "grbl.path.window_full"), "free"},
    {"grbl.path.z_in_path", QT_TRANSLATE_NOOP3("ui::words::GrblBackendWords", "segment %1 asks Z to follow the path: GRBL cannot", "grbl.path.z_in_path"), "segment"},
    {"grbl.probe.no_answer", QT_TRANSLATE_NOOP3("ui::words::GrblBackendWords", "no answer from %1 within %2, neither to a GRBL status query nor to a BenchPilot HELLO: check power, cable and baud rate", "grbl.probe.no_answer"), "link,seconds"},
    {"grbl.probe.unreadable", QT_TRANSLATE_NOOP3("ui::words::GrblBackendWords", "%1 sent %2 bytes within %3 that are neither GRBL lines nor BenchPilot frames: a wrong baud rate, or another kind of device", "grbl.probe.unreadable"), "link,bytes,seconds"},
    {"grbl.probe.found_grbl", QT_TRANSLATE_NOOP3("ui::words::GrblBackendWords", "%1 %2", "grbl.probe.found_grbl"), "firmware,version"},
    {"grbl.probe.found_grbl_unnamed", QT_TRANSLATE_NOOP3("ui::words::GrblBackendWords", "a GRBL controller", "grbl.probe.found_grbl_unnamed")},
    {"grbl.probe.found_benchpilot", QT_TRANSLATE_NOOP3("ui::words::GrblBackendWords", "BenchPilot protocol %1 (%2)", "grbl.probe.found_benchpilot"), "version,instrument"},
    {"grbl.profile.axis_letter", QT_TRANSLATE_NOOP3("ui::words::GrblBackendWords", "must be one upper-case axis letter (got \"%1\")", "grbl.profile.axis_letter"), "text"},
    {"grbl.profile.axes_order", QT_TRANSLATE_NOOP3("ui::words::GrblBackendWords", "the %1 has axes %2 in that order (got \"%3\")", "grbl.profile.axes_order"), "instrument,wanted,got"},
    {"grbl.profile.not_grbl_axis", QT_TRANSLATE_NOOP3("ui::words::GrblBackendWords", "\"%1\" is not a GRBL axis (X, Y, Z, A, B, C)", "grbl.profile.not_grbl_axis"), "axis"},
    {"grbl.profile.grbl_axis_used", QT_TRANSLATE_NOOP3("ui::words::GrblBackendWords", "GRBL axis %1 is already used", "grbl.profile.grbl_axis_used"), "axis"},
    {"grbl.profile.stage_no_pump", QT_TRANSLATE_NOOP3("ui::words::GrblBackendWords", "the stage has no pump", "grbl.profile.stage_no_pump")},
    {"grbl.profile.pump_axis_used", QT_TRANSLATE_NOOP3("ui::words::GrblBackendWords", "GRBL axis %1 already drives another axis", "grbl.profile.pump_axis_used"), "axis"},
    {"grbl.profile.ul_per_mm_range", QT_TRANSLATE_NOOP3("ui::words::GrblBackendWords", "must be above 0 and at most %2 (got %1)", "grbl.profile.ul_per_mm_range"), "value,max"},
    {"grbl.profile.stop_budget_too_small", QT_TRANSLATE_NOOP3("ui::words::GrblBackendWords", "must exceed link_latency_s + refresh_s + 0.01 s (%2), or not even a creeping jog can keep it (got %1)", "grbl.profile.stop_budget_too_small"), "value,least"},
};

const TermRow kTerms[] = {
    {"grbl.request.unlock", QT_TRANSLATE_NOOP3("ui::words::GrblBackendWords", "unlock", "grbl.request.unlock")},
    {"grbl.request.dwell", QT_TRANSLATE_NOOP3("ui::words::GrblBackendWords", "dwell", "grbl.request.dwell")},
    {"grbl.request.trigger", QT_TRANSLATE_NOOP3("ui::words::GrblBackendWords", "trigger", "grbl.request.trigger")},
    {"grbl.request.status", QT_TRANSLATE_NOOP3("ui::words::GrblBackendWords", "status", "grbl.request.status")},
};
// clang-format on

class GrblBackendWords {
    Q_DECLARE_TR_FUNCTIONS(ui::words::GrblBackendWords)
public:
    static QString text(const motion::msg::Message& m);
    static QString term(const std::string& id);

private:
    static QString meaning(const dev::grbl::CodeMeaning* c);
};

QString GrblBackendWords::meaning(const dev::grbl::CodeMeaning* c)
{
    return c ? QCoreApplication::translate("grbl", c->text) : tr("a code this version of BenchPilot does not know");
}

QString GrblBackendWords::text(const motion::msg::Message& m)
{
    const std::string& id = m.id;
    auto a = [&m](const char* name) { return ui::words::arg(m, name); };
    if (id == "grbl.identify.refused") {
        motion::msg::Message worded = m;  // the row's %3 is the code's meaning
        worded.args.push_back(motion::msg::verbatim("meaning", meaning(dev::grbl::errorMeaning(static_cast<int>(m.integer("code")))).toStdString()));
        return fromRows("ui::words::GrblBackendWords", kRows, worded);
    }
    if (const QString t = fromRows("ui::words::GrblBackendWords", kRows, m); !t.isNull())
        return t;
    if (id == "grbl.jog.speed_limited")
        return tr("The jog runs at %1 instead of %2, so that it stops within %3 of a release, and of a lost link.")
            .arg(a("speed"), a("asked"), a("budget"));
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
    if (const QString t = fromTerms("ui::words::GrblBackendWords", kTerms, id); !t.isNull())
        return t;
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
    return {};
}

} // namespace

QString grblBackend(const motion::msg::Message& m) { return GrblBackendWords::text(m); }
QString grblBackendTerm(const std::string& id) { return GrblBackendWords::term(id); }

} // namespace ui::words::areas
