#pragma once
// Where the plot widgets find channel data. In the application that is the
// telemetry hub; benches and tests hand the plots bare ChannelStores. The plots
// only read: they never own, fill or copy a store.
#include "device/telemetry/channel_store.h"
#include "device/telemetry/telemetry_hub.h"

#include <QColor>
#include <QHash>
#include <QPointer>
#include <QString>

#include <cmath>

namespace ui {

inline bool sameChannel(const dev::tele::ChannelKey& a, const dev::tele::ChannelKey& b)
{
    return a.instrument == b.instrument && a.ref.axis == b.ref.axis && a.ref.kind == b.ref.kind;
}

/// A stable integer for a channel (instrument, axis, kind), for hashes and object names.
inline int channelId(const dev::tele::ChannelKey& k)
{
    return (k.instrument << 16) | (int(k.ref.axis) << 8) | int(static_cast<std::uint8_t>(k.ref.kind));
}

class PlotDataSource {
public:
    virtual ~PlotDataSource() = default;
    /// nullptr when the channel has no store (not subscribed, instrument gone).
    virtual const dev::tele::ChannelStore* store(const dev::tele::ChannelKey& key) const = 0;
    virtual QString channelName(const dev::tele::ChannelKey& key) const = 0;
    virtual QString channelUnit(const dev::tele::ChannelKey& key) const = 0;
    /// Device time (s) of the instrument's newest sample; NaN when there is none.
    virtual double latestTimeS(int instrument) const = 0;
    virtual QString instrumentName(int instrument) const = 0;
};

/// The application's source: the telemetry hub (which may go before the widgets do).
class HubPlotSource final : public PlotDataSource {
public:
    explicit HubPlotSource(const dev::tele::TelemetryHub* hub = nullptr) : m_hub(hub) {}
    void setHub(const dev::tele::TelemetryHub* hub) { m_hub = hub; }
    /// The live store, or the recorded history when it reaches further back (TelemetryHub::viewStore).
    const dev::tele::ChannelStore* store(const dev::tele::ChannelKey& key) const override { return m_hub ? m_hub->viewStore(key) : nullptr; }
    QString channelName(const dev::tele::ChannelKey& key) const override { return m_hub ? m_hub->channelName(key) : QString(); }
    QString channelUnit(const dev::tele::ChannelKey& key) const override { return m_hub ? m_hub->channelUnit(key) : QString(); }
    double latestTimeS(int instrument) const override { return m_hub ? m_hub->latestTimeS(instrument) : std::nan(""); }
    QString instrumentName(int instrument) const override { return m_hub ? m_hub->instrumentName(instrument) : QString(); }

private:
    QPointer<const dev::tele::TelemetryHub> m_hub;
};

/// Stores held by someone else (a bench, a test), registered one by one.
class StorePlotSource final : public PlotDataSource {
public:
    void add(const dev::tele::ChannelKey& key, const dev::tele::ChannelStore* store, const QString& name, const QString& unit)
    {
        m_entries.insert(channelId(key), Entry{store, name, unit});
    }
    const dev::tele::ChannelStore* store(const dev::tele::ChannelKey& key) const override { return m_entries.value(channelId(key)).store; }
    QString channelName(const dev::tele::ChannelKey& key) const override { return m_entries.value(channelId(key)).name; }
    QString channelUnit(const dev::tele::ChannelKey& key) const override { return m_entries.value(channelId(key)).unit; }
    void setInstrumentName(int instrument, const QString& name) { m_names.insert(instrument, name); }
    QString instrumentName(int instrument) const override { return m_names.value(instrument, QString::number(instrument)); }
    double latestTimeS(int instrument) const override
    {
        double latest = std::nan("");
        for (auto it = m_entries.cbegin(); it != m_entries.cend(); ++it)
            if ((it.key() >> 16) == instrument && it->store && !it->store->empty())
                latest = std::isnan(latest) ? it->store->lastTime() : std::max(latest, it->store->lastTime());
        return latest;
    }

private:
    struct Entry {
        const dev::tele::ChannelStore* store = nullptr;
        QString name, unit;
    };
    QHash<int, Entry> m_entries;
    QHash<int, QString> m_names;
};

} // namespace ui
