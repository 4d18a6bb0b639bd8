#include "imaging/tile_configuration.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <locale>
#include <sstream>

namespace imaging {
namespace {

std::string_view trimmed(std::string_view s)
{
    const char* ws = " \t\r\n\f\v";
    const auto a = s.find_first_not_of(ws);
    if (a == std::string_view::npos)
        return {};
    const auto b = s.find_last_not_of(ws);
    return s.substr(a, b - a + 1);
}

/// A number as Java's Double.parseDouble takes it (Fiji's reader): plain decimal or exponent.
bool parseNumber(std::string_view s, double& out)
{
    s = trimmed(s);
    if (s.empty() || s.size() > 64)
        return false;
    std::istringstream in{std::string(s)};
    in.imbue(std::locale::classic());
    in >> out;
    // A position beyond a billion pixels is no mosaic's: refused, so any accepted
    // number writes back in a short fixed-point form.
    return !in.fail() && in.peek() == std::char_traits<char>::eof() && std::isfinite(out) && std::abs(out) <= 1e9;
}

motion::msg::Problem at(const std::string& file, int line, const char* id, std::vector<motion::msg::Arg> args = {})
{
    return motion::msg::Problem(file, line, 0, "", motion::msg::make(id, std::move(args)));
}

} // namespace

motion::msg::Checked<std::vector<TileEntry>> parseTileConfiguration(std::string_view text, const std::string& fileName)
{
    using Result = motion::msg::Checked<std::vector<TileEntry>>;
    std::vector<TileEntry> tiles;
    motion::msg::Problems problems;
    int dim = 0;
    int lineNo = 0;
    std::size_t pos = 0;
    while (pos <= text.size()) {
        const std::size_t end = text.find('\n', pos);
        const std::string_view raw = text.substr(pos, end == std::string_view::npos ? std::string_view::npos : end - pos);
        pos = end == std::string_view::npos ? text.size() + 1 : end + 1;
        ++lineNo;
        const std::string_view line = trimmed(raw);
        if (line.size() <= 3 || line.front() == '#')
            continue;
        if (line.rfind("dim", 0) == 0 && line.find('=') != std::string_view::npos && line.find(';') == std::string_view::npos) {
            double d = 0;
            if (!parseNumber(line.substr(line.find('=') + 1), d) || (d != 2 && d != 3)) {
                problems.push_back(at(fileName, lineNo, "imaging.tileconfig.bad_dim"));
                continue;
            }
            dim = static_cast<int>(d);
            continue;
        }
        if (dim == 0) {
            problems.push_back(at(fileName, lineNo, "imaging.tileconfig.no_dim"));
            continue;
        }
        std::vector<std::string_view> fields;
        std::size_t f = 0;
        while (true) {
            const std::size_t semi = line.find(';', f);
            fields.push_back(line.substr(f, semi == std::string_view::npos ? std::string_view::npos : semi - f));
            if (semi == std::string_view::npos)
                break;
            f = semi + 1;
        }
        if (fields.size() != 3) {
            problems.push_back(at(fileName, lineNo, "imaging.tileconfig.not_three_fields", {motion::msg::integer("count", static_cast<long long>(fields.size()))}));
            continue;
        }
        const std::string_view name = trimmed(fields[0]);
        std::string_view coords = trimmed(fields[2]);
        if (name.empty()) {
            problems.push_back(at(fileName, lineNo, "imaging.tileconfig.no_file"));
            continue;
        }
        if (coords.size() < 2 || coords.front() != '(' || coords.back() != ')') {
            problems.push_back(at(fileName, lineNo, "imaging.tileconfig.bad_position"));
            continue;
        }
        coords = coords.substr(1, coords.size() - 2);
        std::vector<double> values;
        bool ok = true;
        std::size_t c = 0;
        while (ok) {
            const std::size_t comma = coords.find(',', c);
            double v = 0;
            ok = parseNumber(coords.substr(c, comma == std::string_view::npos ? std::string_view::npos : comma - c), v);
            values.push_back(v);
            if (comma == std::string_view::npos)
                break;
            c = comma + 1;
        }
        if (!ok || static_cast<int>(values.size()) != dim) {
            problems.push_back(at(fileName, lineNo, "imaging.tileconfig.bad_position"));
            continue;
        }
        tiles.push_back({std::string(name), {values[0], values[1]}, lineNo});
    }
    if (tiles.empty() && !motion::msg::hasErrors(problems))
        problems.push_back(at(fileName, 0, "imaging.tileconfig.no_tiles"));
    if (motion::msg::hasErrors(problems))
        return Result::refused(std::move(problems));
    return Result::ok(std::move(tiles));
}

std::string tileConfigurationText(const std::vector<TileEntry>& tiles)
{
    std::string out = "# Define the number of dimensions we are working on\ndim = 2\n\n# Define the image coordinates\n";
    // The C locale whatever the program's (Qt sets the user's): Fiji reads '.' decimals.
    std::ostringstream s;
    s.imbue(std::locale::classic());
    s.setf(std::ios::fixed);
    s.precision(3);
    for (const TileEntry& t : tiles)
        s << t.file << "; ; (" << t.positionPx.x() + 0.0 << ", " << t.positionPx.y() + 0.0 << ")\n";
    return out + s.str();
}

} // namespace imaging
