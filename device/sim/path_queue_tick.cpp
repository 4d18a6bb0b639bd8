// The path queue's execution, one machine tick at a time: look-ahead re-planning when the queue
// changes, the path speed under its cap, the point-by-point walk, Z following XY, and the ends
// of a path (done, starved, held, aborted at rest).
#include "device/sim/path_queue.h"

#include "device/sim/sim_machine.h"
#include "motion/jerk_limited.h"
#include "motion/path/junction_planner.h"
#include "motion/seed_scurve.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace dev::sim {

using dev::proto::PathReason;
using dev::proto::PathState;

void PathQueue::replan()
{
    if (!m_cur || m_cur->zPhase) {
        m_exitMmS = 0;
        return;
    }
    // The running segment's remainder first (entered at the speed we have), then everything
    // queued, ending at rest after the last: what is not queued yet cannot be counted on.
    std::vector<motion::path::PlanBlock> blocks;
    blocks.reserve(static_cast<std::size_t>(m_queue.size()) + 1);
    motion::path::PlanBlock now;
    now.lengthMm = std::max(0.0, m_cur->seg.lengthMm - m_cur->sMm);
    now.nominalMmS = m_cur->seg.nominalMmS;
    now.maxEntryMmS = 1e300;
    now.stopAfter = m_cur->seg.geo.zMm.has_value();
    blocks.push_back(now);
    for (std::size_t k = 0; const Queued* q = m_queue.peek(k); ++k) {
        motion::path::PlanBlock b;
        b.lengthMm = q->lengthMm;
        b.nominalMmS = q->nominalMmS;
        b.maxEntryMmS = q->maxEntryMmS;
        b.stopAfter = q->geo.zMm.has_value();
        blocks.push_back(b);
    }
    motion::path::planSpeeds(blocks, m_accelMmS2, {m_speedMmS}, {0.0});
    m_exitMmS = blocks.front().exitMmS;
}

bool PathQueue::takeNext()
{
    auto next = m_queue.tryPop();
    if (!next)
        return false;
    const motion::GridPoint from = m_havePrevGrid ? m_gridAt : motion::GridPoint{0, 0};
    Active a;
    a.seg = std::move(*next);
    if (a.seg.geo.isArc())
        a.walker = motion::path::GridWalker::arc(from, a.seg.gridEnd, a.seg.gridCenter, a.seg.geo.ccw());
    if (!a.walker)  // a line, or an arc append() proved walkable (never taken): the straight walk
        a.walker = motion::path::GridWalker::line(from, a.seg.gridEnd);
    m_cur = std::move(a);
    m_executing = m_cur->seg.index;
    replan();
    return true;
}

void PathQueue::finishSegment()
{
    m_gridAt = m_cur->walker->position();
    m_havePrevGrid = true;
    m_prevGeo = m_cur->seg.geo;
    m_havePrev = true;
    const std::uint32_t index = m_cur->seg.index;
    m_cur.reset();
    m_executing = index + 1;
    event(dev::proto::EventKind::PathSegmentDone, index, {});
}

void PathQueue::setReferences()
{
    const motion::GridPoint p = m_cur->walker->position();
    const motion::path::Vec2 t = motion::path::tangentAt(m_cur->seg.geo, m_cur->sMm);
    if (m_crossCouplingGain > 0) {
        // Seed 000's cross-coupled control on the open-loop analyzer: the encoders show how far
        // the carriage is off the path across it (lead error, play); the correction moves both
        // motors together along the path's normal until it is back, leaving the along-track
        // position to the walk. A count of dead-band keeps quantization from hunting.
        SimAxis& ax = *m.st(m_x).plant;
        SimAxis& ay = *m.st(m_y).plant;
        if (const auto e = contourErrorMm(ax.reportedMeasured(), ay.reportedMeasured())) {
            const double count = std::max(ax.config().resolution, ay.config().resolution);
            if (std::fabs(*e) > count)
                m_crossCorrectionMm = std::clamp(m_crossCorrectionMm - m_crossCouplingGain * *e, -kMaxCrossCorrectionMm,
                                                 kMaxCrossCorrectionMm);
        }
    }
    const motion::path::Vec2 n{-t.y, t.x};  // left of travel
    m.st(m_x).plant->setReference(gridToMachine(m_x, p.x) + m_crossCorrectionMm * n.x, m_speedMmS * t.x);
    m.st(m_y).plant->setReference(gridToMachine(m_y, p.y) + m_crossCorrectionMm * n.y, m_speedMmS * t.y);
}

void PathQueue::startZ()
{
    Active& a = *m_cur;
    a.zPhase = true;
    a.zBraking = false;
    a.zT = 0;
    a.zV = 0;
    auto& z = *m.st(m_z).plant;
    a.zStart = z.reference();
    const double d = a.seg.zMachine - a.zStart;
    const auto& c = z.config();
    a.zProfile.reset();
    if (std::fabs(d) < 1e-9)
        return;
    // Z runs its own profile, as a MOVE of Z would (seed 000: the simplified S-curve on the analyzer).
    if (m.m_cfg.profile == ProfileKind::SeedSCurve) {
        const double accelTime = std::max(c.accelTimeS, 1.5 * c.defaultSpeed / c.maxAccel);
        if (auto p = motion::SeedSCurve::plan(d, c.defaultSpeed, accelTime))
            a.zProfile = std::make_shared<motion::SeedSCurve>(*p);
    } else if (auto p = motion::JerkLimitedProfile::plan(d, motion::JerkLimits{c.defaultSpeed, c.maxAccel, c.maxJerk})) {
        a.zProfile = std::make_shared<motion::JerkLimitedProfile>(*p);
    }
}

