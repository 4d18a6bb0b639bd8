#pragma once
// The simulated stage's errors as a file an engineer writes: schema
// "benchpilot.stage-errors", version 1 (docs/accuracy.md, "The stage-error file").
// What benchpilot-sim --stage-errors FILE and --stage-errors beside --sim read; the
// model is motion/metrology/grid/stage_errors.h. Members left out keep the
// built-in stage's errors (builtInStageErrors()).
#include "motion/checked.h"
#include "device/files/accuracy/file_problem.h"
#include "motion/metrology/grid/stage_errors.h"

#include <QString>

#include <optional>
#include <string>
#include <string_view>

namespace dev::files::accuracy {

constexpr const char* kStageErrorsSchema = "benchpilot.stage-errors";
constexpr int kStageErrorsVersion = 1;

/// The value, or every problem why not (motion/checked.h).
using StageErrorsRead = motion::msg::Checked<motion::metrology::StageErrors>;

std::string stageErrorsToJson(const motion::metrology::StageErrors& e);
/// Plain C++: what the fuzzer drives.
StageErrorsRead stageErrorsFromJson(std::string_view text, std::string_view fileName);
StageErrorsRead loadStageErrorsFile(const QString& path);
bool saveStageErrorsFile(const QString& path, const motion::metrology::StageErrors& e, motion::msg::Message* error);

/// A JSON array of numbers at `key` of `o`, each element's problem at its own place;
/// nullopt when absent (and not required) or when any element is not a number.
std::optional<std::vector<double>> numberList(dev::files::json::ObjectReader& o, std::string_view key, bool required);

} // namespace dev::files::accuracy
