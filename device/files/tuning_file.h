#pragma once
// Tuning results as files people keep: schema "benchpilot.tuning", version 1
// (docs/tuning_results.md). Reading reports every problem at once with line,
// column and field path; writing is atomic.
#include "device/files/json_fields.h"
#include "motion/control/tuning/tuning_result.h"

#include <QString>

#include <optional>
#include <string>
#include <string_view>

namespace dev::files {

constexpr const char* kTuningSchema = "benchpilot.tuning";
constexpr int kTuningVersion = 1;

/// The document, pretty-printed; the rules table is written beside Ku and Tu for
/// readers (a reader recomputes it from Ku and Tu and does not trust it).
std::string tuningToJson(const motion::control::TuningResult& result);

struct TuningRead {
    std::optional<motion::control::TuningResult> result;
    dev::files::json::Problems problems;  ///< empty when read; problems.format(file) for logs, ui::words::fileProblems for people
};
/// Plain C++: what the fuzzer drives.
TuningRead tuningFromJson(std::string_view text);

bool saveTuningFile(const QString& path, const motion::control::TuningResult& result, motion::msg::Message* error);
std::optional<motion::control::TuningResult> loadTuningFile(const QString& path, dev::files::json::Problems* problems);

} // namespace dev::files
