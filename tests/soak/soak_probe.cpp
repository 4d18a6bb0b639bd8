#include "soak_probe.h"

#include <QFile>
#include <QJsonArray>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <unistd.h>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace soak {
namespace {

double percentile(std::vector<float> v, double p)
{
    if (v.empty())
        return 0;
    const std::size_t k = std::min(v.size() - 1, static_cast<std::size_t>(std::ceil(p * static_cast<double>(v.size()))) - 1);
    std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k), v.end());
    return v[k];
}

double maxOf(const std::vector<float>& v) { return v.empty() ? 0 : *std::max_element(v.begin(), v.end()); }

double mb(qint64 kb) { return static_cast<double>(kb) / 1024.0; }

std::string format(const char* f, double a, double b = 0)
{
    char buf[256];
    std::snprintf(buf, sizeof buf, f, a, b);
    return buf;
}

} // namespace

qint64 rssKb()
{
    // statm: size resident shared text lib data dt, in pages.
    QFile f(QStringLiteral("/proc/self/statm"));
    if (!f.open(QIODevice::ReadOnly))
        return 0;
    const QList<QByteArray> fields = f.readAll().split(' ');
    return fields.size() > 1 ? fields[1].toLongLong() * (sysconf(_SC_PAGESIZE) / 1024) : 0;
}

qint64 heapKb()
{
    // RSS also counts pages the allocator keeps after a free; the bytes in use show a leak sooner.
#if defined(__GLIBC__) && (__GLIBC__ > 2 || (__GLIBC__ == 2 && __GLIBC_MINOR__ >= 33))
    return static_cast<qint64>(mallinfo2().uordblks / 1024);
#else
    return 0;
#endif
}

Probe::Probe(std::vector<Station*> stations, dev::tele::TelemetryHub& hub, PlotConsumer& plots, Tally& tally)
    : m_stations(std::move(stations)), m_hub(hub), m_plots(plots), m_tally(tally)
{
    m_timer.setTimerType(Qt::PreciseTimer);
    m_timer.setInterval(kProbeMs);
    connect(&m_timer, &QTimer::timeout, this, &Probe::tick);
}

void Probe::start()
{
    m_sim0.clear();
    for (Station* s : m_stations)
        m_sim0.push_back(s->deviceTimeS());
    m_wall.start();
    m_lastNs = 0;
    m_timer.start();
    snapshot();  // the starting point: memory after connecting and homing
}

double Probe::simS()
{
    double t = 1e300;
    for (std::size_t i = 0; i < m_stations.size(); ++i)
        t = std::min(t, m_stations[i]->deviceTimeS() - m_sim0[i]);
    return m_stations.empty() ? 0 : t;
}

void Probe::tick()
{
    // Lateness: how much longer than its interval the timer took to come round. The
    // simulators run on this thread too (as the GUI's in-process ones do): their ticks,
    // the clients, the hub and the plots all take their turn before the timer's.
    const qint64 now = m_wall.nsecsElapsed();
    const double late = std::max(0.0, static_cast<double>(now - m_lastNs) / 1e6 - kProbeMs);
    m_lastNs = now;
    m_periodLate.push_back(static_cast<float>(late));
    m_allLate.push_back(static_cast<float>(late));
    if (m_allLate.size() % 10 == 0)
        m_rssMaxKb = std::max(m_rssMaxKb, rssKb());
}

quint64 Probe::linkErrors(Station& s)
{
    const dev::LinkStats c = s.client.stats();
    const dev::proto::DecoderStats& d = s.link.host().firmware().decoderStats();
    return c.crcErrors + c.malformed + c.oversize + c.droppedBytes + c.timeouts + d.crcErrors + d.malformed + d.oversize
        + s.trouble.linkErrorSignals + s.trouble.refusals + s.trouble.linkDrops;
}

