// Machine profiles: the examples load, a profile round-trips, and every mistake a person can make
// in one is reported with its place and field — axes that do not fit the instrument, a GRBL axis
// used twice, a pump on the stage, a jog budget no jog could keep, an unknown field.
#include "device/files/machine_profile_file.h"

#include <QDir>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <optional>

namespace {

using dev::files::MachineProfile;

dev::files::json::Problems problemsOf(std::string_view text)
{
    const auto r = dev::files::parseMachineProfile(text);
    EXPECT_FALSE(r.profile.has_value());
    return r.problems;
}

/// The problem at `path` with message `id`, or nullopt (the failure prints them all).
std::optional<motion::msg::Problem> find(const dev::files::json::Problems& problems, const std::string& path, const std::string& id)
{
    for (const auto& p : problems.list())
        if (p.path == path && p.message.id == id)
            return p;
    ADD_FAILURE() << "no " << id << " at " << path << " in\n" << problems.format("p.machine.json");
    return std::nullopt;
}

std::string withAxes(const std::string& instrument, const std::string& axes, const std::string& extra = {})
{
    return R"({"schema": "benchpilot.machine-profile", "version": 1, "instrument": ")" + instrument + R"(", "axes": )" + axes
           + extra + "}";
}

TEST(MachineProfileFile, TheExamplesLoadAndSayWhatTheyWire)
{
    const QDir dir(QStringLiteral(BP_SOURCE_DIR "/resources/examples"));
    const QStringList names = dir.entryList({QStringLiteral("*.machine.json")});
    ASSERT_GE(names.size(), 3);
    for (const QString& n : names) {
        MachineProfile p;
        dev::files::json::Problems problems;
        ASSERT_TRUE(dev::files::loadMachineProfileFile(dir.filePath(n), &p, &problems)) << problems.format(n.toStdString());
        EXPECT_TRUE(dev::files::validate(p).empty()) << n.toStdString();
    }
    MachineProfile sim;
    ASSERT_TRUE(dev::files::loadMachineProfileFile(dir.filePath(QStringLiteral("analyzer-grbl-sim.machine.json")), &sim, nullptr));
    EXPECT_EQ(sim.instrument, dev::proto::DeviceKind::Analyzer);
    EXPECT_EQ(sim.protocol, MachineProfile::Protocol::Grbl);
    EXPECT_EQ(sim.grblAxisOf('P'), 'A');
    EXPECT_DOUBLE_EQ(sim.pump->ulPerMm, 1.0);
    MachineProfile uno;
    ASSERT_TRUE(dev::files::loadMachineProfileFile(dir.filePath(QStringLiteral("stage-grbl-uno.machine.json")), &uno, nullptr));
    ASSERT_TRUE(uno.trigger.has_value());
    EXPECT_EQ(uno.trigger->output, MachineProfile::TriggerOutput::CoolantFlood);
    EXPECT_DOUBLE_EQ(uno.statusPollHz, 5);
}

TEST(MachineProfileFile, AProfileRoundTripsThroughItsFile)
{
    MachineProfile p = dev::files::defaultProfile(dev::proto::DeviceKind::Analyzer);
    p.name = "bench 3";
    p.pump->ulPerMm = 12.5;
    p.trigger = MachineProfile::Trigger{MachineProfile::TriggerOutput::GrblHalDigital, 3};
    p.inchReports = MachineProfile::InchReports::Refuse;
    p.jog.refreshS = 0.04;
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("bench.machine.json"));
    motion::msg::Message error;
    ASSERT_TRUE(dev::files::saveMachineProfileFile(path, p, &error)) << motion::msg::debugString(error);
    MachineProfile back;
    dev::files::json::Problems problems;
    ASSERT_TRUE(dev::files::loadMachineProfileFile(path, &back, &problems)) << problems.format("bench.machine.json");
    EXPECT_EQ(dev::files::writeMachineProfile(back), dev::files::writeMachineProfile(p));
    EXPECT_EQ(back.trigger->port, 3);
    EXPECT_DOUBLE_EQ(back.pump->ulPerMm, 12.5);
}

