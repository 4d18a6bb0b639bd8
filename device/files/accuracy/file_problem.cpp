#include "device/files/accuracy/file_problem.h"

#include "device/files/plates/json_path.h"

namespace dev::files::accuracy {

motion::msg::Problem fromParseError(const dev::files::json::ParseError& e, std::string_view file)
{
    return {std::string(file), e.position.line, e.position.column, "", motion::msg::make("file.json_syntax", {motion::msg::nested("detail", e.message)})};
}

void addJsonProblems(const dev::files::json::Problems& found, std::string_view file, motion::msg::Problems& out)
{
    for (const motion::msg::Problem& p : found.list())
        out.push_back({std::string(file), p.line, p.column, p.path, motion::msg::make("file.json_field", {motion::msg::nested("detail", p.message)})});
}

void addModelProblems(const motion::msg::Problems& found, const dev::files::json::Value& root, std::string_view file, motion::msg::Problems& out)
{
    for (const motion::msg::Problem& p : found) {
        const dev::files::json::Position at = dev::files::plates::positionOfPath(root, p.path);
        out.push_back({std::string(file), at.line, at.column, p.path, p.message, p.severity});
    }
}

} // namespace dev::files::accuracy
