// InstrumentClient, part 1 of 4: construction, the connection state machine
// (connect, disconnect, link lost) and the HELLO handshake that identifies the
// device and brings the link to Ready. The request machinery is in
// instrument_client_requests.cpp, status/limits/telemetry upkeep in
// instrument_client_status.cpp, the commands in instrument_client_commands.cpp.
#include "device/client/instrument_client.h"

#include <QCoreApplication>

namespace dev {

InstrumentClient::InstrumentClient(QObject* parent) : QObject(parent)
{
    qRegisterMetaType<dev::LinkState>();
    qRegisterMetaType<dev::InstrumentStatus>();
    qRegisterMetaType<dev::DeviceEvent>();
    qRegisterMetaType<dev::RequestError>();
    m_clock.start();
    m_timeoutTimer.setInterval(20);
    connect(&m_timeoutTimer, &QTimer::timeout, this, &InstrumentClient::checkTimeouts);
    m_statusTimer.setInterval(kStatusPollMs);
    connect(&m_statusTimer, &QTimer::timeout, this, &InstrumentClient::pollStatus);
    m_jogTimer.setInterval(kJogRefreshMs);
    m_jogTimer.setTimerType(Qt::PreciseTimer);
    connect(&m_jogTimer, &QTimer::timeout, this, &InstrumentClient::refreshJogs);
}

InstrumentClient::~InstrumentClient()
{
    // Queued callbacks may refer to widgets already gone: drop them silently.
    m_queue.clear();
    m_realtime.clear();
    if (m_transport)
        for (const auto& c : m_transportConnections)
            disconnect(c);
}

qint64 InstrumentClient::nowMs() const { return m_clock.elapsed(); }

void InstrumentClient::setTransport(Transport* transport)
{
    if (m_transport) {
        disconnectLink();
        for (const auto& c : m_transportConnections)
            disconnect(c);
        m_transportConnections.clear();
    }
    m_transport = transport;
    if (!transport)
        return;
    m_transportConnections << connect(transport, &Transport::bytesReceived, this, &InstrumentClient::onBytes);
    m_transportConnections << connect(transport, &Transport::opened, this, [this] {
        if (m_state != LinkState::Connecting)
            return;
        m_decoder.reset();
        m_timeoutTimer.start();
        send(proto::MsgType::Hello, {}, [this](const auto& err, const auto& payload) { onHello(err, payload); });
    });
    m_transportConnections << connect(transport, &Transport::failed, this, [this](const QString& why) {
        if (m_state != LinkState::Connecting)
            return;
        emit linkError(why);
        setState(LinkState::Disconnected);
    });
    m_transportConnections << connect(transport, &Transport::lost, this, [this](const QString& why) { linkGone(why); });
}

QString InstrumentClient::linkDescription() const { return m_transport ? m_transport->describe() : tr("no link"); }

void InstrumentClient::setState(LinkState s)
{
    if (m_state == s)
        return;
    m_state = s;
    if (s == LinkState::Ready)
        m_statusTimer.start();
    else
        m_statusTimer.stop();
    emit stateChanged(s);
}

void InstrumentClient::connectLink()
{
    if (!m_transport) {
        emit linkError(tr("no connection chosen"));
        return;
    }
    if (m_state == LinkState::Connecting || m_state == LinkState::Identified || m_state == LinkState::Ready)
        return;
    m_consecutiveTimeouts = 0;
    setState(LinkState::Connecting);
    m_transport->open();
}

void InstrumentClient::disconnectLink()
{
    stopAllJogs();
    failAll(RequestError::Kind::LinkDown, tr("disconnected"));
    m_timeoutTimer.stop();
    m_jogTimer.stop();
    if (m_transport)
        m_transport->close();
    setState(LinkState::Disconnected);
}

void InstrumentClient::linkGone(const QString& why)
{
    if (m_state == LinkState::Disconnected || m_state == LinkState::Lost)
        return;
    m_jogs.clear();
    m_jogTimer.stop();
    failAll(RequestError::Kind::LinkDown, why);
    m_timeoutTimer.stop();
    if (m_transport)
        m_transport->close();
    emit linkError(tr("link lost: %1").arg(why));
    setState(LinkState::Lost);
}

LinkStats InstrumentClient::stats() const
{
    LinkStats s = m_stats;
    const auto& d = m_decoder.stats();
    s.framesIn = d.frames;
    s.crcErrors = d.crcErrors;
    s.malformed = d.malformed;
    s.oversize = d.oversize;
    s.droppedBytes = d.droppedBytes;
    return s;
}

// ---- handshake ------------------------------------------------------------------

void InstrumentClient::onHello(const std::optional<RequestError>& err, const proto::Bytes& payload)
{
    if (m_state != LinkState::Connecting)
        return;
    auto fail = [this](const QString& why) {
        emit linkError(why);
        m_timeoutTimer.stop();
        if (m_transport)
            m_transport->close();
        setState(LinkState::Disconnected);
    };
    if (err) {
        fail(err->kind == RequestError::Kind::Timeout
                 ? tr("no answer from %1: check power, cable and baud rate").arg(linkDescription())
                 : err->message);
        return;
    }
    const auto h = proto::decodeHelloReply(payload);
    if (!h) {
        fail(tr("%1 answered HELLO with something that is not BenchPilot protocol").arg(linkDescription()));
        return;
    }
    if (h->protocolVersion != proto::kProtocolVersion) {
        fail(tr("the device speaks protocol version %1; this BenchPilot speaks version %2")
                 .arg(h->protocolVersion)
                 .arg(proto::kProtocolVersion));
        return;
    }
    DeviceIdentity id;
    id.kind = h->kind;
    id.protocolVersion = h->protocolVersion;
    id.capabilities = h->capabilities;
    id.model = QString::fromStdString(h->model);
    id.firmware = QString::fromStdString(h->firmware);
    id.linkBaud = h->linkBaud;
    id.maxTelemetryRateHz = h->maxTelemetryRateHz;
    id.jogWatchdogMs = h->jogWatchdogMs;
    for (const auto& a : h->axes) {
        AxisDescriptor d;
        d.letter = QChar(a.letter);
        d.unit = a.unit;
        d.travelMin = a.travelMin / d.wireScale();
        d.travelMax = a.travelMax / d.wireScale();
        d.maxSpeed = a.maxSpeed / d.wireScale();
        d.resolution = a.resolution / d.wireScale();
        id.axes.push_back(d);
    }
    m_identity = id;
    m_status = InstrumentStatus{};
    m_status.axes.resize(id.axes.size());
    m_limits = QVector<SoftLimits>(id.axes.size());
    setState(LinkState::Identified);
    emit identified(m_identity);

    // Limits, a first status and the default telemetry; Ready once all three answered.
    auto remaining = std::make_shared<int>(3);
    auto oneDone = [this, remaining] {
        if (--*remaining == 0 && m_state == LinkState::Identified)
            setState(LinkState::Ready);
    };
    refreshLimits(oneDone);
    m_statusPending = true;
    send(proto::MsgType::Status, {}, [this, oneDone](const auto& e, const auto& p) {
        m_statusPending = false;
        if (!e)
            applyStatus(p);
        oneDone();
    });
    QVector<proto::ChannelRef> channels;
    for (int i = 0; i < m_identity.axes.size(); ++i) {
        channels.push_back({static_cast<std::uint8_t>(i), proto::ChannelKind::Commanded});
        channels.push_back({static_cast<std::uint8_t>(i), proto::ChannelKind::Measured});
    }
    subscribe(channels, kDefaultTelemetryHz, [oneDone](const auto&, const auto&) { oneDone(); });
}

} // namespace dev
