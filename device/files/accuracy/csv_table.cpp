#include "device/files/accuracy/csv_table.h"

#include <algorithm>
#include <charconv>
#include <cstdio>

namespace dev::files::accuracy {

namespace {

bool isContinuationByte(char c)
{
    return (static_cast<unsigned char>(c) & 0xC0) == 0x80;
}

std::string trim(std::string s)
{
    const auto first = s.find_first_not_of(" \t");
    if (first == std::string::npos)
        return {};
    const auto last = s.find_last_not_of(" \t");
    return s.substr(first, last - first + 1);
}



/// The unit suffixes a length column may carry, and what one of it is in mm.
std::optional<double> unitToMm(std::string_view suffix)
{
    if (suffix == "mm")
        return 1.0;
    if (suffix == "um" || suffix == "\xC2\xB5m" || suffix == "\xCE\xBCm")  // µ as micro sign or Greek mu
        return 1e-3;
    if (suffix == "nm")
        return 1e-6;
    if (suffix == "m")
        return 1e3;
    if (suffix == "in")
        return 25.4;
    return std::nullopt;
}


/// The column whose name is `stem` + "_" + a unit. Problems for a unit it cannot
/// read, for two such columns, and for none.

} // namespace

CsvTable parseCsv(std::string_view text, std::string_view file)
{
    CsvTable out;
    if (text.substr(0, 3) == "\xEF\xBB\xBF")
        text.remove_prefix(3);
    std::size_t i = 0;
    int line = 1, column = 1;
    auto advance = [&]() {
        const char c = text[i++];
        if (c == '\n') {
            ++line;
            column = 1;
        } else if (!isContinuationByte(c)) {
            ++column;
        }
    };
    while (i < text.size()) {
        CsvRow row;
        row.line = line;
        bool rowDone = false;
        while (!rowDone) {
            CsvCell cell;
            // Spaces before a quote are allowed (and dropped), as spreadsheets read them.
            std::size_t lead = i;
            while (lead < text.size() && (text[lead] == ' ' || text[lead] == '\t'))
                ++lead;
            if (lead < text.size() && text[lead] == '"') {
                while (i < lead)
                    advance();
                cell.column = column;
                const int openLine = line, openColumn = column;
                advance();
                bool closed = false;
                while (i < text.size()) {
                    if (text[i] == '"') {
                        if (i + 1 < text.size() && text[i + 1] == '"') {
                            cell.text += '"';
                            advance();
                            advance();
                            continue;
                        }
                        advance();
                        closed = true;
                        break;
                    }
                    cell.text += text[i];
                    advance();
                }
                if (!closed) {
                    out.problems.push_back({std::string(file), openLine, openColumn, "", motion::msg::make("file.csv.unterminated_quote")});
                    return out;
                }
                std::size_t after = i;
                while (after < text.size() && (text[after] == ' ' || text[after] == '\t' || text[after] == '\r'))
                    ++after;
                if (after < text.size() && text[after] != ',' && text[after] != '\n') {
                    while (i < after)
                        advance();
                    out.problems.push_back({std::string(file), line, column, "", motion::msg::make("file.csv.text_after_quote")});
                    // Skip to the end of the line and go on, so later lines are still checked.
                    while (i < text.size() && text[i] != '\n')
                        advance();
                }
                while (i < text.size() && text[i] != ',' && text[i] != '\n')
                    advance();
            } else {
                cell.column = column;
                std::string raw;
                while (i < text.size() && text[i] != ',' && text[i] != '\n') {
                    raw += text[i];
                    advance();
                }
                if (!raw.empty() && raw.back() == '\r')
                    raw.pop_back();
                cell.text = trim(raw);
            }
            row.cells.push_back(std::move(cell));
            if (i < text.size() && text[i] == ',') {
                advance();
                continue;
            }
            if (i < text.size())
                advance();  // the '\n'
            rowDone = true;
        }
        const bool blank = std::all_of(row.cells.begin(), row.cells.end(), [](const CsvCell& c) { return c.text.empty(); }) && row.cells.size() == 1;
        if (!blank)
            out.rows.push_back(std::move(row));
    }
    return out;
}

std::string asciiLower(std::string_view s)
{
    // Not std::tolower: Qt programs run in the user's locale, and header names are ASCII.
    std::string out(s);
    for (char& c : out)
        if (c >= 'A' && c <= 'Z')
            c = static_cast<char>(c - 'A' + 'a');
    return out;
}

std::optional<double> parseNumber(std::string_view text)
{
    if (!text.empty() && text.front() == '+')
        text.remove_prefix(1);
    if (text.empty() || text.front() == '+')
        return std::nullopt;
    double v = 0;
    const auto r = std::from_chars(text.data(), text.data() + text.size(), v);
    if (r.ec != std::errc() || r.ptr != text.data() + text.size())
        return std::nullopt;
    return v;
}

int findColumn(const CsvRow& header, std::string_view name)
{
    const std::string wanted = asciiLower(name);
    for (std::size_t c = 0; c < header.cells.size(); ++c)
        if (asciiLower(header.cells[c].text) == wanted)
            return static_cast<int>(c);
    return -1;
}

bool looksSemicolonSeparated(const CsvRow& header)
{
    return header.cells.size() == 1 && header.cells[0].text.find(';') != std::string::npos;
}

LengthColumn findLengthColumn(const CsvRow& header, const std::string& stem, const std::string& usualName, std::string_view file, motion::msg::Problems& out)
{
    LengthColumn found;
    for (std::size_t c = 0; c < header.cells.size(); ++c) {
        const std::string name = asciiLower(header.cells[c].text);
        if (name.rfind(stem + "_", 0) != 0)
            continue;
        const auto unit = unitToMm(std::string_view(name).substr(stem.size() + 1));
        if (!unit) {
            out.push_back({std::string(file), header.line, header.cells[c].column, header.cells[c].text,
                           motion::msg::make("accuracy.csv.unknown_unit", {motion::msg::verbatim("column", header.cells[c].text), motion::msg::verbatim("units", "mm, um, nm, m, in")})});
            return {-2, 1};
        }
        if (found.index >= 0) {
            out.push_back({std::string(file), header.line, header.cells[c].column, header.cells[c].text,
                           motion::msg::make("accuracy.csv.duplicate_column", {motion::msg::verbatim("column", header.cells[c].text)})});
            return {-2, 1};
        }
        found = {static_cast<int>(c), *unit};
    }
    if (found.index == -1)
        out.push_back({std::string(file), header.line, 1, "",
                       motion::msg::make("accuracy.csv.missing_column", {motion::msg::verbatim("column", usualName)})});
    return found;
}

int findRequiredColumn(const CsvRow& header, const char* name, std::string_view file, motion::msg::Problems& out)
{
    const int c = findColumn(header, name);
    if (c < 0)
        out.push_back({std::string(file), header.line, 1, "", motion::msg::make("accuracy.csv.missing_column", {motion::msg::verbatim("column", name)})});
    return c;
}

std::string csvField(const std::string& text)
{
    if (text.find_first_of(",\"\r\n") == std::string::npos && (text.empty() || (text.front() != ' ' && text.back() != ' ')))
        return text;
    std::string out = "\"";
    for (char c : text) {
        if (c == '"')
            out += '"';
        out += c;
    }
    return out + "\"";
}

std::string csvNumber(double v)
{
    char buf[64];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    return std::string(buf, r.ptr);
}

} // namespace dev::files::accuracy
