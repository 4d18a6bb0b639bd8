#include "device/backends/grbl/grbl_gcode.h"
#include "motion/numbers.h"

#include <cmath>
#include <cstdio>

namespace dev::grbl {

std::string formatNumber(double value, int decimals)
{
    if (!std::isfinite(value))
        return "nan";
    if (decimals < 0)
        decimals = 0;
    if (decimals > 6)
        decimals = 6;
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, value);
    std::string s(buf);
    if (s.find('.') != std::string::npos) {
        while (s.back() == '0')
            s.pop_back();
        if (s.back() == '.')
            s.pop_back();
    }
    if (s == "-0")
        s = "0";
    return s;
}

namespace {

constexpr double kMaxAbsMm = 1e6;        ///< 1 km: anything larger is a unit mistake, and GRBL's float loses µm
constexpr double kMaxFeedMmMin = 1e6;
using motion::kPi;

GcodeLine refuse(motion::msg::Message why)
{
    GcodeLine l;
    l.problem = std::move(why);
    return l;
}

GcodeLine finish(std::string text)
{
    if (text.size() > kMaxLineChars)
        return refuse(motion::msg::make("grbl.gcode.too_long", {motion::msg::verbatim("line", text),
                                                        motion::msg::integer("limit", static_cast<long long>(kMaxLineChars), motion::msg::Unit::Byte)}));
    GcodeLine l;
    l.text = std::move(text);
    return l;
}

bool finiteWord(char letter, double v, double limit, GcodeLine& fail)
{
    if (std::isfinite(v) && std::fabs(v) <= limit)
        return true;
    fail = refuse(motion::msg::make("grbl.gcode.not_finite", {motion::msg::verbatim("word", std::string(1, letter))}));
    return false;
}

bool feedOk(double feed, GcodeLine& fail)
{
    if (std::isfinite(feed) && feed > 0 && feed <= kMaxFeedMmMin)
        return true;
    fail = refuse(motion::msg::make("grbl.gcode.bad_feed", {motion::msg::real("feed", std::isfinite(feed) ? feed : 0, motion::msg::Unit::MmPerMin)}));
    return false;
}

bool axisLetterOk(char c) { return c == 'X' || c == 'Y' || c == 'Z' || c == 'A' || c == 'B' || c == 'C'; }

/// " X10 Y-2" for the axes; false (with `fail` set) on a bad letter or number.
bool axisWords(const std::vector<AxisValue>& axes, std::string& out, GcodeLine& fail)
{
    if (axes.empty()) {
        fail = refuse(motion::msg::make("grbl.gcode.no_axes"));
        return false;
    }
    for (const auto& a : axes) {
        if (!axisLetterOk(a.letter)) {
            fail = refuse(motion::msg::make("grbl.gcode.bad_axis", {motion::msg::verbatim("axis", std::string(1, a.letter))}));
            return false;
        }
        if (!finiteWord(a.letter, a.mm, kMaxAbsMm, fail))
            return false;
        out += ' ';
        out += a.letter;
        out += formatNumber(a.mm);
    }
    return true;
}

} // namespace

GcodeLine moveLine(Motion motion, bool relative, const std::vector<AxisValue>& axes, double feedMmMin)
{
    GcodeLine fail;
    std::string s = relative ? "G91 G21 " : "G90 G21 ";
    s += motion == Motion::Rapid ? "G0" : "G1";
    if (!axisWords(axes, s, fail))
        return fail;
    if (motion == Motion::Feed) {
        if (!feedOk(feedMmMin, fail))
            return fail;
        s += " F" + formatNumber(feedMmMin, 1);
    }
    return finish(std::move(s));
}

GcodeLine arcLine(ArcDirection dir, double endXMm, double endYMm, double i, double j, double feedMmMin)
{
    GcodeLine fail;
    if (!finiteWord('X', endXMm, kMaxAbsMm, fail) || !finiteWord('Y', endYMm, kMaxAbsMm, fail)
        || !finiteWord('I', i, kMaxAbsMm, fail) || !finiteWord('J', j, kMaxAbsMm, fail) || !feedOk(feedMmMin, fail))
        return fail;
    std::string s = "G90 G21 G17 ";
    s += dir == ArcDirection::Clockwise ? "G2" : "G3";
    s += " X" + formatNumber(endXMm) + " Y" + formatNumber(endYMm) + " I" + formatNumber(i) + " J" + formatNumber(j);
    s += " F" + formatNumber(feedMmMin, 1);
    return finish(std::move(s));
}

std::vector<GcodeLine> circleLines(double cx, double cy, double r, ArcDirection dir, double feedMmMin)
{
    // Quarter points, going round the way the arcs turn: counter-clockwise visits +Y first.
    const double sign = dir == ArcDirection::CounterClockwise ? 1.0 : -1.0;
    std::vector<GcodeLine> out;
    double x = cx + r, y = cy;
    for (int q = 1; q <= 4; ++q) {
        const double angle = sign * q * (kPi / 2);
        // Exact quarter points: cos/sin of multiples of π/2 are rounded to 0 and ±1.
        const double c = std::round(std::cos(angle)), s = std::round(std::sin(angle));
        const double ex = cx + r * c, ey = cy + r * s;
        out.push_back(arcLine(dir, ex, ey, cx - x, cy - y, feedMmMin));
        x = ex;
        y = ey;
    }
    return out;
}

GcodeLine dwellLine(double seconds)
{
    // GRBL 1.1 requires P > 0 (the interface document's G4 P0.01 example); 3 decimals = 1 ms.
    if (!std::isfinite(seconds) || seconds < 0.001 || seconds > 1e5)
        return refuse(motion::msg::make("grbl.gcode.bad_dwell", {motion::msg::real("seconds", std::isfinite(seconds) ? seconds : 0, motion::msg::Unit::S)}));
    return finish("G4 P" + formatNumber(seconds, 3));
}

GcodeLine jogLine(const std::vector<AxisValue>& deltas, double feedMmMin)
{
    GcodeLine fail;
    std::string s = "$J=G91 G21";
    if (!axisWords(deltas, s, fail))
        return fail;
    if (!feedOk(feedMmMin, fail))
        return fail;
    s += " F" + formatNumber(feedMmMin, 1);
    return finish(std::move(s));
}

GcodeLine outputLine(TriggerOutput kind, bool on, int port, bool synchronized)
{
    if (kind == TriggerOutput::Coolant)
        return finish(on ? "M8" : "M9");
    if (port < 0 || port > 255)
        return refuse(motion::msg::make("grbl.gcode.bad_port", {motion::msg::integer("port", port, motion::msg::Unit::None)}));
    const char* m = synchronized ? (on ? "M62" : "M63") : (on ? "M64" : "M65");
    return finish(std::string(m) + " P" + std::to_string(port));
}

GcodeLine settingWriteLine(int id, double value)
{
    GcodeLine fail;
    if (id < 0 || id > 9999)
        return refuse(motion::msg::make("grbl.gcode.bad_setting", {motion::msg::integer("setting", id, motion::msg::Unit::None)}));
    if (!finiteWord('$', value, 1e9, fail))
        return fail;
    return finish("$" + std::to_string(id) + "=" + formatNumber(value, 4));
}

} // namespace dev::grbl
