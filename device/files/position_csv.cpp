#include "device/files/position_csv.h"

#include <cctype>
#include <cstdio>

namespace dev::files {

std::string csvField(const std::string& text)
{
    if (text.find_first_of(",\"\r\n") == std::string::npos)
        return text;
    std::string out = "\"";
    for (char c : text) {
        if (c == '"')
            out += '"';
        out += c;
    }
    return out + "\"";
}

namespace {

std::string fixed(double v, int decimals)
{
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    return buf;
}

std::string lower(char axis) { return std::string(1, static_cast<char>(std::tolower(static_cast<unsigned char>(axis)))); }

} // namespace

std::string positionRecordsCsv(const std::vector<motion::PositionRecord>& records, const std::string& axes,
                               const std::vector<CsvColumn>& extra)
{
    std::string out = "target,label";
    for (const CsvColumn& c : extra)
        out += "," + csvField(c.name);
    for (const char* kind : {"planned", "commanded", "measured"})
        for (char a : axes)
            out += std::string(",") + kind + "_" + lower(a) + "_mm";
    for (char a : axes)
        out += ",error_" + lower(a) + "_um";
    out += ",device_time_us,settle_s\r\n";
    for (std::size_t r = 0; r < records.size(); ++r) {
        const motion::PositionRecord& rec = records[r];
        out += std::to_string(rec.target) + "," + csvField(rec.label);
        for (const CsvColumn& c : extra)
            out += "," + (r < c.cells.size() ? csvField(c.cells[r]) : std::string());
        // Millimetres to the nanometre, errors to the nanometre in µm: finer than the grating.
        auto axisCells = [&](const std::vector<double>& v) {
            for (std::size_t a = 0; a < axes.size(); ++a)
                out += "," + (a < v.size() ? fixed(v[a], 6) : std::string());
        };
        axisCells(rec.plannedMm);
        axisCells(rec.commandedMm);
        axisCells(rec.measuredMm);
        for (std::size_t a = 0; a < axes.size(); ++a)
            out += "," + (rec.measured() && a < rec.measuredMm.size() && a < rec.commandedMm.size()
                              ? fixed((rec.measuredMm[a] - rec.commandedMm[a]) * 1e3, 3)
                              : std::string());
        out += "," + (rec.measured() ? std::to_string(rec.deviceTimeUs) : std::string());
        out += "," + (rec.measured() ? fixed(rec.settleS, 4) : std::string());
        out += "\r\n";
    }
    return out;
}

} // namespace dev::files
