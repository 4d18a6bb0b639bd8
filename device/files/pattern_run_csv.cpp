#include "device/files/pattern_run_csv.h"

#include "device/files/text_file.h"

#include <charconv>

namespace dev::files {

namespace {
/// Shortest text that reads back to the same double.
void number(std::string& out, double v)
{
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    out.append(buf, r.ptr);
}
} // namespace

std::string patternRunCsv(const std::vector<dev::jobs::PatternRunSample>& samples)
{
    std::string out = "time_s,commanded_x_mm,commanded_y_mm,measured_x_mm,measured_y_mm,path_mm,contour_um,segment\n";
    out.reserve(out.size() + samples.size() * 96);
    for (const auto& s : samples) {
        for (double v : {s.tS, s.commanded.x, s.commanded.y, s.measured.x, s.measured.y, s.pathMm, s.contourMm * 1e3}) {
            number(out, v);
            out += ',';
        }
        out += std::to_string(s.segment);
        out += '\n';
    }
    return out;
}

bool savePatternRunCsv(const QString& path, const std::vector<dev::jobs::PatternRunSample>& samples, motion::msg::Message* error)
{
    return writeAtomically(path, patternRunCsv(samples), error);
}

} // namespace dev::files
