#include "device/jobs/scan_launch.h"

#include "motion/long_move.h"

namespace dev::jobs {

using Kind = ScanDecision::Kind;

ScanDecision ScanLaunch::prepare(const motion::scan::ScanPlan& plan, const QString& folder, bool restart)
{
    m_plan = plan;
    m_folder = folder;
    // A run paused or stopped part-way is continued as it stands in the runner; a complete
    // one is prepared again, which asks whether to take it anew.
    const bool keep = !restart && m_holding && m_runner->totalTiles() > 0 && m_runner->state() != ScanRunner::State::Finished
        && motion::scan::validate(plan).empty() && holds(motion::scan::layoutFingerprint(plan, motion::scan::layoutScan(plan)), &folder);
    if (!keep) {
        ScanDecision d;
        ScanRunner::Refusal why = ScanRunner::Refusal::None;
        if (!m_runner->prepare(plan, folder, restart, &d.error, &why)) {
            d.kind = why == ScanRunner::Refusal::OtherScansLog ? Kind::OtherScansLog : Kind::Refused;
            return d;
        }
        if (m_runner->state() == ScanRunner::State::Finished) {
            d.kind = Kind::AllTaken;
            return d;
        }
        m_holding = true;
        m_heldFingerprint = motion::scan::layoutFingerprint(plan, m_runner->layout());
        m_heldFolder = folder;
    }
    ScanDecision d;
    d.blockers = m_runner->preflight();
    d.kind = d.blockers.empty() ? Kind::Ready : Kind::Blocked;
    if (d.kind == Kind::Ready)
        d.outlook = outlook();
    return d;
}

ScanOutlook ScanLaunch::outlook() const
{
    ScanOutlook o;
    o.takenTiles = m_runner->takenTiles();
    o.totalTiles = m_runner->totalTiles();
    o.resume = o.takenTiles > 0;
    o.etaS = m_runner->etaS();
    o.longRun = o.etaS > kAskLongerThanS;
    const auto& path = m_runner->layout().path;
    if (path.empty())
        return o;
    o.firstTileMm = path.front().target;
    const dev::Instrument* stage = m_runner->instrument();
    const auto& axes = stage->status().axes;
    const auto& described = stage->identity().axes;
    if (o.resume || axes.size() < 2 || described.size() < 2)
        return o;
    const double to[2] = {o.firstTileMm.xMm, o.firstTileMm.yMm};
    for (int i = 0; i < 2; ++i)
        o.longApproach = o.longApproach
            || motion::isLongMove(axes[i].commanded, to[i], described[i].travelMax - described[i].travelMin);
    return o;
}

bool ScanLaunch::holds(std::uint64_t fingerprint, const QString* folder) const
{
    return m_holding && m_heldFingerprint == fingerprint && (!folder || *folder == m_heldFolder);
}

} // namespace dev::jobs
