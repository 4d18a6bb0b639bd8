// plan(): the segments of each pattern shape.
#include "motion/plans/pattern.h"
#include "motion/numbers.h"

#include "motion/chords.h"

#include <cmath>

namespace motion::plans {

using motion::path::Segment;
using motion::path::SegmentKind;

namespace {

double rad(double deg) { return deg * kPi / 180.0; }
Vec2 polar(Vec2 c, double r, double angleRad) { return {c.x + r * std::cos(angleRad), c.y + r * std::sin(angleRad)}; }

struct Builder {
    std::vector<Segment> out;
    double feed;
    Vec2 at;

    void lineTo(Vec2 to)
    {
        Segment s;
        s.kind = SegmentKind::Line;
        s.start = at;
        s.end = to;
        s.feedMmS = feed;
        out.push_back(s);
        at = to;
    }
    /// An arc around `c` (radius |at − c|) sweeping `sweepRad` > 0, in pieces of at most 90°.
    void arc(Vec2 c, double sweepRad, bool clockwise)
    {
        const double r = motion::path::norm(at - c);
        const double a0 = std::atan2(at.y - c.y, at.x - c.x);
        const int pieces = std::max(1, static_cast<int>(std::ceil(sweepRad / (kPi / 2) - 1e-9)));
        for (int k = 1; k <= pieces; ++k) {
            const double a = a0 + (clockwise ? -1.0 : 1.0) * sweepRad * k / pieces;
            Segment s;
            s.kind = clockwise ? SegmentKind::ArcCw : SegmentKind::ArcCcw;
            s.start = at;
            s.center = c;
            s.end = polar(c, r, a);
            s.feedMmS = feed;
            out.push_back(s);
            at = s.end;
        }
    }
};

std::vector<Segment> wave(const Pattern& p)
{
    const WaveParams& w = p.wave;
    const auto chords = motion::sineChords(w.amplitudeMm, w.wavelengthMm, w.lengthMm, w.toleranceMm,
                                           p.shape == PatternShape::Cosine);
    const double c = std::cos(rad(w.angleDeg)), s = std::sin(rad(w.angleDeg));
    auto place = [&](const motion::PointMm& q) { return Vec2{w.originMm.x + c * q.x - s * q.y, w.originMm.y + s * q.x + c * q.y}; };
    Builder b{{}, p.feedMmS, place(chords.front())};
    for (std::size_t k = 1; k < chords.size(); ++k)
        b.lineTo(place(chords[k]));
    return b.out;
}

std::vector<Segment> spiral(const Pattern& p)
{
    // Half turn k has radius r0 + k·pitch/2 around C (k even) or C + pitch/2 along the start
    // direction (k odd); consecutive half circles meet on that diameter with the same tangent.
    const SpiralParams& sp = p.spiral;
    const double a0 = rad(sp.startDeg);
    const Vec2 u{std::cos(a0), std::sin(a0)};
    const Vec2 other = sp.centerMm + (sp.pitchMm / 2) * u;
    Builder b{{}, p.feedMmS, sp.centerMm + sp.startRadiusMm * u};
    const int halves = static_cast<int>(std::lround(sp.turns * 2));
    for (int k = 0; k < halves; ++k)
        b.arc(k % 2 == 0 ? sp.centerMm : other, kPi, sp.clockwise);
    return b.out;
}

std::vector<Segment> raster(const Pattern& p)
{
    const RasterParams& r = p.raster;
    const double along = r.alongY ? r.heightMm : r.widthMm;
    const double across = r.alongY ? r.widthMm : r.heightMm;
    const int passes = static_cast<int>(std::floor(across / r.spacingMm + 1e-9)) + 1;
    auto at = [&](double a, double b) {
        return r.alongY ? Vec2{r.cornerMm.x + b, r.cornerMm.y + a} : Vec2{r.cornerMm.x + a, r.cornerMm.y + b};
    };
    Builder b{{}, p.feedMmS, r.cornerMm};
    for (int k = 0; k < passes; ++k) {
        const double offset = k * r.spacingMm;
        if (k > 0)
            b.lineTo(at(k % 2 == 1 ? along : 0.0, offset));
        b.lineTo(at(k % 2 == 0 ? along : 0.0, offset));
    }
    return b.out;
}

}  // namespace

std::vector<Segment> plan(const Pattern& p)
{
    if (!validate(p).empty())
        return {};
    switch (p.shape) {
    case PatternShape::Line: {
        Builder b{{}, p.feedMmS, p.line.startMm};
        b.lineTo(p.line.endMm);
        return b.out;
    }
    case PatternShape::Rectangle: {
        const RectangleParams& r = p.rectangle;
        const Vec2 c = r.cornerMm;
        Builder b{{}, p.feedMmS, c};
        const Vec2 right{c.x + r.widthMm, c.y}, up{c.x, c.y + r.heightMm}, far{c.x + r.widthMm, c.y + r.heightMm};
        const Vec2 corners[2][4] = {{right, far, up, c}, {up, far, right, c}};
        for (const Vec2& v : corners[r.clockwise ? 1 : 0])
            b.lineTo(v);
        return b.out;
    }
    case PatternShape::Circle: {
        const CircleParams& ci = p.circle;
        Builder b{{}, p.feedMmS, polar(ci.centerMm, ci.radiusMm, rad(ci.startDeg))};
        b.arc(ci.centerMm, 2 * kPi, ci.clockwise);
        b.out.back().end = b.out.front().start;  // closes exactly, whatever the rounding of cos/sin
        return b.out;
    }
    case PatternShape::Arc: {
        const ArcParams& a = p.arc;
        Builder b{{}, p.feedMmS, polar(a.centerMm, a.radiusMm, rad(a.startDeg))};
        b.arc(a.centerMm, rad(a.sweepDeg), a.clockwise);
        return b.out;
    }
    case PatternShape::Sine:
    case PatternShape::Cosine: return wave(p);
    case PatternShape::Spiral: return spiral(p);
    case PatternShape::Raster: return raster(p);
    }
    return {};
}

}  // namespace motion::plans