const Figures& Probe::snapshot()
{
    Figures f;
    f.simS = simS();
    f.wallS = m_wall.nsecsElapsed() / 1e9;
    f.rssKb = rssKb();
    f.heapKb = heapKb();
    m_rssMaxKb = std::max(m_rssMaxKb, f.rssKb);
    f.latencyMaxMs = maxOf(m_periodLate);
    f.latencyP99Ms = percentile(m_periodLate, 0.99);
    f.latencyTicks = m_periodLate.size();
    m_periodLate.clear();
    for (std::size_t i = 0; i < m_stations.size(); ++i) {
        Station& s = *m_stations[i];
        const dev::LinkStats c = s.client.stats();
        f.samples += c.telemetrySamples;
        f.lostSamples += c.lostSamples;
        f.retransmits += c.retransmits;
        f.lateReplies += c.lateReplies;
        f.hubLostSamples += m_hub.lostSamples(static_cast<int>(i));
        f.droppedBatches += s.link.host().firmware().droppedTelemetryBatches();
        f.linkErrors += linkErrors(s);
        f.jogExpired += s.trouble.jogExpired;
    }
    f.jobsDone = m_tally.done();
    f.jobsFailed = m_tally.failed();
    f.plotFrames = m_plots.frames();
    f.storeBytes = m_plots.storeBytes();
    m_periods.push_back(f);
    return m_periods.back();
}

double Probe::latencyMaxMs() const { return maxOf(m_allLate); }
double Probe::latencyP99Ms() const { return percentile(m_allLate, 0.99); }

std::vector<std::string> Probe::verdict(const Bounds& b, const std::vector<std::string>& kinds) const
{
    std::vector<std::string> out;
    if (m_periods.size() < 2)
        return {"no figures: the soak never ran"};
    const Figures& end = m_periods.back();
    if (end.lost() > 0)
        out.push_back(std::to_string(end.lost()) + " telemetry samples or batches lost on a clean link");
    if (end.linkErrors > 0)
        out.push_back(std::to_string(end.linkErrors) + " link errors on a clean link");
    if (end.jogExpired > 0)
        out.push_back(std::to_string(end.jogExpired) + " jogs expired on the device although the host renewed them in time");
    if (end.jobsFailed > 0)
        out.push_back(std::to_string(end.jobsFailed) + " jobs failed");
    if (b.everyKind)
        for (const auto& k : kinds) {
            const auto it = m_tally.byKind.find(k);
            if (it == m_tally.byKind.end() || it->second.done == 0)
                out.push_back("no " + k + " job finished");
        }
    if (b.latencyMaxMs > 0 && latencyMaxMs() > b.latencyMaxMs)
        out.push_back(format("event loop %.1f ms late at worst (bound %.0f ms)", latencyMaxMs(), b.latencyMaxMs));
    if (b.latencyP99Ms > 0 && latencyP99Ms() > b.latencyP99Ms)
        out.push_back(format("event loop %.1f ms late at the 99th percentile (bound %.0f ms)", latencyP99Ms(), b.latencyP99Ms));
    if (b.judgeGrowth) {
        // Growth over the second half: the first half is warm-up (stores filling their
        // windows, the allocator's arenas, Qt's caches).
        const Figures* half = &m_periods.front();
        for (const Figures& f : m_periods)
            if (f.simS >= end.simS / 2) {
                half = &f;
                break;
            }
        const double allowedKb = std::max(b.growthMb * 1024, b.growthPercent / 100 * static_cast<double>(half->rssKb));
        const double grownKb = static_cast<double>(end.rssKb - half->rssKb);
        if (grownKb > allowedKb)
            out.push_back(format("RSS grew %.1f MiB over the second half (bound %.1f MiB)", grownKb / 1024, allowedKb / 1024));
    }
    return out;
}

void Probe::printHeader(std::FILE* out)
{
    std::fprintf(out, "%8s %7s %6s %8s %8s %8s %8s %10s %5s %6s %7s %6s %6s %7s\n", "sim_min", "wall_s", "scale", "rss_MiB",
                 "heap_MiB", "lat_max", "lat_p99", "samples", "lost", "linkerr", "retries", "jobs", "failed", "frames");
}

void Probe::printRow(std::FILE* out, const Figures& f)
{
    // Latency is of the period ending on the row; the counters are totals.
    std::fprintf(out, "%8.1f %7.1f %6.1f %8.1f %8.1f %8.1f %8.1f %10llu %5llu %6llu %7llu %6llu %6llu %7llu\n", f.simS / 60, f.wallS,
                 f.wallS > 0 ? f.simS / f.wallS : 0.0, mb(f.rssKb), mb(f.heapKb), f.latencyMaxMs, f.latencyP99Ms,
                 static_cast<unsigned long long>(f.samples), static_cast<unsigned long long>(f.lost()),
                 static_cast<unsigned long long>(f.linkErrors), static_cast<unsigned long long>(f.retransmits),
                 static_cast<unsigned long long>(f.jobsDone), static_cast<unsigned long long>(f.jobsFailed),
                 static_cast<unsigned long long>(f.plotFrames));
}

