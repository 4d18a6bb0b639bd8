// The path queue's requests: begin, append (with every check a segment must pass before it is
// queued), status, hold, resume, clear, and the machine's stop / abort hooks. Execution is in
// path_queue_tick.cpp.
#include "device/sim/path_queue.h"

#include "device/sim/sim_machine.h"
#include "motion/path/junction_planner.h"
#include "motion/profile.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace dev::sim {

using motion::GridPoint;
using motion::path::Segment;
using motion::path::SegmentKind;
using motion::path::Vec2;
using dev::proto::ErrorCode;
using dev::proto::PathReason;
using dev::proto::PathState;

PathQueue::PathQueue(SimMachine& machine) : m(machine)
{
    for (int i = 0; i < m.axisCount(); ++i) {
        const char l = m.st(i).plant->config().letter;
        if (l == 'X')
            m_x = i;
        else if (l == 'Y')
            m_y = i;
        else if (l == 'Z' && m.m_cfg.zAfterXy)
            m_z = i;
    }
    if (m.axisCount() >= 2) {
        const auto& cx = m.st(m_x).plant->config();
        const auto& cy = m.st(m_y).plant->config();
        m_stepMm = std::min(cx.stepSize, cy.stepSize);
        m_maxSpeedMmS = std::min(cx.maxSpeed, cy.maxSpeed);
        m_accelMmS2 = m_defaultAccelMmS2 = kDefaultAccelShare * std::min(cx.maxAccel, cy.maxAccel);
    }
    if (!m.m_cfg.closedLoop)
        m_crossCouplingGain = kDefaultCrossCouplingGain;
}

PathQueue::~PathQueue() = default;

bool PathQueue::active() const
{
    return m_state != PathState::Idle && m_state != PathState::Done && m_state != PathState::Aborted;
}

bool PathQueue::moving() const { return active() && (m_speedMmS > 0 || (m_cur && m_cur->zPhase)); }

std::uint8_t PathQueue::axisMask() const
{
    if (m.axisCount() < 2)
        return 0;
    auto mask = static_cast<std::uint8_t>((1u << m_x) | (1u << m_y));
    if (m_z >= 0)
        mask = static_cast<std::uint8_t>(mask | (1u << m_z));
    return mask;
}

PathQueue::Result PathQueue::refuse(ErrorCode code, int axis, double value, const std::string& text) const
{
    return m.error(code, axis, value, text);
}

std::string PathQueue::where(std::uint32_t index, const Segment& s) const
{
    return "segment " + std::to_string(index) + " (" + motion::path::segmentKindName(s.kind) + ")";
}

double PathQueue::gridToMachine(int axis, std::int64_t steps) const
{
    return (axis == m_x ? m_originX : m_originY) + static_cast<double>(steps) * m_stepMm;
}

void PathQueue::reserveAxes(bool reserve)
{
    for (int i = 0; i < m.axisCount(); ++i) {
        if (!(axisMask() & (1u << i)))
            continue;
        auto& s = m.st(i);
        if (reserve) {
            s.mode = SimMachine::Mode::Path;
            s.segment = -1;
            s.lostReported = false;
        } else if (s.mode == SimMachine::Mode::Path) {
            s.mode = SimMachine::Mode::Idle;
            s.v = s.vTarget = 0;
        }
    }
}

void PathQueue::event(dev::proto::EventKind kind, std::uint32_t index, const std::string& text)
{
    // A held or ended path says why by its PathReason; one that ran as planned says so.
    const bool why = kind == dev::proto::EventKind::PathHeld || kind == dev::proto::EventKind::PathAborted;
    const std::uint8_t code = why && m_reason != PathReason::None ? static_cast<std::uint8_t>(m_reason) : dev::proto::reason::kPathRan;
    m.raiseEvent(kind, -1, text, code);
    m.m_events.back().position = static_cast<std::int32_t>(index);
}

