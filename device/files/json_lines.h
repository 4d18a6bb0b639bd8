#pragma once
// Reading a run log kept as JSON Lines (the scan's, the accuracy bench's, the recipe
// run's): one JSON value a line, appended and flushed as the run goes. A whole file
// is never rewritten, so a crash can only tear the last line; what each reader makes
// of a torn line and of a blank one is its format's own (each says so in its header).
// Plain C++, like json.h.
#include "device/files/json_fields.h"

#include <optional>
#include <string_view>

namespace dev::files::json {

/// One line of a JSON Lines text, without its newline.
struct TextLine {
    std::string_view text;
    int number = 0;         ///< 1-based, as problems name it
    bool complete = false;  ///< ended by a newline: a last line without one may be torn
};

/// The lines of a text one at a time, each with its number. A text that ends with a
/// newline has no empty line after it.
class TextLines {
public:
    explicit TextLines(std::string_view text) : m_text(text) {}
    std::optional<TextLine> next();

private:
    std::string_view m_text;
    std::size_t m_at = 0;
    int m_number = 0;
};

/// Nothing but spaces, tabs and a carriage return.
bool isBlank(std::string_view line);

/// A line's JSON: the value, or a torn last line, or an error.
enum class LineOutcome { Value, Torn, Error };
/// Parses `line` into `parsed`. A line that does not parse is Torn — the write a crash
/// cut short, which a reader drops — when it has no newline and `mayBeTorn`; otherwise
/// Error, with the parser's message in `problems` at the line's number and column.
LineOutcome parseLine(const TextLine& line, bool mayBeTorn, ParseResult& parsed, Problems& problems);

/// The problems a line's value was read with (each at line 1, the line parsed alone),
/// moved to the line `lineNo` of the file.
void addAtLine(Problems& into, const Problems& line, int lineNo);

} // namespace dev::files::json
