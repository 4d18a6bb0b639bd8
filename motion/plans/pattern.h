#pragma once
// Patterns an operator runs on an instrument to see how well it follows a contour: line,
// rectangle, circle, arc, sine and cosine (seed 002's equal-angle chords), spiral and raster
// (serpentine). A Pattern is a plain data model: the shape, its parameters (every shape keeps
// its own, so switching shapes in a form loses nothing), the feed rate and, on the analyzer, the
// Z height to work at. validate() returns every problem at once; plan() turns a valid pattern
// into LINE/ARC segments in the instrument's coordinates (mm).
//
// Field names are those of the pattern file (docs/patterns.md): a problem names the field the
// way a person sees it in the file and in the form ("radius_mm").

#include "motion/path/junction_planner.h"
#include "motion/path/path_geometry.h"
#include "motion/message.h"
#include "motion/problem.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace motion::plans {

using motion::path::Vec2;

enum class PatternShape { Line, Rectangle, Circle, Arc, Sine, Cosine, Spiral, Raster };
constexpr PatternShape kAllShapes[] = {PatternShape::Line,   PatternShape::Rectangle, PatternShape::Circle,
                                       PatternShape::Arc,    PatternShape::Sine,      PatternShape::Cosine,
                                       PatternShape::Spiral, PatternShape::Raster};
const char* shapeName(PatternShape s);  ///< "line", "rectangle", …: the file's and the CLI's word
const char* segmentKindTerm(motion::path::SegmentKind k);  ///< "segment.line", "segment.arc_cw", "segment.arc_ccw"
std::optional<PatternShape> shapeFromName(std::string_view name);

struct LineParams {
    Vec2 startMm{20, 20};
    Vec2 endMm{50, 60};                  ///< default: seed 000's tan θ = 4/3, 50 mm long
};
struct RectangleParams {
    Vec2 cornerMm{30, 30};               ///< lower-left
    double widthMm = 40, heightMm = 30;
    bool clockwise = false;
};
struct CircleParams {
    Vec2 centerMm{50, 50};
    double radiusMm = 5;                 ///< default: the 10 mm circle of the stage's acceptance test
    double startDeg = 0;                 ///< where on the circle it starts and ends
    bool clockwise = false;
};
struct ArcParams {
    Vec2 centerMm{50, 50};
    double radiusMm = 10;
    double startDeg = 0;
    double sweepDeg = 90;                ///< 0 < sweep ≤ 360, in the direction below
    bool clockwise = false;
};
/// Sine and cosine: y = A·sin(2πx/W) (or cos) for x in [0, length], in a frame whose x axis
/// leaves `originMm` at `angleDeg`. Run as equal-x chords each within `toleranceMm` of the curve.
struct WaveParams {
    Vec2 originMm{20, 50};
    double amplitudeMm = 5;
    double wavelengthMm = 20;
    double lengthMm = 60;
    double angleDeg = 0;
    double toleranceMm = 0.002;
};
/// Archimedean-like spiral from tangent-continuous half circles around two centres half a
/// pitch apart (the radius grows by the pitch every turn), so it runs without a stop.
struct SpiralParams {
    Vec2 centerMm{50, 50};
    double startRadiusMm = 1;
    double pitchMm = 2;                  ///< radius gained per turn
    double turns = 4;                    ///< whole or half turns
    double startDeg = 0;
    bool clockwise = false;
};
/// Serpentine: parallel passes `spacingMm` apart joined by short steps, covering the rectangle.
struct RasterParams {
    Vec2 cornerMm{30, 30};
    double widthMm = 40, heightMm = 20;
    double spacingMm = 2;
    bool alongY = false;                 ///< passes run along Y (stepping in X) instead of along X
};

struct Pattern {
    std::string name;
    PatternShape shape = PatternShape::Circle;
    double feedMmS = 2;
    /// Analyzer: Z goes to this height once XY is at the pattern's start (seed 000: Z follows
    /// XY) and stays there while the pattern runs.
    std::optional<double> zMm;
    LineParams line;
    RectangleParams rectangle;
    CircleParams circle;
    ArcParams arc;
    WaveParams wave;                     ///< sine and cosine
    SpiralParams spiral;
    RasterParams raster;
};

/// Every problem of the pattern's own numbers (not the instrument's limits: see
/// outsideLimits), each at its field ("radius_mm", "feed_mm_s") with pattern.not_above
/// {value, min}, … (docs/patterns.md, "Messages").
motion::msg::Problems validate(const Pattern& p);
/// The segments, in order; empty if the pattern is not valid. Arcs are split into pieces of at
/// most 90° so every piece has one unambiguous sweep.
std::vector<motion::path::Segment> plan(const Pattern& p);

/// Most segments a pattern may plan into (a safety net against typos such as a 0.0001 mm raster).
constexpr std::size_t kMaxSegments = 200000;

/// The first segment that leaves a box of soft limits, with where and by how much.
struct LimitViolation {
    std::size_t segment = 0;
    int axis = 0;                        ///< 0 X, 1 Y
    double reachesMm = 0;                ///< the coordinate it reaches
    double limitMm = 0;                  ///< the limit it crosses
    bool upper = false;
    motion::msg::Message message;                ///< pattern.segment_above_limit / _below_limit {segment, kind, axis, value, limit}
};
std::optional<LimitViolation> outsideLimits(const std::vector<motion::path::Segment>& path, const motion::path::Box& limits);

/// Bounding box of a whole path.
motion::path::Box boundsOf(const std::vector<motion::path::Segment>& path);

/// Time to run the path from rest to rest under the instrument's path limits (look-ahead as the
/// device plans it).
double estimatedTimeS(const std::vector<motion::path::Segment>& path, const motion::path::PathLimits& limits);

}  // namespace motion::plans
