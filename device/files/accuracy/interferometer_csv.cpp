#include "device/files/accuracy/interferometer_csv.h"

#include "device/files/accuracy/csv_table.h"
#include "device/files/accuracy/load_text.h"
#include "device/files/text_file.h"
#include "motion/metrology/linear/run_sequence.h"

#include <charconv>
#include <cmath>

namespace dev::files::accuracy {

using motion::metrology::Direction;
using motion::metrology::Reading;

namespace {

/// A target in an export is the stop's when it is this close (interferometer
/// software echoes the targets it was given, rounded to its display).
constexpr double kTargetMatchMm = 0.001;

std::optional<int> wholeNumber(const std::string& text)
{
    int n = 0;
    const auto r = std::from_chars(text.data(), text.data() + text.size(), n);
    if (text.empty() || r.ec != std::errc() || r.ptr != text.data() + text.size())
        return std::nullopt;
    return n;
}

/// A length column that may be absent: its index (−1 none), or −2 after a problem.
LengthColumn optionalLength(const CsvRow& header, const std::string& stem, std::string_view file, motion::msg::Problems& out)
{
    motion::msg::Problems scratch;
    const LengthColumn c = findLengthColumn(header, stem, stem + "_mm", file, scratch);
    if (c.index == -2)
        out.insert(out.end(), scratch.begin(), scratch.end());
    return c;
}

std::optional<Direction> exportDirection(const std::string& text)
{
    const std::string t = asciiLower(text);
    if (t == "up" || t == "forward" || t == "fwd" || t == "+")
        return Direction::Up;
    if (t == "down" || t == "backward" || t == "bwd" || t == "-")
        return Direction::Down;
    return std::nullopt;
}

motion::msg::Arg directionArg(const char* name, Direction d) { return motion::msg::term(name, motion::metrology::directionTermId(d)); }

} // namespace

std::string targetSequenceCsv(const std::vector<SequenceStop>& stops)
{
    std::string out = "index,target_mm,direction,cycle,time_s,settled\r\n";
    for (const SequenceStop& s : stops)
        out += std::to_string(s.index) + "," + csvNumber(s.targetMm) + "," + motion::metrology::directionName(s.direction) + ","
            + std::to_string(s.cycle) + "," + csvNumber(std::round(s.timeS * 1e3) / 1e3) + "," + (s.settled ? "yes" : "no") + "\r\n";
    return out;
}

SequenceRead targetSequenceFromCsv(std::string_view text, std::string_view fileName)
{
    SequenceRead out;
    const std::string file(fileName);
    CsvTable table = parseCsv(text, fileName);
    out.problems = table.problems;
    if (hasErrors(out.problems))
        return out;
    if (table.rows.size() < 2) {
        out.problems.push_back({file, table.rows.empty() ? 0 : table.rows.front().line, 0, "", motion::msg::make("accuracy.csv.no_readings")});
        return out;
    }
    const CsvRow& header = table.rows.front();
    if (looksSemicolonSeparated(header)) {
        out.problems.push_back({file, header.line, 1, "", motion::msg::make("file.csv.semicolons")});
        return out;
    }
    const int index = findRequiredColumn(header, "index", fileName, out.problems);
    const LengthColumn target = findLengthColumn(header, "target", "target_mm", fileName, out.problems);
    const int direction = findRequiredColumn(header, "direction", fileName, out.problems);
    const int cycle = findRequiredColumn(header, "cycle", fileName, out.problems);
    const int time = findColumn(header, "time_s");
    const int settled = findColumn(header, "settled");
    if (hasErrors(out.problems))
        return out;
    for (std::size_t r = 1; r < table.rows.size(); ++r) {
        const CsvRow& row = table.rows[r];
        if (row.cells.size() != header.cells.size()) {
            out.problems.push_back({file, row.line, 1, "",
                                    motion::msg::make("accuracy.csv.wrong_cell_count", {motion::msg::integer("count", static_cast<long long>(row.cells.size())),
                                                                                motion::msg::integer("expected", static_cast<long long>(header.cells.size()))})});
            continue;
        }
        SequenceStop s;
        const CsvCell& ic = row.cells[static_cast<std::size_t>(index)];
        const auto n = wholeNumber(ic.text);
        if (!n || *n != static_cast<int>(r)) {
            out.problems.push_back({file, row.line, ic.column, "index",
                                    motion::msg::make("accuracy.import.index_out_of_order", {motion::msg::verbatim("text", ic.text), motion::msg::integer("expected", static_cast<long long>(r))})});
            continue;
        }
        s.index = *n;
        const CsvCell& tc = row.cells[static_cast<std::size_t>(target.index)];
        const auto t = parseNumber(tc.text);
        if (!t || !std::isfinite(*t * target.toMm)) {
            out.problems.push_back({file, row.line, tc.column, header.cells[static_cast<std::size_t>(target.index)].text,
                                    t ? motion::msg::make("accuracy.value_not_finite") : motion::msg::make("accuracy.csv.not_a_number", {motion::msg::verbatim("text", tc.text)})});
            continue;
        }
        s.targetMm = *t * target.toMm;
        const CsvCell& dc = row.cells[static_cast<std::size_t>(direction)];
        const auto d = motion::metrology::directionFromName(asciiLower(dc.text));
        if (!d) {
            out.problems.push_back({file, row.line, dc.column, "direction", motion::msg::make("accuracy.csv.unknown_direction", {motion::msg::verbatim("text", dc.text)})});
            continue;
        }
        s.direction = *d;
        const CsvCell& cc = row.cells[static_cast<std::size_t>(cycle)];
        const auto c = wholeNumber(cc.text);
        if (!c || *c < 1) {
            out.problems.push_back({file, row.line, cc.column, "cycle", motion::msg::make("accuracy.csv.not_a_cycle", {motion::msg::verbatim("text", cc.text)})});
            continue;
        }
        s.cycle = *c;
        if (time >= 0) {
            const CsvCell& timeCell = row.cells[static_cast<std::size_t>(time)];
            const auto v = parseNumber(timeCell.text);
            if (!v) {
                out.problems.push_back({file, row.line, timeCell.column, "time_s", motion::msg::make("accuracy.csv.not_a_number", {motion::msg::verbatim("text", timeCell.text)})});
                continue;
            }
            // Device seconds since the run began: a run of 30 years is a typo.
            motion::msg::Problems range;
            if (!motion::metrology::checkRange(range, "time_s", *v, 0, 1e9, motion::msg::Unit::S)) {
                out.problems.push_back({file, row.line, timeCell.column, "time_s", range.front().message});
                continue;
            }
            s.timeS = *v;
        }
        if (settled >= 0)
            s.settled = asciiLower(row.cells[static_cast<std::size_t>(settled)].text) != "no";
        out.stops.push_back(s);
    }
    if (hasErrors(out.problems))
        out.stops.clear();
    return out;
}

InterferometerImport importInterferometerCsv(std::string_view exportText, std::string_view fileName, const std::vector<SequenceStop>& sequence)
{
    InterferometerImport out;
    const std::string file(fileName);
    CsvTable table = parseCsv(exportText, fileName);
    out.problems = table.problems;
    if (hasErrors(out.problems))
        return out;
    if (table.rows.empty()) {
        out.problems.push_back({file, 0, 0, "", motion::msg::make("accuracy.csv.no_readings")});
        return out;
    }
    const CsvRow& header = table.rows.front();
    if (looksSemicolonSeparated(header)) {
        out.problems.push_back({file, header.line, 1, "", motion::msg::make("file.csv.semicolons")});
        return out;
    }
    // The value: a position or a deviation, exactly one of them.
    LengthColumn value;
    bool isDeviation = false;
    std::string valueName;
    for (const char* stem : {"measured", "position", "reading", "deviation", "error"}) {
        const LengthColumn c = optionalLength(header, stem, fileName, out.problems);
        if (c.index == -2)
            return out;
        if (c.index < 0)
            continue;
        if (value.index >= 0) {
            out.problems.push_back({file, header.line, header.cells[static_cast<std::size_t>(c.index)].column,
                                    header.cells[static_cast<std::size_t>(c.index)].text,
                                    motion::msg::make("accuracy.csv.duplicate_column", {motion::msg::verbatim("column", header.cells[static_cast<std::size_t>(c.index)].text)})});
            return out;
        }
        value = c;
        valueName = header.cells[static_cast<std::size_t>(c.index)].text;
        isDeviation = std::string(stem) == "deviation" || std::string(stem) == "error";
    }
    if (value.index < 0) {
        out.problems.push_back({file, header.line, 1, "", motion::msg::make("accuracy.csv.missing_column", {motion::msg::verbatim("column", "measured_mm")})});
        return out;
    }
    const LengthColumn target = optionalLength(header, "target", fileName, out.problems);
    if (target.index == -2)
        return out;
    const int direction = findColumn(header, "direction");

    const std::size_t rows = table.rows.size() - 1;
    if (rows != sequence.size()) {
        const int line = rows == 0 ? header.line : table.rows.back().line;
        out.problems.push_back({file, line, 1, "",
                                motion::msg::make("accuracy.import.count_differs", {motion::msg::integer("count", static_cast<long long>(rows)),
                                                                            motion::msg::integer("expected", static_cast<long long>(sequence.size()))})});
        return out;
    }
    for (std::size_t k = 0; k < rows; ++k) {
        const CsvRow& row = table.rows[k + 1];
        const SequenceStop& stop = sequence[k];
        if (row.cells.size() != header.cells.size()) {
            out.problems.push_back({file, row.line, 1, "",
                                    motion::msg::make("accuracy.csv.wrong_cell_count", {motion::msg::integer("count", static_cast<long long>(row.cells.size())),
                                                                                motion::msg::integer("expected", static_cast<long long>(header.cells.size()))})});
            continue;
        }
        const CsvCell& vc = row.cells[static_cast<std::size_t>(value.index)];
        const auto v = parseNumber(vc.text);
        if (!v) {
            out.problems.push_back({file, row.line, vc.column, valueName, motion::msg::make("accuracy.csv.not_a_number", {motion::msg::verbatim("text", vc.text)})});
            continue;
        }
        if (!std::isfinite(*v * value.toMm)) {
            out.problems.push_back({file, row.line, vc.column, valueName, motion::msg::make("accuracy.value_not_finite")});
            continue;
        }
        if (direction >= 0) {
            const CsvCell& dc = row.cells[static_cast<std::size_t>(direction)];
            const auto d = exportDirection(dc.text);
            if (!d) {
                out.problems.push_back({file, row.line, dc.column, "direction", motion::msg::make("accuracy.csv.unknown_direction", {motion::msg::verbatim("text", dc.text)})});
                continue;
            }
            if (*d != stop.direction) {
                out.problems.push_back({file, row.line, dc.column, "direction",
                                        motion::msg::make("accuracy.import.direction_differs",
                                                  {motion::msg::integer("index", stop.index), directionArg("direction", *d),
                                                   directionArg("expected", stop.direction), motion::msg::real("target", stop.targetMm, motion::msg::Unit::Mm)})});
                continue;
            }
        }
        if (target.index >= 0) {
            const CsvCell& tc = row.cells[static_cast<std::size_t>(target.index)];
            const auto t = parseNumber(tc.text);
            if (!t || !std::isfinite(*t * target.toMm)) {
                out.problems.push_back({file, row.line, tc.column, header.cells[static_cast<std::size_t>(target.index)].text,
                                        t ? motion::msg::make("accuracy.value_not_finite") : motion::msg::make("accuracy.csv.not_a_number", {motion::msg::verbatim("text", tc.text)})});
                continue;
            }
            if (std::fabs(*t * target.toMm - stop.targetMm) > kTargetMatchMm) {
                out.problems.push_back({file, row.line, tc.column, header.cells[static_cast<std::size_t>(target.index)].text,
                                        motion::msg::make("accuracy.import.target_differs",
                                                  {motion::msg::integer("index", stop.index), motion::msg::real("target", *t * target.toMm, motion::msg::Unit::Mm),
                                                   motion::msg::real("expected", stop.targetMm, motion::msg::Unit::Mm)})});
                continue;
            }
        }
        Reading r;
        r.targetMm = stop.targetMm;
        r.direction = stop.direction;
        r.cycle = stop.cycle;
        r.measuredMm = isDeviation ? stop.targetMm + *v * value.toMm : *v * value.toMm;
        out.readings.push_back(r);
    }
    if (hasErrors(out.problems))
        out.readings.clear();
    return out;
}

SequenceRead loadTargetSequence(const QString& path)
{
    SequenceRead out;
    std::string name;
    const auto text = loadText(path, name, out.problems);
    return text ? targetSequenceFromCsv(*text, name) : out;
}

bool saveTargetSequence(const QString& path, const std::vector<SequenceStop>& stops, motion::msg::Message* error)
{
    return dev::files::writeAtomically(path, targetSequenceCsv(stops), error);
}

InterferometerImport loadInterferometerExport(const QString& path, const std::vector<SequenceStop>& sequence)
{
    InterferometerImport out;
    std::string name;
    const auto text = loadText(path, name, out.problems);
    return text ? importInterferometerCsv(*text, name, sequence) : out;
}

std::optional<motion::msg::Message> sequenceMismatch(const std::vector<SequenceStop>& sequence, const motion::metrology::AxisTest& test)
{
    const std::vector<motion::metrology::Stop> planned = motion::metrology::runSequence(test);
    if (sequence.size() != planned.size())
        return motion::msg::make("accuracy.import.not_this_test_count", {motion::msg::integer("count", static_cast<long long>(sequence.size())),
                                                                 motion::msg::integer("expected", static_cast<long long>(planned.size())),
                                                                 motion::msg::verbatim("test", test.name)});
    for (std::size_t k = 0; k < planned.size(); ++k) {
        const SequenceStop& s = sequence[k];
        const motion::metrology::Stop& p = planned[k];
        if (std::fabs(s.targetMm - p.targetMm) > kTargetMatchMm || s.direction != p.direction || s.cycle != p.cycle)
            return motion::msg::make("accuracy.import.not_this_test_stop",
                             {motion::msg::integer("stop", static_cast<long long>(k + 1)), motion::msg::real("target", s.targetMm, motion::msg::Unit::Mm),
                              directionArg("direction", s.direction), motion::msg::integer("cycle", s.cycle),
                              motion::msg::real("expected", p.targetMm, motion::msg::Unit::Mm), directionArg("expected_direction", p.direction),
                              motion::msg::integer("expected_cycle", p.cycle), motion::msg::verbatim("test", test.name)});
    }
    return std::nullopt;
}

} // namespace dev::files::accuracy