QJsonObject Probe::json(const Bounds& b, const std::vector<std::string>& kinds) const
{
    QJsonArray periods;
    for (const Figures& f : m_periods)
        periods.append(QJsonObject{{QStringLiteral("sim_s"), f.simS},
                                   {QStringLiteral("wall_s"), f.wallS},
                                   {QStringLiteral("rss_kib"), f.rssKb},
                                   {QStringLiteral("heap_kib"), f.heapKb},
                                   {QStringLiteral("latency_max_ms"), f.latencyMaxMs},
                                   {QStringLiteral("latency_p99_ms"), f.latencyP99Ms},
                                   {QStringLiteral("latency_ticks"), static_cast<qint64>(f.latencyTicks)},
                                   {QStringLiteral("samples"), static_cast<qint64>(f.samples)},
                                   {QStringLiteral("lost_samples"), static_cast<qint64>(f.lostSamples)},
                                   {QStringLiteral("hub_lost_samples"), static_cast<qint64>(f.hubLostSamples)},
                                   {QStringLiteral("dropped_batches"), static_cast<qint64>(f.droppedBatches)},
                                   {QStringLiteral("link_errors"), static_cast<qint64>(f.linkErrors)},
                                   {QStringLiteral("jogs_expired"), static_cast<qint64>(f.jogExpired)},
                                   {QStringLiteral("retransmits"), static_cast<qint64>(f.retransmits)},
                                   {QStringLiteral("late_replies"), static_cast<qint64>(f.lateReplies)},
                                   {QStringLiteral("jobs_done"), static_cast<qint64>(f.jobsDone)},
                                   {QStringLiteral("jobs_failed"), static_cast<qint64>(f.jobsFailed)},
                                   {QStringLiteral("plot_frames"), static_cast<qint64>(f.plotFrames)},
                                   {QStringLiteral("store_bytes"), static_cast<qint64>(f.storeBytes)}});
    QJsonObject jobs;
    for (const auto& [kind, c] : m_tally.byKind)
        jobs.insert(QString::fromStdString(kind),
                    QJsonObject{{QStringLiteral("done"), static_cast<qint64>(c.done)}, {QStringLiteral("failed"), static_cast<qint64>(c.failed)}});
    QJsonArray failures, verdictLines, trouble;
    for (const auto& f : m_tally.failures)
        failures.append(QString::fromStdString(f));
    for (const auto& v : verdict(b, kinds))
        verdictLines.append(QString::fromStdString(v));
    for (Station* s : m_stations)
        for (const auto& m : s->trouble.firstMessages)
            trouble.append(QString::fromStdString(m));
    return QJsonObject{{QStringLiteral("periods"), periods},
                       {QStringLiteral("jobs"), jobs},
                       {QStringLiteral("job_failures"), failures},
                       {QStringLiteral("link_messages"), trouble},
                       {QStringLiteral("rss_max_kib"), m_rssMaxKb},
                       {QStringLiteral("latency_max_ms"), latencyMaxMs()},
                       {QStringLiteral("latency_p99_ms"), latencyP99Ms()},
                       {QStringLiteral("pattern_underruns"), static_cast<qint64>(m_tally.patternUnderruns)},
                       {QStringLiteral("max_contour_um"), m_tally.maxContourUm},
                       {QStringLiteral("bounds"), QJsonObject{{QStringLiteral("latency_max_ms"), b.latencyMaxMs},
                                                              {QStringLiteral("latency_p99_ms"), b.latencyP99Ms},
                                                              {QStringLiteral("growth_mib"), b.growthMb},
                                                              {QStringLiteral("growth_percent"), b.growthPercent},
                                                              {QStringLiteral("judge_growth"), b.judgeGrowth}}},
                       {QStringLiteral("failures"), verdictLines},
                       {QStringLiteral("passed"), verdictLines.isEmpty()}};
}

} // namespace soak
