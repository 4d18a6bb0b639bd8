#include "motion/path/path_geometry.h"
#include "motion/numbers.h"

#include <algorithm>
#include <cmath>

namespace motion::path {

namespace {
constexpr double kTwoPi = 2 * kPi;
/// End points closer than this are the same point (a full circle): well below a nanometre,
/// the wire's resolution.
constexpr double kSamePointMm = 1e-7;

/// Angle from the arc's start to p, in the arc's direction, in [0, 2π).
double angleFromStart(const Segment& s, Vec2 p)
{
    const Vec2 a = s.start - s.center, b = p - s.center;
    double phi = std::atan2(cross(a, b), dot(a, b));  // ccw angle a → b in (-π, π]
    if (!s.ccw())
        phi = -phi;
    if (phi < 0)
        phi += kTwoPi;
    return phi >= kTwoPi ? 0.0 : phi;
}
}  // namespace

double norm(Vec2 a) { return std::hypot(a.x, a.y); }

const char* segmentKindName(SegmentKind k)
{
    switch (k) {
    case SegmentKind::Line: return "LINE";
    case SegmentKind::ArcCw: return "ARC CW";
    case SegmentKind::ArcCcw: return "ARC CCW";
    }
    return "?";
}

double radiusMm(const Segment& s) { return s.isArc() ? norm(s.start - s.center) : 0.0; }

double sweepRad(const Segment& s)
{
    if (!s.isArc())
        return 0.0;
    if (norm(s.end - s.start) < kSamePointMm)
        return kTwoPi;
    const double phi = angleFromStart(s, s.end);
    return phi > 0 ? phi : kTwoPi;
}

double lengthMm(const Segment& s) { return s.isArc() ? radiusMm(s) * sweepRad(s) : norm(s.end - s.start); }

Vec2 pointAt(const Segment& s, double sMm)
{
    const double len = lengthMm(s);
    const double at = std::clamp(sMm, 0.0, len);
    if (!s.isArc()) {
        if (len <= 0)
            return s.start;
        return s.start + (at / len) * (s.end - s.start);
    }
    const double r = radiusMm(s);
    if (r <= 0)
        return s.start;
    const Vec2 a = s.start - s.center;
    const double a0 = std::atan2(a.y, a.x);
    const double ang = a0 + (s.ccw() ? 1.0 : -1.0) * at / r;
    return s.center + Vec2{r * std::cos(ang), r * std::sin(ang)};
}

Vec2 tangentAt(const Segment& s, double sMm)
{
    if (!s.isArc()) {
        const Vec2 d = s.end - s.start;
        const double n = norm(d);
        return n > 0 ? (1.0 / n) * d : Vec2{1, 0};
    }
    const Vec2 p = pointAt(s, sMm) - s.center;
    const double n = norm(p);
    if (n <= 0)
        return {1, 0};
    // Counter-clockwise travel runs along (-y, x); clockwise along (y, -x).
    return s.ccw() ? Vec2{-p.y / n, p.x / n} : Vec2{p.y / n, -p.x / n};
}

Vec2 startTangent(const Segment& s) { return tangentAt(s, 0.0); }
Vec2 endTangent(const Segment& s) { return tangentAt(s, lengthMm(s)); }

Box boundingBox(const Segment& s)
{
    const Vec2 e = pointAt(s, lengthMm(s));
    Box b{std::min(s.start.x, e.x), std::min(s.start.y, e.y), std::max(s.start.x, e.x), std::max(s.start.y, e.y)};
    if (!s.isArc())
        return b;
    const double r = radiusMm(s), sweep = sweepRad(s);
    // The circle's four axis extremes, each included when the arc passes it.
    const Vec2 extremes[4] = {{r, 0}, {0, r}, {-r, 0}, {0, -r}};
    for (const Vec2& d : extremes) {
        const Vec2 p = s.center + d;
        if (angleFromStart(s, p) <= sweep + 1e-12) {
            b.minX = std::min(b.minX, p.x);
            b.maxX = std::max(b.maxX, p.x);
            b.minY = std::min(b.minY, p.y);
            b.maxY = std::max(b.maxY, p.y);
        }
    }
    return b;
}

Nearest nearestOn(const Segment& s, Vec2 p)
{
    const double len = lengthMm(s);
    auto toEnd = [&](double along) {
        const Vec2 q = pointAt(s, along);
        const double d = norm(p - q);
        const double side = cross(tangentAt(s, along), p - q);
        return Nearest{along, side < 0 ? -d : d};
    };
    if (!s.isArc()) {
        if (len <= 0)
            return toEnd(0);
        const Vec2 u = (1.0 / len) * (s.end - s.start);
        const double along = dot(p - s.start, u);
        if (along <= 0)
            return toEnd(0);
        if (along >= len)
            return toEnd(len);
        return {along, cross(u, p - s.start)};
    }
    const double r = radiusMm(s);
    const double phi = angleFromStart(s, p);
    const double sweep = sweepRad(s);
    if (phi <= sweep && r > 0) {
        const double fromCenter = norm(p - s.center);
        // Left of counter-clockwise travel is towards the centre; of clockwise travel, away from it.
        return {r * phi, s.ccw() ? r - fromCenter : fromCenter - r};
    }
    // Beyond the end angle: whichever end is nearer.
    const Nearest a = toEnd(0), b = toEnd(len);
    return std::fabs(a.distanceMm) <= std::fabs(b.distanceMm) ? a : b;
}

double deflectionRad(Vec2 a, Vec2 b)
{
    return std::fabs(std::atan2(cross(a, b), dot(a, b)));
}

double pathLengthMm(const std::vector<Segment>& path)
{
    double sum = 0;
    for (const Segment& s : path)
        sum += lengthMm(s);
    return sum;
}

}  // namespace motion::path
