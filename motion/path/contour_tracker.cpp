#include "motion/path/contour_tracker.h"

#include <algorithm>
#include <cmath>

namespace motion::path {

ContourTracker::ContourTracker(std::vector<Segment> path, std::size_t firstCounted)
    : m_path(std::move(path)), m_firstCounted(firstCounted)
{
    m_starts.reserve(m_path.size() + 1);
    double sum = 0;
    m_starts.push_back(0);
    for (const Segment& s : m_path) {
        sum += lengthMm(s);
        m_starts.push_back(sum);
    }
}

double ContourTracker::startOfMm(std::size_t segment) const
{
    return m_starts[std::min(segment, m_starts.size() - 1)];
}

void ContourTracker::seek(std::size_t segment)
{
    if (!m_path.empty()) {
        m_cursor = std::min(segment, m_path.size() - 1);
        m_lastPathMm = m_starts[m_cursor];
    }
}

ContourSample ContourTracker::add(Vec2 measured)
{
    ContourSample best;
    if (m_path.empty())
        return best;
    const std::size_t lo = m_cursor >= kBehind ? m_cursor - kBehind : 0;
    double bestAbs = 1e300;
    for (std::size_t k = lo; k < m_path.size() && (k <= m_cursor + 1 || m_starts[k] <= m_lastPathMm + kAheadMm); ++k) {
        const Nearest n = nearestOn(m_path[k], measured);
        // Ties go to the earlier segment: a closed path's last segment ends where its first
        // begins, and a point there has only just arrived, not gone all the way round.
        if (std::fabs(n.distanceMm) < bestAbs) {
            bestAbs = std::fabs(n.distanceMm);
            best.segment = k;
            best.errorMm = n.distanceMm;
            best.pathMm = m_starts[k] + n.alongMm;
        }
    }
    // The cursor follows the walk forward only, never back past where it has been judged.
    m_cursor = std::max(m_cursor, best.segment);
    m_lastPathMm = std::max(m_lastPathMm, best.pathMm);
    if (best.segment >= m_firstCounted) {
        ++m_summary.samples;
        m_sumSq += best.errorMm * best.errorMm;
        if (std::fabs(best.errorMm) > m_summary.maxAbsMm) {
            m_summary.maxAbsMm = std::fabs(best.errorMm);
            m_summary.atPathMm = best.pathMm;
        }
    }
    return best;
}

const ContourSummary& ContourTracker::summary() const
{
    m_summary.rmsMm = m_summary.samples ? std::sqrt(m_sumSq / static_cast<double>(m_summary.samples)) : 0.0;
    return m_summary;
}

ContourSummary summarize(const std::vector<ContourSample>& samples)
{
    ContourSummary s;
    double sumSq = 0;
    for (const ContourSample& c : samples) {
        ++s.samples;
        sumSq += c.errorMm * c.errorMm;
        if (std::fabs(c.errorMm) > s.maxAbsMm) {
            s.maxAbsMm = std::fabs(c.errorMm);
            s.atPathMm = c.pathMm;
        }
    }
    s.rmsMm = s.samples ? std::sqrt(sumSq / static_cast<double>(s.samples)) : 0.0;
    return s;
}

}  // namespace motion::path
