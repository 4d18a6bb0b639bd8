#include "device/camera/sim_socket_camera.h"

#include <QLocalSocket>

#include <algorithm>
#include <chrono>

namespace dev::camera {

namespace {

namespace m = motion::msg;

/// The server says hello as soon as it accepts: a second is long, five leave room for a loaded machine.
constexpr int kSimSocketHelloMs = 5000;
/// Beyond the exposure: a 2048² frame renders in tens of ms, but captures may be queued behind others.
constexpr int kSimSocketAnswerGraceMs = 30000;
/// The live view's fastest pace, as the in-process simulated camera's.
constexpr int kSimSocketLiveMinPeriodMs = 33;

std::int64_t socketNowUs()
{
    return std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

} // namespace

SimSocketCamera::SimSocketCamera(const QString& path, QObject* parent)
    : Camera(parent), m_path(path), m_helloTimeoutMs(kSimSocketHelloMs), m_answerGraceMs(kSimSocketAnswerGraceMs)
{
    m_clock.start();
    m_deadline.setSingleShot(true);
    connect(&m_deadline, &QTimer::timeout, this, &SimSocketCamera::onDeadline);
    m_liveTimer.setSingleShot(true);
    connect(&m_liveTimer, &QTimer::timeout, this, [this] {
        if (m_live && m_open && !m_liveInFlight)
            send(0, true, std::nullopt);
    });
}

SimSocketCamera::~SimSocketCamera()
{
    if (m_socket) {
        m_socket->disconnect(this);
        m_socket->abort();
        delete m_socket;
    }
}

Capabilities SimSocketCamera::capabilities() const
{
    Capabilities c;
    c.live = true;
    c.exposure = true;
    return c;
}

void SimSocketCamera::setTimeoutsMs(int helloMs, int answerGraceMs)
{
    m_helloTimeoutMs = std::max(1, helloMs);
    m_answerGraceMs = std::max(1, answerGraceMs);
}

void SimSocketCamera::setExposureMs(double ms)
{
    if (ms > 0)
        m_exposureMs = std::min(ms, kSimWireMaxExposureMs);
}

m::Message SimSocketCamera::socketMessage(const char* id) const { return m::make(id, {m::verbatim("socket", m_path.toStdString())}); }

void SimSocketCamera::open()
{
    if (m_open) {
        emit opened();
        return;
    }
    if (m_opening)
        return;
    m_opening = true;
    m_dead.reset();
    m_reader = SimWireReader(SimWireReader::Side::Client);
    // Connected from the event loop: a failure is told after the caller has had the chance
    // to listen for it (and captures asked meanwhile wait for the hello).
    QTimer::singleShot(0, this, &SimSocketCamera::connectNow);
}

void SimSocketCamera::connectNow()
{
    if (!m_opening)
        return;
    auto* socket = new QLocalSocket(this);
    m_socket = socket;
    connect(socket, &QLocalSocket::readyRead, this, [this, socket] {
        if (socket == m_socket)
            readAnswers();
    });
    connect(socket, &QLocalSocket::errorOccurred, this, [this, socket](QLocalSocket::LocalSocketError) {
        if (socket != m_socket || m_dead)
            return;
        // Before the hello, whatever went wrong (no file, a socket no one serves, no access): no server.
        if (!m_open)
            goDead(socketMessage("camera.socket.no_server"));
        else
            goDead(socketMessage("camera.socket.lost"));
    }, Qt::QueuedConnection);
    connect(socket, &QLocalSocket::disconnected, this, [this, socket] {
        if (socket == m_socket && !m_dead)
            goDead(socketMessage("camera.socket.lost"));
    }, Qt::QueuedConnection);
    armDeadline();
    socket->connectToServer(m_path);
}

void SimSocketCamera::close()
{
    const bool was = m_open || m_opening;
    stopLive();
    dropAll(m::make("camera.closed_during_capture", {m::verbatim("source", source().toStdString())}), false);
    if (was)
        emit closed();
}

void SimSocketCamera::dropAll(const m::Message& why, bool toRequestZero)
{
    m_open = false;
    m_opening = false;
    m_liveInFlight = false;
    m_liveTimer.stop();
    m_deadline.stop();
    if (m_socket) {
        m_socket->disconnect(this);
        m_socket->abort();
        m_socket->deleteLater();
        m_socket = nullptr;
    }
    const auto asked = std::move(m_asked);
    const auto waiting = std::move(m_waiting);
    m_asked.clear();
    m_waiting.clear();
    if (toRequestZero)
        emit failed(0, m::Problem("", why));
    for (const auto& [wire, a] : asked)
        if (!a.live)
            emit failed(a.requestId, m::Problem("", why));
    for (const CaptureRequest& r : waiting)
        emit failed(r.id, m::Problem("", why));
}

void SimSocketCamera::startLive()
{
    if (!m_open && !m_opening)
        open();
    m_live = true;
    scheduleLive();
}

void SimSocketCamera::stopLive()
{
    m_live = false;
    m_liveTimer.stop();
}

void SimSocketCamera::scheduleLive()
{
    if (m_live && m_open && !m_liveInFlight && !m_liveTimer.isActive())
        m_liveTimer.start(std::max(kSimSocketLiveMinPeriodMs, static_cast<int>(m_exposureMs)));
}

void SimSocketCamera::capture(const CaptureRequest& request)
{
    if (m_dead && !m_opening) {
        emit failed(request.id, m::Problem("", *m_dead));
        return;
    }
    if (!m_open && !m_opening) {
        emit failed(request.id, m::Problem("", m::make("camera.not_open", {m::verbatim("source", source().toStdString())})));
        return;
    }
    if (!m_open) {
        m_waiting.push_back(request);
        return;
    }
    send(request.id, false, request.geometry);
}

void SimSocketCamera::send(std::uint64_t requestId, bool live, const std::optional<CameraGeometry>& geometry)
{
    SimWireCapture c;
    c.id = m_nextWireId++;
    c.exposureMs = m_exposureMs;
    c.geometry = geometry;
    Asked a;
    a.requestId = requestId;
    a.live = live;
    a.waitMs = static_cast<qint64>(m_exposureMs) + m_answerGraceMs;
    a.deadlineMs = m_clock.elapsed() + a.waitMs;
    a.sentHostUs = socketNowUs();
    m_asked.emplace(c.id, a);
    if (live)
        m_liveInFlight = true;
    const std::string bytes = encodeSimWire(c);
    m_socket->write(bytes.data(), static_cast<qint64>(bytes.size()));
    armDeadline();
}

void SimSocketCamera::readAnswers()
{
    const QByteArray bytes = m_socket->readAll();
    m_reader.feed(bytes.constData(), static_cast<std::size_t>(bytes.size()));
    while (m_socket && !m_dead) {
        SimWireMessage message;
        m::Message why;
        const auto r = m_reader.next(&message, &why);
        if (r == SimWireReader::Result::NeedMore)
            return;
        if (r == SimWireReader::Result::Broken) {
            goDead(m::make("camera.socket.garbled", {m::verbatim("socket", m_path.toStdString()), m::nested("reason", why)}));
            return;
        }
        if (auto* hello = std::get_if<SimWireHello>(&message)) {
            if (m_open)
                continue;  // said once; a second changes nothing
            m_hello = *hello;
            m_open = true;
            m_opening = false;
            armDeadline();
            emit opened();
            const auto waiting = std::move(m_waiting);
            m_waiting.clear();
            for (const CaptureRequest& req : waiting)
                if (m_open)
                    send(req.id, false, req.geometry);
            scheduleLive();
        } else if (auto* frame = std::get_if<SimWireFrame>(&message)) {
            if (!m_open) {
                goDead(m::make("camera.socket.garbled", {m::verbatim("socket", m_path.toStdString()),
                                                         m::nested("reason", m::make("camera.wire.unexpected", {m::verbatim("type", "frame")}))}));
                return;
            }
            onFrame(std::move(*frame));
        } else if (auto* error = std::get_if<SimWireError>(&message)) {
            onServerError(*error);
        }
    }
}

void SimSocketCamera::onFrame(SimWireFrame&& answer)
{
    const auto it = m_asked.find(answer.id);
    if (it == m_asked.end())
        return;  // a capture that timed out or was closed: its frame is late
    const Asked a = it->second;
    m_asked.erase(it);
    armDeadline();
    Frame f = std::move(answer.frame);
    f.startedHostUs = a.sentHostUs;
    f.sequence = ++m_sequence;
    if (a.live) {
        m_liveInFlight = false;
        if (m_live)
            emit liveFrame(f);
        scheduleLive();
    } else {
        emit captured(a.requestId, f);
    }
}

void SimSocketCamera::onServerError(const SimWireError& error)
{
    const m::Message why = m::make("camera.socket.server_error", {m::verbatim("socket", m_path.toStdString()), m::verbatim("code", error.code),
                                                                 m::verbatim("detail", error.detail)});
    const auto it = m_asked.find(error.id);
    if (error.id == 0 || it == m_asked.end()) {
        if (error.id == 0)
            goDead(why);  // about the connection: the server hangs up after it
        return;
    }
    const Asked a = it->second;
    m_asked.erase(it);
    armDeadline();
    failAsked(a, why);
}

void SimSocketCamera::failAsked(const Asked& a, const m::Message& why)
{
    if (a.live) {
        // Said once; the live view stops rather than repeat it thirty times a second.
        m_liveInFlight = false;
        m_live = false;
        emit failed(0, m::Problem("", why));
    } else {
        emit failed(a.requestId, m::Problem("", why));
    }
}

void SimSocketCamera::goDead(const m::Message& why)
{
    m_dead = why;
    const bool wasOpen = m_open;
    // The live view and the one who opened hear it once, on request 0; each capture on its own id.
    dropAll(why, true);
    if (wasOpen)
        emit closed();
}

void SimSocketCamera::armDeadline()
{
    qint64 earliest = -1;
    if (m_opening && !m_open)
        earliest = m_clock.elapsed() + m_helloTimeoutMs;
    for (const auto& [wire, a] : m_asked)
        earliest = earliest < 0 ? a.deadlineMs : std::min(earliest, a.deadlineMs);
    // An hello deadline is set once, when connecting; re-arming must not push it back.
    if (m_opening && !m_open && m_deadline.isActive())
        return;
    if (earliest < 0) {
        m_deadline.stop();
        return;
    }
    m_deadline.start(static_cast<int>(std::max<qint64>(0, earliest - m_clock.elapsed())));
}

void SimSocketCamera::onDeadline()
{
    const qint64 now = m_clock.elapsed();
    if (m_opening && !m_open) {
        goDead(m::make("camera.socket.timeout", {m::verbatim("socket", m_path.toStdString()),
                                                 m::real("seconds", m_helloTimeoutMs / 1000.0, m::Unit::S)}));
        return;
    }
    std::vector<std::pair<std::uint64_t, Asked>> late;
    for (auto it = m_asked.begin(); it != m_asked.end();) {
        if (it->second.deadlineMs <= now) {
            late.emplace_back(*it);
            it = m_asked.erase(it);
        } else {
            ++it;
        }
    }
    armDeadline();
    for (const auto& [wire, a] : late) {
        const auto why = m::make("camera.socket.timeout", {m::verbatim("socket", m_path.toStdString()),
                                                           m::real("seconds", static_cast<double>(a.waitMs) / 1000.0, m::Unit::S)});
        failAsked(a, why);
    }
}

} // namespace dev::camera
