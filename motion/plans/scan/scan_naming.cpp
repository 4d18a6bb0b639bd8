#include "motion/plans/scan/scan_naming.h"

#include <cstdio>

namespace motion::scan {

namespace {

struct Placeholder {
    enum Kind { Index, Row, Col } kind = Index;
    int width = 0;  ///< zero-padded to this many digits; 0 = as is
};

/// Parses "{name}" or "{name:0N}" starting at `open`; returns the position after '}'.
std::optional<std::size_t> parsePlaceholder(const std::string& s, std::size_t open, Placeholder* out, std::string* error)
{
    const std::size_t close = s.find('}', open);
    if (close == std::string::npos) {
        *error = "'{' at character " + std::to_string(open + 1) + " is never closed";
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
        *error = "unknown placeholder {" + body + "}; use {i}, {row} or {col}, optionally padded as {i:03}";
        return std::nullopt;
    }
    out->width = 0;
    if (colon != std::string::npos) {
        const std::string spec = body.substr(colon + 1);
        if (spec.size() != 2 || spec[0] != '0' || spec[1] < '1' || spec[1] > '9') {
            *error = "placeholder {" + body + "}: the width must look like :03 (a zero and one digit)";
            return std::nullopt;
        }
        out->width = spec[1] - '0';
    }
    return close + 1;
}

} // namespace

std::optional<std::string> checkFilePattern(const std::string& pattern)
{
    if (pattern.empty())
        return std::string("must not be empty");
    if (pattern.front() == ' ' || pattern.back() == ' ' || pattern.front() == '\t' || pattern.back() == '\t')
        return std::string("must not start or end with a space (Fiji trims file names)");
    if (pattern.front() == '#')
        return std::string("must not start with '#' (Fiji reads such a line as a comment)");
    bool index = false, row = false, col = false;
    for (std::size_t i = 0; i < pattern.size();) {
        const char ch = pattern[i];
        if (ch == ';')
            return std::string("must not contain ';' (it separates the fields of a TileConfiguration line)");
        if (ch == '/' || ch == '\\')
            return std::string("must be a file name without a folder ('/' or '\\')");
        if (static_cast<unsigned char>(ch) < 0x20)
            return std::string("must not contain control characters or line breaks");
        if (ch == '}')
            return "'}' at character " + std::to_string(i + 1) + " has no '{'";
        if (ch != '{') {
            ++i;
            continue;
        }
        Placeholder p;
        std::string error;
        const auto next = parsePlaceholder(pattern, i, &p, &error);
        if (!next)
            return error;
        index = index || p.kind == Placeholder::Index;
        row = row || p.kind == Placeholder::Row;
        col = col || p.kind == Placeholder::Col;
        i = *next;
    }
    if (!index && !(row && col))
        return std::string("must contain {i}, or both {row} and {col}, so every tile gets its own file");
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
        std::string error;
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
