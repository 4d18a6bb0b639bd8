// BenchPilotClient, part 1 of 5: construction, the connection state machine
// (connect, disconnect, link lost) and the HELLO handshake that identifies the
// device and brings the link to Ready. The request machinery is in
// benchpilot_client_requests.cpp, status/limits/telemetry upkeep in
// benchpilot_client_status.cpp, the commands in benchpilot_client_commands.cpp,
// capabilities, the parts and the rest of dev::Instrument in
// benchpilot_client_instrument.cpp.
#include "device/backends/benchpilot/benchpilot_client.h"

#include "device/backends/benchpilot/protocol_path_client.h"
#include "device/backends/benchpilot/protocol_compensation_client.h"
#include "device/backends/benchpilot/protocol_tuning_client.h"

#include <QCoreApplication>

namespace dev {

BenchPilotClient::BenchPilotClient(QObject* parent)
    : Instrument(parent), m_paths(new ProtocolPathClient(this, this)), m_tuning(new ProtocolTuningClient(this, this)),
      m_compensation(new ProtocolCompensationClient(this, this))
{
    m_clock.start();
    m_timeoutTimer.setInterval(kCheckPeriodMs);
    connect(&m_timeoutTimer, &QTimer::timeout, this, &BenchPilotClient::checkTimeouts);
    m_statusTimer.setInterval(kStatusPollMs);
    connect(&m_statusTimer, &QTimer::timeout, this, &BenchPilotClient::pollStatus);
    m_jogTimer.setInterval(kJogRefreshMs);
    m_jogTimer.setTimerType(Qt::PreciseTimer);
    connect(&m_jogTimer, &QTimer::timeout, this, &BenchPilotClient::refreshJogs);
}

BenchPilotClient::~BenchPilotClient()
{
    // Queued callbacks may refer to widgets already gone: drop them silently.
    m_queue.clear();
    m_realtime.clear();
    if (m_transport)
        for (const auto& c : m_transportConnections)
            disconnect(c);
}

qint64 BenchPilotClient::nowMs() const { return m_clock.elapsed(); }

void BenchPilotClient::setTransport(Transport* transport)
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
    m_transportConnections << connect(transport, &Transport::bytesReceived, this, &BenchPilotClient::onBytes);
    m_transportConnections << connect(transport, &Transport::opened, this, [this] {
        if (m_state != LinkState::Connecting)
            return;
        m_decoder.reset();
        m_connectStartedMs = nowMs();
        m_damagedAtConnect = m_decoder.stats().crcErrors + m_decoder.stats().malformed;
        // The last check of an earlier link is no measure of this one: counted as a hold-up
        // of the host's event loop, it put the first retry off by as long as the link was down.
        m_lastCheckMs = 0;
        m_timeoutTimer.start();
        sayHello(true);
    });
    m_transportConnections << connect(transport, &Transport::failed, this, [this](const motion::msg::Message& why) {
        if (m_state != LinkState::Connecting)
            return;
        emit linkError(why);
        setState(LinkState::Disconnected);
    });
    m_transportConnections << connect(transport, &Transport::lost, this, [this](const motion::msg::Message& why) { linkGone(why); });
}

QString BenchPilotClient::linkDescription() const { return m_transport ? m_transport->describe() : tr("no link"); }

void BenchPilotClient::setState(LinkState s)
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

void BenchPilotClient::connectLink()
{
    if (!m_transport) {
        emit linkError(motion::msg::make("link.no_connection_chosen"));
        return;
    }
    if (m_state == LinkState::Connecting || m_state == LinkState::Identified || m_state == LinkState::Ready)
        return;
    // A new line (or the same after a replug) is measured afresh, and a device that
    // restarted numbers its events afresh.
    m_srttMs = -1;
    m_rttVarMs = 0;
    m_retried.clear();
    m_recentEventCount = m_recentEventNext = 0;
    // The device's sample counter ran on while the link was down: what it numbered then
    // was never sent, not lost on the wire.
    m_haveSampleIndex = false;
    setState(LinkState::Connecting);
    m_transport->open();
}

void BenchPilotClient::disconnectLink()
{
    stopAllJogs();
    failAll(RequestError::Kind::LinkDown, motion::msg::make("link.disconnected"));
    m_timeoutTimer.stop();
    m_jogTimer.stop();
    if (m_transport)
        m_transport->close();
    setState(LinkState::Disconnected);
}

void BenchPilotClient::linkGone(const motion::msg::Message& why)
{
    if (m_state == LinkState::Disconnected || m_state == LinkState::Lost)
        return;
    m_jogs.clear();
    m_jogTimer.stop();
    failAll(RequestError::Kind::LinkDown, why);
    m_timeoutTimer.stop();
    if (m_transport)
        m_transport->close();
    emit linkError(motion::msg::make("link.lost", {motion::msg::nested("cause", why)}));
    setState(LinkState::Lost);
}

LinkStats BenchPilotClient::stats() const
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

void BenchPilotClient::sayHello(bool readsExtensions)
{
    // A device that knows no event reasons ignores that bit and sends its text alone.
    const dev::proto::Bytes payload =
        readsExtensions ? dev::proto::encode(dev::proto::HelloRequest{dev::proto::HelloReadsExtensions | dev::proto::HelloReadsEventReasons}) : dev::proto::Bytes{};
    send(dev::proto::MsgType::Hello, payload,
         [this, readsExtensions](const auto& err, const auto& reply) { onHello(err, reply, readsExtensions); });
}

