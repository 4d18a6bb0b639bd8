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
    const dev::grbl::CodeMeaning* errors = dev::grbl::errorTable(&n);
    ASSERT_GT(n, 50u);
    for (std::size_t i = 0; i < n; ++i) {
        // As the client reports it: with the request it refused (a term the sentence may leave out).
        motion::msg::Message m = dev::grbl::errorMessage(errors[i].code, "G1 X5 F600");
        m.args.push_back(motion::msg::term("request", "request.move"));
        const QString text = ui::words::text(m);
        EXPECT_TRUE(text.contains(QString::number(errors[i].code))) << text.toStdString();
        EXPECT_TRUE(text.contains(QString::fromUtf8(errors[i].text))) << text.toStdString();
        EXPECT_TRUE(text.contains(QStringLiteral("\"G1 X5 F600\""))) << text.toStdString();
    }
    const dev::grbl::CodeMeaning* alarms = dev::grbl::alarmTable(&n);
    ASSERT_GE(n, 9u);
    for (std::size_t i = 0; i < n; ++i) {
        const QString text = ui::words::text(dev::grbl::alarmMessage(alarms[i].code));
        EXPECT_TRUE(text.contains(QString::number(alarms[i].code))) << text.toStdString();
        EXPECT_TRUE(text.contains(QString::fromUtf8(alarms[i].text))) << text.toStdString();
    }
    // A code from a newer firmware is still shown, with its number.
    EXPECT_TRUE(ui::words::text(dev::grbl::errorMessage(250, "")).contains(QStringLiteral("250")));
    // The handshake's refusal names the command and the code's meaning.
    EXPECT_EQ(ui::words::text(motion::msg::make("grbl.identify.refused", {motion::msg::verbatim("command", "$$"), motion::msg::integer("code", 9, motion::msg::Unit::None)})),
              QStringLiteral("the controller refused $$ with error:9 (%1)").arg(QString::fromUtf8(dev::grbl::errorMeaning(9)->text)));
}

