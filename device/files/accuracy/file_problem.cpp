#include "device/files/accuracy/file_problem.h"

#include "device/files/plates/json_path.h"

namespace accuracyfiles {

bool hasErrors(const FileProblems& problems)
{
    for (const FileProblem& p : problems)
        if (!p.warning)
            return true;
    return false;
}

std::string debugFormat(const FileProblems& problems)
{
    std::string out;
    for (const FileProblem& p : problems) {
        out += p.file + ":" + std::to_string(p.line) + ":" + std::to_string(p.column) + ": ";
        if (!p.path.empty())
            out += p.path + ": ";
        if (p.warning)
            out += "warning: ";
        out += msg::debugString(p.message) + "\n";
    }
    return out;
}

FileProblem fromParseError(const jsonio::ParseError& e, std::string_view file)
{
    return {std::string(file), e.position.line, e.position.column, "", msg::make("file.json_syntax", {msg::nested("detail", e.message)}), false};
}

void addJsonProblems(const jsonio::Problems& found, std::string_view file, FileProblems& out)
{
    for (const jsonio::Problem& p : found.list())
        out.push_back({std::string(file), p.position.line, p.position.column, p.path, msg::make("file.json_field", {msg::nested("detail", p.message)}),
                       false});
}

void addModelProblems(const motion::metrology::Problems& found, const jsonio::Value& root, std::string_view file, FileProblems& out)
{
    for (const motion::metrology::Problem& p : found) {
        const jsonio::Position at = platefiles::positionOfPath(root, p.path);
        out.push_back({std::string(file), at.line, at.column, p.path, p.message, p.warning});
    }
}

} // namespace accuracyfiles
