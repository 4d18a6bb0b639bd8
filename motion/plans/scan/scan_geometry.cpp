#include "motion/plans/scan/scan_geometry.h"

#include <algorithm>
#include <cmath>

namespace motion::scan {

Rect rectFromCorners(Point2 a, Point2 b)
{
    return {std::min(a.xMm, b.xMm), std::min(a.yMm, b.yMm), std::max(a.xMm, b.xMm), std::max(a.yMm, b.yMm)};
}

Rect rectFromCentre(Point2 c, double widthMm, double heightMm)
{
    return rectFromCorners({c.xMm - 0.5 * widthMm, c.yMm - 0.5 * heightMm}, {c.xMm + 0.5 * widthMm, c.yMm + 0.5 * heightMm});
}

Rect boundingBox(const std::vector<Point2>& points)
{
    if (points.empty())
        return {};
    Rect r{points[0].xMm, points[0].yMm, points[0].xMm, points[0].yMm};
    for (const Point2& p : points) {
        r.x0Mm = std::min(r.x0Mm, p.xMm);
        r.y0Mm = std::min(r.y0Mm, p.yMm);
        r.x1Mm = std::max(r.x1Mm, p.xMm);
        r.y1Mm = std::max(r.y1Mm, p.yMm);
    }
    return r;
}

double signedArea(const std::vector<Point2>& polygon)
{
    const std::size_t n = polygon.size();
    if (n < 3)
        return 0;
    double twice = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const Point2& a = polygon[i];
        const Point2& b = polygon[(i + 1) % n];
        twice += a.xMm * b.yMm - b.xMm * a.yMm;
    }
    return 0.5 * twice;
}

namespace {

/// One Sutherland–Hodgman pass: keeps the side of the line `coord(p) = limit` where
/// `keep(p)` holds, adding the crossing points.
template <class Coord, class Keep>
void clipAgainst(const std::vector<Point2>& in, std::vector<Point2>& out, Coord coord, double limit, Keep keep)
{
    out.clear();
    const std::size_t n = in.size();
    for (std::size_t i = 0; i < n; ++i) {
        const Point2& cur = in[i];
        const Point2& prev = in[(i + n - 1) % n];
        const bool curIn = keep(cur), prevIn = keep(prev);
        if (curIn != prevIn) {
            const double t = (limit - coord(prev)) / (coord(cur) - coord(prev));
            out.push_back({prev.xMm + t * (cur.xMm - prev.xMm), prev.yMm + t * (cur.yMm - prev.yMm)});
        }
        if (curIn)
            out.push_back(cur);
    }
}

double cross(Point2 o, Point2 a, Point2 b) { return (a.xMm - o.xMm) * (b.yMm - o.yMm) - (a.yMm - o.yMm) * (b.xMm - o.xMm); }

bool onSegment(Point2 a, Point2 b, Point2 p)
{
    return std::min(a.xMm, b.xMm) <= p.xMm && p.xMm <= std::max(a.xMm, b.xMm) && std::min(a.yMm, b.yMm) <= p.yMm
        && p.yMm <= std::max(a.yMm, b.yMm);
}

int sign(double v) { return (v > 0) - (v < 0); }

bool segmentsTouch(Point2 a, Point2 b, Point2 c, Point2 d)
{
    const int d1 = sign(cross(c, d, a)), d2 = sign(cross(c, d, b));
    const int d3 = sign(cross(a, b, c)), d4 = sign(cross(a, b, d));
    if (d1 * d2 < 0 && d3 * d4 < 0)
        return true;
    return (d1 == 0 && onSegment(c, d, a)) || (d2 == 0 && onSegment(c, d, b)) || (d3 == 0 && onSegment(a, b, c))
        || (d4 == 0 && onSegment(a, b, d));
}

} // namespace

double intersectionArea(const std::vector<Point2>& polygon, const Rect& rect, std::vector<Point2>* scratch)
{
    if (polygon.size() < 3)
        return 0;
    // Quick answers first: most tiles of a grid lie wholly inside or outside the outline's box.
    const Rect box = boundingBox(polygon);
    if (box.x1Mm <= rect.x0Mm || box.x0Mm >= rect.x1Mm || box.y1Mm <= rect.y0Mm || box.y0Mm >= rect.y1Mm)
        return 0;
    std::vector<Point2> local;
    std::vector<Point2>& a = scratch ? *scratch : local;
    std::vector<Point2> b;
    b.reserve(polygon.size() + 8);
    auto x = [](const Point2& p) { return p.xMm; };
    auto y = [](const Point2& p) { return p.yMm; };
    clipAgainst(polygon, b, x, rect.x0Mm, [&](const Point2& p) { return p.xMm >= rect.x0Mm; });
    clipAgainst(b, a, x, rect.x1Mm, [&](const Point2& p) { return p.xMm <= rect.x1Mm; });
    clipAgainst(a, b, y, rect.y0Mm, [&](const Point2& p) { return p.yMm >= rect.y0Mm; });
    clipAgainst(b, a, y, rect.y1Mm, [&](const Point2& p) { return p.yMm <= rect.y1Mm; });
    return std::fabs(signedArea(a));
}

bool selfIntersects(const std::vector<Point2>& polygon)
{
    const std::size_t n = polygon.size();
    if (n < 3)
        return false;
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i + 1; j < n; ++j)
            if (polygon[i].xMm == polygon[j].xMm && polygon[i].yMm == polygon[j].yMm)
                return true;
    for (std::size_t i = 0; i < n; ++i) {
        const Point2 a = polygon[i], b = polygon[(i + 1) % n];
        for (std::size_t j = i + 1; j < n; ++j) {
            const Point2 c = polygon[j], d = polygon[(j + 1) % n];
            const bool adjacent = j == i + 1 || (i == 0 && j == n - 1);
            if (adjacent) {
                // Neighbours share a vertex; they are wrong only when they fold back
                // onto each other (collinear and overlapping beyond that vertex).
                const Point2 shared = j == i + 1 ? b : a;
                const Point2 p = j == i + 1 ? a : b;
                const Point2 q = j == i + 1 ? d : c;
                if (cross(shared, p, q) == 0
                    && (p.xMm - shared.xMm) * (q.xMm - shared.xMm) + (p.yMm - shared.yMm) * (q.yMm - shared.yMm) > 0)
                    return true;
                continue;
            }
            if (segmentsTouch(a, b, c, d))
                return true;
        }
    }
    return false;
}

} // namespace motion::scan
