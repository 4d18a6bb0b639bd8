#include "motion/plans/scan/scan_naming.h"

#include <cstdio>

namespace motion::scan {

namespace {

struct Placeholder {
    enum Kind { Index, Row, Col } kind = Index;
    int width = 0;  ///< zero-padded to this many digits; 0 = as is
};

/// Parses "{name}" or "{name:0N}" starting at `open`; returns the position after '}'.
std::optional<std::size_t> parsePlaceholder(const std::string& s, std::size_t open, Placeholder* out, motion::msg::Message* error)
{
    const std::size_t close = s.find('}', open);
    if (close == std::string::npos) {
        *error = motion::msg::make("scan.naming.unclosed_brace", {motion::msg::integer("position", static_cast<long long>(open + 1), motion::msg::Unit::None)});
        return std::nullopt;
    }
    const std::string body = s.substr(open + 1, close - open - 1);
    const std::size_t colon = body.find(':');
    const std::string name = body.substr(0, colon);
    if (name == "i")
        out->kind = Placeholder::Index;
    else if (name == "row")
        out->kind = Placeholder::Row;
    else if (name == "col")
        out->kind = Placeholder::Col;
    else {
        *error = motion::msg::make("scan.naming.unknown_placeholder", {motion::msg::verbatim("placeholder", "{" + body + "}")});
        return std::nullopt;
    }
    out->width = 0;
    if (colon != std::string::npos) {
        const std::string spec = body.substr(colon + 1);
        if (spec.size() != 2 || spec[0] != '0' || spec[1] < '1' || spec[1] > '9') {
            *error = motion::msg::make("scan.naming.bad_width", {motion::msg::verbatim("placeholder", "{" + body + "}")});
            return std::nullopt;
        }
        out->width = spec[1] - '0';
    }
    return close + 1;
}

} // namespace

std::optional<motion::msg::Message> checkFilePattern(const std::string& pattern)
{
    if (pattern.empty())
        return motion::msg::make("scan.naming.empty");
    if (pattern.front() == ' ' || pattern.back() == ' ' || pattern.front() == '\t' || pattern.back() == '\t')
        return motion::msg::make("scan.naming.edge_space");
    if (pattern.front() == '#')
        return motion::msg::make("scan.naming.starts_with_hash");
    bool index = false, row = false, col = false;
    for (std::size_t i = 0; i < pattern.size();) {
        const char ch = pattern[i];
        if (ch == ';')
            return motion::msg::make("scan.naming.semicolon");
        if (ch == '/' || ch == '\\')
            return motion::msg::make("scan.naming.folder");
        if (static_cast<unsigned char>(ch) < 0x20)
            return motion::msg::make("scan.naming.control_character");
        if (ch == '}')
            return motion::msg::make("scan.naming.unopened_brace", {motion::msg::integer("position", static_cast<long long>(i + 1), motion::msg::Unit::None)});
        if (ch != '{') {
            ++i;
            continue;
        }
        Placeholder p;
        motion::msg::Message error;
        const auto next = parsePlaceholder(pattern, i, &p, &error);
        if (!next)
            return error;
        index = index || p.kind == Placeholder::Index;
        row = row || p.kind == Placeholder::Row;
        col = col || p.kind == Placeholder::Col;
        i = *next;
    }
    if (!index && !(row && col))
        return motion::msg::make("scan.naming.no_index");
    return std::nullopt;
}

std::string tileFileName(const ExportNaming& naming, int index, int row, int col)
{
    const std::string& s = naming.filePattern;
    std::string out;
    out.reserve(s.size() + 8);
    for (std::size_t i = 0; i < s.size();) {
        if (s[i] != '{') {
            out += s[i++];
            continue;
        }
        Placeholder p;
        motion::msg::Message error;
        const auto next = parsePlaceholder(s, i, &p, &error);
        if (!next) {  // not checked: keep the text as it is rather than guess
            out += s.substr(i);
            break;
        }
        const int value = p.kind == Placeholder::Index ? naming.firstIndex + index : (p.kind == Placeholder::Row ? row : col);
        char buf[32];
        std::snprintf(buf, sizeof buf, "%0*d", p.width, value);
        out += buf;
        i = *next;
    }
    return out;
}

} // namespace motion::scan
