#pragma once
// What the soak measures while it runs: memory (RSS from /proc/self/statm, the heap
// in use from glibc), how late the event loop serves a 10 ms timer, telemetry that
// never arrived, link trouble, and the jobs. A snapshot per reporting period; the
// verdict against the stated bounds (docs/testing.md, "Soak") at the end.
#include "soak_jobs.h"
#include "soak_rig.h"

#include <QElapsedTimer>
#include <QJsonObject>
#include <QTimer>

#include <string>
#include <vector>

namespace soak {

/// One snapshot: counters are totals since the start, latency is of the period just ended.
struct Figures {
    double simS = 0, wallS = 0;            ///< device time and wall time since the soak began
    qint64 rssKb = 0, heapKb = 0;
    double latencyMaxMs = 0, latencyP99Ms = 0;
    quint64 latencyTicks = 0;
    quint64 samples = 0;                   ///< telemetry samples received (both instruments)
    quint64 lostSamples = 0;               ///< gaps in the sample counter, as the clients count them
    quint64 hubLostSamples = 0;            ///< the same, as the telemetry hub counts them
    quint64 droppedBatches = 0;            ///< batches the firmware dropped because its output backed up
    quint64 linkErrors = 0;                ///< see Probe::linkErrors
    quint64 retransmits = 0, lateReplies = 0;
    quint64 jogExpired = 0;                ///< JogExpired events: a renewed jog that stopped by itself
    quint64 jobsDone = 0, jobsFailed = 0;
    quint64 plotFrames = 0;
    std::size_t storeBytes = 0;            ///< the hub's stores of what the plots want
    quint64 lost() const { return lostSamples + hubLostSamples + droppedBatches; }
};

/// The bounds the verdict holds the run to; 0 switches a timing bound off (the short
/// variant in the default test run judges no timing: a loaded machine is not a defect).
struct Bounds {
    double latencyMaxMs = 250;
    double latencyP99Ms = 50;
    double growthMb = 4;       ///< RSS growth over the second half allowed: this many MiB ...
    double growthPercent = 5;  ///< ... or this share of the half-way RSS, whichever is larger
    bool judgeGrowth = true;
    bool everyKind = true;     ///< every kind of job finished at least once
};

class Probe : public QObject {
    Q_OBJECT
public:
    static constexpr int kProbeMs = 10;

    Probe(std::vector<Station*> stations, dev::tele::TelemetryHub& hub, PlotConsumer& plots, Tally& tally);
    void start();
    /// Device seconds since start() (the slower of the two clocks).
    double simS();
    /// Takes a snapshot and starts a new latency period.
    const Figures& snapshot();
    const std::vector<Figures>& periods() const { return m_periods; }
    qint64 rssMaxKb() const { return m_rssMaxKb; }
    double latencyMaxMs() const;
    double latencyP99Ms() const;
    quint64 latencyTicks() const { return m_allLate.size(); }

    /// Link trouble of one station: damaged frames either way, bytes the decoders dropped,
    /// requests that timed out, linkError and requestFailed signals, and the link dropping.
    static quint64 linkErrors(Station& s);

    /// Everything that fails the soak, one sentence each; empty = passed.
    std::vector<std::string> verdict(const Bounds& bounds, const std::vector<std::string>& kinds) const;
    /// The table, a row per snapshot: printHeader() once, then printRow() as they are taken.
    static void printHeader(std::FILE* out);
    static void printRow(std::FILE* out, const Figures& f);
    QJsonObject json(const Bounds& bounds, const std::vector<std::string>& kinds) const;

private:
    void tick();

    std::vector<Station*> m_stations;
    dev::tele::TelemetryHub& m_hub;
    PlotConsumer& m_plots;
    Tally& m_tally;
    std::vector<double> m_sim0;
    QTimer m_timer;
    QElapsedTimer m_wall;
    qint64 m_lastNs = 0;
    std::vector<float> m_periodLate, m_allLate;  ///< ms late per timer tick
    qint64 m_rssMaxKb = 0;
    std::vector<Figures> m_periods;
};

qint64 rssKb();
qint64 heapKb();

} // namespace soak
