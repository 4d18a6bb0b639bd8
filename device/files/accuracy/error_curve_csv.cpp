#include "device/files/accuracy/error_curve_csv.h"

#include "device/files/accuracy/csv_table.h"

#include <cmath>

namespace dev::files::accuracy {

using motion::metrology::FitPoint;

ErrorCurveRead errorCurveFromCsv(std::string_view text, std::string_view fileName)
{
    ErrorCurveRead out;
    const std::string file(fileName);
    const CsvTable table = parseCsv(text, fileName);
    out.problems = table.problems;
    if (hasErrors(out.problems))
        return out;
    if (table.rows.size() < 2) {
        out.problems.push_back({file, table.rows.empty() ? 0 : table.rows[0].line, table.rows.empty() ? 0 : 1, "", motion::msg::make("accuracy.csv.no_readings")});
        return out;
    }
    const CsvRow& header = table.rows.front();
    if (looksSemicolonSeparated(header)) {
        out.problems.push_back({file, header.line, 1, "", motion::msg::make("file.csv.semicolons")});
        return out;
    }
    const LengthColumn position = findLengthColumn(header, "position", "position_mm", fileName, out.problems);
    // error_up_um and error_down_um are the writer's extra columns, not a second error column.
    CsvRow errorHeader = header;
    for (CsvCell& c : errorHeader.cells)
        if (asciiLower(c.text) == "error_up_um" || asciiLower(c.text) == "error_down_um")
            c.text.clear();
    const LengthColumn error = findLengthColumn(errorHeader, "error", "error_um", fileName, out.problems);
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
        double v[2] = {0, 0};
        bool good = true;
        const LengthColumn cols[2] = {position, error};
        for (int k = 0; k < 2; ++k) {
            const CsvCell& cell = row.cells[static_cast<std::size_t>(cols[k].index)];
            const std::string& name = header.cells[static_cast<std::size_t>(cols[k].index)].text;
            const auto n = parseNumber(cell.text);
            if (!n) {
                out.problems.push_back({file, row.line, cell.column, name, motion::msg::make("accuracy.csv.not_a_number", {motion::msg::verbatim("text", cell.text)})});
                good = false;
            } else if (!std::isfinite(*n * cols[k].toMm * (k == 1 ? 1e3 : 1))) {  // finite in mm and µm too
                out.problems.push_back({file, row.line, cell.column, name, motion::msg::make("accuracy.value_not_finite")});
                good = false;
            } else {
                v[k] = *n * cols[k].toMm;
            }
        }
        if (good)
            out.points.push_back({v[0], v[1] * 1e3});  // error in µm
    }
    return out;
}

std::string errorCurveCsv(const motion::metrology::Evaluation& e)
{
    std::string out = "position_mm,error_um,error_up_um,error_down_um\r\n";
    for (const auto& t : e.targets)
        out += csvNumber(t.targetMm) + "," + csvNumber(t.meanMm * 1e3) + "," + csvNumber(t.meanUpMm * 1e3) + ","
            + (t.meanDownMm ? csvNumber(*t.meanDownMm * 1e3) : std::string()) + "\r\n";
    return out;
}

std::vector<FitPoint> fitPointsOf(const motion::metrology::Evaluation& e)
{
    std::vector<FitPoint> out;
    for (const auto& t : e.targets)
        out.push_back({t.targetMm, t.meanMm * 1e3});
    return out;
}

} // namespace dev::files::accuracy
