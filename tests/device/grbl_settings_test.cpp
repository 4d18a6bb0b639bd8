// $$ settings → machine limits: units, masks, inches, missing and broken values.
#include "device/backends/grbl/grbl_lines.h"
#include "device/backends/grbl/grbl_settings.h"

#include <gtest/gtest.h>

#include <sstream>

namespace {

using namespace dev::grbl;

/// The $$ printout of the GRBL 1.1 settings document's example machine, with homing on.
const char* kStockDump = "$0=10\n$1=25\n$2=0\n$3=2\n$4=0\n$5=0\n$6=0\n$10=1\n$11=0.010\n$12=0.002\n$13=0\n$20=1\n$21=1\n$22=1\n"
                         "$23=3\n$24=25.000\n$25=500.000\n$26=250\n$27=1.000\n$30=1000.\n$31=0.\n$32=0\n$100=250.000\n"
                         "$101=250.000\n$102=250.000\n$110=500.000\n$111=600.000\n$112=300.000\n$120=10.000\n"
                         "$121=20.000\n$122=5.000\n$130=200.000\n$131=150.000\n$132=50.000\nok\n";

Settings read(const std::string& dump)
{
    Settings s;
    std::istringstream in(dump);
    std::string line;
    while (std::getline(in, line))
        if (classifyLine(line).kind == LineKind::Setting)
            s.add(*parseSettingLine(line));
    return s;
}

TEST(GrblSettings, StockDumpGivesPerAxisLimitsInMmAndSeconds)
{
    const Settings s = read(kStockDump);
    EXPECT_EQ(s.size(), 34u);
    const LimitsRead r = machineLimits(s);
    ASSERT_TRUE(r.limits) << (r.problems.empty() ? "" : motion::msg::debugString(r.problems[0]));
    const MachineLimits& m = *r.limits;
    ASSERT_EQ(m.axes.size(), 3u);
    EXPECT_DOUBLE_EQ(m.axes[0].maxRateMmS, 500.0 / 60);  // mm/min → mm/s
    EXPECT_DOUBLE_EQ(m.axes[1].maxRateMmS, 10.0);
    EXPECT_DOUBLE_EQ(m.axes[2].accelMmS2, 5.0);
    EXPECT_DOUBLE_EQ(m.axes[1].maxTravelMm, 150.0);
    EXPECT_DOUBLE_EQ(m.axes[0].stepsPerMm, 250.0);
    EXPECT_TRUE(m.softLimits);
    EXPECT_TRUE(m.hardLimits);
    EXPECT_TRUE(m.homingEnabled);
    EXPECT_FALSE(m.reportInches);
    EXPECT_TRUE(m.reportsMachinePosition);
    EXPECT_DOUBLE_EQ(m.junctionDeviationMm, 0.01);
    EXPECT_DOUBLE_EQ(m.arcToleranceMm, 0.002);
    EXPECT_DOUBLE_EQ(m.homingPulloffMm, 1.0);
    // $3=2: Y's direction inverted; $23=3: X and Y home towards −.
    EXPECT_FALSE(m.axes[0].directionInverted);
    EXPECT_TRUE(m.axes[1].directionInverted);
    EXPECT_TRUE(m.axes[0].homesNegative);
    EXPECT_TRUE(m.axes[1].homesNegative);
    EXPECT_FALSE(m.axes[2].homesNegative);
    EXPECT_TRUE(r.warnings.empty());
}

TEST(GrblSettings, InchReportsAreFlaggedAndLimitsStayInMillimetres)
{
    Settings s = read(kStockDump);
    s.set(setting::kReportInches, 1);
    const LimitsRead r = machineLimits(s);
    ASSERT_TRUE(r.limits);
    EXPECT_TRUE(r.limits->reportInches);
    // GRBL keeps settings in mm whatever $13 says: 500 mm/min is not read as 500 in/min.
    EXPECT_DOUBLE_EQ(r.limits->axes[0].maxRateMmS, 500.0 / 60);
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_EQ(r.warnings[0].id, "grbl.settings.report_inches");
}

TEST(GrblSettings, GrblHalFlagMaskAndExtraAxes)
{
    Settings s = read(kStockDump);
    s.set(setting::kHomingCycle, 9);  // grblHAL: enabled + force origin
    s.set(113, 1200);
    s.set(123, 50);
    s.set(133, 360);
    const LimitsRead r = machineLimits(s, "XYZA");
    ASSERT_TRUE(r.limits);
    EXPECT_TRUE(r.limits->homingEnabled);
    ASSERT_EQ(r.limits->axes.size(), 4u);
    EXPECT_EQ(r.limits->axes[3].letter, 'A');
    EXPECT_DOUBLE_EQ(r.limits->axes[3].maxRateMmS, 20.0);
}

TEST(GrblSettings, MissingOrNonPositiveLimitsAreRefusedByNumber)
{
    Settings s = read(kStockDump);
    Settings missing;
    for (const auto& [id, v] : s.values())
        if (id != 121)
            missing.set(id, v);
    missing.set(132, 0);
    const LimitsRead r = machineLimits(missing);
    EXPECT_FALSE(r.limits);
    ASSERT_EQ(r.problems.size(), 2u);
    EXPECT_EQ(r.problems[0].id, "grbl.settings.missing");
    EXPECT_EQ(r.problems[0].integer("setting"), 121);
    EXPECT_EQ(r.problems[0].text("axis"), "Y");
    EXPECT_EQ(r.problems[1].id, "grbl.settings.invalid");
    EXPECT_EQ(r.problems[1].integer("setting"), 132);
}

TEST(GrblSettings, SoftLimitsWithoutHomingAreWarnedAbout)
{
    Settings s = read(kStockDump);
    s.set(setting::kHomingCycle, 0);
    const LimitsRead r = machineLimits(s);
    ASSERT_TRUE(r.limits);
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_EQ(r.warnings[0].id, "grbl.settings.soft_limits_without_homing");
}

} // namespace
