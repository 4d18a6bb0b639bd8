#include "device/files/accuracy/readings_csv.h"

#include "device/files/accuracy/csv_table.h"
#include "device/files/accuracy/load_text.h"
#include "device/files/text_file.h"

#include <charconv>
#include <cmath>

namespace dev::files::accuracy {

using motion::metrology::Direction;
using motion::metrology::Reading;

ReadingsRead readingsFromCsv(std::string_view text, std::string_view fileName)
{
    ReadingsRead out;
    const std::string file(fileName);
    CsvTable table = parseCsv(text, fileName);
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
    const LengthColumn target = findLengthColumn(header, "target", "target_mm", fileName, out.problems);
    const LengthColumn measured = findLengthColumn(header, "measured", "measured_mm", fileName, out.problems);
    const int direction = findRequiredColumn(header, "direction", fileName, out.problems);
    const int cycle = findRequiredColumn(header, "cycle", fileName, out.problems);
    if (hasErrors(out.problems))
        return out;
    if (table.rows.size() == 1) {
        out.problems.push_back({file, header.line, 1, "", motion::msg::make("accuracy.csv.no_readings")});
        return out;
    }

    for (std::size_t r = 1; r < table.rows.size(); ++r) {
        const CsvRow& row = table.rows[r];
        if (row.cells.size() != header.cells.size()) {
            out.problems.push_back({file, row.line, 1, "",
                                    motion::msg::make("accuracy.csv.wrong_cell_count", {motion::msg::integer("count", static_cast<long long>(row.cells.size())),
                                                                                motion::msg::integer("expected", static_cast<long long>(header.cells.size()))})});
            continue;
        }
        bool good = true;
        auto length = [&](const LengthColumn& col, double& into) {
            const CsvCell& cell = row.cells[static_cast<std::size_t>(col.index)];
            const std::string& name = header.cells[static_cast<std::size_t>(col.index)].text;
            const auto v = parseNumber(cell.text);
            if (!v) {
                out.problems.push_back({file, row.line, cell.column, name, motion::msg::make("accuracy.csv.not_a_number", {motion::msg::verbatim("text", cell.text)})});
                good = false;
            } else if (!std::isfinite(*v * col.toMm)) {  // 1e308 m is not finite in mm
                out.problems.push_back({file, row.line, cell.column, name, motion::msg::make("accuracy.value_not_finite")});
                good = false;
            } else {
                into = *v * col.toMm;
            }
        };
        Reading reading;
        length(target, reading.targetMm);
        length(measured, reading.measuredMm);
        const CsvCell& d = row.cells[static_cast<std::size_t>(direction)];
        if (const auto dir = motion::metrology::directionFromName(asciiLower(d.text)))
            reading.direction = *dir;
        else {
            out.problems.push_back({file, row.line, d.column, "direction", motion::msg::make("accuracy.csv.unknown_direction", {motion::msg::verbatim("text", d.text)})});
            good = false;
        }
        const CsvCell& c = row.cells[static_cast<std::size_t>(cycle)];
        int n = 0;
        const auto parsed = std::from_chars(c.text.data(), c.text.data() + c.text.size(), n);
        if (c.text.empty() || parsed.ec != std::errc() || parsed.ptr != c.text.data() + c.text.size() || n < 1) {
            out.problems.push_back({file, row.line, c.column, "cycle", motion::msg::make("accuracy.csv.not_a_cycle", {motion::msg::verbatim("text", c.text)})});
            good = false;
        } else {
            reading.cycle = n;
        }
        if (good) {
            out.readings.push_back(reading);
            out.lines.push_back(row.line);
        }
    }
    return out;
}

motion::msg::Problems placeReadingProblems(const motion::msg::Problems& found, const ReadingsRead& read, std::string_view fileName)
{
    motion::msg::Problems out;
    for (const motion::msg::Problem& p : found) {
        int line = 0;
        std::string field;
        // "readings[12]" or "readings[12].measured_mm": the reading's line.
        if (p.path.rfind("readings[", 0) == 0) {
            std::size_t k = 0;
            const char* first = p.path.data() + 9;
            const auto r = std::from_chars(first, p.path.data() + p.path.size(), k);
            if (r.ec == std::errc() && k < read.lines.size())
                line = read.lines[k];
            const auto dot = p.path.find('.', 9);
            if (dot != std::string::npos)
                field = p.path.substr(dot + 1);
        }
        out.push_back({std::string(fileName), line, line > 0 ? 1 : 0, field, p.message, p.severity});
    }
    return out;
}

AnalyzedReadings analyzeReadingsCsv(std::string_view text, std::string_view fileName)
{
    AnalyzedReadings out;
    out.read = readingsFromCsv(text, fileName);
    out.problems = out.read.problems;
    if (!out.read.ok())
        return out;
    out.evaluation = motion::metrology::evaluate(out.read.readings);
    const motion::msg::Problems placed = placeReadingProblems(out.evaluation.problems, out.read, fileName);
    out.problems.insert(out.problems.end(), placed.begin(), placed.end());
    return out;
}

std::string readingsToCsv(const std::vector<Reading>& readings)
{
    std::string out = "target_mm,direction,cycle,measured_mm,deviation_um\r\n";
    for (const Reading& r : readings)
        out += csvNumber(r.targetMm) + "," + motion::metrology::directionName(r.direction) + "," + std::to_string(r.cycle) + ","
            + csvNumber(r.measuredMm) + "," + csvNumber(std::round(r.deviationMm() * 1e9) / 1e6) + "\r\n";
    return out;
}

ReadingsRead loadReadingsCsv(const QString& path)
{
    ReadingsRead out;
    std::string name;
    const auto text = loadText(path, name, out.problems);
    return text ? readingsFromCsv(*text, name) : out;
}

bool saveReadingsCsv(const QString& path, const std::vector<Reading>& readings, motion::msg::Message* error)
{
    return dev::files::writeAtomically(path, readingsToCsv(readings), error);
}

} // namespace dev::files::accuracy
