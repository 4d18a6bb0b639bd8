// Words for the grbl.* ids (docs/grbl.md, "Messages"). error:N and ALARM:N are worded
// with their meaning from device/backends/grbl/grbl_codes.cpp (context "grbl"); the
// rest is one row per id, the English source with %1, %2 … for the arguments
// named beside it (word_table.h).
#include "widgets/wording/areas.h"
#include "widgets/wording/word_table.h"
#include "device/backends/grbl/grbl_codes.h"

#include <QCoreApplication>

namespace ui::words::areas {
namespace {

// clang-format off
const Row kRows[] = {
    {"grbl.error.worded", QT_TRANSLATE_NOOP3("ui::words::GrblWords", "error %1: %2 (answering \"%3\")", "grbl.error.worded"), "code,meaning,line"},
    {"grbl.error.worded_no_line", QT_TRANSLATE_NOOP3("ui::words::GrblWords", "error %1: %2", "grbl.error.worded_no_line"), "code,meaning"},
    {"grbl.error.refused", QT_TRANSLATE_NOOP3("ui::words::GrblWords", "%1 refused by the controller: error %2: %3 (answering \"%4\")", "grbl.error.refused"), "request,code,meaning,line"},
    {"grbl.error.refused_no_line", QT_TRANSLATE_NOOP3("ui::words::GrblWords", "%1 refused by the controller: error %2: %3", "grbl.error.refused_no_line"), "request,code,meaning"},
    {"grbl.alarm.worded", QT_TRANSLATE_NOOP3("ui::words::GrblWords", "alarm %1: %2", "grbl.alarm.worded"), "code,meaning"},
    {"grbl.error.unknown_code", QT_TRANSLATE_NOOP3("ui::words::GrblWords", "a code this BenchPilot does not know (see the controller's documentation)", "grbl.error.unknown_code")},
    {"grbl.alarm.unknown_code", QT_TRANSLATE_NOOP3("ui::words::GrblWords", "a code this BenchPilot does not know (see the controller's documentation)", "grbl.alarm.unknown_code")},
    {"grbl.status.malformed", QT_TRANSLATE_NOOP3("ui::words::GrblWords", "a status report that cannot be read (%1): %2", "grbl.status.malformed"), "reason,line"},
    {"grbl.settings.missing", QT_TRANSLATE_NOOP3("ui::words::GrblWords", "$%1 (%2) is missing from the settings ($$)", "grbl.settings.missing"), "setting,axis"},
    {"grbl.settings.invalid", QT_TRANSLATE_NOOP3("ui::words::GrblWords", "$%1 (%2) is %3: it must be above 0", "grbl.settings.invalid"), "setting,axis,value"},
    {"grbl.settings.report_inches", QT_TRANSLATE_NOOP3("ui::words::GrblWords", "$13=1: the controller reports in inches; BenchPilot converts them to mm", "grbl.settings.report_inches")},
    {"grbl.settings.soft_limits_without_homing", QT_TRANSLATE_NOOP3("ui::words::GrblWords", "$20=1 with $22=0: soft limits are on but homing is off, so the limits have no reference", "grbl.settings.soft_limits_without_homing")},
    {"grbl.jog.budget_too_small", QT_TRANSLATE_NOOP3("ui::words::GrblWords", "even a creeping jog cannot stop within %1: the link takes %2 and jogs are refreshed every %3", "grbl.jog.budget_too_small"), "budget,latency,refresh"},
    {"grbl.gcode.not_finite", QT_TRANSLATE_NOOP3("ui::words::GrblWords", "the %1 word is not a finite number", "grbl.gcode.not_finite"), "word"},
    {"grbl.gcode.bad_feed", QT_TRANSLATE_NOOP3("ui::words::GrblWords", "the feed %1 must be above 0", "grbl.gcode.bad_feed"), "feed"},
    {"grbl.gcode.bad_dwell", QT_TRANSLATE_NOOP3("ui::words::GrblWords", "the dwell %1 must be 0 or more", "grbl.gcode.bad_dwell"), "seconds"},
    {"grbl.gcode.bad_axis", QT_TRANSLATE_NOOP3("ui::words::GrblWords", "%1 is not an axis GRBL moves", "grbl.gcode.bad_axis"), "axis"},
    {"grbl.gcode.no_axes", QT_TRANSLATE_NOOP3("ui::words::GrblWords", "a move needs at least one axis", "grbl.gcode.no_axes")},
    {"grbl.gcode.bad_port", QT_TRANSLATE_NOOP3("ui::words::GrblWords", "output port %1 is not one GRBL has", "grbl.gcode.bad_port"), "port"},
    {"grbl.gcode.bad_setting", QT_TRANSLATE_NOOP3("ui::words::GrblWords", "$%1 is not a setting number", "grbl.gcode.bad_setting"), "setting"},
    {"grbl.gcode.too_long", QT_TRANSLATE_NOOP3("ui::words::GrblWords", "the line is longer than GRBL accepts (%1): %2", "grbl.gcode.too_long"), "limit,line"},
};

const TermRow kTerms[] = {
    {"grbl.status.unknown_state", QT_TRANSLATE_NOOP3("ui::words::GrblWords", "unknown state", "grbl.status.unknown_state")},
    {"grbl.status.bad_substate", QT_TRANSLATE_NOOP3("ui::words::GrblWords", "bad sub-state", "grbl.status.bad_substate")},
    {"grbl.status.bad_position", QT_TRANSLATE_NOOP3("ui::words::GrblWords", "bad position", "grbl.status.bad_position")},
    {"grbl.status.bad_offset", QT_TRANSLATE_NOOP3("ui::words::GrblWords", "bad work offset", "grbl.status.bad_offset")},
    {"grbl.status.bad_buffer", QT_TRANSLATE_NOOP3("ui::words::GrblWords", "bad buffer state", "grbl.status.bad_buffer")},
    {"grbl.status.bad_line_number", QT_TRANSLATE_NOOP3("ui::words::GrblWords", "bad line number", "grbl.status.bad_line_number")},
    {"grbl.status.bad_feed", QT_TRANSLATE_NOOP3("ui::words::GrblWords", "bad feed and speed", "grbl.status.bad_feed")},
    {"grbl.status.bad_pins", QT_TRANSLATE_NOOP3("ui::words::GrblWords", "bad pin state", "grbl.status.bad_pins")},
    {"grbl.status.bad_overrides", QT_TRANSLATE_NOOP3("ui::words::GrblWords", "bad overrides", "grbl.status.bad_overrides")},
    {"grbl.status.bad_accessories", QT_TRANSLATE_NOOP3("ui::words::GrblWords", "bad accessory state", "grbl.status.bad_accessories")},
    {"grbl.status.no_position", QT_TRANSLATE_NOOP3("ui::words::GrblWords", "no position", "grbl.status.no_position")},
};
// clang-format on

/// grbl.error {code, line} and grbl.alarm {code}: the code's meaning (translated in
/// the "grbl" context), or that it is a code this host does not know.
QString codeSentence(const motion::msg::Message& m, const Row* rows, std::size_t count)
{
    const bool error = m.id == "grbl.error";
    if (!error && m.id != "grbl.alarm")
        return {};
    const int code = static_cast<int>(m.integer("code"));
    const dev::grbl::CodeMeaning* c = error ? dev::grbl::errorMeaning(code) : dev::grbl::alarmMeaning(code);
    motion::msg::Message worded = m;
    const QString meaning = c ? QCoreApplication::translate("grbl", c->text)
                              : fromRows("ui::words::GrblWords", rows, count, motion::msg::make(error ? "grbl.error.unknown_code" : "grbl.alarm.unknown_code"));
    worded.args.push_back(motion::msg::verbatim("meaning", meaning.toStdString()));
    // An error that answers one of our requests says which (grbl.error{code, line, request}).
    const char* withRequest = m.text("line").empty() ? "grbl.error.refused_no_line" : "grbl.error.refused";
    const char* plain = m.text("line").empty() ? "grbl.error.worded_no_line" : "grbl.error.worded";
    worded.id = !error ? "grbl.alarm.worded" : (m.arg("request") ? withRequest : plain);
    return fromRows("ui::words::GrblWords", rows, count, worded);
}

} // namespace

QString grbl(const motion::msg::Message& m)
{
    const QString special = codeSentence(m, kRows, std::size(kRows));
    if (!special.isNull())
        return special;
    const QString t = fromRows("ui::words::GrblWords", kRows, m);
    return t.isNull() ? grblBackend(m) : t;
}
QString grblTerm(const std::string& id)
{
    const QString t = fromTerms("ui::words::GrblWords", kTerms, id);
    return t.isNull() ? grblBackendTerm(id) : t;
}

} // namespace ui::words::areas