// ---- requests -----------------------------------------------------------------------

PathQueue::Result PathQueue::begin(const dev::proto::PathBeginRequest& r)
{
    if (m.axisCount() < 2)
        return refuse(ErrorCode::BadAxis, -1, 0, "this instrument has no XY axes to run a path on");
    if (m.m_estop)
        return refuse(ErrorCode::EStopActive, -1, 0, "E-stop is active: send reset before running a path");
    if (active())
        return refuse(ErrorCode::Busy, -1, 0, "a path is already queued: clear it before beginning another");
    for (int i : {m_x, m_y})
        if (!m.homed(i))
            return refuse(ErrorCode::NotHomed, i, 0,
                          std::string("axis ") + m.st(i).plant->config().letter + " is not homed: home it before running a path");
    if (auto e = m.checkAxes(axisMask(), true))
        return e;
    const double minAccel = std::min(m.st(m_x).plant->config().maxAccel, m.st(m_y).plant->config().maxAccel);
    const double accel = r.accel == 0 ? kDefaultAccelShare * minAccel : r.accel / 1e6;
    if (accel > minAccel + 1e-9)
        return refuse(ErrorCode::OutOfRange, -1, r.accel,
                      "path acceleration " + std::to_string(accel) + " mm/s² is above the XY maximum "
                          + std::to_string(minAccel) + " mm/s²");
    const double jd = r.junctionDeviation == 0 ? kDefaultJunctionDeviationMm : r.junctionDeviation / 1e6;
    if (jd > kMaxJunctionDeviationMm)
        return refuse(ErrorCode::OutOfRange, -1, r.junctionDeviation, "junction deviation above 1 mm");
    m_accelMmS2 = accel;
    m_junctionMm = jd;
    m_queue.clear();
    m_cur.reset();
    m_havePrev = false;
    m_havePrevGrid = false;
    m_gridAt = {0, 0};
    m_lastQueued = false;
    m_abortAtRest = false;
    m_nextIndex = m_executing = r.firstIndex;
    m_underruns = 0;
    m_speedMmS = m_exitMmS = 0;
    m_crossCorrectionMm = 0;
    m_reason = PathReason::None;
    m_originX = m.st(m_x).plant->reference();
    m_originY = m.st(m_y).plant->reference();
    m_tailEnd = {m_originX, m_originY};
    m_tailGrid = {0, 0};
    m_tailStops = true;
    m_state = PathState::Filling;
    reserveAxes(true);
    return std::nullopt;
}

