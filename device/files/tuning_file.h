#pragma once
// Tuning results as files people keep: schema "benchpilot.tuning", version 1
// (docs/tuning_results.md). Reading reports every problem at once with line,
// column and field path; writing is atomic.
#include "motion/control/tuning/tuning_result.h"

#include <QString>

#include <optional>
#include <string>
#include <string_view>

namespace files {

constexpr const char* kTuningSchema = "benchpilot.tuning";
constexpr int kTuningVersion = 1;

/// The document, pretty-printed; the rules table is written beside Ku and Tu for
/// readers (a reader recomputes it from Ku and Tu and does not trust it).
std::string tuningToJson(const motion::control::TuningResult& result);

struct TuningRead {
    std::optional<motion::control::TuningResult> result;
    std::string problems;  ///< one line per problem ("FILE:LINE:COLUMN: PATH: MESSAGE"); empty when read
};
/// Plain C++: what the fuzzer drives.
TuningRead tuningFromJson(std::string_view text, std::string_view fileName);

bool saveTuningFile(const QString& path, const motion::control::TuningResult& result, QString* error);
std::optional<motion::control::TuningResult> loadTuningFile(const QString& path, QString* error);

} // namespace files
