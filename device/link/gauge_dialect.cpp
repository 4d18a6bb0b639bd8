#include "device/link/gauge_dialect.h"

#include <charconv>
#include <cmath>
#include <cstdio>

namespace dev::gaugewire {
namespace {

bool isSpace(char c) { return c == ' ' || c == '\t'; }
bool isDigit(char c) { return c >= '0' && c <= '9'; }

std::string lower(std::string_view s)
{
    std::string out(s);
    for (char& c : out)
        if (c >= 'A' && c <= 'Z')
            c = static_cast<char>(c - 'A' + 'a');
    return out;
}

/// mm per unit, or 0 for a unit this dialect does not know.
double unitToMm(std::string_view unit)
{
    const std::string u = lower(unit);
    if (u == "mm")
        return 1;
    // µ as U+00B5 (micro sign, C2 B5) or U+03BC (Greek mu, CE BC).
    if (u == "um" || u == "\xC2\xB5m" || u == "\xCE\xBCm")
        return 1e-3;
    if (u == "in" || u == "inch")
        return 25.4;
    return 0;
}

motion::msg::Message notAReading(std::string_view line, const std::string& port)
{
    return motion::msg::make("gauge.not_a_reading", {motion::msg::verbatim("port", port), motion::msg::verbatim("text", printable(line))});
}

} // namespace

std::string printable(std::string_view bytes)
{
    std::string out;
    std::size_t shown = 0;
    for (std::size_t i = 0; i < bytes.size(); ++i) {
        if (shown >= 80) {
            out += "\xE2\x80\xA6";  // …
            break;
        }
        const auto b = static_cast<unsigned char>(bytes[i]);
        ++shown;
        if (b >= 0x20 && b < 0x7F) {
            out.push_back(static_cast<char>(b));
            continue;
        }
        // A well-formed UTF-8 sequence stays as it is (a gauge that prints "µm").
        int extra = (b & 0xE0) == 0xC0 ? 1 : (b & 0xF0) == 0xE0 ? 2 : (b & 0xF8) == 0xF0 ? 3 : 0;
        if (b >= 0xC2 && extra > 0 && i + static_cast<std::size_t>(extra) < bytes.size()) {
            bool ok = true;
            for (int k = 1; k <= extra; ++k)
                if ((static_cast<unsigned char>(bytes[i + static_cast<std::size_t>(k)]) & 0xC0) != 0x80)
                    ok = false;
            if (ok) {
                out.append(bytes.substr(i, static_cast<std::size_t>(extra) + 1));
                i += static_cast<std::size_t>(extra);
                continue;
            }
        }
        char buf[8];
        if (b == '\r')
            out += "\\r";
        else if (b == '\n')
            out += "\\n";
        else if (b == '\t')
            out += "\\t";
        else {
            std::snprintf(buf, sizeof buf, "\\x%02X", b);
            out += buf;
        }
    }
    return out;
}

Answer parseAnswer(std::string_view line, const std::string& port)
{
    Answer a;
    std::size_t i = 0;
    while (i < line.size() && isSpace(line[i]))
        ++i;
    std::string number;
    if (i < line.size() && (line[i] == '+' || line[i] == '-'))
        number.push_back(line[i++]);
    std::size_t digits = 0, significant = 0;
    bool point = false;
    while (i < line.size() && (isDigit(line[i]) || (line[i] == '.' && !point))) {
        if (line[i] == '.')
            point = true;
        else
            ++digits;
        number.push_back(line[i++]);
        ++significant;
    }
    if (digits == 0 || significant > 15) {
        a.problem = notAReading(line, port);
        return a;
    }
    const std::size_t afterNumber = i;
    while (i < line.size() && isSpace(line[i]))
        ++i;
    std::size_t unitEnd = i;
    while (unitEnd < line.size() && !isSpace(line[unitEnd]))
        ++unitEnd;
    const std::string_view unit = line.substr(i, unitEnd - i);
    std::size_t rest = unitEnd;
    while (rest < line.size() && isSpace(line[rest]))
        ++rest;
    if (rest != line.size() || unit.empty()) {
        a.problem = notAReading(line, port);
        return a;
    }
    // The unit must start right after the number or after spaces: "12.3mm" and
    // "12.3 mm" are readings, "12.3,4 mm" is not (the ',' would be the unit's start).
    if (afterNumber < line.size() && !isSpace(line[afterNumber]) && !((line[afterNumber] | 0x20) >= 'a' && (line[afterNumber] | 0x20) <= 'z')
        && static_cast<unsigned char>(line[afterNumber]) < 0x80) {
        a.problem = notAReading(line, port);
        return a;
    }
    const double toMm = unitToMm(unit);
    if (toMm == 0) {
        a.problem = motion::msg::make("gauge.unknown_unit", {motion::msg::verbatim("port", port), motion::msg::verbatim("text", printable(line)),
                                                     motion::msg::verbatim("unit", printable(unit))});
        return a;
    }
    // from_chars: the C locale's '.', whatever locale the program runs in (strtod
    // would read "12.5" as 12 under a decimal-comma locale).
    std::string_view digitsText(number);
    if (!digitsText.empty() && digitsText.front() == '+')
        digitsText.remove_prefix(1);
    double v = 0;
    const auto r = std::from_chars(digitsText.data(), digitsText.data() + digitsText.size(), v);
    if (r.ec != std::errc() || r.ptr != digitsText.data() + digitsText.size() || !std::isfinite(v)) {
        a.problem = notAReading(line, port);
        return a;
    }
    a.valueMm = v * toMm;
    return a;
}

} // namespace dev::gaugewire