PathQueue::Result PathQueue::check(const dev::proto::PathSegmentWire& w, std::uint32_t index, const Vec2& from,
                                   const GridPoint& gridFrom, Queued& q) const
{
    auto& sx = m.st(m_x);
    auto& sy = m.st(m_y);
    q.index = index;
    Segment& g = q.geo;
    g.kind = w.kind == dev::proto::PathSegmentKind::Line ? SegmentKind::Line
             : w.kind == dev::proto::PathSegmentKind::ArcCw ? SegmentKind::ArcCw : SegmentKind::ArcCcw;
    g.start = from;
    g.end = {w.x / 1e6 + sx.offset, w.y / 1e6 + sy.offset};
    g.center = {w.cx / 1e6 + sx.offset, w.cy / 1e6 + sy.offset};
    g.feedMmS = w.feed / 1e6;
    const std::string at = where(index, g);
    if (!(g.feedMmS > 0) || g.feedMmS > m_maxSpeedMmS + 1e-9)
        return refuse(ErrorCode::OutOfRange, -1, w.feed,
                      at + ": feed " + m.fmt(m_x, g.feedMmS) + "/s must be above 0 and at most the XY maximum "
                          + m.fmt(m_x, m_maxSpeedMmS) + "/s");
    auto toGrid = [&](double machine, double origin) { return std::llround((machine - origin) / m_stepMm); };
    q.gridEnd = {toGrid(g.end.x, m_originX), toGrid(g.end.y, m_originY)};
    if (g.isArc()) {
        q.gridCenter = {toGrid(g.center.x, m_originX), toGrid(g.center.y, m_originY)};
        const double r0 = motion::path::norm(from - g.center), r1 = motion::path::norm(g.end - g.center);
        const double tol = 4 * m_stepMm;
        if (r0 < 2 * m_stepMm)
            return refuse(ErrorCode::PathGeometry, -1, index,
                          at + ": radius " + m.fmt(m_x, r0) + " is below two steps (" + m.fmt(m_x, 2 * m_stepMm) + ")");
        if (std::fabs(r1 - r0) > tol)
            return refuse(ErrorCode::PathGeometry, -1, index,
                          at + ": its end is " + m.fmt(m_x, std::fabs(r1 - r0))
                              + " off the circle through its start (at most " + m.fmt(m_x, tol) + ")");
        if (!motion::path::GridWalker::arc(gridFrom, q.gridEnd, q.gridCenter, g.ccw()))
            return refuse(ErrorCode::PathGeometry, -1, index, at + ": the arc cannot be walked on the step grid");
    }
    q.lengthMm = motion::path::lengthMm(g);
    q.nominalMmS = std::min(g.feedMmS, m_maxSpeedMmS);
    if (g.isArc())
        q.nominalMmS = std::min(q.nominalMmS, motion::path::arcSpeedLimitMmS(motion::path::radiusMm(g), m_accelMmS2));
    // Soft limits: the whole segment, arcs' bulges included, must stay inside them.
    const motion::path::Box b = motion::path::boundingBox(g);
    for (int i : {m_x, m_y}) {
        const double lo = i == m_x ? b.minX : b.minY, hi = i == m_x ? b.maxX : b.maxY;
        const auto& s = m.st(i);
        const double minM = m.softMinMachine(i), maxM = m.softMaxMachine(i);
        if (lo < minM - 1e-9 || hi > maxM + 1e-9) {
            const bool low = lo < minM - 1e-9;
            const double lim = (low ? minM : maxM) - s.offset;
            return refuse(ErrorCode::SoftLimit, i, lim,
                          at + " reaches " + s.plant->config().letter + " = " + m.fmt(i, (low ? lo : hi) - s.offset)
                              + ", beyond the " + (low ? "lower" : "upper") + " soft limit " + m.fmt(i, lim));
        }
    }
    if (w.hasZ) {
        if (m_z < 0)
            return refuse(ErrorCode::BadAxis, -1, index, at + ": carries a Z target but this instrument has no following Z axis");
        auto& sz = m.st(m_z);
        if (!sz.homed)
            return refuse(ErrorCode::NotHomed, m_z, w.z / 1e6, at + ": axis Z is not homed: home it before a path that moves it");
        q.zMachine = w.z / 1e6 + sz.offset;
        if (q.zMachine < m.softMinMachine(m_z) - 1e-9 || q.zMachine > m.softMaxMachine(m_z) + 1e-9) {
            const bool low = q.zMachine < m.softMinMachine(m_z);
            const double lim = (low ? m.softMinMachine(m_z) : m.softMaxMachine(m_z)) - sz.offset;
            return refuse(ErrorCode::SoftLimit, m_z, lim,
                          at + ": Z target " + m.fmt(m_z, w.z / 1e6) + " is beyond the " + (low ? "lower" : "upper")
                              + " soft limit " + m.fmt(m_z, lim));
        }
        g.zMm = q.zMachine;
    }
    return std::nullopt;
}

