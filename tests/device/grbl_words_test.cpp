// Every GRBL error and alarm is shown with its documented meaning (and an error with the line it
// answers); every grbl.* id the backend, the protocol probe and the machine profile reader emit,
// and every reason it gives for a missing capability, is worded — none falls back to the id.
#include "widgets/wording/wording.h"

#include "device/backends/grbl/grbl_codes.h"
#include "device/client/capabilities.h"
#include "motion/message.h"

#include <QCoreApplication>

#include <algorithm>

#include <gtest/gtest.h>

namespace {

TEST(GrblWords, EveryErrorAndAlarmIsShownWithItsMeaning)
{
    std::size_t n = 0;
    const grbl::CodeMeaning* errors = grbl::errorTable(&n);
    ASSERT_GT(n, 50u);
    for (std::size_t i = 0; i < n; ++i) {
        // As the client reports it: with the request it refused (a term the sentence may leave out).
        msg::Message m = grbl::errorMessage(errors[i].code, "G1 X5 F600");
        m.args.push_back(msg::term("request", "request.move"));
        const QString text = words::text(m);
        EXPECT_TRUE(text.contains(QString::number(errors[i].code))) << text.toStdString();
        EXPECT_TRUE(text.contains(QString::fromUtf8(errors[i].text))) << text.toStdString();
        EXPECT_TRUE(text.contains(QStringLiteral("\"G1 X5 F600\""))) << text.toStdString();
    }
    const grbl::CodeMeaning* alarms = grbl::alarmTable(&n);
    ASSERT_GE(n, 9u);
    for (std::size_t i = 0; i < n; ++i) {
        const QString text = words::text(grbl::alarmMessage(alarms[i].code));
        EXPECT_TRUE(text.contains(QString::number(alarms[i].code))) << text.toStdString();
        EXPECT_TRUE(text.contains(QString::fromUtf8(alarms[i].text))) << text.toStdString();
    }
    // A code from a newer firmware is still shown, with its number.
    EXPECT_TRUE(words::text(grbl::errorMessage(250, "")).contains(QStringLiteral("250")));
    // The handshake's refusal names the command and the code's meaning.
    EXPECT_EQ(words::text(msg::make("grbl.identify.refused", {msg::verbatim("command", "$$"), msg::integer("code", 9, msg::Unit::None)})),
              QStringLiteral("the controller refused $$ with error:9 (%1)").arg(QString::fromUtf8(grbl::errorMeaning(9)->text)));
}

TEST(GrblWords, EveryIdTheBackendEmitsIsWorded)
{
    const msg::Arg link = msg::verbatim("link", "/dev/ttyUSB0 at 115200 Bd");
    const msg::Arg seconds = msg::real("seconds", 5, msg::Unit::S);
    const std::vector<msg::Message> all = {
        msg::make("grbl.status.malformed", {msg::verbatim("line", "<Idle|MPos:x>"), msg::term("reason", "grbl.status.bad_position")}),
        msg::make("grbl.settings.missing", {msg::integer("setting", 110, msg::Unit::None), msg::verbatim("axis", "X")}),
        msg::make("grbl.settings.invalid", {msg::integer("setting", 120, msg::Unit::None), msg::verbatim("axis", "Y"), msg::real("value", 0)}),
        msg::make("grbl.settings.report_inches"),
        msg::make("grbl.settings.soft_limits_without_homing"),
        msg::make("grbl.jog.budget_too_small", {msg::real("budget", 0.25, msg::Unit::S), msg::real("latency", 0.02, msg::Unit::S),
                                                msg::real("refresh", 0.25, msg::Unit::S)}),
        msg::make("grbl.jog.speed_limited", {msg::real("asked", 100, msg::Unit::MmPerS), msg::real("speed", 18.9, msg::Unit::MmPerS),
                                             msg::real("budget", 0.25, msg::Unit::S)}),
        msg::make("grbl.gcode.not_finite", {msg::verbatim("word", "X")}),
        msg::make("grbl.gcode.bad_feed", {msg::real("feed", 0, msg::Unit::MmPerMin)}),
        msg::make("grbl.gcode.bad_dwell", {msg::real("seconds", 0, msg::Unit::S)}),
        msg::make("grbl.gcode.bad_axis", {msg::verbatim("axis", "Q")}),
        msg::make("grbl.gcode.no_axes"),
        msg::make("grbl.gcode.bad_port", {msg::integer("port", 300, msg::Unit::None)}),
        msg::make("grbl.gcode.bad_setting", {msg::integer("setting", -1, msg::Unit::None)}),
        msg::make("grbl.gcode.too_long", {msg::verbatim("line", "G1 X1"), msg::integer("limit", 79, msg::Unit::Byte)}),
        msg::make("grbl.device_message", {msg::verbatim("text", "Caution: Unlocked")}),
        msg::make("grbl.device_line", {msg::verbatim("line", "[GC:G0 G54]")}),
        msg::make("grbl.unknown_line", {msg::verbatim("line", "xyz"), msg::integer("count", 1)}),
        msg::make("grbl.line_too_long", {msg::integer("limit", 1024, msg::Unit::Byte)}),
        msg::make("grbl.connect.no_answer", {link, seconds}),
        msg::make("grbl.connect.no_grbl_line", {link, msg::integer("bytes", 37), seconds}),
        msg::make("grbl.connect.never_acknowledged", {link, seconds}),
        msg::make("grbl.connect.identify_silent", {link}),
        msg::make("grbl.identify.not_answered", {msg::verbatim("command", "$I"), msg::nested("cause", msg::make("grbl.reset_flushed"))}),
        msg::make("grbl.identify.refused", {msg::verbatim("command", "$$"), msg::integer("code", 3, msg::Unit::None)}),
        msg::make("grbl.identify.no_limits", {msg::nested("problem", msg::make("grbl.settings.missing", {msg::integer("setting", 110, msg::Unit::None),
                                                                                                          msg::verbatim("axis", "X")})),
                                              msg::integer("count", 2)}),
        msg::make("grbl.identify.inches_refused"),
        msg::make("grbl.identify.axis_missing", {msg::verbatim("axis", "Z"), msg::verbatim("grbl_axis", "Z"), msg::verbatim("axes", "XY")}),
        msg::make("grbl.identify.pump_axis_missing", {msg::verbatim("grbl_axis", "A"), msg::verbatim("axes", "XYZ")}),
        msg::make("grbl.silent", {msg::real("seconds", 2.5, msg::Unit::S)}),
        msg::make("grbl.silent_with_noise", {msg::real("seconds", 2.5, msg::Unit::S), msg::integer("count", 4)}),
        msg::make("grbl.reset_by_itself"),
        msg::make("grbl.reset_flushed"),
        msg::make("grbl.stop_timeout", {msg::real("seconds", 5, msg::Unit::S)}),
        msg::make("grbl.stop_overtaken_by_estop"),
        msg::make("grbl.beyond_travel", {msg::verbatim("axis", "X"), msg::real("target", 150, msg::Unit::Mm), msg::real("min", 0, msg::Unit::Mm),
                                         msg::real("max", 100, msg::Unit::Mm), msg::integer("setting", 130, msg::Unit::None)}),
        msg::make("grbl.line_not_sent", {msg::term("request", "request.move"), msg::verbatim("line", "G0 X1")}),
        msg::make("grbl.estop_latched", {msg::term("request", "request.home")}),
        msg::make("grbl.home_one_or_all", {msg::verbatim("axes", "XY")}),
        msg::make("grbl.set_zero_while_moving"),
        msg::make("grbl.set_zero_no_axis"),
        msg::make("grbl.soft_limits_fixed"),
        msg::make("grbl.move_in_alarm"),
        msg::make("grbl.move_not_established", {msg::verbatim("axis", "Y")}),
        msg::make("grbl.no_trigger_output"),
        msg::make("grbl.trigger_bad_width", {msg::real("width", -1, msg::Unit::S)}),
        msg::make("grbl.event.estop"),
        msg::make("grbl.event.estop_cleared"),
        msg::make("grbl.event.position", {msg::real("work", 0, msg::Unit::Mm), msg::real("machine", -41.712, msg::Unit::Mm)}),
        msg::make("grbl.home_kept", {msg::verbatim("axes", "XY")}),
        msg::make("grbl.home_lost_restart", {msg::verbatim("axes", "XY")}),
        msg::make("grbl.home_lost_changed", {msg::verbatim("axes", "XY")}),
        msg::make("grbl.home_not_saved", {msg::verbatim("file", "/home/u/.local/share/BenchPilot/grbl-homes.json")}),
        msg::make("grbl.path.already_running"),
        msg::make("grbl.path.not_begun"),
        msg::make("grbl.path.out_of_sequence", {msg::integer("expected", 4, msg::Unit::None), msg::integer("sent", 6, msg::Unit::None)}),
        msg::make("grbl.path.window_full", {msg::integer("free", 3)}),
        msg::make("grbl.path.z_in_path", {msg::integer("segment", 2, msg::Unit::None)}),
        msg::make("grbl.probe.no_answer", {link, seconds}),
        msg::make("grbl.probe.unreadable", {link, msg::integer("bytes", 12), seconds}),
        msg::make("grbl.probe.found_grbl", {msg::verbatim("firmware", "grblHAL"), msg::verbatim("version", "1.1f")}),
        msg::make("grbl.probe.found_grbl_unnamed"),
        msg::make("grbl.probe.found_benchpilot", {msg::integer("version", 1, msg::Unit::None), msg::term("instrument", "instrument.stage")}),
        msg::make("grbl.profile.axis_letter", {msg::verbatim("text", "xy")}),
        msg::make("grbl.profile.axes_order", {msg::term("instrument", "instrument.stage"), msg::verbatim("wanted", "XY"), msg::verbatim("got", "X")}),
        msg::make("grbl.profile.not_grbl_axis", {msg::verbatim("axis", "Q")}),
        msg::make("grbl.profile.grbl_axis_used", {msg::verbatim("axis", "X")}),
        msg::make("grbl.profile.stage_no_pump"),
        msg::make("grbl.profile.pump_axis_used", {msg::verbatim("axis", "Z")}),
        msg::make("grbl.profile.ul_per_mm_range", {msg::real("value", 0), msg::real("max", 1e6)}),
        msg::make("grbl.profile.stop_budget_too_small", {msg::real("value", 0.25, msg::Unit::S), msg::real("least", 0.31, msg::Unit::S)}),
        msg::make("grbl.controller_reset", {msg::integer("lost", 2), msg::verbatim("first", "G1 X3")}),
        msg::make("grbl.controller_reset", {msg::integer("lost", 0), msg::verbatim("first", "")}),
    };
    for (const auto& m : all) {
        const QString text = words::text(m);
        EXPECT_FALSE(text.contains(QString::fromStdString(m.id))) << text.toStdString();
        EXPECT_FALSE(text.isEmpty()) << m.id;
        EXPECT_FALSE(text.contains(QLatin1Char('%'))) << text.toStdString();  // every %N filled
    }
    // The GRBL engineer's sentences, with their arguments in place.
    auto byId = [&all](const char* id) {
        return *std::find_if(all.begin(), all.end(), [id](const msg::Message& m) { return m.id == id; });
    };
    EXPECT_EQ(words::text(byId("grbl.beyond_travel")), QStringLiteral("X 150.000 mm is beyond the machine travel 0.000 mm … 100.000 mm (work coordinates, G54; the controller's $130): "
                                                   "refused before sending, since GRBL would stop with ALARM:2 and need a reset"));
    // Where an axis ended up says which number is in which coordinates (machine vs work).
    EXPECT_EQ(words::text(byId("grbl.event.position")), QStringLiteral("work position (G54) 0.000 mm, machine position -41.712 mm"));
    EXPECT_EQ(words::text(byId("grbl.line_not_sent")), QStringLiteral("move: the line \"G0 X1\" cannot be sent"));
    EXPECT_EQ(words::text(byId("grbl.probe.found_benchpilot")), QStringLiteral("BenchPilot protocol 1 (stage)"));
    for (const char* request : {"grbl.request.unlock", "grbl.request.dwell", "grbl.request.trigger", "grbl.request.status"})
        EXPECT_NE(words::term(request), QString::fromLatin1(request));
    EXPECT_EQ(words::text(all.back()), QStringLiteral("The controller reset by itself; its position is no longer trusted."));
    for (const char* reason : {"unknown_state", "bad_substate", "bad_position", "bad_offset", "bad_buffer", "bad_line_number",
                               "bad_feed", "bad_pins", "bad_overrides", "bad_accessories", "no_position"}) {
        const std::string id = std::string("grbl.status.") + reason;
        EXPECT_NE(words::term(id), QString::fromStdString(id));
    }
}

TEST(GrblWords, TheReasonsForWhatGrblCannotDoAreSentences)
{
    for (const char* because : {"capability.because.grbl_homing_disabled", "capability.because.grbl_open_loop",
                                "capability.because.grbl_no_watchdog", "capability.because.grbl_machine_travel",
                                "capability.because.grbl_xy_plane", "capability.because.no_pump_in_profile",
                                "capability.because.no_trigger_in_profile"})
        EXPECT_NE(words::term(because), QString::fromLatin1(because));
    const msg::Message m = msg::make(dev::missingId(dev::Capability::StopsOnHostLoss),
                                     {msg::term("instrument", "instrument.stage"), msg::verbatim("family", "Grbl 1.1h"),
                                      msg::term("because", "capability.because.grbl_no_watchdog")});
    EXPECT_EQ(words::text(m), QStringLiteral("The stage (Grbl 1.1h) has no way to stop by itself when BenchPilot goes quiet: GRBL "
                                             "cannot notice that BenchPilot went away; what is queued ahead of a jog runs out within "
                                             "the machine profile's stop budget (250 ms unless it says otherwise)."));
}

} // namespace