/// Why a connect got no whole HELLO reply, in the shape the line had: nothing at all (power,
/// cable, port), frames that all arrived damaged until the handshake's patience ran out (a
/// noisy line or a wrong baud rate), or damaged frames and then silence (the device went
/// away mid-connect). One "no answer" for all three sent the operator to the wrong cause.
motion::msg::Message BenchPilotClient::connectUnanswered() const
{
    const motion::msg::Arg link = motion::msg::verbatim("link", linkDescription().toStdString());
    const auto& ds = m_decoder.stats();
    const quint64 all = ds.crcErrors + ds.malformed;
    const quint64 damaged = all > m_damagedAtConnect ? all - m_damagedAtConnect : 0;
    if (damaged == 0)
        return motion::msg::make("link.no_answer", {link});
    const qint64 now = nowMs();
    const motion::msg::Arg frames = motion::msg::integer("damaged", static_cast<long long>(damaged));
    if (now - m_connectStartedMs >= kConnectGiveUpMs)
        return motion::msg::make("link.only_damaged", {link, motion::msg::real("seconds", (now - m_connectStartedMs) / 1000.0, motion::msg::Unit::S), frames});
    return motion::msg::make("link.went_silent",
                     {link, frames, motion::msg::real("seconds", (now - std::max(m_lastDamagedFrameMs, m_lastFrameMs)) / 1000.0, motion::msg::Unit::S)});
}

void BenchPilotClient::onHello(const std::optional<RequestError>& err, const dev::proto::Bytes& payload, bool askedExtensions)
{
    if (m_state != LinkState::Connecting)
        return;
    auto fail = [this](const motion::msg::Message& why) {
        emit linkError(why);
        m_timeoutTimer.stop();
        if (m_transport)
            m_transport->close();
        setState(LinkState::Disconnected);
    };
    if (err && askedExtensions && err->kind == RequestError::Kind::Device && err->code == dev::proto::ErrorCode::BadPayload) {
        // Protocol 1.0 firmware knows no HELLO payload: ask it the way it understands,
        // and time moves without its limits (docs/protocol.md, "HELLO").
        sayHello(false);
        return;
    }
    if (err) {
        fail(err->kind == RequestError::Kind::Timeout ? connectUnanswered() : err->message);
        return;
    }
    const auto h = dev::proto::decodeHelloReply(payload);
    if (!h) {
        fail(motion::msg::make("link.not_benchpilot", {motion::msg::verbatim("link", linkDescription().toStdString())}));
        return;
    }
    if (h->protocolVersion != dev::proto::kProtocolVersion) {
        fail(motion::msg::make("link.protocol_version", {motion::msg::integer("device", h->protocolVersion, motion::msg::Unit::None),
                                                 motion::msg::integer("host", dev::proto::kProtocolVersion, motion::msg::Unit::None)}));
        return;
    }
    DeviceIdentity id;
    id.kind = h->kind;
    id.family = QStringLiteral("BenchPilot protocol %1").arg(h->protocolVersion);
    id.protocolVersion = h->protocolVersion;
    id.protocolCapabilities = h->capabilities;
    id.model = QString::fromStdString(h->model);
    id.firmware = QString::fromStdString(h->firmware);
    id.linkBaud = h->linkBaud;
    id.maxTelemetryRateHz = h->maxTelemetryRateHz;
    id.jogWatchdogMs = h->jogWatchdogMs;
    for (std::size_t i = 0; i < h->axes.size(); ++i) {
        const auto& a = h->axes[i];
        AxisDescriptor d;
        d.letter = QChar(a.letter);
        d.unit = a.unit;
        const double k = d.wireScale();
        d.travelMin = a.travelMin / k;
        d.travelMax = a.travelMax / k;
        d.maxSpeed = a.maxSpeed / k;
        d.resolution = a.resolution / k;
        if (h->motionLimits) {
            // Rates of change come in thousandths of the axis unit (µm, nL), speeds in wire units.
            const auto& l = h->motionLimits->axes[i];
            d.maxAccel = l.maxAccel / 1e3;
            d.maxJerk = l.maxJerk / 1e3;
            d.defaultSpeed = l.defaultSpeed / k;
            d.minAccelTimeS = l.minAccelTimeUs / 1e6;
        }
        id.axes.push_back(d);
    }
    if (h->motionLimits)
        id.motionProfile = h->motionLimits->profile;
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
    send(dev::proto::MsgType::Status, {}, [this, oneDone](const auto& e, const auto& p) {
        m_statusPending = false;
        if (!e)
            applyStatus(p);
        oneDone();
    });
    QVector<dev::proto::ChannelRef> channels;
    for (int i = 0; i < m_identity.axes.size(); ++i) {
        channels.push_back({static_cast<std::uint8_t>(i), dev::proto::ChannelKind::Commanded});
        channels.push_back({static_cast<std::uint8_t>(i), dev::proto::ChannelKind::Measured});
    }
    subscribe(channels, kDefaultTelemetryHz, [oneDone](const auto&, const auto&) { oneDone(); });
}

} // namespace dev
