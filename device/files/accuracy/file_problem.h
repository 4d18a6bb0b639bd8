#pragma once
// What the accuracy-bench file readers report: every problem at once, each with
// the file, line and column, the field (a JSON path or a CSV column name) and a
// message for a person (an id plus typed arguments; worded in widgets/ or app/).
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

namespace accuracyfiles {

struct FileProblem {
    std::string file;
    int line = 0;       ///< 1-based; 0: the file as a whole (it cannot be read, it is empty)
    int column = 0;     ///< 1-based, in characters
    std::string path;   ///< "targets_mm[3]", "settle.timeout_s", a CSV column name; "" for none
    msg::Message message;
    bool warning = false;
};
using FileProblems = std::vector<FileProblem>;

bool hasErrors(const FileProblems& problems);

/// "FILE:LINE:COLUMN: PATH: id{args}", one a line: for logs, fuzzers and test
/// failures, never for people.
std::string debugFormat(const FileProblems& problems);

/// A JSON syntax error, or ObjectReader's structural problems, as messages.
FileProblem fromParseError(const jsonio::ParseError& e, std::string_view file);
void addJsonProblems(const jsonio::Problems& found, std::string_view file, FileProblems& out);

/// A data model's problems (paths only) placed at the value their path names in
/// the parsed document, or at the nearest enclosing value that exists.
void addModelProblems(const motion::metrology::Problems& found, const jsonio::Value& root, std::string_view file, FileProblems& out);

} // namespace accuracyfiles
