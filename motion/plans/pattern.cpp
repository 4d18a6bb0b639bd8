#include "motion/plans/pattern.h"

#include "motion/chords.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace motion::plans {

using motion::path::Box;
using motion::path::Segment;

namespace {

std::string num(double v)
{
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return buf;
}

struct Checker {
    std::vector<PatternProblem>& out;
    void finite(const char* field, double v)
    {
        if (!std::isfinite(v))
            out.push_back({field, "must be a number"});
    }
    void point(const char* field, Vec2 v)
    {
        if (!std::isfinite(v.x) || !std::isfinite(v.y))
            out.push_back({field, "must be two numbers [x, y]"});
    }
    void above(const char* field, double v, double lo)
    {
        if (!std::isfinite(v) || !(v > lo))
            out.push_back({field, "must be above " + num(lo) + " (got " + num(v) + ")"});
    }
    void within(const char* field, double v, double lo, double hi)
    {
        if (!std::isfinite(v) || v < lo || v > hi)
            out.push_back({field, "must be from " + num(lo) + " to " + num(hi) + " (got " + num(v) + ")"});
    }
};

}  // namespace

const char* shapeName(PatternShape s)
{
    switch (s) {
    case PatternShape::Line: return "line";
    case PatternShape::Rectangle: return "rectangle";
    case PatternShape::Circle: return "circle";
    case PatternShape::Arc: return "arc";
    case PatternShape::Sine: return "sine";
    case PatternShape::Cosine: return "cosine";
    case PatternShape::Spiral: return "spiral";
    case PatternShape::Raster: return "raster";
    }
    return "?";
}

std::optional<PatternShape> shapeFromName(std::string_view name)
{
    for (PatternShape s : kAllShapes)
        if (name == shapeName(s))
            return s;
    return std::nullopt;
}

std::vector<PatternProblem> validate(const Pattern& p)
{
    std::vector<PatternProblem> out;
    Checker c{out};
    c.within("feed_mm_s", p.feedMmS, 1e-3, 1000);
    if (p.zMm)
        c.finite("z_mm", *p.zMm);
    switch (p.shape) {
    case PatternShape::Line:
        c.point("start_mm", p.line.startMm);
        c.point("end_mm", p.line.endMm);
        if (motion::path::norm(p.line.endMm - p.line.startMm) < 1e-6)
            out.push_back({"end_mm", "must differ from start_mm: the line has no length"});
        break;
    case PatternShape::Rectangle:
        c.point("corner_mm", p.rectangle.cornerMm);
        c.above("width_mm", p.rectangle.widthMm, 0);
        c.above("height_mm", p.rectangle.heightMm, 0);
        break;
    case PatternShape::Circle:
        c.point("center_mm", p.circle.centerMm);
        c.above("radius_mm", p.circle.radiusMm, 0);
        c.finite("start_deg", p.circle.startDeg);
        break;
    case PatternShape::Arc:
        c.point("center_mm", p.arc.centerMm);
        c.above("radius_mm", p.arc.radiusMm, 0);
        c.finite("start_deg", p.arc.startDeg);
        c.within("sweep_deg", p.arc.sweepDeg, 1e-6, 360);
        break;
    case PatternShape::Sine:
    case PatternShape::Cosine: {
        const WaveParams& w = p.wave;
        c.point("origin_mm", w.originMm);
        c.above("amplitude_mm", w.amplitudeMm, 0);
        c.above("wavelength_mm", w.wavelengthMm, 0);
        c.above("length_mm", w.lengthMm, 0);
        c.finite("angle_deg", w.angleDeg);
        c.within("tolerance_mm", w.toleranceMm, 1e-5, 1);
        if (out.empty()) {
            // Chord width from the tolerance (motion/chords.h): h = √(8·tol / (A·k²)).
            const double k = 2 * 3.14159265358979323846 / w.wavelengthMm;
            const double h = std::sqrt(8 * w.toleranceMm / (w.amplitudeMm * k * k));
            if (w.lengthMm / h > static_cast<double>(kMaxSegments))
                out.push_back({"tolerance_mm", "gives " + num(std::ceil(w.lengthMm / h)) + " chords, more than "
                                                   + num(static_cast<double>(kMaxSegments)) + ": loosen it or shorten the wave"});
        }
        break;
    }
    case PatternShape::Spiral: {
        const SpiralParams& s = p.spiral;
        c.point("center_mm", s.centerMm);
        c.above("start_radius_mm", s.startRadiusMm, 0);
        c.above("pitch_mm", s.pitchMm, 0);
        c.within("turns", s.turns, 0.5, 1000);
        c.finite("start_deg", s.startDeg);
        if (std::isfinite(s.turns) && std::fabs(s.turns * 2 - std::round(s.turns * 2)) > 1e-9)
            out.push_back({"turns", "must be a whole or half number of turns (got " + num(s.turns) + ")"});
        break;
    }
    case PatternShape::Raster: {
        const RasterParams& r = p.raster;
        c.point("corner_mm", r.cornerMm);
        c.above("width_mm", r.widthMm, 0);
        c.above("height_mm", r.heightMm, 0);
        c.above("spacing_mm", r.spacingMm, 0);
        if (out.empty()) {
            const double across = r.alongY ? r.widthMm : r.heightMm;
            const double passes = std::floor(across / r.spacingMm + 1e-9) + 1;
            if (2 * passes - 1 > static_cast<double>(kMaxSegments))
                out.push_back({"spacing_mm", "gives " + num(passes) + " passes: too many, widen the spacing"});
        }
        break;
    }
    }
    return out;
}

