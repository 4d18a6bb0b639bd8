// TelemetryHub: the flight recorder's side. The recorder keeps
// every instrument's positions and following errors within a fixed budget
// (history_recorder.h); here the hub turns it on, picks between it and the live
// stores for a plot, and exports it as CSV.
#include "device/telemetry/telemetry_hub.h"
#include "device/telemetry/telemetry_hub_detail.h"

#include <QDir>
#include <QSaveFile>

#include <cmath>
#include <vector>

namespace dev::tele {
namespace {
/// A live store "covers the window" when its oldest sample is at most this much
/// younger than the window's start: one batch late (≤ 105 ms) is still covering.
constexpr double kCoverSlackS = 0.25;

struct HistoryColumn {
    ChannelKey key;
    const ChannelStore* store = nullptr;
    std::size_t next = 0;
};
} // namespace

void TelemetryHub::enableHistory(const HistoryBudget& budget)
{
    if (m_history)
        return;
    m_history = std::make_unique<HistoryRecorder>(budget);
    scheduleApply();  // identified instruments stream the history's channels from now on
}

const ChannelStore* TelemetryHub::historyStore(const ChannelKey& key) const
{
    return m_history ? m_history->store(key.instrument, key.ref) : nullptr;
}

const ChannelStore* TelemetryHub::viewStore(const ChannelKey& key) const
{
    const ChannelStore* live = store(key);
    const ChannelStore* kept = historyStore(key);
    if (!kept || kept->empty())
        return live;
    if (!live || live->empty())
        return kept;
    const Instrument* in = instrument(key.instrument);
    const double end = m_paused && in && !std::isnan(in->pausedAtS) ? in->pausedAtS : live->lastTime();
    if (live->firstTime() <= end - m_windowS + kCoverSlackS)
        return live;  // the window at the rate the screens asked for
    return kept->firstTime() < live->firstTime() - kCoverSlackS ? kept : live;
}

QVector<ChannelKey> TelemetryHub::historyChannels() const
{
    QVector<ChannelKey> out;
    if (!m_history)
        return out;
    for (const auto& [index, in] : m_instruments)
        for (const auto& ref : m_history->channels(index))
            out.push_back(ChannelKey{index, ref});
    return out;
}

double TelemetryHub::historySpanS(int index) const { return m_history ? m_history->spanS(index) : 0.0; }

bool TelemetryHub::exportHistory(const QString& csvPath, double spanS, motion::msg::Message* error, quint64* rows) const
{
    auto fail = [error](const motion::msg::Message& why) {
        if (error)
            *error = why;
        return false;
    };
    const QVector<ChannelKey> keys = historyChannels();
    std::vector<HistoryColumn> cols;
    for (const auto& k : keys) {
        const ChannelStore* s = historyStore(k);
        if (s && !s->empty())
            cols.push_back(HistoryColumn{k, s, 0});
    }
    if (cols.empty())
        return fail(motion::msg::make("telemetry.history_empty"));
    QSaveFile file(csvPath);
    const auto cannotWrite = [&] {
        return motion::msg::make("file.cannot_write", {motion::msg::verbatim("file", QDir::toNativeSeparators(csvPath).toStdString()),
                                               motion::msg::verbatim("detail", file.errorString().toStdString())});
    };
    if (!file.open(QIODevice::WriteOnly | QIODevice::Text))
        return fail(cannotWrite());
    QByteArray out = "time_s,instrument";
    for (const auto& c : cols) {
        const QString unit = channelUnit(c.key);
        out += ',' + csvCell(unit.isEmpty() ? channelName(c.key) : tr("%1 [%2]").arg(channelName(c.key), unit));
    }
    out += '\n';
    quint64 written = 0;
    // One instrument after the other (their clocks are unrelated); within one, its
    // channels were kept from the same batches, so they share sample times: a row is
    // one time, merged like the plots' export in case a channel started later.
    for (const int index : instruments()) {
        double latest = std::nan("");
        for (auto& c : cols)
            if (c.key.instrument == index && !(c.store->lastTime() <= latest))
                latest = c.store->lastTime();
        if (std::isnan(latest))
            continue;
        // 0.1 µs of slack: "the last second" includes the sample exactly a second old.
        const double from = spanS > 0 ? latest - spanS - 1e-7 : -std::numeric_limits<double>::infinity();
        for (auto& c : cols)
            if (c.key.instrument == index)
                c.next = std::isfinite(from) ? c.store->lowerBound(from) : 0;
        const QByteArray who = csvCell(instrumentName(index));
        for (;;) {
            double t = std::numeric_limits<double>::infinity();
            for (const auto& c : cols)
                if (c.key.instrument == index && c.next < c.store->size())
                    t = std::min(t, c.store->at(c.next).tS);
            if (!std::isfinite(t))
                break;
            out += QByteArray::number(t, 'f', 6) + ',' + who;
            for (auto& c : cols) {
                out += ',';
                // Same time within 0.1 µs: device clocks tick in whole µs.
                if (c.key.instrument == index && c.next < c.store->size() && std::abs(c.store->at(c.next).tS - t) < 1e-7)
                    appendShortest(out, c.store->at(c.next++).value);
            }
            out += '\n';
            ++written;
            if (out.size() > (1 << 16)) {
                file.write(out);
                out.resize(0);
            }
        }
    }
    file.write(out);
    if (!file.commit())
        return fail(cannotWrite());
    if (rows)
        *rows = written;
    return true;
}

} // namespace dev::tele
