// TelemetryHub, core: construction, the instruments it serves and the channels
// each offers (names, units). The rest of the class is split by responsibility:
// telemetry_hub_subscription.cpp (wants → SUBSCRIBE), telemetry_hub_stores.cpp
// (batches into the rolling stores, window, pause, sample counts) and
// telemetry_hub_recording.cpp (CSV recording).
#include "device/telemetry/telemetry_hub.h"
#include "device/telemetry/telemetry_hub_detail.h"

#include "device/protocol/messages_tuning.h"

namespace dev::tele {
namespace {
QString kindWord(dev::proto::ChannelKind k)
{
    switch (k) {
    case dev::proto::ChannelKind::Commanded: return TelemetryHub::tr("commanded");
    case dev::proto::ChannelKind::Measured: return TelemetryHub::tr("measured");
    case dev::proto::ChannelKind::Velocity: return TelemetryHub::tr("velocity");
    case dev::proto::ChannelKind::FollowingError: return TelemetryHub::tr("following error");
    case dev::proto::ChannelKind::ControllerOutput: return TelemetryHub::tr("controller output");
    case dev::proto::ChannelKind::Switches: return TelemetryHub::tr("switches");
    case dev::proto::ChannelKind::ContourError: return TelemetryHub::tr("contour error");
    case dev::proto::ChannelKind::ControllerU: return TelemetryHub::tr("controller output u");
    }
    return {};
}
} // namespace

size_t qHash(const ChannelKey& key, size_t seed) noexcept
{
    return ::qHash((static_cast<quint64>(static_cast<quint32>(key.instrument)) << 16) | (quint64(key.ref.axis) << 8)
                       | static_cast<quint64>(key.ref.kind),
                   seed);
}

TelemetryHub::Instrument::Instrument() : latestS(kNaN), pausedAtS(kNaN) {}

TelemetryHub::TelemetryHub(QObject* parent) : QObject(parent)
{
    qRegisterMetaType<dev::tele::ChannelKey>();
    m_flushTimer.setInterval(kRecordFlushMs);
    connect(&m_flushTimer, &QTimer::timeout, this, &TelemetryHub::flushRecording);
}

TelemetryHub::~TelemetryHub()
{
    if (m_record) {
        flushRecording();
        m_record.reset();
    }
    for (auto& [index, in] : m_instruments)
        for (const auto& c : in.connections)
            disconnect(c);
}

TelemetryHub::Instrument* TelemetryHub::instrument(int index)
{
    const auto it = m_instruments.find(index);
    return it == m_instruments.end() ? nullptr : &it->second;
}

const TelemetryHub::Instrument* TelemetryHub::instrument(int index) const
{
    const auto it = m_instruments.find(index);
    return it == m_instruments.end() ? nullptr : &it->second;
}

void TelemetryHub::addInstrument(int index, const QString& name, dev::Instrument* client)
{
    if (Instrument* old = instrument(index))
        for (const auto& c : old->connections)
            disconnect(c);
    Instrument& in = m_instruments[index];
    in = Instrument{};
    if (m_history)
        m_history->forget(index);  // another instrument at this index: its history is not this one's
    in.name = name;
    in.client = client;
    if (client) {
        in.connections << connect(client, &dev::Instrument::stateChanged, this,
                                  [this, index](dev::LinkState s) { onStateChanged(index, s); });
        in.connections << connect(client, &dev::Instrument::telemetryReceived, this,
                                  [this, index](const dev::proto::TelemetryBatch& b) { onBatch(index, b); });
        in.connections << connect(client, &QObject::destroyed, this, [this, index] {
            if (Instrument* i = instrument(index))
                i->subscribeInFlight = false;
        });
    }
    recomputeCollected();
    if (client && client->isReady())
        onStateChanged(index, dev::LinkState::Ready);
}

QVector<int> TelemetryHub::instruments() const
{
    QVector<int> out;
    for (const auto& [index, in] : m_instruments)
        out << index;
    return out;
}

void TelemetryHub::setInstrumentName(int index, const QString& name)
{
    const auto it = m_instruments.find(index);
    if (it != m_instruments.end())
        it->second.name = name;
}

QString TelemetryHub::instrumentName(int index) const
{
    const Instrument* in = instrument(index);
    return in ? in->name : QString();
}

// ---- channels -------------------------------------------------------------------

QVector<ChannelKey> TelemetryHub::availableChannels(int index) const
{
    QVector<ChannelKey> out;
    const Instrument* in = instrument(index);
    if (!in || !in->client)
        return out;
    const dev::DeviceIdentity& id = in->client->identity();
    const dev::Capabilities can = in->client->capabilities();
    const bool pid = can.testFlag(dev::Capability::ClosedLoop);
    using K = dev::proto::ChannelKind;
    for (int a = 0; a < id.axes.size(); ++a) {
        const auto axis = static_cast<std::uint8_t>(a);
        for (K k : {K::Commanded, K::Measured, K::Velocity, K::FollowingError, K::ControllerOutput, K::Switches}) {
            if (k == K::ControllerOutput && !pid)
                continue;
            out.push_back(ChannelKey{index, {axis, k}});
        }
        if (can.testFlag(dev::Capability::PidGains))  // tuning: the PID's own output
            out.push_back(ChannelKey{index, {axis, K::ControllerU}});
    }
    if (pid)
        out.push_back(ChannelKey{index, {dev::proto::kNoAxis, K::ContourError}});
    return out;
}

QString TelemetryHub::channelName(const ChannelKey& key) const
{
    const Instrument* in = instrument(key.instrument);
    const QString who = in ? in->name : tr("Instrument %1").arg(key.instrument);
    if (key.ref.kind == dev::proto::ChannelKind::ContourError)
        return tr("%1 %2").arg(who, kindWord(key.ref.kind));
    QString axis = QString::number(key.ref.axis);
    if (in && in->client && key.ref.axis < in->client->identity().axes.size())
        axis = in->client->identity().axes[key.ref.axis].letter;
    return tr("%1 %2 %3").arg(who, axis, kindWord(key.ref.kind));
}

QString TelemetryHub::channelUnit(const ChannelKey& key) const
{
    const Instrument* in = instrument(key.instrument);
    bool microlitre = false;
    if (in && in->client && key.ref.axis < in->client->identity().axes.size())
        microlitre = in->client->identity().axes[key.ref.axis].unit == dev::proto::AxisUnit::Microlitre;
    switch (key.ref.kind) {
    case dev::proto::ChannelKind::Commanded:
    case dev::proto::ChannelKind::Measured: return microlitre ? QStringLiteral("µL") : QStringLiteral("mm");
    case dev::proto::ChannelKind::Velocity: return microlitre ? QStringLiteral("µL/s") : QStringLiteral("mm/s");
    case dev::proto::ChannelKind::FollowingError: return microlitre ? QStringLiteral("nL") : QStringLiteral("µm");
    case dev::proto::ChannelKind::ControllerOutput: return QStringLiteral("steps/s");
    case dev::proto::ChannelKind::Switches: return QString();
    case dev::proto::ChannelKind::ContourError:
    case dev::proto::ChannelKind::ControllerU: return QStringLiteral("µm");
    }
    return {};
}

double TelemetryHub::unitFactor(const ChannelKey& key) const
{
    // toAxisUnits() gives mm (µL); errors are a thousand times smaller than travel.
    switch (key.ref.kind) {
    case dev::proto::ChannelKind::FollowingError:
    case dev::proto::ChannelKind::ContourError:
    case dev::proto::ChannelKind::ControllerU: return 1000.0;
    default: return 1.0;
    }
}

} // namespace dev::tele
