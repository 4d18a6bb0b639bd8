#include "device/files/accuracy/scale_certificate_csv.h"

#include "device/files/accuracy/csv_table.h"
#include "device/files/accuracy/load_text.h"

#include <cmath>

namespace dev::files::accuracy {

namespace {

/// The deviation column's unit: a deviation of a micrometre is written in µm or nm.
constexpr double kMaxDeviationUm = 1000;

} // namespace

ScaleCertificateRead scaleCertificateFromCsv(std::string_view text, std::string_view fileName, const ScaleGeometry& scale)
{
    const std::string file(fileName);
    motion::msg::Problems problems;
    // The header line: "# benchpilot.scale-certificate 1".
    const std::size_t firstEnd = text.find('\n');
    std::string first(text.substr(0, firstEnd));
    if (first.size() >= 3 && static_cast<unsigned char>(first[0]) == 0xEF && static_cast<unsigned char>(first[1]) == 0xBB
        && static_cast<unsigned char>(first[2]) == 0xBF)
        first.erase(0, 3);
    while (!first.empty() && (first.back() == '\r' || first.back() == ' '))
        first.pop_back();
    const std::string expected = std::string("# ") + kScaleCertificateSchema + " ";
    if (first.rfind(expected, 0) != 0) {
        problems.push_back({file, 1, 1, "", motion::msg::make("accuracy.certificate.no_schema", {motion::msg::verbatim("schema", kScaleCertificateSchema)})});
        return ScaleCertificateRead::refused(std::move(problems));
    }
    const std::string version = first.substr(expected.size());
    if (version != std::to_string(kScaleCertificateVersion)) {
        problems.push_back({file, 1, static_cast<int>(expected.size()) + 1, "",
                            motion::msg::make("accuracy.certificate.version", {motion::msg::verbatim("version", version),
                                                                               motion::msg::integer("supported", kScaleCertificateVersion)})});
        return ScaleCertificateRead::refused(std::move(problems));
    }
    // The rest as CSV, the notes blanked so every line keeps its number.
    std::string body(text);
    for (std::size_t at = 0; at < body.size();) {
        const std::size_t end = body.find('\n', at);
        const std::size_t stop = end == std::string::npos ? body.size() : end;
        std::size_t c = at;
        while (c < stop && (body[c] == ' ' || body[c] == '\t'))
            ++c;
        if ((c < stop && body[c] == '#') || at == 0)
            for (std::size_t k = at; k < stop; ++k)
                body[k] = ' ';
        at = stop + 1;
    }
    CsvTable table = parseCsv(body, fileName);
    problems.insert(problems.end(), table.problems.begin(), table.problems.end());
    if (table.rows.empty()) {
        problems.push_back({file, 1, 1, "", motion::msg::make("accuracy.csv.no_readings")});
        return ScaleCertificateRead::refused(std::move(problems));
    }
    const CsvRow& header = table.rows.front();
    const LengthColumn grad = findLengthColumn(header, "graduation", "graduation_mm", fileName, problems);
    const LengthColumn dev = findLengthColumn(header, "deviation", "deviation_um", fileName, problems);
    if (grad.index < 0 || dev.index < 0)
        return ScaleCertificateRead::refused(std::move(problems));
    motion::metrology::ScaleCertificate cert;
    double previous = -1e300;
    for (std::size_t r = 1; r < table.rows.size(); ++r) {
        const CsvRow& row = table.rows[r];
        if (row.cells.size() != header.cells.size()) {
            problems.push_back({file, row.line, 1, "",
                                motion::msg::make("accuracy.csv.wrong_cell_count", {motion::msg::integer("count", static_cast<long long>(row.cells.size())),
                                                                                    motion::msg::integer("expected", static_cast<long long>(header.cells.size()))})});
            continue;
        }
        auto number = [&](const LengthColumn& col, double toUnit, double* into) {
            const CsvCell& cell = row.cells[static_cast<std::size_t>(col.index)];
            const std::string& name = header.cells[static_cast<std::size_t>(col.index)].text;
            const auto v = parseNumber(cell.text);
            if (!v) {
                problems.push_back({file, row.line, cell.column, name, motion::msg::make("accuracy.csv.not_a_number", {motion::msg::verbatim("text", cell.text)})});
                return false;
            }
            // The unit's factor first: µm to µm is then exactly 1, and a value reads back as written.
            const double factor = col.toMm * toUnit;
            if (!std::isfinite(*v * factor)) {
                problems.push_back({file, row.line, cell.column, name, motion::msg::make("accuracy.value_not_finite")});
                return false;
            }
            *into = *v * factor;
            return true;
        };
        double g = 0, d = 0;
        const bool haveG = number(grad, 1.0, &g);
        const bool haveD = number(dev, 1000.0, &d);
        if (!haveG || !haveD)
            continue;
        const CsvCell& gCell = row.cells[static_cast<std::size_t>(grad.index)];
        const std::string& gName = header.cells[static_cast<std::size_t>(grad.index)].text;
        const double k = g / scale.pitchMm;
        if (g < -1e-9 || g > scale.lengthMm + 1e-9) {
            problems.push_back({file, row.line, gCell.column, gName,
                                motion::msg::make("accuracy.certificate.outside_scale", {motion::msg::real("graduation", g, motion::msg::Unit::Mm),
                                                                                         motion::msg::real("length", scale.lengthMm, motion::msg::Unit::Mm)})});
        } else if (std::fabs(k - std::round(k)) > 1e-6) {
            problems.push_back({file, row.line, gCell.column, gName,
                                motion::msg::make("accuracy.certificate.off_pitch", {motion::msg::real("graduation", g, motion::msg::Unit::Mm),
                                                                                     motion::msg::real("pitch", scale.pitchMm, motion::msg::Unit::Mm)})});
        } else if (!(g > previous)) {
            problems.push_back({file, row.line, gCell.column, gName,
                                motion::msg::make("accuracy.certificate.not_increasing", {motion::msg::real("graduation", g, motion::msg::Unit::Mm),
                                                                                          motion::msg::real("previous", previous, motion::msg::Unit::Mm)})});
        } else if (std::fabs(d) > kMaxDeviationUm) {
            const CsvCell& dCell = row.cells[static_cast<std::size_t>(dev.index)];
            problems.push_back({file, row.line, dCell.column, header.cells[static_cast<std::size_t>(dev.index)].text,
                                motion::msg::make("accuracy.value_above", {motion::msg::real("value", std::fabs(d), motion::msg::Unit::Um),
                                                                           motion::msg::real("max", kMaxDeviationUm, motion::msg::Unit::Um)})});
        } else {
            cert.graduationMm.push_back(g);
            cert.deviationUm.push_back(d);
            previous = g;
        }
    }
    if (cert.graduationMm.empty() && !motion::msg::hasErrors(problems))
        problems.push_back({file, header.line, 1, "", motion::msg::make("accuracy.csv.no_readings")});
    return ScaleCertificateRead::from(cert, std::move(problems));
}

ScaleCertificateRead loadScaleCertificateFile(const QString& path, const ScaleGeometry& scale)
{
    motion::msg::Problems problems;
    std::string name;
    const auto text = loadText(path, name, problems);
    return text ? scaleCertificateFromCsv(*text, name, scale) : ScaleCertificateRead::refused(std::move(problems));
}

std::string scaleCertificateToCsv(const motion::metrology::ScaleCertificate& c)
{
    std::string out = std::string("# ") + kScaleCertificateSchema + " " + std::to_string(kScaleCertificateVersion) + "\ngraduation_mm,deviation_um\n";
    for (std::size_t k = 0; k < c.graduationMm.size() && k < c.deviationUm.size(); ++k)
        out += csvNumber(c.graduationMm[k]) + "," + csvNumber(c.deviationUm[k]) + "\n";
    return out;
}

} // namespace dev::files::accuracy
