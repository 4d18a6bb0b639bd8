// Machine profiles: the examples load, a profile round-trips, and every mistake a person can make
// in one is reported with its place and field — axes that do not fit the instrument, a GRBL axis
// used twice, a pump on the stage, a jog budget no jog could keep, an unknown field.
#include "device/files/machine_profile_file.h"

#include <QDir>
#include <QTemporaryDir>

#include <gtest/gtest.h>

namespace {

using files::MachineProfile;

std::string problemsOf(std::string_view text)
{
    const auto r = files::parseMachineProfile(text);
    EXPECT_FALSE(r.profile.has_value());
    return r.problems.format("p.machine.json");
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
        QString error;
        ASSERT_TRUE(files::loadMachineProfileFile(dir.filePath(n), &p, &error)) << error.toStdString();
        EXPECT_TRUE(files::validate(p).empty()) << n.toStdString();
    }
    MachineProfile sim;
    ASSERT_TRUE(files::loadMachineProfileFile(dir.filePath(QStringLiteral("analyzer-grbl-sim.machine.json")), &sim, nullptr));
    EXPECT_EQ(sim.instrument, proto::DeviceKind::Analyzer);
    EXPECT_EQ(sim.protocol, MachineProfile::Protocol::Grbl);
    EXPECT_EQ(sim.grblAxisOf('P'), 'A');
    EXPECT_DOUBLE_EQ(sim.pump->ulPerMm, 1.0);
    MachineProfile uno;
    ASSERT_TRUE(files::loadMachineProfileFile(dir.filePath(QStringLiteral("stage-grbl-uno.machine.json")), &uno, nullptr));
    ASSERT_TRUE(uno.trigger.has_value());
    EXPECT_EQ(uno.trigger->output, MachineProfile::TriggerOutput::CoolantFlood);
    EXPECT_DOUBLE_EQ(uno.statusPollHz, 5);
}

TEST(MachineProfileFile, AProfileRoundTripsThroughItsFile)
{
    MachineProfile p = files::defaultProfile(proto::DeviceKind::Analyzer);
    p.name = "bench 3";
    p.pump->ulPerMm = 12.5;
    p.trigger = MachineProfile::Trigger{MachineProfile::TriggerOutput::GrblHalDigital, 3};
    p.inchReports = MachineProfile::InchReports::Refuse;
    p.jog.refreshS = 0.04;
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("bench.machine.json"));
    QString error;
    ASSERT_TRUE(files::saveMachineProfileFile(path, p, &error)) << error.toStdString();
    MachineProfile back;
    ASSERT_TRUE(files::loadMachineProfileFile(path, &back, &error)) << error.toStdString();
    EXPECT_EQ(files::writeMachineProfile(back), files::writeMachineProfile(p));
    EXPECT_EQ(back.trigger->port, 3);
    EXPECT_DOUBLE_EQ(back.pump->ulPerMm, 12.5);
}

TEST(MachineProfileFile, MistakesAreReportedWithTheirPlaceAndField)
{
    // The stage has X and Y; the analyzer X, Y and Z, in that order.
    EXPECT_NE(problemsOf(withAxes("stage", R"([{"axis": "X", "grbl_axis": "X"}])")).find("axes: the stage has axes XY"), std::string::npos);
    // A GRBL axis driving two instrument axes.
    const std::string twice = problemsOf(withAxes("stage", R"([{"axis": "X", "grbl_axis": "X"}, {"axis": "Y", "grbl_axis": "X"}])"));
    EXPECT_NE(twice.find("axes[1].grbl_axis: GRBL axis X is already used"), std::string::npos) << twice;
    // A letter GRBL does not have.
    EXPECT_NE(problemsOf(withAxes("stage", R"([{"axis": "X", "grbl_axis": "Q"}, {"axis": "Y", "grbl_axis": "Y"}])"))
                  .find("\"Q\" is not a GRBL axis"),
              std::string::npos);
    // A pump on the stage, a pump on an axis already used.
    const std::string xy = R"([{"axis": "X", "grbl_axis": "X"}, {"axis": "Y", "grbl_axis": "Y"}])";
    EXPECT_NE(problemsOf(withAxes("stage", xy, R"(, "pump": {"grbl_axis": "A", "ul_per_mm": 2})")).find("pump: the stage has no pump"),
              std::string::npos);
    const std::string xyz = R"([{"axis": "X", "grbl_axis": "X"}, {"axis": "Y", "grbl_axis": "Y"}, {"axis": "Z", "grbl_axis": "Z"}])";
    EXPECT_NE(problemsOf(withAxes("analyzer", xyz, R"(, "pump": {"grbl_axis": "Z", "ul_per_mm": 2})")).find("already drives another axis"),
              std::string::npos);
    // A jog budget that not even a creeping jog can keep.
    const std::string budget = problemsOf(withAxes("stage", xy, R"(, "jog": {"link_latency_s": 0.2, "refresh_s": 0.1, "stop_budget_s": 0.25})"));
    EXPECT_NE(budget.find("jog.stop_budget_s: must exceed"), std::string::npos) << budget;
    // Out of range, wrong words, unknown fields (with the nearest known name).
    EXPECT_NE(problemsOf(withAxes("stage", xy, R"(, "status_poll_hz": 50)")).find("status_poll_hz"), std::string::npos);
    EXPECT_NE(problemsOf(withAxes("stage", xy, R"(, "trigger": {"output": "laser"})")).find("trigger.output"), std::string::npos);
    const std::string unknown = problemsOf(withAxes("stage", xy, R"(, "status_poll": 5)"));
    EXPECT_NE(unknown.find("status_poll_hz"), std::string::npos) << unknown;
    // The place: file, line and column.
    EXPECT_EQ(problemsOf("{\n  \"schema\": \"benchpilot.machine-profile\",\n  \"version\": 1,\n  \"instrument\": \"mill\",\n  \"axes\": []\n}")
                  .rfind("p.machine.json:4:", 0),
              0u);
    // Another file's schema, a newer version.
    EXPECT_NE(problemsOf(R"({"schema": "benchpilot.pattern", "version": 1})").find("benchpilot.machine-profile"), std::string::npos);
    EXPECT_NE(problemsOf(R"({"schema": "benchpilot.machine-profile", "version": 9})").find("newer"), std::string::npos);
}

TEST(MachineProfileFile, TheDefaultWiringIsValidAndSaysWhere)
{
    for (const auto kind : {proto::DeviceKind::Analyzer, proto::DeviceKind::Stage}) {
        const MachineProfile p = files::defaultProfile(kind);
        EXPECT_TRUE(files::validate(p).empty());
        EXPECT_EQ(p.grblAxisOf('X'), 'X');
        EXPECT_EQ(p.grblAxisOf('P'), kind == proto::DeviceKind::Analyzer ? 'A' : 0);
        EXPECT_FALSE(p.trigger.has_value());
        EXPECT_DOUBLE_EQ(p.statusPollHz, 10);
    }
}

} // namespace
