#include "device/camera/sim_true_geometry.h"

#include <cmath>
#include <cstdlib>
#include <locale>
#include <sstream>

namespace dev::camera {

namespace {

/// A number the whole of `text` spells, within (lo, hi].
std::optional<double> trueNumber(const std::string& text, double lo, double hi)
{
    std::istringstream in(text);
    in.imbue(std::locale::classic());
    double v = 0;
    if (!(in >> v) || !in.eof() || !std::isfinite(v) || !(v > lo && v <= hi))
        return std::nullopt;
    return v;
}

/// The largest pixel the simulated camera takes (its socket's own bound).
constexpr double kTrueMaxPixelUm = 1000;

} // namespace

bool parseSimTrueGeometry(const std::string& text, SimTrueGeometry* out, std::string* badPart)
{
    SimTrueGeometry g;
    std::size_t from = 0;
    while (from <= text.size()) {
        const std::size_t comma = text.find(',', from);
        std::string part = text.substr(from, comma == std::string::npos ? std::string::npos : comma - from);
        from = comma == std::string::npos ? text.size() + 1 : comma + 1;
        while (!part.empty() && part.front() == ' ')
            part.erase(part.begin());
        while (!part.empty() && part.back() == ' ')
            part.pop_back();
        if (part.empty())
            continue;
        const std::size_t eq = part.find('=');
        const std::string key = part.substr(0, eq);
        const std::string value = eq == std::string::npos ? std::string() : part.substr(eq + 1);
        bool ok = false;
        if (key == "mirror" && eq == std::string::npos) {
            g.mirrored = ok = true;
        } else if (key == "rotation-deg") {
            g.rotationDeg = trueNumber(value, -360.000001, 360);
            ok = g.rotationDeg.has_value();
        } else if (key == "pixel-um") {
            const std::size_t colon = value.find(':');
            g.pixelXUm = trueNumber(value.substr(0, colon), 0, kTrueMaxPixelUm);
            g.pixelYUm = colon == std::string::npos ? g.pixelXUm : trueNumber(value.substr(colon + 1), 0, kTrueMaxPixelUm);
            ok = g.pixelXUm && g.pixelYUm;
        }
        if (!ok) {
            *badPart = part;
            return false;
        }
    }
    *out = g;
    return true;
}

std::string simTrueGeometryText(const SimTrueGeometry& g)
{
    std::ostringstream s;
    s.imbue(std::locale::classic());
    s.precision(12);
    const char* sep = "";
    if (g.pixelXUm) {
        s << "pixel-um=" << *g.pixelXUm;
        if (g.pixelYUm && *g.pixelYUm != *g.pixelXUm)
            s << ':' << *g.pixelYUm;
        sep = ",";
    }
    if (g.rotationDeg) {
        s << sep << "rotation-deg=" << *g.rotationDeg;
        sep = ",";
    }
    if (g.mirrored)
        s << sep << "mirror";
    return s.str();
}

CameraGeometry trueGeometryOf(const CameraGeometry& asked, const SimTrueGeometry& truth)
{
    CameraGeometry g = asked;
    if (truth.pixelXUm)
        g.pixelUm = *truth.pixelXUm;
    if (truth.pixelYUm)
        g.pixelYUm = *truth.pixelYUm;
    if (truth.rotationDeg)
        g.rotationDeg = *truth.rotationDeg;
    if (truth.mirrored)
        g.imageYAlongMinusY = false;
    return g;
}

} // namespace dev::camera