void PathQueue::atRest()
{
    m_speedMmS = 0;
    if (m_abortAtRest) {
        const PathReason why = m_reason;
        endPath(PathState::Aborted, why,
                why == PathReason::Cleared ? "path cleared"
                : why == PathReason::Stop  ? "path stopped"
                                           : "a new host session began: the path it did not queue was dropped");
        return;
    }
    m_state = PathState::Held;
    event(dev::proto::EventKind::PathHeld, status().executingIndex, std::string("held: ") + dev::proto::pathReasonName(m_reason));
}

void PathQueue::tickZ(double dtS)
{
    Active& a = *m_cur;
    SimAxis& z = *m.st(m_z).plant;
    if (a.zBraking || m_state == PathState::Holding) {
        // A hold or stop caught Z on its way: brake at Z's own rate, finish the move on resume.
        if (!a.zBraking) {
            a.zBraking = true;
        }
        const double acc = z.config().maxAccel;
        a.zV = a.zV > 0 ? std::max(0.0, a.zV - acc * dtS) : std::min(0.0, a.zV + acc * dtS);
        z.setReference(z.reference() + a.zV * dtS, a.zV);
        if (a.zV == 0)
            atRest();
        return;
    }
    if (!a.zProfile) {
        finishSegment();
        return;
    }
    a.zT += dtS;
    const motion::ProfileSample p = a.zProfile->at(a.zT);
    a.zV = p.v;
    if (a.zT >= a.zProfile->duration()) {
        z.setReference(a.zStart + a.zProfile->distance(), 0);
        finishSegment();
        return;
    }
    z.setReference(a.zStart + p.s, p.v);
}

void PathQueue::tickXy(double dtS)
{
    Active& a = *m_cur;
    const double length = a.seg.lengthMm;
    const double remaining = std::max(0.0, length - a.sMm);
    // Fast enough to reach the segment's feed, never so fast that the planned exit speed (0 at
    // the end of what is queued) could not be reached by braking at the path acceleration.
    const double cap = std::min(a.seg.nominalMmS, std::sqrt(m_exitMmS * m_exitMmS + 2 * m_accelMmS2 * remaining));
    const double dv = m_accelMmS2 * dtS;
    double v = m_speedMmS;
    if (m_state == PathState::Holding)
        v = std::max(0.0, v - dv);
    else if (v < cap)
        v = std::min(cap, v + dv);
    v = std::min(v, cap);
    if (m_state != PathState::Holding && remaining > 0 && v < dv)
        v = dv;  // creep the last micrometres instead of approaching the end asymptotically
    m_speedMmS = v;
    a.sMm += v * dtS;
    if (a.sMm >= length) {
        const double carry = a.sMm - length;
        a.sMm = length;
        a.walker->advanceTo(1.0);
        setReferences();
        if (a.seg.geo.zMm) {
            m_speedMmS = 0;
            m.st(m_x).plant->setReference(m.st(m_x).plant->reference(), 0);
            m.st(m_y).plant->setReference(m.st(m_y).plant->reference(), 0);
            startZ();
            return;
        }
        if (m_exitMmS == 0)
            m_speedMmS = 0;  // a stop was planned here (a reversal, the queue's end): at rest, nothing carries
        finishSegment();
        if (carry > 0 && m_speedMmS > 0 && takeNext()) {
            m_cur->sMm = std::min(carry, m_cur->seg.lengthMm);
            if (m_cur->seg.lengthMm > 0)
                m_cur->walker->advanceTo(m_cur->sMm / m_cur->seg.lengthMm);
            setReferences();
        }
        return;
    }
    a.walker->advanceTo(length > 0 ? a.sMm / length : 1.0);
    setReferences();
    if (m_state == PathState::Holding && v == 0)
        atRest();
}

void PathQueue::tick()
{
    if (m_state != PathState::Running && m_state != PathState::Holding)
        return;
    if (!m_cur && !takeNext()) {
        // Nothing left to run: the previous segment brought the machine to rest.
        m_speedMmS = 0;
        if (m_state == PathState::Holding) {
            atRest();
        } else if (m_lastQueued) {
            const std::uint32_t last = m_nextIndex == 0 ? 0 : m_nextIndex - 1;
            endPath(PathState::Done, PathReason::None, "path done", last);
        } else {
            m_state = PathState::Starved;
            if (m_underruns < 0xFFFF)
                ++m_underruns;
            event(dev::proto::EventKind::PathUnderrun, m_executing == 0 ? 0 : m_executing - 1,
                  "the queue ran dry: at rest until more segments arrive");
        }
        return;
    }
    if (m_cur->zPhase)
        tickZ(SimMachine::kTickS);
    else
        tickXy(SimMachine::kTickS);
}

std::optional<double> PathQueue::contourErrorMm(double measuredX, double measuredY) const
{
    if (!m_cur && !m_havePrev)
        return std::nullopt;
    const motion::path::Vec2 p{measuredX, measuredY};
    double best = 1e300, signedBest = 0;
    auto consider = [&](const motion::path::Segment& s) {
        const double d = motion::path::nearestOn(s, p).distanceMm;
        if (std::fabs(d) < best) {
            best = std::fabs(d);
            signedBest = d;
        }
    };
    if (m_cur)
        consider(m_cur->seg.geo);
    if (m_havePrev)
        consider(m_prevGeo);
    return signedBest;
}

} // namespace dev::sim
