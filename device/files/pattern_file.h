#pragma once
// Pattern files (docs/patterns.md): one pattern — its shape, parameters, feed and Z height — as
// JSON with "schema": "benchpilot.pattern", "version": 1. Reading reports every problem at once
// (file:line:column: field: message), the pattern's own validation included, so a file that
// loads is a pattern that plans. The text functions are plain C++ (fuzzed); the file functions
// add the atomic write and the size-capped read.
#include "device/files/json_fields.h"
#include "motion/plans/pattern.h"

#include <QString>

#include <optional>
#include <string>
#include <string_view>

namespace dev::files {

constexpr std::string_view kPatternSchema = "benchpilot.pattern";
constexpr int kPatternVersion = 1;
/// Pattern files are named NAME.pattern.json.
constexpr std::string_view kPatternSuffix = ".pattern.json";

struct PatternReadResult {
    std::optional<motion::plans::Pattern> pattern;
    dev::files::json::Problems problems;  ///< empty when pattern is set
};
PatternReadResult parsePattern(std::string_view text);
/// Two-space indented JSON of the pattern: the header, then the common fields, then the fields
/// of its shape (only those).
std::string writePattern(const motion::plans::Pattern& pattern);

/// False with every problem in *problems (ui::words::fileProblems words them with the file's name).
bool loadPatternFile(const QString& path, motion::plans::Pattern* pattern, dev::files::json::Problems* problems);
bool savePatternFile(const QString& path, const motion::plans::Pattern& pattern, motion::msg::Message* error);

} // namespace dev::files
