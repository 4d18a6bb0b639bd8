#include "device/files/accuracy/file_problem.h"

#include "device/files/plates/json_path.h"

namespace accuracyfiles {

msg::Problem fromParseError(const jsonio::ParseError& e, std::string_view file)
{
    return {std::string(file), e.position.line, e.position.column, "", msg::make("file.json_syntax", {msg::nested("detail", e.message)})};
}

void addJsonProblems(const jsonio::Problems& found, std::string_view file, msg::Problems& out)
{
    for (const msg::Problem& p : found.list())
        out.push_back({std::string(file), p.line, p.column, p.path, msg::make("file.json_field", {msg::nested("detail", p.message)})});
}

void addModelProblems(const msg::Problems& found, const jsonio::Value& root, std::string_view file, msg::Problems& out)
{
    for (const msg::Problem& p : found) {
        const jsonio::Position at = platefiles::positionOfPath(root, p.path);
        out.push_back({std::string(file), at.line, at.column, p.path, p.message, p.severity});
    }
}

} // namespace accuracyfiles
