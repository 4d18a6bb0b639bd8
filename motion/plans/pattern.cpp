#include "motion/plans/pattern.h"

#include "motion/chords.h"

#include <algorithm>
#include <cmath>

namespace motion::plans {

using motion::path::Box;
using motion::path::Segment;

namespace {

using motion::msg::Unit;

struct Checker {
    motion::msg::Problems& out;
    void finite(const char* field, double v)
    {
        if (!std::isfinite(v))
            out.push_back(motion::msg::error(field, motion::msg::make("pattern.not_a_number")));
    }
    void point(const char* field, Vec2 v)
    {
        if (!std::isfinite(v.x) || !std::isfinite(v.y))
            out.push_back(motion::msg::error(field, motion::msg::make("pattern.not_a_point")));
    }
    void above(const char* field, double v, double lo, Unit unit)
    {
        if (!std::isfinite(v) || !(v > lo))
            out.push_back(motion::msg::error(field, motion::msg::make("pattern.not_above", {motion::msg::real("value", v, unit), motion::msg::real("min", lo, unit)})));
    }
    void within(const char* field, double v, double lo, double hi, Unit unit)
    {
        if (!std::isfinite(v) || v < lo || v > hi)
            out.push_back(motion::msg::error(field, motion::msg::make("pattern.out_of_range",
                                            {motion::msg::real("value", v, unit), motion::msg::real("min", lo, unit), motion::msg::real("max", hi, unit)})));
    }
};

}  // namespace

const char* segmentKindTerm(motion::path::SegmentKind k)
{
    switch (k) {
    case motion::path::SegmentKind::Line: return "segment.line";
    case motion::path::SegmentKind::ArcCw: return "segment.arc_cw";
    case motion::path::SegmentKind::ArcCcw: return "segment.arc_ccw";
    }
    return "segment.line";
}

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

motion::msg::Problems validate(const Pattern& p)
{
    motion::msg::Problems out;
    Checker c{out};
    c.within("feed_mm_s", p.feedMmS, 1e-3, 1000, Unit::MmPerS);
    if (p.zMm)
        c.finite("z_mm", *p.zMm);
    switch (p.shape) {
    case PatternShape::Line:
        c.point("start_mm", p.line.startMm);
        c.point("end_mm", p.line.endMm);
        if (motion::path::norm(p.line.endMm - p.line.startMm) < 1e-6)
            out.push_back(motion::msg::error("end_mm", motion::msg::make("pattern.line_has_no_length")));
        break;
    case PatternShape::Rectangle:
        c.point("corner_mm", p.rectangle.cornerMm);
        c.above("width_mm", p.rectangle.widthMm, 0, Unit::Mm);
        c.above("height_mm", p.rectangle.heightMm, 0, Unit::Mm);
        break;
    case PatternShape::Circle:
        c.point("center_mm", p.circle.centerMm);
        c.above("radius_mm", p.circle.radiusMm, 0, Unit::Mm);
        c.finite("start_deg", p.circle.startDeg);
        break;
    case PatternShape::Arc:
        c.point("center_mm", p.arc.centerMm);
        c.above("radius_mm", p.arc.radiusMm, 0, Unit::Mm);
        c.finite("start_deg", p.arc.startDeg);
        c.within("sweep_deg", p.arc.sweepDeg, 1e-6, 360, Unit::Deg);
        break;
    case PatternShape::Sine:
    case PatternShape::Cosine: {
        const WaveParams& w = p.wave;
        c.point("origin_mm", w.originMm);
        c.above("amplitude_mm", w.amplitudeMm, 0, Unit::Mm);
        c.above("wavelength_mm", w.wavelengthMm, 0, Unit::Mm);
        c.above("length_mm", w.lengthMm, 0, Unit::Mm);
        c.finite("angle_deg", w.angleDeg);
        c.within("tolerance_mm", w.toleranceMm, 1e-5, 1, Unit::Mm);
        if (out.empty()) {
            // Chord width from the tolerance (motion/chords.h): h = √(8·tol / (A·k²)).
            const double k = 2 * 3.14159265358979323846 / w.wavelengthMm;
            const double h = std::sqrt(8 * w.toleranceMm / (w.amplitudeMm * k * k));
            if (w.lengthMm / h > static_cast<double>(kMaxSegments))
                out.push_back(motion::msg::error("tolerance_mm", motion::msg::make("pattern.too_many_chords",
                                                          {motion::msg::real("count", std::ceil(w.lengthMm / h), Unit::Count),
                                                           motion::msg::integer("max", static_cast<long long>(kMaxSegments))})));
        }
        break;
    }
    case PatternShape::Spiral: {
        const SpiralParams& s = p.spiral;
        c.point("center_mm", s.centerMm);
        c.above("start_radius_mm", s.startRadiusMm, 0, Unit::Mm);
        c.above("pitch_mm", s.pitchMm, 0, Unit::Mm);
        c.within("turns", s.turns, 0.5, 1000, Unit::None);
        c.finite("start_deg", s.startDeg);
        if (std::isfinite(s.turns) && std::fabs(s.turns * 2 - std::round(s.turns * 2)) > 1e-9)
            out.push_back(motion::msg::error("turns", motion::msg::make("pattern.not_half_turns", {motion::msg::real("value", s.turns)})));
        break;
    }
    case PatternShape::Raster: {
        const RasterParams& r = p.raster;
        c.point("corner_mm", r.cornerMm);
        c.above("width_mm", r.widthMm, 0, Unit::Mm);
        c.above("height_mm", r.heightMm, 0, Unit::Mm);
        c.above("spacing_mm", r.spacingMm, 0, Unit::Mm);
        if (out.empty()) {
            const double across = r.alongY ? r.widthMm : r.heightMm;
            const double passes = std::floor(across / r.spacingMm + 1e-9) + 1;
            if (2 * passes - 1 > static_cast<double>(kMaxSegments))
                out.push_back(motion::msg::error("spacing_mm", motion::msg::make("pattern.too_many_passes", {motion::msg::real("count", passes, Unit::Count),
                                                                                 motion::msg::integer("max", static_cast<long long>(kMaxSegments / 2))})));
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
            v.message = motion::msg::make(c.upper ? "pattern.segment_above_limit" : "pattern.segment_below_limit",
                                  {motion::msg::integer("segment", static_cast<long long>(k), Unit::None),
                                   motion::msg::term("kind", segmentKindTerm(path[k].kind)), motion::msg::verbatim("axis", c.axis == 0 ? "X" : "Y"),
                                   motion::msg::real("value", c.reaches, Unit::Mm), motion::msg::real("limit", c.limit, Unit::Mm)});
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
