#pragma once
// The way from "Run" to a running scan, one for every front end: the Scan screen, the
// CLI's `scan run` and, through the CLI's command table, the scripting API. It decides
// which run log a run continues, what needs a person's word first (another plan's log in
// the folder, a scan already complete), what keeps it from starting, and what starting
// would do (resume or fresh, how long, where the first move goes and whether that is a
// long move). Front ends only ask and show: they word their question from this data, so
// a screen and a script cannot disagree about what Run does.
#include "device/jobs/scan_runner.h"

#include <cstdint>
#include <vector>

namespace dev::jobs {

/// What starting the prepared run now would do.
struct ScanOutlook {
    bool resume = false;  ///< continues a run log at its next tile; false: takes every tile from the first
    int takenTiles = 0;   ///< tiles already in the run log
    int totalTiles = 0;
    double etaS = 0;      ///< time left, estimated on the device's limits
    motion::scan::Point2 firstTileMm{};  ///< the first tile of the path: where a fresh run's first move goes
    /// A fresh run whose first move is long on some axis (motion::isLongMove from where the
    /// stage stands now); a resumed run never counts, its approach is the run's own.
    bool longApproach = false;
    bool longRun = false;  ///< etaS is longer than ScanLaunch::kAskLongerThanS
    /// A person (or --yes) agrees first.
    bool needsConfirmation() const { return longRun || longApproach; }
};

/// One answer on the way from "Run" to running.
struct ScanDecision {
    enum class Kind {
        Refused,        ///< `error` says why; no answer of a person changes it
        OtherScansLog,  ///< the folder holds another plan's run log (`error` says so): beginAnew() keeps it aside
        AllTaken,       ///< the folder's run log has every tile: beginAnew() takes them all again
        Blocked,        ///< prepared, but `blockers` (scan.run.*) keep it from starting now
        Ready,          ///< prepared and nothing in the way: `outlook` says what start() does
    };
    Kind kind = Kind::Refused;
    motion::msg::Message error;
    std::vector<motion::msg::Message> blockers;
    ScanOutlook outlook;
};

class ScanLaunch {
public:
    /// A run longer than this asks first (the screen), or needs --yes (the CLI).
    static constexpr double kAskLongerThanS = 60;

    /// `runner` outlives this and is the one that runs; it is not owned.
    explicit ScanLaunch(ScanRunner* runner) : m_runner(runner) {}

    /// Makes `plan` in `folder` the runner's run. The run it holds already is kept when it
    /// is this plan in this folder and not complete (a pause or a stop continues where it
    /// is); otherwise the runner prepares it, continuing the folder's run log of the same
    /// tiles. `restart` keeps any run log there aside and begins anew.
    ScanDecision prepare(const motion::scan::ScanPlan& plan, const QString& folder, bool restart = false);
    /// A person agreed to OtherScansLog or AllTaken: the last plan and folder, begun anew.
    ScanDecision beginAnew() { return prepare(m_plan, m_folder, true); }
    /// What start() would do now; the runner must be prepared.
    ScanOutlook outlook() const;
    bool start(motion::msg::Message* error) { return m_runner->start(error); }

    /// The runner holds a run of this layout that got past prepare(), in `folder` when one
    /// is given: its taken tiles and measured positions are this plan's.
    bool holds(std::uint64_t fingerprint, const QString* folder = nullptr) const;

private:
    ScanRunner* m_runner;
    motion::scan::ScanPlan m_plan;  ///< the last plan asked for, for beginAnew()
    QString m_folder;
    bool m_holding = false;  ///< the runner holds a run this prepared that got to Blocked or Ready
    std::uint64_t m_heldFingerprint = 0;
    QString m_heldFolder;
};

} // namespace dev::jobs
