// The lines the GRBL client sends: exact text, limits, and refusals with a reason.
#include "device/backends/grbl/grbl_gcode.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using namespace dev::grbl;

TEST(GrblGcode, NumbersArePlainDecimalsWithoutNoise)
{
    EXPECT_EQ(formatNumber(10), "10");
    EXPECT_EQ(formatNumber(10.5), "10.5");
    EXPECT_EQ(formatNumber(-0.00004), "0");  // never "-0"
    EXPECT_EQ(formatNumber(-0.0001), "-0.0001");
    EXPECT_EQ(formatNumber(1e-9), "0");
    EXPECT_EQ(formatNumber(123456.78916), "123456.7892");
    EXPECT_EQ(formatNumber(2.5, 0), "2");  // %.0f rounds half to even
}

TEST(GrblGcode, MovesSayUnitsAndDistanceModeOnEveryLine)
{
    EXPECT_EQ(moveLine(Motion::Feed, false, {{'X', 10}, {'Y', 5.25}}, 600).text, "G90 G21 G1 X10 Y5.25 F600");
    EXPECT_EQ(moveLine(Motion::Rapid, true, {{'Z', -2}}).text, "G91 G21 G0 Z-2");
    const GcodeLine noFeed = moveLine(Motion::Feed, false, {{'X', 1}}, 0);
    EXPECT_FALSE(noFeed.ok());
    EXPECT_EQ(noFeed.problem.id, "grbl.gcode.bad_feed");
    EXPECT_EQ(moveLine(Motion::Feed, false, {{'X', NAN}}, 100).problem.id, "grbl.gcode.not_finite");
    EXPECT_EQ(moveLine(Motion::Rapid, false, {}).problem.id, "grbl.gcode.no_axes");
    EXPECT_EQ(moveLine(Motion::Rapid, false, {{'Q', 1}}).problem.id, "grbl.gcode.bad_axis");
}

TEST(GrblGcode, LinesLongerThanGrblsBufferAreRefused)
{
    const GcodeLine l = moveLine(Motion::Feed, false,
                                 {{'X', -123456.1234}, {'Y', -123456.1234}, {'Z', -123456.1234}, {'A', -123456.1234},
                                  {'B', -123456.1234}},
                                 123456);
    EXPECT_FALSE(l.ok());
    EXPECT_EQ(l.problem.id, "grbl.gcode.too_long");
    EXPECT_EQ(l.problem.integer("limit"), 79);
}

TEST(GrblGcode, ArcsInCentreForm)
{
    EXPECT_EQ(arcLine(ArcDirection::Clockwise, 10, 0, 5, 0, 600).text, "G90 G21 G17 G2 X10 Y0 I5 J0 F600");
    EXPECT_EQ(arcLine(ArcDirection::CounterClockwise, 0, 10, -10, 0, 1200.5).text, "G90 G21 G17 G3 X0 Y10 I-10 J0 F1200.5");
}

TEST(GrblGcode, ACircleIsFourQuartersEndingWhereItStarted)
{
    // A 10 mm circle (radius 5) around (50, 50), clockwise from (55, 50).
    const auto lines = circleLines(50, 50, 5, ArcDirection::Clockwise, 600);
    ASSERT_EQ(lines.size(), 4u);
    EXPECT_EQ(lines[0].text, "G90 G21 G17 G2 X50 Y45 I-5 J0 F600");
    EXPECT_EQ(lines[1].text, "G90 G21 G17 G2 X45 Y50 I0 J5 F600");
    EXPECT_EQ(lines[2].text, "G90 G21 G17 G2 X50 Y55 I5 J0 F600");
    EXPECT_EQ(lines[3].text, "G90 G21 G17 G2 X55 Y50 I0 J-5 F600");
    const auto ccw = circleLines(0, 0, 2.5, ArcDirection::CounterClockwise, 300);
    EXPECT_EQ(ccw[0].text, "G90 G21 G17 G3 X0 Y2.5 I-2.5 J0 F300");
    EXPECT_EQ(ccw[3].text, "G90 G21 G17 G3 X2.5 Y0 I0 J2.5 F300");
}

TEST(GrblGcode, DwellIsInSeconds)
{
    EXPECT_EQ(dwellLine(0.5).text, "G4 P0.5");
    EXPECT_EQ(dwellLine(0.01).text, "G4 P0.01");
    EXPECT_EQ(dwellLine(0).problem.id, "grbl.gcode.bad_dwell");  // GRBL needs P > 0
    EXPECT_FALSE(dwellLine(-1).ok());
}

TEST(GrblGcode, JogsAreIncrementalMillimetres)
{
    EXPECT_EQ(jogLine({{'X', 0.5}, {'Y', -1}}, 600).text, "$J=G91 G21 X0.5 Y-1 F600");
    EXPECT_FALSE(jogLine({{'X', 1}}, -5).ok());
}

TEST(GrblGcode, TriggerOutputs)
{
    EXPECT_EQ(outputLine(TriggerOutput::GrblHalDigital, true, 2, false).text, "M64 P2");
    EXPECT_EQ(outputLine(TriggerOutput::GrblHalDigital, false, 2, false).text, "M65 P2");
    EXPECT_EQ(outputLine(TriggerOutput::GrblHalDigital, true, 0, true).text, "M62 P0");
    EXPECT_EQ(outputLine(TriggerOutput::GrblHalDigital, false, 0, true).text, "M63 P0");
    EXPECT_EQ(outputLine(TriggerOutput::Coolant, true).text, "M8");
    EXPECT_EQ(outputLine(TriggerOutput::Coolant, false).text, "M9");
    EXPECT_EQ(outputLine(TriggerOutput::GrblHalDigital, true, -1).problem.id, "grbl.gcode.bad_port");
}

TEST(GrblGcode, SystemCommands)
{
    EXPECT_EQ(homingLine(), "$H");
    EXPECT_EQ(unlockLine(), "$X");
    EXPECT_EQ(settingsLine(), "$$");
    EXPECT_EQ(buildInfoLine(), "$I");
    EXPECT_EQ(parserStateLine(), "$G");
    EXPECT_EQ(settingWriteLine(110, 6000).text, "$110=6000");
    EXPECT_EQ(settingWriteLine(12, 0.002).text, "$12=0.002");
    EXPECT_FALSE(settingWriteLine(-1, 1).ok());
}

} // namespace
