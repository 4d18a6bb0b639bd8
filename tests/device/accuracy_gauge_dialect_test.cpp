// The gauge dialect BenchPilot reads (docs/accuracy.md, "Gauge dialect"): a signed
// reading with its unit, in mm, µm or inches; everything else refused with what the
// gauge sent, made printable.
#include "device/link/gauge_dialect.h"

#include <gtest/gtest.h>

namespace {

using dev::gaugewire::parseAnswer;

double value(const std::string& line)
{
    const auto a = parseAnswer(line, "/dev/ttyUSB1");
    EXPECT_TRUE(a.valueMm.has_value()) << line << ": " << motion::msg::debugString(a.problem);
    return a.valueMm.value_or(-999);
}

TEST(AccuracyGaugeDialect, ReadsSignedReadingsInTheUnitsItKnows)
{
    EXPECT_DOUBLE_EQ(value("+012.3456 mm"), 12.3456);
    EXPECT_DOUBLE_EQ(value("-003.2000 mm"), -3.2);
    EXPECT_DOUBLE_EQ(value("12.3456mm"), 12.3456) << "no sign, no space";
    EXPECT_DOUBLE_EQ(value("  +0.5 MM  "), 0.5) << "spaces around, unit in capitals";
    EXPECT_DOUBLE_EQ(value("+1234.5 um"), 1.2345);
    EXPECT_DOUBLE_EQ(value("+1234.5 \xC2\xB5m"), 1.2345) << "µ as the micro sign";
    EXPECT_DOUBLE_EQ(value("+1234.5 \xCE\xBCm"), 1.2345) << "µ as Greek mu";
    EXPECT_DOUBLE_EQ(value("+0.50000 in"), 12.7);
    EXPECT_DOUBLE_EQ(value(".5 mm"), 0.5);
}

TEST(AccuracyGaugeDialect, RefusesWhatIsNotAReadingAndSaysWhatItSaw)
{
    for (const char* line : {"Err 7", "--.-- mm", "+012,3456 mm", "1e-3 mm", "+ mm", "", "12.3.4 mm", "mm 12", "12 mm extra",
                             "12345678901234567 mm"}) {
        const auto a = parseAnswer(line, "/dev/ttyUSB1");
        EXPECT_FALSE(a.valueMm) << line;
        EXPECT_EQ(a.problem.id, "gauge.not_a_reading") << line;
        EXPECT_EQ(a.problem.text("port"), "/dev/ttyUSB1");
        EXPECT_EQ(a.problem.text("text"), line);
    }
}

TEST(AccuracyGaugeDialect, AReadingWithoutAUnitOrInAnotherIsRefused)
{
    auto a = parseAnswer("+012.3456", "COM3");
    EXPECT_EQ(a.problem.id, "gauge.not_a_reading") << "a gauge set to inches would otherwise read as mm";
    a = parseAnswer("+012.3456 cm", "COM3");
    EXPECT_EQ(a.problem.id, "gauge.unknown_unit");
    EXPECT_EQ(a.problem.text("unit"), "cm");
}

TEST(AccuracyGaugeDialect, ControlBytesAreShownEscaped)
{
    EXPECT_EQ(dev::gaugewire::printable(std::string("\x01+1\tmm\xFF", 7)), "\\x01+1\\tmm\\xFF");
    EXPECT_EQ(dev::gaugewire::printable("5 \xC2\xB5m"), "5 \xC2\xB5m") << "UTF-8 stays";
    EXPECT_EQ(dev::gaugewire::printable(std::string(100, 'x')).size(), 80u + 3u) << "cut at 80 with an ellipsis";
}

} // namespace
