#include "motion/interpolation.h"

#include <cmath>
#include <cstdlib>

namespace motion {

LineInterpolator::LineInterpolator(std::int64_t xe, std::int64_t ye)
    : m_xe(std::llabs(xe)), m_ye(std::llabs(ye)), m_remaining(m_xe + m_ye),
      m_sx(static_cast<std::int8_t>(xe < 0 ? -1 : 1)), m_sy(static_cast<std::int8_t>(ye < 0 ? -1 : 1)),
      m_xMajor(m_xe >= m_ye)
{
}

std::int64_t interpolateLineCodes(std::int64_t xe, std::int64_t ye, std::uint8_t* out)
{
    const std::int64_t ax = std::llabs(xe), ay = std::llabs(ye);
    const std::int64_t n = ax + ay;
    const std::uint8_t codeX = xe < 0 ? 2 : 0, codeY = ye < 0 ? 3 : 1;
    // Ties go to the longer axis; folding that into F's sign (F' = 2F + bias, bias = +1 when x is
    // the longer axis, -1 otherwise) leaves a single comparison per step that compiles to selects.
    const std::int64_t bias = ax >= ay ? 1 : -1;
    std::int64_t f2 = bias;  // 2F + bias with F = 0
    const std::int64_t dX = -2 * ay, dY = 2 * ax;
    for (std::int64_t i = 0; i < n; ++i) {
        const bool stepX = f2 > 0;
        f2 += stepX ? dX : dY;
        out[i] = stepX ? codeX : codeY;
    }
    return n;
}

std::vector<GridPoint> interpolateLinePoints(std::int64_t xe, std::int64_t ye)
{
    std::vector<GridPoint> points;
    points.reserve(static_cast<std::size_t>(std::llabs(xe) + std::llabs(ye) + 1));
    GridPoint p;
    points.push_back(p);
    LineInterpolator line(xe, ye);
    while (!line.done()) {
        const GridStep s = line.next();
        p.x += s.dx;
        p.y += s.dy;
        points.push_back(p);
    }
    return points;
}

// Quadrants are numbered in the direction of travel, each owning one of its boundary rays so
// every point but the centre has exactly one quadrant and both moves allowed there keep going
// the right way round:
//   CCW: 0 = {x>0, y≥0}, 1 = {x≤0, y>0}, 2 = {x<0, y≤0}, 3 = {x≥0, y<0}
//   CW:  0 = {x≥0, y>0}, 1 = {x>0, y≤0}, 2 = {x≤0, y<0}, 3 = {x<0, y≥0}
int ArcInterpolator::quadrant(std::int64_t x, std::int64_t y) const
{
    if (m_ccw) {
        if (x > 0 && y >= 0) return 0;
        if (x <= 0 && y > 0) return 1;
        if (x < 0 && y <= 0) return 2;
        return 3;
    }
    if (x >= 0 && y > 0) return 0;
    if (x > 0 && y <= 0) return 1;
    if (x <= 0 && y < 0) return 2;
    return 3;
}

std::optional<ArcInterpolator> ArcInterpolator::create(GridPoint start, GridPoint end, bool counterClockwise)
{
    const double rStart = std::hypot(static_cast<double>(start.x), static_cast<double>(start.y));
    const double rEnd = std::hypot(static_cast<double>(end.x), static_cast<double>(end.y));
    if (rStart < 2.0 || std::fabs(rEnd - rStart) > 0.5)  // radius 1 would step through the centre
        return std::nullopt;
    ArcInterpolator a;
    a.m_x = start.x;
    a.m_y = start.y;
    a.m_xe = end.x;
    a.m_ye = end.y;
    a.m_f = 0;  // the start defines the circle
    a.m_ccw = counterClockwise;
    a.m_quadrant = a.quadrant(start.x, start.y);
    const int qEnd = a.quadrant(end.x, end.y);
    int crossings = (qEnd - a.m_quadrant + 4) % 4;
    if (crossings == 0) {
        // Same quadrant: a short arc if the end lies ahead of the start, else all the way round.
        const double cross = static_cast<double>(start.x) * end.y - static_cast<double>(start.y) * end.x;
        const bool ahead = counterClockwise ? cross > 0 : cross < 0;
        if (!ahead)
            crossings = 4;
    }
    a.m_crossingsLeft = crossings;
    return a;
}

bool ArcInterpolator::pastEnd() const
{
    // Within one quadrant the walk's angle is monotonic, so the sign of end × p says whether
    // the walk has reached the end's ray.
    const double cross = static_cast<double>(m_xe) * m_y - static_cast<double>(m_ye) * m_x;
    return m_ccw ? cross >= 0 : cross <= 0;
}

GridStep ArcInterpolator::next()
{
    GridStep s;
    if (m_done)
        return s;
    if (m_finishing) {
        // At most a step or two from the end's ray back onto the end point itself.
        if (m_x != m_xe)
            s.dx = static_cast<std::int8_t>(m_xe > m_x ? 1 : -1);
        else
            s.dy = static_cast<std::int8_t>(m_ye > m_y ? 1 : -1);
        m_x += s.dx;
        m_y += s.dy;
        m_done = m_x == m_xe && m_y == m_ye;
        return s;
    }
    // Reduce / increase moves of this quadrant (see quadrant()).
    static constexpr std::int8_t kCcwReduce[4][2] = {{-1, 0}, {0, -1}, {1, 0}, {0, 1}};
    static constexpr std::int8_t kCcwIncrease[4][2] = {{0, 1}, {-1, 0}, {0, -1}, {1, 0}};
    static constexpr std::int8_t kCwReduce[4][2] = {{0, -1}, {-1, 0}, {0, 1}, {1, 0}};
    static constexpr std::int8_t kCwIncrease[4][2] = {{1, 0}, {0, -1}, {-1, 0}, {0, 1}};
    const auto& table = m_f >= 0 ? (m_ccw ? kCcwReduce : kCwReduce) : (m_ccw ? kCcwIncrease : kCwIncrease);
    s.dx = table[m_quadrant][0];
    s.dy = table[m_quadrant][1];
    m_f += s.dx != 0 ? 2 * s.dx * m_x + 1 : 2 * s.dy * m_y + 1;
    m_x += s.dx;
    m_y += s.dy;
    const int q = quadrant(m_x, m_y);
    if (q != m_quadrant) {
        m_quadrant = q;
        --m_crossingsLeft;
    }
    if (m_crossingsLeft <= 0 && pastEnd()) {
        m_finishing = true;
        m_done = m_x == m_xe && m_y == m_ye;
    }
    return s;
}

std::optional<std::vector<GridPoint>> interpolateArcPoints(GridPoint start, GridPoint end, bool counterClockwise)
{
    auto arc = ArcInterpolator::create(start, end, counterClockwise);
    if (!arc)
        return std::nullopt;
    std::vector<GridPoint> points{start};
    // A full circle has about 8R steps; the guard only stops a logic error from looping forever.
    const double r = std::hypot(static_cast<double>(start.x), static_cast<double>(start.y));
    const auto guard = static_cast<std::int64_t>(8.0 * r + 16.0);
    for (std::int64_t i = 0; !arc->done() && i < guard; ++i) {
        arc->next();
        points.push_back(arc->position());
    }
    if (!arc->done())
        return std::nullopt;
    return points;
}

}  // namespace motion