PathQueue::Result PathQueue::append(const dev::proto::PathAppendRequest& r)
{
    if (m.m_estop)
        return refuse(ErrorCode::EStopActive, -1, 0, "E-stop is active: the path was aborted");
    if (!active())
        return refuse(ErrorCode::PathState, -1, 0,
                      m_state == PathState::Aborted
                          ? std::string("the path was aborted (") + dev::proto::pathReasonName(m_reason) + "): begin a new one"
                          : "no path begun: send PATH_BEGIN first");
    if (m_lastQueued)
        return refuse(ErrorCode::PathState, -1, m_nextIndex, "the path's last segment has already been queued");
    if (r.firstIndex != m_nextIndex)
        return refuse(ErrorCode::PathSequence, -1, m_nextIndex,
                      "segment " + std::to_string(r.firstIndex) + " is out of sequence: the next one expected is "
                          + std::to_string(m_nextIndex));
    const std::size_t freeSlots = m_queue.capacity() - m_queue.size();
    if (r.segments.empty() || r.segments.size() > freeSlots)
        return refuse(ErrorCode::PathQueueFull, -1, static_cast<double>(freeSlots),
                      std::to_string(r.segments.size()) + " segments do not fit: " + std::to_string(freeSlots)
                          + " of " + std::to_string(kCapacity) + " slots are free");
    // Check every segment before queuing any: a refused request leaves the queue as it was.
    std::vector<Queued> accepted;
    accepted.reserve(r.segments.size());
    Vec2 from = m_tailEnd;
    GridPoint gridFrom = m_tailGrid;
    Vec2 tangent = m_tailTangent;
    bool stops = m_tailStops;
    for (std::size_t k = 0; k < r.segments.size(); ++k) {
        Queued q;
        if (auto e = check(r.segments[k], r.firstIndex + static_cast<std::uint32_t>(k), from, gridFrom, q))
            return e;
        q.maxEntryMmS = stops ? 0.0
                              : motion::path::junctionSpeedMmS(tangent, motion::path::startTangent(q.geo), m_accelMmS2,
                                                                m_junctionMm);
        from = q.geo.end;
        gridFrom = q.gridEnd;
        tangent = motion::path::endTangent(q.geo);
        stops = q.geo.zMm.has_value();
        accepted.push_back(std::move(q));
    }
    for (const Queued& q : accepted)
        m_queue.tryPush(q);
    m_tailEnd = from;
    m_tailGrid = gridFrom;
    m_tailTangent = tangent;
    m_tailStops = stops;
    m_nextIndex += static_cast<std::uint32_t>(r.segments.size());
    m_lastQueued = r.flags & dev::proto::PathAppendLast;
    if (m_state == PathState::Filling
        && ((r.flags & (dev::proto::PathAppendStart | dev::proto::PathAppendLast)) || m_queue.full()))
        startRunning();
    else if (m_state == PathState::Starved)
        m_state = PathState::Running;
    replan();
    return std::nullopt;
}

dev::proto::PathStatusReply PathQueue::status() const
{
    dev::proto::PathStatusReply s;
    s.state = m_state;
    s.capacity = static_cast<std::uint8_t>(kCapacity);
    s.freeSlots = static_cast<std::uint8_t>(m_queue.capacity() - m_queue.size());
    s.nextIndex = m_nextIndex;
    s.executingIndex = m_cur ? m_cur->seg.index : m_queue.peek(0) ? m_queue.peek(0)->index : m_executing;
    s.speed = static_cast<std::uint32_t>(std::lround(m_speedMmS * 1e6));
    s.underruns = m_underruns;
    s.reason = m_reason;
    s.accel = static_cast<std::uint32_t>(std::lround(m_accelMmS2 * 1e6));
    s.junctionDeviation = static_cast<std::uint32_t>(std::lround(m_junctionMm * 1e6));
    return s;
}

void PathQueue::startRunning()
{
    m_state = PathState::Running;
    const auto* first = m_queue.peek(0);
    event(dev::proto::EventKind::PathStarted, first ? first->index : m_nextIndex, "path started");
}

