#include "device/files/accuracy/compensation/compensation_exports.h"

#include "device/files/accuracy/csv_table.h"
#include "device/files/text_file.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstdio>

namespace dev::files::accuracy {

using motion::metrology::CompensationModel;
using motion::metrology::TablePoint;

namespace {

constexpr int kDefaultSamples = 41;

std::vector<TablePoint> pointsOf(const CompensationModel& m, const std::vector<double>& nominals)
{
    if (nominals.empty() && m.kind == CompensationModel::Kind::Table) {
        std::vector<TablePoint> out = m.table;
        // A single column carries the backlash beside it: put its halves into the columns.
        if (!m.perDirection)
            for (TablePoint& p : out) {
                p.correctionUpUm += m.backlashUm / 2;
                p.correctionDownUm -= m.backlashUm / 2;
            }
        return out;
    }
    return motion::metrology::sampleTable(m, nominals.empty() ? defaultNominals(m) : nominals);
}

/// Millimetres to the nanometre, as LinuxCNC's own example files write them.
std::string mm6(double v)
{
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.6f", v);
    return std::string(buf) == "-0.000000" ? "0.000000" : buf;
}

std::vector<std::string> splitWhitespace(std::string_view line)
{
    std::vector<std::string> out;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r'))
            ++i;
        std::size_t j = i;
        while (j < line.size() && line[j] != ' ' && line[j] != '\t' && line[j] != '\r')
            ++j;
        if (j > i)
            out.emplace_back(line.substr(i, j - i));
        i = j;
    }
    return out;
}

} // namespace

std::vector<double> defaultNominals(const CompensationModel& m)
{
    std::vector<double> out;
    if (m.kind == CompensationModel::Kind::Table) {
        for (const TablePoint& p : m.table)
            out.push_back(p.nominalMm);
        return out;
    }
    // Fewer points over a short range, so they stay 2 µm or more apart (the table's
    // least spacing, with room for rounding to the nanometre).
    const double span = m.validToMm - m.validFromMm;
    const int count = std::clamp(static_cast<int>(std::floor(span / (2 * motion::metrology::kMinTableSpacingMm))) + 1, 2, kDefaultSamples);
    for (int i = 0; i < count; ++i) {
        const double w = static_cast<double>(i) / (count - 1);
        out.push_back(std::round((m.validFromMm + w * (m.validToMm - m.validFromMm)) * 1e6) / 1e6);
    }
    return out;
}

std::string compensationCsv(const CompensationModel& m, const std::vector<double>& nominalsMm)
{
    std::string out = "nominal_mm,correction_up_um,correction_down_um\r\n";
    for (const TablePoint& p : pointsOf(m, nominalsMm))
        out += csvNumber(p.nominalMm) + "," + csvNumber(p.correctionUpUm) + "," + csvNumber(p.correctionDownUm) + "\r\n";
    return out;
}

std::string linuxcncCompensation(const CompensationModel& m, LinuxcncCompType type, const std::vector<double>& nominalsMm)
{
    std::string out;
    for (const TablePoint& p : pointsOf(m, nominalsMm)) {
        const double up = p.correctionUpUm * 1e-3, down = p.correctionDownUm * 1e-3;
        if (type == LinuxcncCompType::ActualPositions)
            out += mm6(p.nominalMm) + " " + mm6(p.nominalMm - up) + " " + mm6(p.nominalMm - down) + "\n";
        else
            out += mm6(p.nominalMm) + " " + mm6(up) + " " + mm6(down) + "\n";
    }
    return out;
}

LinuxcncRead linuxcncFromText(std::string_view text, std::string_view fileName, LinuxcncCompType type, const std::string& axis)
{
    LinuxcncRead out;
    const std::string file(fileName);
    CompensationModel m;
    m.axis = axis;
    m.kind = CompensationModel::Kind::Table;
    m.perDirection = true;
    int line = 0;
    std::vector<int> pointLines;
    std::size_t start = 0;
    while (start <= text.size()) {
        ++line;
        const std::size_t end = std::min(text.find('\n', start), text.size());
        const std::string_view row = text.substr(start, end - start);
        start = end + 1;
        const auto fields = splitWhitespace(row);
        if (fields.empty()) {
            if (end >= text.size())
                break;
            continue;
        }
        if (fields.size() != 3) {
            out.problems.push_back({file, line, 1, "",
                                    motion::msg::make("compensation.linuxcnc.not_a_triplet", {motion::msg::integer("count", static_cast<long long>(fields.size()))})});
            continue;
        }
        double v[3] = {0, 0, 0};
        bool good = true;
        std::size_t column = 1;
        for (int k = 0; k < 3; ++k) {
            column = row.find(fields[static_cast<std::size_t>(k)], k == 0 ? 0 : column) + 1;
            const auto n = parseNumber(fields[static_cast<std::size_t>(k)]);
            if (!n || !std::isfinite(*n)) {
                out.problems.push_back({file, line, static_cast<int>(column), "",
                                        motion::msg::make("accuracy.csv.not_a_number", {motion::msg::verbatim("text", fields[static_cast<std::size_t>(k)])})});
                good = false;
                break;
            }
            v[k] = *n;
        }
        if (!good)
            continue;
        const double up = type == LinuxcncCompType::ActualPositions ? v[0] - v[1] : v[1];
        const double down = type == LinuxcncCompType::ActualPositions ? v[0] - v[2] : v[2];
        m.table.push_back({v[0], up * 1e3, down * 1e3});
        pointLines.push_back(line);
        if (end >= text.size())
            break;
    }
    if (hasErrors(out.problems))
        return out;
    // The table's own checks, placed on the line of the point they name.
    for (const motion::msg::Problem& p : motion::metrology::validate(m)) {
        int at = 0;
        if (p.path.rfind("table.points[", 0) == 0) {
            const auto k = static_cast<std::size_t>(std::atoi(p.path.c_str() + 13));
            at = k < pointLines.size() ? pointLines[k] : 0;
        }
        out.problems.push_back({file, at, at > 0 ? 1 : 0, p.path, p.message, p.severity});
    }
    if (!hasErrors(out.problems))
        out.model = m;
    return out;
}

bool saveLinuxcncCompensation(const QString& path, const CompensationModel& m, LinuxcncCompType type, motion::msg::Message* error)
{
    return dev::files::writeAtomically(path, linuxcncCompensation(m, type), error);
}

bool saveCompensationCsv(const QString& path, const CompensationModel& m, motion::msg::Message* error)
{
    return dev::files::writeAtomically(path, compensationCsv(m), error);
}

} // namespace dev::files::accuracy