TEST(GrblWords, EveryIdTheBackendEmitsIsWorded)
{
    const motion::msg::Arg link = motion::msg::verbatim("link", "/dev/ttyUSB0 at 115200 Bd");
    const motion::msg::Arg seconds = motion::msg::real("seconds", 5, motion::msg::Unit::S);
    const std::vector<motion::msg::Message> all = {
        motion::msg::make("grbl.status.malformed", {motion::msg::verbatim("line", "<Idle|MPos:x>"), motion::msg::term("reason", "grbl.status.bad_position")}),
        motion::msg::make("grbl.settings.missing", {motion::msg::integer("setting", 110, motion::msg::Unit::None), motion::msg::verbatim("axis", "X")}),
        motion::msg::make("grbl.settings.invalid", {motion::msg::integer("setting", 120, motion::msg::Unit::None), motion::msg::verbatim("axis", "Y"), motion::msg::real("value", 0)}),
        motion::msg::make("grbl.settings.report_inches"),
        motion::msg::make("grbl.settings.soft_limits_without_homing"),
        motion::msg::make("grbl.jog.budget_too_small", {motion::msg::real("budget", 0.25, motion::msg::Unit::S), motion::msg::real("latency", 0.02, motion::msg::Unit::S),
                                                motion::msg::real("refresh", 0.25, motion::msg::Unit::S)}),
        motion::msg::make("grbl.jog.speed_limited", {motion::msg::real("asked", 100, motion::msg::Unit::MmPerS), motion::msg::real("speed", 18.9, motion::msg::Unit::MmPerS),
                                             motion::msg::real("budget", 0.25, motion::msg::Unit::S)}),
        motion::msg::make("grbl.gcode.not_finite", {motion::msg::verbatim("word", "X")}),
        motion::msg::make("grbl.gcode.bad_feed", {motion::msg::real("feed", 0, motion::msg::Unit::MmPerMin)}),
        motion::msg::make("grbl.gcode.bad_dwell", {motion::msg::real("seconds", 0, motion::msg::Unit::S)}),
        motion::msg::make("grbl.gcode.bad_axis", {motion::msg::verbatim("axis", "Q")}),
        motion::msg::make("grbl.gcode.no_axes"),
        motion::msg::make("grbl.gcode.bad_port", {motion::msg::integer("port", 300, motion::msg::Unit::None)}),
        motion::msg::make("grbl.gcode.bad_setting", {motion::msg::integer("setting", -1, motion::msg::Unit::None)}),
        motion::msg::make("grbl.gcode.too_long", {motion::msg::verbatim("line", "G1 X1"), motion::msg::integer("limit", 79, motion::msg::Unit::Byte)}),
        motion::msg::make("grbl.device_message", {motion::msg::verbatim("text", "Caution: Unlocked")}),
        motion::msg::make("grbl.device_line", {motion::msg::verbatim("line", "[GC:G0 G54]")}),
        motion::msg::make("grbl.unknown_line", {motion::msg::verbatim("line", "xyz"), motion::msg::integer("count", 1)}),
        motion::msg::make("grbl.line_too_long", {motion::msg::integer("limit", 1024, motion::msg::Unit::Byte)}),
        motion::msg::make("grbl.connect.no_answer", {link, seconds}),
        motion::msg::make("grbl.connect.no_grbl_line", {link, motion::msg::integer("bytes", 37), seconds}),
        motion::msg::make("grbl.connect.never_acknowledged", {link, seconds}),
        motion::msg::make("grbl.connect.identify_silent", {link}),
        motion::msg::make("grbl.identify.not_answered", {motion::msg::verbatim("command", "$I"), motion::msg::nested("cause", motion::msg::make("grbl.reset_flushed"))}),
        motion::msg::make("grbl.identify.refused", {motion::msg::verbatim("command", "$$"), motion::msg::integer("code", 3, motion::msg::Unit::None)}),
        motion::msg::make("grbl.identify.no_limits", {motion::msg::nested("problem", motion::msg::make("grbl.settings.missing", {motion::msg::integer("setting", 110, motion::msg::Unit::None),
                                                                                                          motion::msg::verbatim("axis", "X")})),
                                              motion::msg::integer("count", 2)}),
        motion::msg::make("grbl.identify.inches_refused"),
        motion::msg::make("grbl.identify.axis_missing", {motion::msg::verbatim("axis", "Z"), motion::msg::verbatim("grbl_axis", "Z"), motion::msg::verbatim("axes", "XY")}),
        motion::msg::make("grbl.identify.pump_axis_missing", {motion::msg::verbatim("grbl_axis", "A"), motion::msg::verbatim("axes", "XYZ")}),
        motion::msg::make("grbl.silent", {motion::msg::real("seconds", 2.5, motion::msg::Unit::S)}),
        motion::msg::make("grbl.silent_with_noise", {motion::msg::real("seconds", 2.5, motion::msg::Unit::S), motion::msg::integer("count", 4)}),
        motion::msg::make("grbl.reset_by_itself"),
        motion::msg::make("grbl.reset_flushed"),
        motion::msg::make("grbl.stop_timeout", {motion::msg::real("seconds", 5, motion::msg::Unit::S)}),
        motion::msg::make("grbl.stop_overtaken_by_estop"),
        motion::msg::make("grbl.beyond_travel", {motion::msg::verbatim("axis", "X"), motion::msg::real("target", 150, motion::msg::Unit::Mm), motion::msg::real("min", 0, motion::msg::Unit::Mm),
                                         motion::msg::real("max", 100, motion::msg::Unit::Mm), motion::msg::integer("setting", 130, motion::msg::Unit::None)}),
        motion::msg::make("grbl.line_not_sent", {motion::msg::term("request", "request.move"), motion::msg::verbatim("line", "G0 X1")}),
        motion::msg::make("grbl.estop_latched", {motion::msg::term("request", "request.home")}),
        motion::msg::make("grbl.home_one_or_all", {motion::msg::verbatim("axes", "XY")}),
        motion::msg::make("grbl.set_zero_while_moving"),
        motion::msg::make("grbl.set_zero_no_axis"),
        motion::msg::make("grbl.soft_limits_fixed"),
        motion::msg::make("grbl.move_in_alarm"),
        motion::msg::make("grbl.move_not_established", {motion::msg::verbatim("axis", "Y")}),
        motion::msg::make("grbl.no_trigger_output"),
        motion::msg::make("grbl.trigger_bad_width", {motion::msg::real("width", -1, motion::msg::Unit::S)}),
        motion::msg::make("grbl.event.estop"),
        motion::msg::make("grbl.event.estop_cleared"),
        motion::msg::make("grbl.event.position", {motion::msg::real("work", 0, motion::msg::Unit::Mm), motion::msg::real("machine", -41.712, motion::msg::Unit::Mm)}),
        motion::msg::make("grbl.home_kept", {motion::msg::verbatim("axes", "XY")}),
        motion::msg::make("grbl.home_lost_restart", {motion::msg::verbatim("axes", "XY")}),
        motion::msg::make("grbl.home_lost_changed", {motion::msg::verbatim("axes", "XY")}),
        motion::msg::make("grbl.home_not_saved", {motion::msg::verbatim("file", "/home/u/.local/share/BenchPilot/grbl-homes.json")}),
        motion::msg::make("grbl.path.already_running"),
        motion::msg::make("grbl.path.not_begun"),
        motion::msg::make("grbl.path.out_of_sequence", {motion::msg::integer("expected", 4, motion::msg::Unit::None), motion::msg::integer("sent", 6, motion::msg::Unit::None)}),
        motion::msg::make("grbl.path.window_full", {motion::msg::integer("free", 3)}),
        motion::msg::make("grbl.path.z_in_path", {motion::msg::integer("segment", 2, motion::msg::Unit::None)}),
        motion::msg::make("grbl.probe.no_answer", {link, seconds}),
        motion::msg::make("grbl.probe.unreadable", {link, motion::msg::integer("bytes", 12), seconds}),
        motion::msg::make("grbl.probe.found_grbl", {motion::msg::verbatim("firmware", "grblHAL"), motion::msg::verbatim("version", "1.1f")}),
        motion::msg::make("grbl.probe.found_grbl_unnamed"),
        motion::msg::make("grbl.probe.found_benchpilot", {motion::msg::integer("version", 1, motion::msg::Unit::None), motion::msg::term("instrument", "instrument.stage")}),
        motion::msg::make("grbl.profile.axis_letter", {motion::msg::verbatim("text", "xy")}),
        motion::msg::make("grbl.profile.axes_order", {motion::msg::term("instrument", "instrument.stage"), motion::msg::verbatim("wanted", "XY"), motion::msg::verbatim("got", "X")}),
        motion::msg::make("grbl.profile.not_grbl_axis", {motion::msg::verbatim("axis", "Q")}),
        motion::msg::make("grbl.profile.grbl_axis_used", {motion::msg::verbatim("axis", "X")}),
        motion::msg::make("grbl.profile.stage_no_pump"),
        motion::msg::make("grbl.profile.pump_axis_used", {motion::msg::verbatim("axis", "Z")}),
        motion::msg::make("grbl.profile.ul_per_mm_range", {motion::msg::real("value", 0), motion::msg::real("max", 1e6)}),
        motion::msg::make("grbl.profile.stop_budget_too_small", {motion::msg::real("value", 0.25, motion::msg::Unit::S), motion::msg::real("least", 0.31, motion::msg::Unit::S)}),
        motion::msg::make("grbl.controller_reset", {motion::msg::integer("lost", 2), motion::msg::verbatim("first", "G1 X3")}),
        motion::msg::make("grbl.controller_reset", {motion::msg::integer("lost", 0), motion::msg::verbatim("first", "")}),
    };
    for (const auto& m : all) {
        const QString text = ui::words::text(m);
        EXPECT_FALSE(text.contains(QString::fromStdString(m.id))) << text.toStdString();
        EXPECT_FALSE(text.isEmpty()) << m.id;
        EXPECT_FALSE(text.contains(QLatin1Char('%'))) << text.toStdString();  // every %N filled
    }
    // The GRBL engineer's sentences, with their arguments in place.
    auto byId = [&all](const char* id) {
        return *std::find_if(all.begin(), all.end(), [id](const motion::msg::Message& m) { return m.id == id; });
    };
    EXPECT_EQ(ui::words::text(byId("grbl.beyond_travel")), QStringLiteral("X 150.000 mm is beyond the machine travel 0.000 mm … 100.000 mm (work coordinates, G54; the controller's $130): "
                                                   "refused before sending, since GRBL would stop with ALARM:2 and need a reset"));
    // Where an axis ended up says which number is in which coordinates (machine vs work).
    EXPECT_EQ(ui::words::text(byId("grbl.event.position")), QStringLiteral("work position (G54) 0.000 mm, machine position -41.712 mm"));
    EXPECT_EQ(ui::words::text(byId("grbl.line_not_sent")), QStringLiteral("move: the line \"G0 X1\" cannot be sent"));
    EXPECT_EQ(ui::words::text(byId("grbl.probe.found_benchpilot")), QStringLiteral("BenchPilot protocol 1 (stage)"));
    for (const char* request : {"grbl.request.unlock", "grbl.request.dwell", "grbl.request.trigger", "grbl.request.status"})
        EXPECT_NE(ui::words::term(request), QString::fromLatin1(request));
    EXPECT_EQ(ui::words::text(all.back()), QStringLiteral("The controller reset by itself; its position is no longer trusted."));
    for (const char* reason : {"unknown_state", "bad_substate", "bad_position", "bad_offset", "bad_buffer", "bad_line_number",
                               "bad_feed", "bad_pins", "bad_overrides", "bad_accessories", "no_position"}) {
        const std::string id = std::string("grbl.status.") + reason;
        EXPECT_NE(ui::words::term(id), QString::fromStdString(id));
    }
}

TEST(GrblWords, TheReasonsForWhatGrblCannotDoAreSentences)
{
    for (const char* because : {"capability.because.grbl_homing_disabled", "capability.because.grbl_open_loop",
                                "capability.because.grbl_no_watchdog", "capability.because.grbl_machine_travel",
                                "capability.because.grbl_xy_plane", "capability.because.no_pump_in_profile",
                                "capability.because.no_trigger_in_profile"})
        EXPECT_NE(ui::words::term(because), QString::fromLatin1(because));
    const motion::msg::Message m = motion::msg::make(dev::missingId(dev::Capability::StopsOnHostLoss),
                                     {motion::msg::term("instrument", "instrument.stage"), motion::msg::verbatim("family", "Grbl 1.1h"),
                                      motion::msg::term("because", "capability.because.grbl_no_watchdog")});
    EXPECT_EQ(ui::words::text(m), QStringLiteral("The stage (Grbl 1.1h) has no way to stop by itself when BenchPilot goes quiet: GRBL "
                                             "cannot notice that BenchPilot went away; what is queued ahead of a jog runs out within "
                                             "the machine profile's stop budget (250 ms unless it says otherwise)."));
}

} // namespace
