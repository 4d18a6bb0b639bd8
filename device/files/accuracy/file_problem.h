#pragma once
// What the accuracy-bench file readers report: every problem at once as motion::msg::Problems,
// each with the file, line and column, the field (a JSON path or a CSV column name)
// and a message for a person (an id plus typed arguments; worded in widgets/ or app/).
//
// The generic JSON layer's problems (file.json.*: "is missing", "must be a number,
// not a string") travel as the nested `detail` of file.json_field and
// file.json_syntax. Everything the accuracy formats check themselves has its own id.
#include "device/files/json.h"
#include "device/files/json_fields.h"
#include "motion/message.h"
#include "motion/metrology/problem.h"

#include <string>
#include <string_view>
#include <vector>

namespace dev::files::accuracy {

/// A JSON syntax error, or ObjectReader's structural problems, as messages.
motion::msg::Problem fromParseError(const dev::files::json::ParseError& e, std::string_view file);
void addJsonProblems(const dev::files::json::Problems& found, std::string_view file, motion::msg::Problems& out);

/// A data model's problems (paths only) placed at the value their path names in
/// the parsed document, or at the nearest enclosing value that exists.
void addModelProblems(const motion::msg::Problems& found, const dev::files::json::Value& root, std::string_view file, motion::msg::Problems& out);

} // namespace dev::files::accuracy
