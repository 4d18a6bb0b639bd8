#include "device/sim/grbl_sim_gcode.h"

#include "device/backends/grbl/grbl_protocol.h"

#include <cmath>
#include <cstdlib>
#include <map>

namespace dev::sim {

namespace err = dev::grbl::err;

std::string grblCleanLine(std::string_view line)
{
    std::string out;
    int paren = 0;
    for (const char c : line) {
        if (c == ';' && paren == 0)
            break;
        if (c == '(') {
            ++paren;
            continue;
        }
        if (c == ')' && paren > 0) {
            --paren;
            continue;
        }
        if (paren > 0 || c == ' ' || c == '\t' || c == '\r')
            continue;
        out.push_back(c >= 'a' && c <= 'z' ? static_cast<char>(c - 'a' + 'A') : c);
    }
    return out;
}

namespace {

struct Word {
    char letter;
    double value;
};

/// Splits a cleaned line into words; error:1 (no letter) or error:2 (bad number).
int words(const std::string& s, std::vector<Word>& out)
{
    std::size_t i = 0;
    while (i < s.size()) {
        const char letter = s[i];
        if (letter < 'A' || letter > 'Z')
            return err::kExpectedCommandLetter;
        ++i;
        const std::size_t start = i;
        if (i < s.size() && (s[i] == '-' || s[i] == '+'))
            ++i;
        bool digits = false;
        while (i < s.size() && ((s[i] >= '0' && s[i] <= '9') || s[i] == '.')) {
            digits = digits || s[i] != '.';
            ++i;
        }
        if (!digits || i - start > 20)
            return err::kBadNumberFormat;
        out.push_back({letter, std::strtod(s.substr(start, i - start).c_str(), nullptr)});
    }
    return 0;
}

/// The code of a G or M word ×10, so G91.1 and G38.2 stay apart from G91 and G38.
int code10(double v) { return static_cast<int>(std::lround(v * 10)); }

struct Words {
    std::map<char, double> values;  ///< every non-G, non-M word
    std::vector<int> g, m;          ///< ×10
};

int collect(const std::vector<Word>& ws, Words& w)
{
    for (const auto& x : ws) {
        if (x.letter == 'G')
            w.g.push_back(code10(x.value));
        else if (x.letter == 'M')
            w.m.push_back(code10(x.value));
        else if (!w.values.emplace(x.letter, x.value).second)
            return err::kWordRepeated;
    }
    return 0;
}

bool take(Words& w, char letter, double& out)
{
    const auto it = w.values.find(letter);
    if (it == w.values.end())
        return false;
    out = it->second;
    w.values.erase(it);
    return true;
}

/// Reads the axis words of `letters` into `target` (absolute work coordinates shifted by the
/// work offset into machine coordinates, or relative to `from`, in mm). False when none was given.
bool axisTarget(Words& w, std::string_view letters, bool relative, bool inches, const std::vector<double>& from,
                const std::vector<double>& offset, std::vector<double>& target)
{
    target = from;
    bool any = false;
    const double k = inches ? dev::grbl::kMmPerInch : 1.0;
    for (std::size_t i = 0; i < letters.size() && i < target.size(); ++i) {
        double v = 0;
        if (take(w, letters[i], v)) {
            target[i] = relative ? from[i] + v * k : v * k + (i < offset.size() ? offset[i] : 0.0);
            any = true;
        }
    }
    return any;
}

bool hasAxisWord(const Words& w, std::string_view letters)
{
    for (const char c : letters)
        if (w.values.count(c))
            return true;
    return false;
}

} // namespace

GrblParse parseGrblLine(std::string_view line, GrblModalState& state, const std::vector<double>& pos,
                        std::string_view axisLetters, bool grblHal, const std::vector<double>& workOffset)
{
    GrblParse r;
    std::vector<Word> ws;
    if ((r.error = words(grblCleanLine(line), ws)))
        return r;
    Words w;
    if ((r.error = collect(ws, w)))
        return r;
    for (const auto& [letter, value] : w.values)
        if (axisLetters.find(letter) == std::string_view::npos && std::string_view("FIJLNPRS").find(letter) == std::string_view::npos)
            return r.error = err::kUnsupportedCommand, r;
    GrblModalState next = state;
    GrblBlock& b = r.block;
    int motion = -1;
    bool dwell = false, setOffset = false;
    for (const int g : w.g) {
        switch (g) {
        case 100: setOffset = true; break;
        case 0: case 10: case 20: case 30:
            if (motion >= 0)
                return r.error = err::kModalGroupViolation, r;
            motion = g / 10;
            break;
        case 40: dwell = true; break;
        case 170: break;
        case 200: next.inches = true; break;
        case 210: next.inches = false; break;
        case 530: b.machineCoordinates = true; break;
        case 540: case 940: break;
        case 900: next.relative = false; break;
        case 910: next.relative = true; break;
        default: return r.error = err::kUnsupportedCommand, r;
        }
    }
    for (const int m : w.m) {
        switch (m) {
        case 30: case 40: case 50: break;  // spindle: no spindle here, accepted like a machine without one
        case 80: b.outputs.push_back({-1, true, true}); next.flood = true; break;
        case 90: b.outputs.push_back({-1, false, true}); next.flood = false; break;
        case 620: case 630: case 640: case 650: {
            if (!grblHal)
                return r.error = err::kUnsupportedCommand, r;
            double port = 0;
            if (!take(w, 'P', port))
                return r.error = err::kValueWordMissing, r;
            if (port < 0 || port != std::floor(port) || port > 255)
                return r.error = err::kCommandValueNotInteger, r;
            b.outputs.push_back({static_cast<int>(port), m == 620 || m == 640, m == 620 || m == 630});
            break;
        }
        default: return r.error = err::kUnsupportedCommand, r;
        }
    }
    double v = 0;
    if (take(w, 'N', v)) {
        if (v < 0 || v > 9999999)
            return r.error = 27, r;
        b.lineNumber = static_cast<long>(v);
    }
    take(w, 'S', v);  // spindle speed: accepted, no spindle
    if (take(w, 'F', v)) {
        if (v < 0)
            return r.error = err::kNegativeValue, r;
        next.feedMmMin = next.inches ? v * dev::grbl::kMmPerInch : v;
    }
    if (motion >= 0)
        next.motion = motion;
    if (b.machineCoordinates && next.motion > 1)
        return r.error = 30, r;

    if (setOffset) {
        // G10 L2 P<n>: the offset itself; G10 L20 P<n>: the offset that makes the present
        // position read the given values. P0 is the active system, P1 G54: the only one here.
        double l = 0, pNumber = 0;
        if (motion >= 0 || dwell)
            return r.error = err::kAxisCommandConflict, r;
        if (!take(w, 'L', l) || !take(w, 'P', pNumber))
            return r.error = err::kValueWordMissing, r;
        if (pNumber != std::floor(pNumber) || pNumber < 0)
            return r.error = err::kCommandValueNotInteger, r;
        if ((l != 2 && l != 20) || pNumber > 1)
            return r.error = err::kUnsupportedCommand, r;  // G55–G59 and L1: not simulated
        b.kind = GrblBlock::Kind::SetWorkOffset;
        b.targetMm = workOffset;
        b.targetMm.resize(pos.size(), 0.0);
        const double k = next.inches ? dev::grbl::kMmPerInch : 1.0;
        for (std::size_t i = 0; i < axisLetters.size() && i < pos.size(); ++i) {
            double word = 0;
            if (take(w, axisLetters[i], word))
                b.targetMm[i] = l == 2 ? word * k : pos[i] - word * k;
        }
    } else if (dwell) {
        if (motion >= 0 || hasAxisWord(w, axisLetters))
            return r.error = err::kAxisCommandConflict, r;
        if (!take(w, 'P', v))
            return r.error = err::kValueWordMissing, r;
        if (v < 0)
            return r.error = err::kNegativeValue, r;
        b.kind = GrblBlock::Kind::Dwell;
        b.dwellS = v;
    } else if (hasAxisWord(w, axisLetters)) {
        if (next.motion >= 2 && !w.values.count('X') && !w.values.count('Y'))
            return r.error = 32, r;
        const bool relative = next.relative && !b.machineCoordinates;
        axisTarget(w, axisLetters, relative, next.inches, pos, b.machineCoordinates ? std::vector<double>{} : workOffset,
                   b.targetMm);
        b.feedMmMin = next.feedMmMin;
        if (next.motion == 0) {
            b.kind = GrblBlock::Kind::Line;
            b.rapid = true;
        } else {
            if (next.feedMmMin <= 0)
                return r.error = err::kUndefinedFeedRate, r;
            if (next.motion == 1) {
                b.kind = GrblBlock::Kind::Line;
            } else {
                double i = 0, j = 0;
                const bool hi = take(w, 'I', i), hj = take(w, 'J', j);
                if (w.values.count('R'))
                    return r.error = err::kUnsupportedCommand, r;  // radius form: not in this simulator
                if (!hi && !hj)
                    return r.error = err::kNoOffsetsInPlane, r;
                const double k = next.inches ? dev::grbl::kMmPerInch : 1.0;
                b.kind = GrblBlock::Kind::Arc;
                b.clockwise = next.motion == 2;
                b.centreMm[0] = pos[0] + i * k;
                b.centreMm[1] = pos[1] + j * k;
                const double r0 = std::hypot(pos[0] - b.centreMm[0], pos[1] - b.centreMm[1]);
                const double r1 = std::hypot(b.targetMm[0] - b.centreMm[0], b.targetMm[1] - b.centreMm[1]);
                // GRBL 1.1's test: off the circle by more than 0.005 mm and 0.1 % of the radius.
                if (r0 < 1e-6 || (std::fabs(r1 - r0) > 0.005 && std::fabs(r1 - r0) > 0.001 * r0))
                    return r.error = err::kInvalidTarget, r;
            }
        }
    } else if (motion >= 1 && motion <= 3) {
        return r.error = err::kNoAxisWords, r;
    }
    if (!w.values.empty())
        return r.error = err::kUnusedWords, r;  // I, J, P, R… that nothing used
    if (b.kind == GrblBlock::Kind::None && !b.outputs.empty())
        b.kind = GrblBlock::Kind::Output;
    state = next;
    return r;
}

GrblParse parseGrblJog(std::string_view command, const GrblModalState& state, const std::vector<double>& pos,
                       std::string_view axisLetters, const std::vector<double>& workOffset)
{
    GrblParse r;
    std::vector<Word> ws;
    if ((r.error = words(grblCleanLine(command), ws)))
        return r;
    Words w;
    if ((r.error = collect(ws, w)))
        return r;
    // Jog modes apply to this line only: the parser state is not touched.
    bool relative = state.relative, inches = state.inches, machine = false;
    for (const int g : w.g) {
        switch (g) {
        case 200: inches = true; break;
        case 210: inches = false; break;
        case 900: relative = false; break;
        case 910: relative = true; break;
        case 530: machine = true; break;
        default: return r.error = err::kInvalidJogCommand, r;
        }
    }
    if (!w.m.empty())
        return r.error = err::kInvalidJogCommand, r;
    for (const auto& [letter, value] : w.values)
        if (axisLetters.find(letter) == std::string_view::npos && letter != 'F' && letter != 'N')
            return r.error = err::kInvalidJogCommand, r;
    double f = 0, n = 0;
    if (!take(w, 'F', f))
        return r.error = err::kUndefinedFeedRate, r;
    if (f <= 0)
        return r.error = err::kNegativeValue, r;
    take(w, 'N', n);
    GrblBlock& b = r.block;
    if (!axisTarget(w, axisLetters, relative && !machine, inches, pos, machine ? std::vector<double>{} : workOffset, b.targetMm))
        return r.error = err::kNoAxisWords, r;
    b.kind = GrblBlock::Kind::Line;
    b.feedMmMin = inches ? f * dev::grbl::kMmPerInch : f;
    return r;
}

} // namespace dev::sim
