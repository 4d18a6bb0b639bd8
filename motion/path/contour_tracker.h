#pragma once
// Contour error of a measured XY trace against the commanded geometric path: for each measured
// point, its signed distance to the nearest point of the path (positive left of travel), and how
// far along the path that nearest point lies. Inside a segment this is the cross-track error
// ε = −sin θ·e_x + cos θ·e_y of seed 000 §4.1 generalised to arcs (the seed prints the along-track
// form; its Table 5 uses this one — see motion/linear_move.h); at a corner it is the distance to
// the corner. Measured against the true lines and circles, not the step grid, and against the
// whole path, so a lagging point near a junction is judged against the segment it is still on.
//
// Points arrive in time order. The tracker keeps a cursor on the path and searches only the
// segment before it and those that begin within kAheadMm of where the last point was judged, so
// a path that comes back near itself or crosses itself (a raster, a spiral, a lead-in that cuts
// through the circle it leads to) is never judged against a later pass, and the cost per point
// does not grow with the path.

#include "motion/path/path_geometry.h"

#include <cstddef>
#include <vector>

namespace motion::path {

struct ContourSample {
    double pathMm = 0;       ///< distance along the whole path to the nearest point
    double errorMm = 0;      ///< signed contour error, left of travel positive
    std::size_t segment = 0; ///< index of the segment the nearest point lies on
};

struct ContourSummary {
    std::size_t samples = 0;
    double maxAbsMm = 0;     ///< largest |error|
    double rmsMm = 0;
    double atPathMm = 0;     ///< where along the path the largest error was
};

class ContourTracker {
public:
    /// `path` is copied. `firstCounted`: segments before it (a lead-in to the pattern's start)
    /// are tracked but not counted in the summary.
    explicit ContourTracker(std::vector<Segment> path, std::size_t firstCounted = 0);

    /// Judges one measured point; the summary counts it when its nearest segment is counted.
    ContourSample add(Vec2 measured);
    /// Moves the cursor (e.g. after a restart from segment k); the search goes on from there.
    void seek(std::size_t segment);

    const ContourSummary& summary() const;
    std::size_t cursor() const { return m_cursor; }
    double startOfMm(std::size_t segment) const;  ///< path distance where a segment begins
    double totalMm() const { return m_starts.empty() ? 0.0 : m_starts.back(); }
    const std::vector<Segment>& path() const { return m_path; }

    /// Segments behind the cursor that are searched (a point lagging at a junction).
    static constexpr std::size_t kBehind = 1;
    /// Segments that begin at most this far along the path past the last judged point are
    /// searched: far more than a machine moves between two telemetry samples.
    static constexpr double kAheadMm = 5.0;

private:
    std::vector<Segment> m_path;
    std::vector<double> m_starts;  ///< m_path.size() + 1 cumulative lengths
    std::size_t m_firstCounted;
    std::size_t m_cursor = 0;
    double m_lastPathMm = 0;
    double m_sumSq = 0;
    mutable ContourSummary m_summary;
};

/// Summary of errors already computed (max |e|, RMS).
ContourSummary summarize(const std::vector<ContourSample>& samples);

}  // namespace motion::path
