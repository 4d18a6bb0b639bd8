#include "motion/plans/plates/wells.h"

#include "motion/plans/plates/labware.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <set>

namespace motion::plates {

std::string formatMm(double v)
{
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return buf;
}

std::string rowName(int row)
{
    if (row < 0)
        return "?";
    if (row < 26)
        return std::string(1, static_cast<char>('A' + row));
    return std::string(1, static_cast<char>('A' + row / 26 - 1)) + static_cast<char>('A' + row % 26);
}

std::string wellName(const WellId& w) { return rowName(w.row) + std::to_string(w.column + 1); }

std::optional<WellId> parseWellName(std::string_view text)
{
    std::size_t i = 0;
    int row = -1;
    while (i < text.size() && std::isalpha(static_cast<unsigned char>(text[i]))) {
        const int letter = std::toupper(static_cast<unsigned char>(text[i])) - 'A';
        row = row < 0 ? letter : (row + 1) * 26 + letter;
        if (++i > 2)
            return std::nullopt;
    }
    if (row < 0 || row >= kMaxRows || i == text.size())
        return std::nullopt;
    int column = 0;
    for (; i < text.size(); ++i) {
        if (!std::isdigit(static_cast<unsigned char>(text[i])))
            return std::nullopt;
        column = column * 10 + (text[i] - '0');
        if (column > kMaxColumns)
            return std::nullopt;
    }
    if (column < 1)
        return std::nullopt;
    return WellId{row, column - 1};
}

namespace {

std::string trim(std::string_view s)
{
    std::size_t a = 0, b = s.size();
    while (a < b && std::isspace(static_cast<unsigned char>(s[a])))
        ++a;
    while (b > a && std::isspace(static_cast<unsigned char>(s[b - 1])))
        --b;
    return std::string(s.substr(a, b - a));
}

bool startsWithWord(const std::string& s, const char* word, std::string* rest)
{
    const std::size_t n = std::char_traits<char>::length(word);
    if (s.size() <= n || !std::isspace(static_cast<unsigned char>(s[n])))
        return false;
    for (std::size_t k = 0; k < n; ++k)
        if (std::tolower(static_cast<unsigned char>(s[k])) != word[k])
            return false;
    *rest = trim(std::string_view(s).substr(n));
    return true;
}

std::string quoted(const std::string& s)
{
    std::string out = "\"";
    for (char c : s.substr(0, 40)) {
        const auto u = static_cast<unsigned char>(c);
        if (c == '"' || c == '\\')
            out += '\\';
        out += u < 0x20 ? '?' : c;
    }
    return out + (s.size() > 40 ? "…\"" : "\"");
}

/// One spec (no commas) → wells, or a problem message.
bool expandOne(const std::string& spec, const Labware& lw, std::vector<WellId>& out, motion::msg::Message* error)
{
    const motion::msg::Arg plateWells = motion::msg::integer("wells", static_cast<long long>(lw.wells.size()));
    auto unknown = [&](const std::string& name) {
        *error = motion::msg::make("plate.unknown_well", {textArg("well", quoted(name)), plateWells});
        return false;
    };
    auto known = [&](const std::string& name, WellId* w) {
        const auto id = parseWellName(name);
        if (!id)
            return false;
        *w = *id;
        return true;
    };
    std::string rest;
    if (spec == "all" || spec == "ALL" || spec == "All") {
        for (const Well& w : lw.wells)
            out.push_back(w.id);
        return true;
    }
    if (startsWithWord(spec, "row", &rest)) {
        WellId w;
        if (!known(rest + "1", &w) || rest.empty() || !std::isalpha(static_cast<unsigned char>(rest.back()))) {
            *error = motion::msg::make("plate.wells.row_needs_letter", {textArg("text", quoted("row " + rest))});
            return false;
        }
        if (w.row >= lw.rows) {
            *error = motion::msg::make("plate.wells.unknown_row", {textArg("row", quoted(rest)), plateWells, textArg("last", rowName(lw.rows - 1))});
            return false;
        }
        for (int c = 0; c < lw.columns; ++c)
            if (lw.well({w.row, c}))
                out.push_back({w.row, c});
        return true;
    }
    if (startsWithWord(spec, "column", &rest)) {
        WellId w;
        if (!known("A" + rest, &w) || rest.empty() || !std::isdigit(static_cast<unsigned char>(rest[0]))) {
            *error = motion::msg::make("plate.wells.column_needs_number", {textArg("text", quoted("column " + rest))});
            return false;
        }
        if (w.column >= lw.columns) {
            *error = motion::msg::make("plate.wells.unknown_column", {textArg("column", quoted(rest)), plateWells, motion::msg::integer("last", lw.columns, motion::msg::Unit::None)});
            return false;
        }
        for (int r = 0; r < lw.rows; ++r)
            if (lw.well({r, w.column}))
                out.push_back({r, w.column});
        return true;
    }
    const std::size_t colon = spec.find(':');
    if (colon != std::string::npos) {
        const std::string a = trim(std::string_view(spec).substr(0, colon));
        const std::string b = trim(std::string_view(spec).substr(colon + 1));
        WellId wa, wb;
        if (!known(a, &wa) || !known(b, &wb)) {
            *error = motion::msg::make("plate.wells.bad_range", {textArg("text", quoted(spec))});
            return false;
        }
        if (!lw.well(wa))
            return unknown(a);
        if (!lw.well(wb))
            return unknown(b);
        const int dr = wb.row >= wa.row ? 1 : -1, dc = wb.column >= wa.column ? 1 : -1;
        for (int r = wa.row;; r += dr) {
            for (int c = wa.column;; c += dc) {
                if (lw.well({r, c}))
                    out.push_back({r, c});
                if (c == wb.column)
                    break;
            }
            if (r == wb.row)
                break;
        }
        return true;
    }
    WellId w;
    if (!known(spec, &w)) {
        *error = motion::msg::make("plate.wells.not_a_well_set", {textArg("text", quoted(spec))});
        return false;
    }
    if (!lw.well(w))
        return unknown(spec);
    out.push_back(w);
    return true;
}

} // namespace

WellSet expandWells(const std::vector<std::string>& specs, const Labware& labware, const std::string& path)
{
    WellSet set;
    std::set<WellId> seen;
    if (specs.empty()) {
        set.problems.push_back({path, motion::msg::make("plate.wells.none")});
        return set;
    }
    for (std::size_t k = 0; k < specs.size(); ++k) {
        const std::string at = specs.size() == 1 ? path : indexPath(path, k);
        const std::string& text = specs[k];
        std::size_t from = 0;
        bool any = false;
        while (from <= text.size()) {
            std::size_t comma = text.find(',', from);
            if (comma == std::string::npos)
                comma = text.size();
            const std::string part = trim(std::string_view(text).substr(from, comma - from));
            from = comma + 1;
            if (part.empty())
                continue;
            any = true;
            std::vector<WellId> wells;
            motion::msg::Message error;
            if (!expandOne(part, labware, wells, &error)) {
                set.problems.push_back({at, error});
                continue;
            }
            for (const WellId& w : wells) {
                if (!seen.insert(w).second) {
                    set.problems.push_back({at, motion::msg::make("plate.wells.named_twice", {textArg("well", wellName(w))})});
                    continue;
                }
                set.wells.push_back(w);
            }
        }
        if (!any)
            set.problems.push_back({at, motion::msg::make("plate.wells.none")});
    }
    return set;
}

std::vector<std::string> describeWells(std::vector<WellId> wells)
{
    std::sort(wells.begin(), wells.end());
    wells.erase(std::unique(wells.begin(), wells.end()), wells.end());
    std::vector<std::string> out;
    if (wells.empty())
        return out;
    int r0 = wells.front().row, r1 = r0, c0 = wells.front().column, c1 = c0;
    for (const WellId& w : wells) {
        r0 = std::min(r0, w.row);
        r1 = std::max(r1, w.row);
        c0 = std::min(c0, w.column);
        c1 = std::max(c1, w.column);
    }
    if (wells.size() > 1 && static_cast<std::size_t>((r1 - r0 + 1) * (c1 - c0 + 1)) == wells.size()) {
        out.push_back(wellName({r0, c0}) + ":" + wellName({r1, c1}));
        return out;
    }
    for (std::size_t i = 0; i < wells.size();) {
        std::size_t j = i;
        while (j + 1 < wells.size() && wells[j + 1].row == wells[i].row && wells[j + 1].column == wells[j].column + 1)
            ++j;
        out.push_back(j == i ? wellName(wells[i]) : wellName(wells[i]) + ":" + wellName(wells[j]));
        i = j + 1;
    }
    return out;
}

} // namespace motion::plates
