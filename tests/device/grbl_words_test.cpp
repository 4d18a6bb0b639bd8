// Every GRBL error and alarm is shown with its documented meaning (and an error with the line it
// answers); every grbl.* id the backend emits, and every reason it gives for a missing
// capability, is worded — none falls back to the id.
#include "widgets/wording/wording.h"

#include "device/backends/grbl/grbl_codes.h"
#include "device/client/capabilities.h"
#include "motion/message.h"

#include <QCoreApplication>

#include <gtest/gtest.h>

namespace {

TEST(GrblWords, EveryErrorAndAlarmIsShownWithItsMeaning)
{
    std::size_t n = 0;
    const grbl::CodeMeaning* errors = grbl::errorTable(&n);
    ASSERT_GT(n, 50u);
    for (std::size_t i = 0; i < n; ++i) {
        const QString text = words::text(grbl::errorMessage(errors[i].code, "G1 X5 F600"));
        EXPECT_TRUE(text.startsWith(QStringLiteral("error:%1 — ").arg(errors[i].code))) << text.toStdString();
        EXPECT_TRUE(text.contains(QString::fromUtf8(errors[i].text))) << text.toStdString();
        EXPECT_TRUE(text.contains(QStringLiteral("\"G1 X5 F600\""))) << text.toStdString();
    }
    const grbl::CodeMeaning* alarms = grbl::alarmTable(&n);
    ASSERT_GE(n, 9u);
    for (std::size_t i = 0; i < n; ++i) {
        const QString text = words::text(grbl::alarmMessage(alarms[i].code));
        EXPECT_EQ(text, QStringLiteral("ALARM:%1 — %2").arg(alarms[i].code).arg(QString::fromUtf8(alarms[i].text)));
    }
    // A code from a newer firmware is still shown, with its number.
    EXPECT_TRUE(words::text(grbl::errorMessage(250, "")).startsWith(QStringLiteral("error:250 — ")));
}

TEST(GrblWords, EveryIdTheBackendEmitsIsWorded)
{
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
        msg::make("grbl.controller_reset", {msg::integer("lost", 2), msg::verbatim("first", "G1 X3")}),
        msg::make("grbl.controller_reset", {msg::integer("lost", 0), msg::verbatim("first", "")}),
    };
    for (const auto& m : all) {
        const QString text = words::text(m);
        EXPECT_FALSE(text.contains(QString::fromStdString(m.id))) << text.toStdString();
        EXPECT_FALSE(text.isEmpty()) << m.id;
    }
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
