#pragma once
// Runs one path segment point by point on the motors' step grid (seed 002's 逐点比较法): the
// walker owns a LineInterpolator or ArcInterpolator and takes whole steps — one axis at a time,
// each chosen by the sign of the deviation F — until the walk has come as far along the segment
// as the speed profile says it should be by now. The machine's reference is therefore always a
// grid point within one step of the true line or circle, and the interpolators' deviation bound
// holds along the whole path, not just at its vertices.
//
// Progress is measured along the real geometry, not by counting steps: a step count would run a
// 45° stretch √2 slower than an axis-parallel one. A line's progress is the projection of the
// walk's point onto it; an arc's is the angle swept so far over the whole sweep.
//
// Grid coordinates are whole steps from an origin the caller chooses (the path's start), so a
// segment's end is rounded once and consecutive segments meet exactly.

#include "motion/interpolation.h"

#include <cstdint>
#include <optional>
#include <variant>

namespace motion::path {

class GridWalker {
public:
    /// A straight walk from `from` to `to` (steps).
    static GridWalker line(GridPoint from, GridPoint to);
    /// An arc around `center` from `from` to `to` (steps), the short or long way as the direction
    /// says; `to == from` is a full circle. Rounding leaves `to` up to about a step off the circle
    /// through `from`: the arc ends on the circle point nearest to `to` and a straight step or two
    /// finish onto `to`. nullopt when the radius is under 2 steps or `to` is more than
    /// `maxRadiusMismatchSteps` off that circle.
    static std::optional<GridWalker> arc(GridPoint from, GridPoint to, GridPoint center, bool counterClockwise,
                                         double maxRadiusMismatchSteps = 4.0);

    /// Steps until the walk has come `fraction` (0…1) of the way; 1 walks to the end. Returns the
    /// number of steps taken. Progress never runs backwards: a smaller fraction takes no step.
    std::int64_t advanceTo(double fraction);
    /// One step, whatever the progress (a preview draws every point); not when done().
    void step();
    GridPoint position() const { return m_pos; }
    bool done() const;
    std::int64_t stepsTaken() const { return m_steps; }
    /// How far the walk has come, 0…1, by the measure advanceTo uses.
    double progress() const;

private:
    GridWalker() = default;

    GridPoint m_pos;
    GridPoint m_from, m_to;
    // Line.
    std::optional<LineInterpolator> m_line;
    double m_lineLen2 = 0;       ///< |to − from|², steps²
    // Arc.
    std::optional<ArcInterpolator> m_arc;
    GridPoint m_center;
    GridPoint m_arcEnd;          ///< on the circle; then a short line to m_to
    bool m_ccw = true;
    double m_sweepRad = 0;
    double m_sweptRad = 0;       ///< unwrapped angle walked so far
    double m_lastAngle = 0;
    std::optional<LineInterpolator> m_finish;
    std::int64_t m_steps = 0;
};

}  // namespace motion::path