TEST(MachineProfileFile, MistakesAreReportedWithTheirPlaceAndField)
{
    // The stage has X and Y; the analyzer X, Y and Z, in that order.
    if (const auto p = find(problemsOf(withAxes("stage", R"([{"axis": "X", "grbl_axis": "X"}])")), "axes", "grbl.profile.axes_order")) {
        EXPECT_EQ(p->message.text("instrument"), "instrument.stage");
        EXPECT_EQ(p->message.text("wanted"), "XY");
        EXPECT_EQ(p->message.text("got"), "X");
    }
    // A GRBL axis driving two instrument axes.
    if (const auto p = find(problemsOf(withAxes("stage", R"([{"axis": "X", "grbl_axis": "X"}, {"axis": "Y", "grbl_axis": "X"}])")),
                             "axes[1].grbl_axis", "grbl.profile.grbl_axis_used")) {
        EXPECT_EQ(p->message.text("axis"), "X");
    }
    // A letter GRBL does not have; a letter that is not one.
    if (const auto p = find(problemsOf(withAxes("stage", R"([{"axis": "X", "grbl_axis": "Q"}, {"axis": "Y", "grbl_axis": "Y"}])")),
                             "axes[0].grbl_axis", "grbl.profile.not_grbl_axis")) {
        EXPECT_EQ(p->message.text("axis"), "Q");
    }
    if (const auto p = find(problemsOf(withAxes("stage", R"([{"axis": "x", "grbl_axis": "X"}, {"axis": "Y", "grbl_axis": "Y"}])")),
                             "axes[0].axis", "grbl.profile.axis_letter")) {
        EXPECT_EQ(p->message.text("text"), "x");
    }
    // A pump on the stage, a pump on an axis already used.
    const std::string xy = R"([{"axis": "X", "grbl_axis": "X"}, {"axis": "Y", "grbl_axis": "Y"}])";
    find(problemsOf(withAxes("stage", xy, R"(, "pump": {"grbl_axis": "A", "ul_per_mm": 2})")), "pump", "grbl.profile.stage_no_pump");
    const std::string xyz = R"([{"axis": "X", "grbl_axis": "X"}, {"axis": "Y", "grbl_axis": "Y"}, {"axis": "Z", "grbl_axis": "Z"}])";
    if (const auto p = find(problemsOf(withAxes("analyzer", xyz, R"(, "pump": {"grbl_axis": "Z", "ul_per_mm": 2})")), "pump.grbl_axis",
                             "grbl.profile.pump_axis_used")) {
        EXPECT_EQ(p->message.text("axis"), "Z");
    }
    // A jog budget that not even a creeping jog can keep.
    if (const auto p = find(problemsOf(withAxes("stage", xy, R"(, "jog": {"link_latency_s": 0.2, "refresh_s": 0.1, "stop_budget_s": 0.25})")),
                             "jog.stop_budget_s", "grbl.profile.stop_budget_too_small")) {
        EXPECT_DOUBLE_EQ(p->message.number("value"), 0.25);
        EXPECT_NEAR(p->message.number("least"), 0.31, 1e-12);
    }
    // Out of range, wrong words, unknown fields (with the nearest known name).
    if (const auto p = find(problemsOf(withAxes("stage", xy, R"(, "status_poll_hz": 50)")), "status_poll_hz", "file.json.out_of_range")) {
        EXPECT_DOUBLE_EQ(p->message.number("value"), 50);
    }
    find(problemsOf(withAxes("stage", xy, R"(, "trigger": {"output": "laser"})")), "trigger.output", "file.json.not_one_of");
    if (const auto p = find(problemsOf(withAxes("stage", xy, R"(, "status_poll": 5)")), "status_poll", "file.json.unknown_field_suggest")) {
        EXPECT_EQ(p->message.text("suggestion"), "status_poll_hz");
    }
    // The place: line and column.
    const dev::files::json::Problems mill =
        problemsOf("{\n  \"schema\": \"benchpilot.machine-profile\",\n  \"version\": 1,\n  \"instrument\": \"mill\",\n  \"axes\": []\n}");
    if (const auto p = find(mill, "instrument", "file.json.not_one_of")) {
        EXPECT_EQ(p->line, 4);
        EXPECT_EQ(p->column, 17);
    }
    // Another file's schema, a newer version.
    if (const auto p = find(problemsOf(R"({"schema": "benchpilot.pattern", "version": 1})"), "schema", "file.json.schema_wrong")) {
        EXPECT_EQ(p->message.text("schema"), "benchpilot.machine-profile");
    }
    find(problemsOf(R"({"schema": "benchpilot.machine-profile", "version": 9})"), "version", "file.json.version_newer");
}

TEST(MachineProfileFile, AFileThatCannotBeReadSaysSo)
{
    dev::files::json::Problems problems;
    EXPECT_FALSE(dev::files::loadMachineProfileFile(QStringLiteral("/nonexistent/x.machine.json"), nullptr, &problems));
    ASSERT_EQ(problems.size(), 1u);
    EXPECT_EQ(problems.list().front().line, 0);  // the file as a whole
    EXPECT_FALSE(problems.list().front().message.empty());
}

TEST(MachineProfileFile, TheDefaultWiringIsValidAndSaysWhere)
{
    for (const auto kind : {dev::proto::DeviceKind::Analyzer, dev::proto::DeviceKind::Stage}) {
        const MachineProfile p = dev::files::defaultProfile(kind);
        EXPECT_TRUE(dev::files::validate(p).empty());
        EXPECT_EQ(p.grblAxisOf('X'), 'X');
        EXPECT_EQ(p.grblAxisOf('P'), kind == dev::proto::DeviceKind::Analyzer ? 'A' : 0);
        EXPECT_FALSE(p.trigger.has_value());
        EXPECT_DOUBLE_EQ(p.statusPollHz, 10);
    }
}

} // namespace