Box boundsOf(const std::vector<Segment>& path)
{
    Box b{1e300, 1e300, -1e300, -1e300};
    for (const Segment& s : path) {
        const Box e = motion::path::boundingBox(s);
        b.minX = std::min(b.minX, e.minX);
        b.minY = std::min(b.minY, e.minY);
        b.maxX = std::max(b.maxX, e.maxX);
        b.maxY = std::max(b.maxY, e.maxY);
    }
    if (path.empty())
        return {};
    return b;
}

std::optional<LimitViolation> outsideLimits(const std::vector<Segment>& path, const Box& limits)
{
    constexpr double kSlackMm = 1e-6;  // a nanometre of rounding is not a violation
    for (std::size_t k = 0; k < path.size(); ++k) {
        const Box b = motion::path::boundingBox(path[k]);
        const struct {
            int axis;
            bool upper;
            double reaches, limit;
            bool out;
        } checks[] = {{0, false, b.minX, limits.minX, b.minX < limits.minX - kSlackMm},
                      {0, true, b.maxX, limits.maxX, b.maxX > limits.maxX + kSlackMm},
                      {1, false, b.minY, limits.minY, b.minY < limits.minY - kSlackMm},
                      {1, true, b.maxY, limits.maxY, b.maxY > limits.maxY + kSlackMm}};
        for (const auto& c : checks) {
            if (!c.out)
                continue;
            LimitViolation v;
            v.segment = k;
            v.axis = c.axis;
            v.reachesMm = c.reaches;
            v.limitMm = c.limit;
            v.upper = c.upper;
            char buf[200];
            std::snprintf(buf, sizeof buf, "segment %zu (%s) reaches %c = %.3f mm, beyond the %s soft limit %.3f mm", k,
                          motion::path::segmentKindName(path[k].kind), c.axis == 0 ? 'X' : 'Y', c.reaches,
                          c.upper ? "upper" : "lower", c.limit);
            v.message = buf;
            return v;
        }
    }
    return std::nullopt;
}

double estimatedTimeS(const std::vector<Segment>& path, const motion::path::PathLimits& limits)
{
    return motion::path::estimatePath(path, limits).durationS;
}

}  // namespace motion::plans
