#include "motion/path/grid_walker.h"
#include "motion/numbers.h"

#include <cmath>
#include <cstdlib>

namespace motion::path {

namespace {

double radiusOf(GridPoint p, GridPoint c) { return std::hypot(static_cast<double>(p.x - c.x), static_cast<double>(p.y - c.y)); }
double angleOf(GridPoint p, GridPoint c) { return std::atan2(static_cast<double>(p.y - c.y), static_cast<double>(p.x - c.x)); }
GridPoint minus(GridPoint a, GridPoint b) { return {a.x - b.x, a.y - b.y}; }
}  // namespace

GridWalker GridWalker::line(GridPoint from, GridPoint to)
{
    GridWalker w;
    w.m_pos = w.m_from = from;
    w.m_to = to;
    w.m_line.emplace(to.x - from.x, to.y - from.y);
    const double dx = static_cast<double>(to.x - from.x), dy = static_cast<double>(to.y - from.y);
    w.m_lineLen2 = dx * dx + dy * dy;
    return w;
}

std::optional<GridWalker> GridWalker::arc(GridPoint from, GridPoint to, GridPoint center, bool counterClockwise,
                                          double maxRadiusMismatchSteps)
{
    const double r0 = radiusOf(from, center);
    if (r0 < 2.0)
        return std::nullopt;
    const bool full = from == to;
    GridPoint end = from;
    if (!full) {
        const double rTo = radiusOf(to, center);
        if (!(std::fabs(rTo - r0) <= maxRadiusMismatchSteps) || rTo <= 0)
            return std::nullopt;
        // The circle point nearest to `to`: round its projection, then pick the neighbour
        // closest to the circle (one within half a step always exists among them for r ≥ 2).
        const double k = r0 / rTo;
        const GridPoint guess{center.x + std::llround(static_cast<double>(to.x - center.x) * k),
                              center.y + std::llround(static_cast<double>(to.y - center.y) * k)};
        double best = 1e300;
        for (int dx = -2; dx <= 2; ++dx)
            for (int dy = -2; dy <= 2; ++dy) {
                const GridPoint p{guess.x + dx, guess.y + dy};
                const double miss = std::fabs(radiusOf(p, center) - r0) + 1e-9 * (std::abs(dx) + std::abs(dy));
                if (miss < best) {
                    best = miss;
                    end = p;
                }
            }
        if (end == from)  // an arc shorter than a step: a straight step or two does it
            return line(from, to);
    }
    auto interp = ArcInterpolator::create(minus(from, center), minus(end, center), counterClockwise);
    if (!interp)
        return std::nullopt;
    GridWalker w;
    w.m_pos = w.m_from = from;
    w.m_to = to;
    w.m_arc = interp;
    w.m_center = center;
    w.m_arcEnd = end;
    w.m_ccw = counterClockwise;
    w.m_lastAngle = angleOf(from, center);
    if (full) {
        w.m_sweepRad = 2 * kPi;
    } else {
        double phi = angleOf(end, center) - w.m_lastAngle;
        if (!counterClockwise)
            phi = -phi;
        while (phi <= 0)
            phi += 2 * kPi;
        while (phi > 2 * kPi)
            phi -= 2 * kPi;
        w.m_sweepRad = phi;
    }
    return w;
}

bool GridWalker::done() const
{
    if (m_line)
        return m_line->done();
    return m_arc->done() && m_pos == m_to;
}

double GridWalker::progress() const
{
    if (m_line) {
        if (m_lineLen2 <= 0)
            return 1.0;
        const double px = static_cast<double>(m_pos.x - m_from.x), py = static_cast<double>(m_pos.y - m_from.y);
        const double dx = static_cast<double>(m_to.x - m_from.x), dy = static_cast<double>(m_to.y - m_from.y);
        return (px * dx + py * dy) / m_lineLen2;
    }
    if (m_arc->done())
        return 1.0;
    return m_sweptRad / m_sweepRad;
}

void GridWalker::step()
{
    GridStep s;
    if (m_line) {
        s = m_line->next();
        m_pos.x += s.dx;
        m_pos.y += s.dy;
    } else if (!m_arc->done()) {
        m_arc->next();
        const GridPoint rel = m_arc->position();
        m_pos = {m_center.x + rel.x, m_center.y + rel.y};
        const double a = angleOf(m_pos, m_center);
        double d = a - m_lastAngle;
        if (d > kPi)
            d -= 2 * kPi;
        else if (d <= -kPi)
            d += 2 * kPi;
        m_sweptRad += m_ccw ? d : -d;
        m_lastAngle = a;
    } else {
        if (!m_finish)
            m_finish.emplace(m_to.x - m_arcEnd.x, m_to.y - m_arcEnd.y);
        s = m_finish->next();
        m_pos.x += s.dx;
        m_pos.y += s.dy;
    }
    ++m_steps;
}

std::int64_t GridWalker::advanceTo(double fraction)
{
    const std::int64_t before = m_steps;
    while (!done()) {
        if (fraction < 1.0) {
            if (m_line && progress() >= fraction)
                break;
            if (m_arc && (m_arc->done() || m_sweptRad >= fraction * m_sweepRad))
                break;  // the finishing steps onto the end belong to the segment's end
        }
        step();
    }
    return m_steps - before;
}

}  // namespace motion::path