PathQueue::Result PathQueue::hold(PathReason why)
{
    if (!active())
        return std::nullopt;  // nothing to hold: a hold is never refused
    if (m_state == PathState::Held || m_state == PathState::Holding)
        return std::nullopt;
    m_reason = why;
    if (moving()) {
        m_state = PathState::Holding;
        if (m_cur && m_cur->zPhase)
            m_cur->zBraking = true;
    } else {
        m_state = PathState::Held;
        event(dev::proto::EventKind::PathHeld, status().executingIndex, std::string("held: ") + dev::proto::pathReasonName(why));
    }
    return std::nullopt;
}

PathQueue::Result PathQueue::resume()
{
    if (m.m_estop)
        return refuse(ErrorCode::EStopActive, -1, 0, "E-stop is active: send reset, then begin the path again");
    if (!active())
        return refuse(ErrorCode::PathState, -1, 0, "no path to resume");
    if (m_abortAtRest)
        return refuse(ErrorCode::PathState, -1, 0, "the path is ending: it cannot be resumed");
    if (m_state == PathState::Filling) {
        startRunning();
    } else if (m_state == PathState::Held || m_state == PathState::Holding) {
        m_state = (m_cur || !m_queue.empty()) ? PathState::Running : PathState::Starved;
        if (m_cur && m_cur->zPhase && m_cur->zBraking)
            startZ();  // Z finishes the move the hold interrupted, from where it stopped
        m_reason = PathReason::None;
    }
    replan();
    return std::nullopt;
}

PathQueue::Result PathQueue::clear()
{
    if (!active())
        return std::nullopt;
    if (moving()) {
        m_abortAtRest = true;
        m_reason = PathReason::Cleared;
        hold(PathReason::Cleared);
        m_state = PathState::Holding;
    } else {
        endPath(PathState::Aborted, PathReason::Cleared, "path cleared");
    }
    return std::nullopt;
}

void PathQueue::stop()
{
    if (!active())
        return;
    if (moving()) {
        m_abortAtRest = true;
        m_state = PathState::Holding;
        m_reason = PathReason::Stop;
        if (m_cur && m_cur->zPhase)
            m_cur->zBraking = true;
    } else {
        endPath(PathState::Aborted, PathReason::Stop, "path stopped");
    }
}

void PathQueue::sessionStarted()
{
    if (!active())
        return;
    if (moving()) {
        m_abortAtRest = true;
        m_state = PathState::Holding;
        m_reason = PathReason::NewSession;
        if (m_cur && m_cur->zPhase)
            m_cur->zBraking = true;
    } else {
        endPath(PathState::Aborted, PathReason::NewSession, "a new host session began: the path it did not queue was dropped");
    }
}

void PathQueue::abortNow(PathReason why, const std::string& text)
{
    if (!active())
        return;
    if (why != PathReason::EStop)
        for (int i = 0; i < m.axisCount(); ++i)
            if ((axisMask() & (1u << i)) && m.st(i).mode == SimMachine::Mode::Path)
                m.st(i).plant->holdHere();  // the switch stopped one axis; the others stop with it
    endPath(PathState::Aborted, why, text);
}

void PathQueue::endPath(PathState state, PathReason why, const std::string& text, std::optional<std::uint32_t> eventIndex)
{
    const std::uint32_t at = eventIndex ? *eventIndex : status().executingIndex;
    m_executing = state == PathState::Done ? m_nextIndex : at;
    m_queue.clear();
    m_cur.reset();
    m_speedMmS = m_exitMmS = 0;
    m_abortAtRest = false;
    m_state = state;
    m_reason = why;
    m_accelMmS2 = m_defaultAccelMmS2;  // what the next path gets unless it asks otherwise
    m_junctionMm = kDefaultJunctionDeviationMm;
    reserveAxes(false);
    if (state == PathState::Done)
        event(dev::proto::EventKind::PathDone, at, text);
    else
        event(dev::proto::EventKind::PathAborted, at, text + " at segment " + std::to_string(at));
}

} // namespace dev::sim
