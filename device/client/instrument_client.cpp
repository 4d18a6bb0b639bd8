#include "device/client/instrument_client.h"

#include <QCoreApplication>

#include <cmath>

namespace dev {
namespace {
QString typeName(proto::MsgType t)
{
    switch (t) {
    case proto::MsgType::Hello: return QStringLiteral("HELLO");
    case proto::MsgType::Status: return QStringLiteral("STATUS");
    case proto::MsgType::Home: return QStringLiteral("HOME");
    case proto::MsgType::Move: return QStringLiteral("MOVE");
    case proto::MsgType::JogStep: return QStringLiteral("JOG_STEP");
    case proto::MsgType::SetZero: return QStringLiteral("SET_ZERO");
    case proto::MsgType::GetLimits: return QStringLiteral("GET_LIMITS");
    case proto::MsgType::SetLimits: return QStringLiteral("SET_LIMITS");
    case proto::MsgType::Subscribe: return QStringLiteral("SUBSCRIBE");
    case proto::MsgType::Reset: return QStringLiteral("RESET");
    case proto::MsgType::JogVelocity: return QStringLiteral("JOG_VELOCITY");
    case proto::MsgType::Stop: return QStringLiteral("STOP");
    case proto::MsgType::EStop: return QStringLiteral("ESTOP");
    default: return QStringLiteral("0x%1").arg(static_cast<int>(t), 2, 16, QLatin1Char('0'));
    }
}

std::int32_t toWire(double v, double scale) { return static_cast<std::int32_t>(std::llround(v * scale)); }
} // namespace

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

// ---- requests -------------------------------------------------------------------

void InstrumentClient::send(proto::MsgType type, const proto::Bytes& payload, RawDone done)
{
    Request r;
    r.type = type;
    r.realtime = proto::isRealtimeType(static_cast<std::uint8_t>(type));
    r.done = std::move(done);
    if (!m_transport || !m_transport->isOpen()) {
        RequestError e;
        e.kind = RequestError::Kind::LinkDown;
        e.message = tr("%1 not sent: the instrument is not connected").arg(typeName(type));
        if (r.done)
            r.done(e, {});
        return;
    }
    r.seq = m_nextSeq++;
    if (m_nextSeq == 0)
        m_nextSeq = 1;
    std::vector<std::uint8_t> wire;
    proto::encodeFrame(static_cast<std::uint8_t>(type), r.seq, payload.data(), payload.size(), wire);
    r.wire = QByteArray(reinterpret_cast<const char*>(wire.data()), static_cast<qsizetype>(wire.size()));
    if (r.realtime) {
        // Realtime requests overtake anything queued: they go out at once.
        transmit(r);
        m_realtime.emplace(r.seq, std::move(r));
        return;
    }
    m_queue.push_back(std::move(r));
    pumpQueue();
}

void InstrumentClient::transmit(Request& r)
{
    ++r.attempts;
    if (r.attempts > 1)
        ++m_stats.retransmits;
    else
        r.firstSentMs = nowMs();
    r.deadlineMs = nowMs() + kReplyTimeoutMs;
    if (m_transport)
        m_transport->write(r.wire);
}

void InstrumentClient::pumpQueue()
{
    if (m_inFlight || m_queue.empty())
        return;
    m_inFlight = true;
    transmit(m_queue.front());
}

void InstrumentClient::complete(Request r, const std::optional<RequestError>& err, const proto::Bytes& payload)
{
    if (!err || err->kind != RequestError::Kind::Timeout)
        m_consecutiveTimeouts = 0;
    if (r.done)
        r.done(err, payload);
}

void InstrumentClient::checkTimeouts()
{
    const qint64 now = nowMs();
    auto timeoutError = [](const Request& r) {
        RequestError e;
        e.kind = RequestError::Kind::Timeout;
        e.message = tr("no reply to %1 after %2 attempts (%3 s): the device is not answering")
                        .arg(typeName(r.type))
                        .arg(kAttempts)
                        .arg(kAttempts * kReplyTimeoutMs / 1000.0, 0, 'f', 1);
        return e;
    };
    std::vector<Request> expired;
    if (m_inFlight && !m_queue.empty() && m_queue.front().deadlineMs <= now) {
        Request& r = m_queue.front();
        if (r.attempts < kAttempts) {
            transmit(r);  // same seq, same bytes: the device answers a repeat from its cache
        } else {
            expired.push_back(std::move(r));
            m_queue.pop_front();
            m_inFlight = false;
        }
    }
    for (auto it = m_realtime.begin(); it != m_realtime.end();) {
        if (it->second.deadlineMs > now) {
            ++it;
            continue;
        }
        if (it->second.attempts < kAttempts) {
            transmit(it->second);
            ++it;
        } else {
            expired.push_back(std::move(it->second));
            it = m_realtime.erase(it);
        }
    }
    // Nothing at all came back while a request was tried kAttempts times: the
    // device is gone, not merely unlucky with one request. Waiting for a second
    // request to time out too would report it only after ~1.9 s or later.
    bool silent = false;
    for (const auto& r : expired)
        silent = silent || m_lastFrameMs < r.firstSentMs;
    for (auto& r : expired) {
        ++m_stats.timeouts;
        ++m_consecutiveTimeouts;
        const RequestError e = timeoutError(r);
        complete(std::move(r), e, {});
    }
    if (!expired.empty() && (m_state == LinkState::Ready || m_state == LinkState::Identified)
        && (silent || m_consecutiveTimeouts >= 2))
        linkGone(tr("the device stopped answering"));
    pumpQueue();
}

void InstrumentClient::failAll(RequestError::Kind kind, const QString& why)
{
    std::deque<Request> queue;
    queue.swap(m_queue);
    std::map<std::uint16_t, Request> rt;
    rt.swap(m_realtime);
    m_inFlight = false;
    m_statusPending = false;
    RequestError e;
    e.kind = kind;
    for (auto& r : queue) {
        e.message = tr("%1 abandoned: %2").arg(typeName(r.type), why);
        if (r.done)
            r.done(e, {});
    }
    for (auto& [seq, r] : rt) {
        e.message = tr("%1 abandoned: %2").arg(typeName(r.type), why);
        if (r.done)
            r.done(e, {});
    }
}

// ---- incoming -------------------------------------------------------------------

void InstrumentClient::onBytes(const QByteArray& bytes)
{
    m_frames.clear();
    m_decoder.feed(reinterpret_cast<const std::uint8_t*>(bytes.constData()), static_cast<std::size_t>(bytes.size()), m_frames);
    if (!m_frames.empty())
        m_lastFrameMs = nowMs();  // garbage alone does not show the device is alive
    for (const auto& f : m_frames)
        onFrame(f);
}

RequestError InstrumentClient::deviceError(const proto::ErrorReply& e) const
{
    RequestError r;
    r.kind = RequestError::Kind::Device;
    r.code = e.code;
    r.axis = e.axis == proto::kNoAxis ? -1 : e.axis;
    r.value = (r.axis >= 0 && r.axis < m_identity.axes.size()) ? e.value / m_identity.axes[r.axis].wireScale() : e.value;
    r.message = QString::fromStdString(e.message);
    if (r.message.isEmpty())
        r.message = QString::fromLatin1(proto::errorCodeName(e.code));
    return r;
}

void InstrumentClient::onFrame(const proto::Frame& f)
{
    if (f.type == static_cast<std::uint8_t>(proto::MsgType::Event)) {
        if (auto e = proto::decodeEvent(f.payload)) {
            DeviceEvent ev;
            ev.kind = e->kind;
            ev.axis = e->axis == proto::kNoAxis ? -1 : e->axis;
            // Instrument-wide events keep the number as sent (path events carry a segment index there).
            ev.position = (ev.axis >= 0 && ev.axis < m_identity.axes.size()) ? e->position / m_identity.axes[ev.axis].wireScale()
                                                                              : e->position;
            ev.deviceTimeUs = e->deviceTimeUs;
            ev.text = QString::fromStdString(e->text);
            ev.hostTime = QDateTime::currentDateTime();
            // Homing moves the coordinate origin, and with it the limits' numbers.
            if (ev.kind == proto::EventKind::HomeDone)
                refreshLimits();
            emit eventReceived(ev);
        }
        return;
    }
    if (f.type == static_cast<std::uint8_t>(proto::MsgType::TelemetryBatch)) {
        auto b = proto::decodeTelemetryBatch(f.payload);
        if (!b)
            return;
        ++m_stats.telemetryBatches;
        m_stats.telemetrySamples += b->sampleCount;
        // The sample counter runs on across batches: a jump is samples the wire lost.
        if (m_haveSampleIndex && b->firstSampleIndex != m_nextSampleIndex) {
            const std::uint32_t gap = b->firstSampleIndex - m_nextSampleIndex;
            if (gap < 0x80000000u) {
                m_stats.lostSamples += gap;
                emit samplesLost(m_stats.lostSamples);
            }
        }
        m_haveSampleIndex = true;
        m_nextSampleIndex = b->firstSampleIndex + b->sampleCount;
        emit telemetryReceived(*b);
        return;
    }
    const bool isError = f.type == static_cast<std::uint8_t>(proto::MsgType::Error);
    if (!isError && !proto::isReplyType(f.type))
        return;
    auto matches = [&](const Request& r) {
        return r.seq == f.seq && (isError || f.type == proto::replyTypeOf(r.type));
    };
    Request r;
    if (m_inFlight && !m_queue.empty() && matches(m_queue.front())) {
        r = std::move(m_queue.front());
        m_queue.pop_front();
        m_inFlight = false;
    } else if (auto it = m_realtime.find(f.seq); it != m_realtime.end() && matches(it->second)) {
        r = std::move(it->second);
        m_realtime.erase(it);
    } else {
        ++m_stats.lateReplies;  // an answer to a retransmission we already had, or to a forgotten request
        return;
    }
    if (isError) {
        const auto e = proto::decodeErrorReply(f.payload);
        RequestError err;
        if (e) {
            err = deviceError(*e);
        } else {
            err.kind = RequestError::Kind::Device;
            err.message = tr("%1 refused with an unreadable error").arg(typeName(r.type));
        }
        complete(std::move(r), err, {});
    } else {
        complete(std::move(r), std::nullopt, f.payload);
    }
    pumpQueue();
}

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

void InstrumentClient::applyStatus(const proto::Bytes& payload)
{
    const auto s = proto::decodeStatusReply(payload);
    if (!s || int(s->axes.size()) != m_identity.axes.size())
        return;
    m_status.estop = s->deviceFlags & proto::DeviceEStop;
    m_status.fault = s->deviceFlags & proto::DeviceFault;
    m_status.deviceTimeUs = s->deviceTimeUs;
    for (int i = 0; i < m_status.axes.size(); ++i) {
        const auto& a = s->axes[size_t(i)];
        const double k = m_identity.axes[i].wireScale();
        auto& r = m_status.axes[i];
        r.commanded = a.commanded / k;
        r.measured = a.measured / k;
        r.homed = a.flags & proto::AxisHomed;
        r.moving = a.flags & proto::AxisMoving;
        r.homing = a.flags & proto::AxisHoming;
        r.jogging = a.flags & proto::AxisJogging;
        r.homeSwitch = a.flags & proto::AxisHomeSwitch;
        r.limitSwitch = a.flags & proto::AxisLimitSwitch;
        r.fault = a.flags & proto::AxisFault;
    }
    emit statusChanged(m_status);
}

void InstrumentClient::refreshLimits(std::function<void()> then)
{
    send(proto::MsgType::GetLimits, {}, [this, then](const auto& e, const auto& p) {
        if (!e)
            if (auto l = proto::decodeLimitsReply(p)) {
                for (int i = 0; i < m_limits.size() && i < int(l->axes.size()); ++i) {
                    const double k = m_identity.axes[i].wireScale();
                    m_limits[i] = {l->axes[size_t(i)].min / k, l->axes[size_t(i)].max / k};
                }
                emit limitsChanged();
            }
        if (then)
            then();
    });
}

void InstrumentClient::pollStatus()
{
    if (m_statusPending || m_state != LinkState::Ready)
        return;
    m_statusPending = true;
    send(proto::MsgType::Status, {}, [this](const auto& e, const auto& p) {
        m_statusPending = false;
        if (!e)
            applyStatus(p);
    });
}

// ---- commands -------------------------------------------------------------------

InstrumentClient::RawDone InstrumentClient::wrap(Callback done, const QString& what)
{
    return [this, done = std::move(done), what](const std::optional<RequestError>& e, const proto::Bytes&) {
        if (e) {
            RequestError err = *e;
            if (!what.isEmpty() && err.kind == RequestError::Kind::Device)
                err.message = tr("%1 refused: %2").arg(what, err.message);
            emit requestFailed(err);
            if (done)
                done(err);
        } else if (done) {
            done(std::nullopt);
        }
    };
}

void InstrumentClient::request(proto::MsgType type, const proto::Bytes& payload, ReplyCallback done, const QString& what)
{
    send(type, payload, [this, done = std::move(done), what](const std::optional<RequestError>& e, const proto::Bytes& reply) {
        if (e) {
            RequestError err = *e;
            if (!what.isEmpty() && err.kind == RequestError::Kind::Device)
                err.message = tr("%1 refused: %2").arg(what, err.message);
            emit requestFailed(err);
            if (done)
                done(err, reply);
        } else if (done) {
            done(std::nullopt, reply);
        }
    });
}

static std::optional<RequestError> invalid(const QString& why)
{
    RequestError e;
    e.kind = RequestError::Kind::Invalid;
    e.message = why;
    return e;
}

void InstrumentClient::home(quint8 axisMask, Callback done)
{
    send(proto::MsgType::Home, proto::encode(proto::HomeRequest{axisMask}), wrap(std::move(done), tr("home")));
}

void InstrumentClient::move(const QVector<QPair<int, double>>& targets, bool relative, double speed, Callback done)
{
    auto refuse = [&](const QString& why) {
        const auto e = invalid(why);
        emit requestFailed(*e);
        if (done)
            done(e);
    };
    if (targets.isEmpty())
        return refuse(tr("move: no axis given"));
    proto::MoveRequest m;
    m.relative = relative;
    QMap<int, double> byAxis;
    for (const auto& [axis, value] : targets) {
        if (axis < 0 || axis >= m_identity.axes.size())
            return refuse(tr("move: axis %1 does not exist on this instrument").arg(axis));
        if (!std::isfinite(value))
            return refuse(tr("move: axis %1 target is not a number").arg(m_identity.axes[axis].letter));
        if (byAxis.contains(axis))
            return refuse(tr("move: axis %1 named twice").arg(m_identity.axes[axis].letter));
        byAxis[axis] = value;
    }
    if (!std::isfinite(speed) || speed < 0)
        return refuse(tr("move: speed must be a positive number"));
    for (auto it = byAxis.cbegin(); it != byAxis.cend(); ++it) {
        m.axisMask = static_cast<std::uint8_t>(m.axisMask | (1u << it.key()));
        m.targets.push_back(toWire(it.value(), m_identity.axes[it.key()].wireScale()));
    }
    m.speed = static_cast<std::uint32_t>(std::llround(speed * m_identity.axes[byAxis.firstKey()].wireScale()));
    send(proto::MsgType::Move, proto::encode(m), wrap(std::move(done), tr("move")));
}

void InstrumentClient::jogStep(int axis, double delta, double speed, Callback done)
{
    if (axis < 0 || axis >= m_identity.axes.size() || !std::isfinite(delta) || !std::isfinite(speed) || speed < 0) {
        const auto e = invalid(tr("jog step: bad axis, step or speed"));
        emit requestFailed(*e);
        if (done)
            done(e);
        return;
    }
    const double k = m_identity.axes[axis].wireScale();
    proto::JogStepRequest r;
    r.axis = static_cast<std::uint8_t>(axis);
    r.delta = toWire(delta, k);
    r.speed = static_cast<std::uint32_t>(std::llround(speed * k));
    send(proto::MsgType::JogStep, proto::encode(r), wrap(std::move(done), tr("jog step")));
}

void InstrumentClient::startJog(int axis, double velocity)
{
    if (axis < 0 || axis >= m_identity.axes.size() || !std::isfinite(velocity))
        return;
    m_jogs[axis] = velocity;
    refreshJogs();
    if (!m_jogTimer.isActive())
        m_jogTimer.start();
}

void InstrumentClient::stopJog(int axis)
{
    if (!m_jogs.contains(axis))
        return;
    m_jogs.remove(axis);
    if (m_jogs.isEmpty())
        m_jogTimer.stop();
    if (axis < 0 || axis >= m_identity.axes.size())
        return;
    proto::JogVelocityRequest r;
    r.axisMask = static_cast<std::uint8_t>(1u << axis);
    r.velocities = {0};
    send(proto::MsgType::JogVelocity, proto::encode(r), wrap({}, tr("jog")));
}

void InstrumentClient::stopAllJogs()
{
    const auto axes = m_jogs.keys();
    for (int a : axes)
        stopJog(a);
}

void InstrumentClient::refreshJogs()
{
    if (m_jogs.isEmpty() || m_state != LinkState::Ready)
        return;
    proto::JogVelocityRequest r;
    for (int axis = 0; axis < m_identity.axes.size(); ++axis) {
        if (!m_jogs.contains(axis))
            continue;
        r.axisMask = static_cast<std::uint8_t>(r.axisMask | (1u << axis));
        r.velocities.push_back(toWire(m_jogs[axis], m_identity.axes[axis].wireScale()));
    }
    send(proto::MsgType::JogVelocity, proto::encode(r), [this, mask = r.axisMask](const auto& e, const auto&) {
        if (!e || e->kind != RequestError::Kind::Device)
            return;
        // A refused jog (busy, E-stop, too fast) ends the hold: say so once.
        for (int axis = 0; axis < 8; ++axis)
            if (mask & (1u << axis))
                m_jogs.remove(axis);
        if (m_jogs.isEmpty())
            m_jogTimer.stop();
        RequestError err = *e;
        err.message = tr("jog refused: %1").arg(err.message);
        emit requestFailed(err);
    });
}

void InstrumentClient::stop(quint8 axisMask, Callback done)
{
    for (int a = 0; a < 8; ++a)
        if (axisMask == 0 || (axisMask & (1u << a)))
            m_jogs.remove(a);
    if (m_jogs.isEmpty())
        m_jogTimer.stop();
    send(proto::MsgType::Stop, proto::encode(proto::AxisMaskRequest{axisMask}), wrap(std::move(done), tr("stop")));
}

void InstrumentClient::estop(Callback done)
{
    m_jogs.clear();
    m_jogTimer.stop();
    send(proto::MsgType::EStop, {}, wrap(std::move(done), tr("E-stop")));
}

void InstrumentClient::reset(Callback done)
{
    send(proto::MsgType::Reset, {}, wrap(std::move(done), tr("reset")));
}

void InstrumentClient::setZero(quint8 axisMask, Callback done)
{
    auto inner = wrap(std::move(done), tr("set zero"));
    send(proto::MsgType::SetZero, proto::encode(proto::AxisMaskRequest{axisMask}), [this, inner](const auto& e, const auto& p) {
        if (!e)
            refreshLimits();
        inner(e, p);
    });
}

void InstrumentClient::setSoftLimits(int axis, double min, double max, Callback done)
{
    if (axis < 0 || axis >= m_identity.axes.size() || !std::isfinite(min) || !std::isfinite(max)) {
        const auto e = invalid(tr("soft limits: bad axis or value"));
        emit requestFailed(*e);
        if (done)
            done(e);
        return;
    }
    const double k = m_identity.axes[axis].wireScale();
    proto::SetLimitsRequest r;
    r.axis = static_cast<std::uint8_t>(axis);
    r.limits = {toWire(min, k), toWire(max, k)};
    auto inner = wrap(std::move(done), tr("soft limits"));
    send(proto::MsgType::SetLimits, proto::encode(r), [this, axis, min, max, inner](const auto& e, const auto& p) {
        if (!e && axis < m_limits.size()) {
            m_limits[axis] = {min, max};
            emit limitsChanged();
        }
        inner(e, p);
    });
}

void InstrumentClient::subscribe(const QVector<proto::ChannelRef>& channels, int rateHz,
                                 std::function<void(const std::optional<RequestError>&, const proto::SubscribeReply&)> done)
{
    proto::SubscribeRequest r;
    r.rateHz = static_cast<std::uint32_t>(std::max(0, rateHz));
    r.channels.assign(channels.begin(), channels.end());
    send(proto::MsgType::Subscribe, proto::encode(r), [this, channels, done](const auto& e, const auto& p) {
        proto::SubscribeReply reply;
        if (!e) {
            if (auto d = proto::decodeSubscribeReply(p))
                reply = *d;
            m_channels = reply.rateHz ? channels : QVector<proto::ChannelRef>{};
            m_rateHz = static_cast<int>(reply.rateHz);
            m_haveSampleIndex = false;  // a new subscription restarts the device's sample counter
        } else if (!done) {
            // A caller with its own handler (the telemetry hub falls back to the
            // stated capacity) decides whether a person needs to hear about it.
            RequestError err = *e;
            err.message = tr("telemetry: %1").arg(err.message);
            emit requestFailed(err);
        }
        if (done)
            done(e, reply);
    });
}

double InstrumentClient::toAxisUnits(const proto::ChannelRef& c, std::int32_t value) const
{
    switch (c.kind) {
    case proto::ChannelKind::Switches:
    case proto::ChannelKind::ControllerOutput:
        return value;
    case proto::ChannelKind::ContourError:
        return value / 1e6;
    default:
        if (c.axis < m_identity.axes.size())
            return value / m_identity.axes[c.axis].wireScale();
        return value;
    }
}

} // namespace dev
