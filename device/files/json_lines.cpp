#include "device/files/json_lines.h"

namespace dev::files::json {

std::optional<TextLine> TextLines::next()
{
    if (m_at >= m_text.size())
        return std::nullopt;
    TextLine line;
    const std::size_t nl = m_text.find('\n', m_at);
    line.complete = nl != std::string_view::npos;
    line.text = m_text.substr(m_at, line.complete ? nl - m_at : std::string_view::npos);
    line.number = ++m_number;
    m_at = line.complete ? nl + 1 : m_text.size();
    return line;
}

bool isBlank(std::string_view line) { return line.find_first_not_of(" \t\r") == std::string_view::npos; }

LineOutcome parseLine(const TextLine& line, bool mayBeTorn, ParseResult& parsed, Problems& problems)
{
    parsed = parse(line.text);
    if (parsed)
        return LineOutcome::Value;
    if (!line.complete && mayBeTorn)
        return LineOutcome::Torn;
    problems.add(Position{line.number, parsed.error.position.column}, "", parsed.error.message);
    return LineOutcome::Error;
}

void addAtLine(Problems& into, const Problems& line, int lineNo)
{
    for (const motion::msg::Problem& p : line.list())
        into.add(Position{lineNo, p.column}, p.path, p.message);
}

} // namespace dev::files::json
