#pragma once
// Accuracy test definitions as files people keep: schema "benchpilot.accuracy-test",
// version 1 (docs/accuracy.md, "Test definition file"). One file holds one test of
// one kind: "axis" (ISO 230-2), "xy-line" (seed 000's linked XY test) or "circle"
// (ISO 230-4). Reading reports every problem at once, the reader's and the test's
// validator's (without the instrument's limits: those are checked when it runs),
// with line, column and field; warnings (fewer than ISO's 5 cycles) do not refuse
// the file. Writing is atomic.
#include "device/files/accuracy/file_problem.h"
#include "motion/metrology/linear/axis_test.h"
#include "motion/metrology/contour/circular_test.h"
#include "motion/metrology/contour/xy_line_test.h"

#include <QString>

#include <optional>
#include <string>
#include <string_view>
#include <variant>

namespace dev::files::accuracy {

constexpr const char* kAccuracyTestSchema = "benchpilot.accuracy-test";
constexpr int kAccuracyTestVersion = 1;

using AccuracyTest = std::variant<motion::metrology::AxisTest, motion::metrology::XyLineTest, motion::metrology::CircularTest>;

std::string accuracyTestToJson(const AccuracyTest& test);

struct AccuracyTestRead {
    std::optional<AccuracyTest> test;   ///< empty when there are errors
    motion::msg::Problems problems;              ///< errors, or warnings beside a test
};
/// Plain C++: what the fuzzer drives.
AccuracyTestRead accuracyTestFromJson(std::string_view text, std::string_view fileName);

AccuracyTestRead loadAccuracyTestFile(const QString& path);
bool saveAccuracyTestFile(const QString& path, const AccuracyTest& test, motion::msg::Message* error);

} // namespace dev::files::accuracy
