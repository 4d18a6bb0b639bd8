#pragma once
// One thing wrong with what a person gave: a plan, a pattern, a machine profile, an
// accuracy test, a recipe, a file. Every validator and reader reports all its problems
// at once as a list of these, so a person fixes the input in one pass, and the CLI, the
// API and the screens word each one the same way (ui::words::problem, ui::words::toJson).
//
// The message is data (an id and typed arguments, motion/message.h), without the
// place: the place is the field path and, where a reader knows it, the file, line and
// column. Plain C++ (no Qt), like the rest of motion/.
#include "motion/message.h"

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace motion::msg {

enum class Severity {
    Error,    ///< refuses the input: a run does not start, a file is not taken
    Warning,  ///< said, and the input is taken all the same
};

struct Problem {
    Problem() = default;
    Problem(std::string atPath, Message what, Severity how = Severity::Error)
        : path(std::move(atPath)), message(std::move(what)), severity(how)
    {
    }
    /// A problem a file reader found at a place in the file.
    Problem(std::string inFile, int atLine, int atColumn, std::string atPath, Message what, Severity how = Severity::Error)
        : path(std::move(atPath)), message(std::move(what)), severity(how), file(std::move(inFile)), line(atLine), column(atColumn)
    {
    }

    std::string path;                   ///< the field at fault ("steps[3].volume_ul", "camera.overlap"); "" for the whole input
    Message message;                    ///< what is wrong, without the place
    Severity severity = Severity::Error;
    std::string file;                   ///< the file's name a person knows ("sampling-96.recipe.json"); "" when not from a file
    int line = 0;                       ///< 1-based; 0 when not known, or the file as a whole
    int column = 0;                     ///< 1-based, in characters; 0 when not known

    bool isWarning() const { return severity == Severity::Warning; }
    bool isError() const { return severity == Severity::Error; }
};
using Problems = std::vector<Problem>;

/// An error (or a warning) at `path`.
Problem error(std::string path, Message message);
Problem warning(std::string path, Message message);

bool hasErrors(const Problems& problems);
int errorCount(const Problems& problems);

/// "settle" + "timeout_s" → "settle.timeout_s"; "" + "cycles" → "cycles".
std::string fieldPath(const std::string& parent, const std::string& key);
/// "targets_mm" + 3 → "targets_mm[3]".
std::string indexPath(const std::string& parent, std::size_t index);

/// "FILE:LINE:COLUMN: PATH: warning: id{args}" (each part only where known), for logs,
/// fuzzers and test failures, never for people: they read ui::words::problem.
std::string debugString(const Problem& p);
/// debugString of each, one a line.
std::string debugFormat(const Problems& problems);

} // namespace motion::msg
