#pragma once
// The geometry of a path in the XY plane: straight LINE segments and circular ARCs (clockwise
// or counter-clockwise around a centre), each with its own feed rate. Shared by the pattern
// generators (motion/plans/), the device's path queue (device/sim/path_queue.h), the contour
// measure (contour_tracker.h) and the screens' previews. Units: mm, mm/s, radians.
//
// An arc's radius is the distance from its centre to its START; its end fixes only the end
// angle (an end a little off the circle, from rounding, does not bend the arc). An arc whose end
// equals its start is a full circle.

#include <optional>
#include <vector>

namespace motion::path {

struct Vec2 {
    double x = 0, y = 0;  ///< mm (or a unit direction)
};
inline Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
inline Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
inline Vec2 operator*(double k, Vec2 a) { return {k * a.x, k * a.y}; }
inline double dot(Vec2 a, Vec2 b) { return a.x * b.x + a.y * b.y; }
inline double cross(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }
double norm(Vec2 a);

enum class SegmentKind { Line, ArcCw, ArcCcw };
const char* segmentKindName(SegmentKind k);  ///< "LINE", "ARC CW", "ARC CCW"

struct Segment {
    SegmentKind kind = SegmentKind::Line;
    Vec2 start, end;       ///< mm
    Vec2 center;           ///< mm, arcs only
    double feedMmS = 0;    ///< the path speed asked for on this segment
    /// Analyzer (seed 000, "Z following"): once the XY part has arrived, Z moves to zMm and the
    /// path goes on only when Z is there. The planner brings XY to rest before it.
    std::optional<double> zMm;

    bool isArc() const { return kind != SegmentKind::Line; }
    bool ccw() const { return kind == SegmentKind::ArcCcw; }
};

struct Box {
    double minX = 0, minY = 0, maxX = 0, maxY = 0;
};

/// Distance along the segment from its start (mm).
double lengthMm(const Segment& s);
double radiusMm(const Segment& s);          ///< arcs: |start - center|; lines: 0
/// Angle swept (rad, > 0) from start to end in the arc's direction; 2π when end == start.
double sweepRad(const Segment& s);
Vec2 pointAt(const Segment& s, double sMm);  ///< clamps s to [0, length]
Vec2 tangentAt(const Segment& s, double sMm);  ///< unit direction of travel
Vec2 startTangent(const Segment& s);
Vec2 endTangent(const Segment& s);
/// Exact bounding box (an arc includes the axis extremes it passes).
Box boundingBox(const Segment& s);

/// Where a point is relative to a segment: the nearest point of the segment (its distance
/// along it, clamped to [0, length]) and the signed distance to it, positive to the LEFT of
/// travel. Inside the segment's span this is the cross-track (contour) error; beyond an end
/// it is the distance to that end point.
struct Nearest {
    double alongMm = 0;
    double distanceMm = 0;  ///< signed, left of travel positive
};
Nearest nearestOn(const Segment& s, Vec2 p);

/// Deflection angle (rad, 0 = straight on, π = reversal) from direction a to direction b.
double deflectionRad(Vec2 a, Vec2 b);

/// Sum of the segments' lengths.
double pathLengthMm(const std::vector<Segment>& path);

}  // namespace motion::path
