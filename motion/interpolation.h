#pragma once
// Seed 002 (image-measuring microscope stage): point-by-point comparison (逐点比较法)
// interpolation of lines and circular arcs in whole steps. Each step: judge the deviation F,
// step one axis, update F incrementally (additions only), check for the end.
//
// Line from (0,0) to (xe,ye), worked on |xe|,|ye| with the signs applied to each step (so all
// eight octants share one loop): F = y·|xe| - x·|ye|; F > 0 → step x (F -= |ye|), F < 0 → step y
// (F += |xe|), F = 0 → step the longer axis. |F| ≤ max(|xe|,|ye|) throughout, so every point is
// within max/√(xe²+ye²) ≤ 1 step of the line. The tie rule is ours: the textbook "F ≥ 0 → x"
// walks off a vertical line (xe = 0) on its first step.
//
// Arc around the origin (centre) from a start to an end point, CW or CCW, across quadrants:
// F = x² + y² - R²; F ≥ 0 → take the move that reduces the radius, F < 0 → the one that
// increases it; which two moves those are depends on the quadrant and the direction.

#include <cstdint>
#include <optional>
#include <vector>

namespace motion {

struct GridPoint {
    std::int64_t x = 0, y = 0;  ///< steps
    bool operator==(const GridPoint& o) const { return x == o.x && y == o.y; }
};

/// One step: exactly one of dx, dy is ±1.
struct GridStep {
    std::int8_t dx = 0, dy = 0;
};

class LineInterpolator {
public:
    LineInterpolator(std::int64_t xe, std::int64_t ye);
    bool done() const { return m_remaining == 0; }
    std::int64_t remaining() const { return m_remaining; }
    /// Next step; must not be called when done().
    GridStep next()
    {
        const bool stepX = m_f > 0 || (m_f == 0 && m_xMajor);
        m_f += stepX ? -m_ye : m_xe;
        --m_remaining;
        return stepX ? GridStep{m_sx, 0} : GridStep{0, m_sy};
    }

private:
    std::int64_t m_xe, m_ye;  ///< |xe|, |ye|
    std::int64_t m_f = 0;     ///< deviation y·|xe| - x·|ye| in the first-quadrant frame
    std::int64_t m_remaining;
    std::int8_t m_sx, m_sy;
    bool m_xMajor;
};

/// Step codes of a whole line into out[0 .. |xe|+|ye|): bit 0 = axis (0 x, 1 y), bit 1 = negative.
/// The hot loop (no branches on the data): returns the number of steps written.
std::int64_t interpolateLineCodes(std::int64_t xe, std::int64_t ye, std::uint8_t* out);

/// All points of the line including (0,0) and (xe,ye).
std::vector<GridPoint> interpolateLinePoints(std::int64_t xe, std::int64_t ye);

class ArcInterpolator {
public:
    /// Start and end relative to the centre, in steps. The end must lie within half a step of the
    /// circle through the start (else nullopt); start == end is a full circle. Radius ≥ 2 steps.
    static std::optional<ArcInterpolator> create(GridPoint start, GridPoint end, bool counterClockwise);

    bool done() const { return m_done; }
    GridPoint position() const { return {m_x, m_y}; }
    GridStep next();

private:
    ArcInterpolator() = default;
    int quadrant(std::int64_t x, std::int64_t y) const;
    bool pastEnd() const;

    std::int64_t m_x = 0, m_y = 0;       ///< current point
    std::int64_t m_xe = 0, m_ye = 0;     ///< end point
    std::int64_t m_f = 0;                ///< x² + y² - R²
    bool m_ccw = true;
    int m_quadrant = 0;
    int m_crossingsLeft = 0;             ///< quadrant boundaries still to cross before the end's quadrant
    bool m_finishing = false;            ///< past the end angle: straight steps onto the end point
    bool m_done = false;
};

/// All points of the arc including start and end (relative to the centre), or nullopt (see create).
std::optional<std::vector<GridPoint>> interpolateArcPoints(GridPoint start, GridPoint end, bool counterClockwise);

}  // namespace motion
