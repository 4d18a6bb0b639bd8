#include "device/camera/sim_camera_server.h"

#include <QFile>
#include <QLocalServer>
#include <QLocalSocket>
#include <QTimer>

#include <chrono>
#include <cmath>

#include <sys/stat.h>
#include <unistd.h>

namespace dev::camera {

namespace {

namespace m = motion::msg;

/// How long a socket found at the path has to answer before it is taken for one left behind.
constexpr int kSimServerProbeMs = 300;

std::int64_t serverNowUs()
{
    return std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

SimWireError wireError(std::uint64_t id, const char* code, std::string detail)
{
    SimWireError e;
    e.id = id;
    e.code = code;
    e.detail = std::move(detail);
    return e;
}

} // namespace

SimCameraServer::SimCameraServer(WorkPointSource workPoint, const SimCameraSettings& settings, QObject* parent)
    : QObject(parent), m_workPoint(std::move(workPoint)), m_settings(settings)
{
    m_pool.setMaxThreadCount(1);
    // The specimen's tables take a moment: built on the worker before the first render.
    auto promise = std::make_shared<std::promise<std::shared_ptr<const Specimen>>>();
    m_specimen = promise->get_future().share();
    const SimCameraSettings s = m_settings;
    m_pool.start([promise, s] { promise->set_value(std::make_shared<const Specimen>(s.specimen, s.seed, s.blurUm)); });
}

SimCameraServer::~SimCameraServer()
{
    m_pool.waitForDone();
    close();
}

bool SimCameraServer::listen(const QString& path, motion::msg::Message* error)
{
    close();
    const QByteArray native = QFile::encodeName(path);
    if (native.isEmpty() || native.size() > kMaxPathBytes) {
        *error = m::make("camera.socket.path_too_long", {m::verbatim("socket", path.toStdString()), m::integer("max", kMaxPathBytes, m::Unit::Byte)});
        return false;
    }
    struct stat st {};
    if (::lstat(native.constData(), &st) == 0) {
        if (!S_ISSOCK(st.st_mode)) {
            *error = m::make("camera.socket.not_a_socket", {m::verbatim("socket", path.toStdString())});
            return false;
        }
        QLocalSocket probe;
        probe.connectToServer(path);
        if (probe.waitForConnected(kSimServerProbeMs)) {
            *error = m::make("camera.socket.in_use", {m::verbatim("socket", path.toStdString())});
            return false;
        }
        ::unlink(native.constData());  // left by a simulator that died
    }
    auto* server = new QLocalServer(this);
    server->setSocketOptions(QLocalServer::UserAccessOption);
    if (!server->listen(path)) {
        *error = m::make("camera.socket.cannot_listen", {m::verbatim("socket", path.toStdString()), m::verbatim("detail", server->errorString().toStdString())});
        delete server;
        return false;
    }
    m_server = server;
    m_path = path;
    connect(m_server, &QLocalServer::newConnection, this, &SimCameraServer::accept);
    return true;
}

void SimCameraServer::close()
{
    for (auto& [socket, client] : m_clients) {
        socket->disconnect(this);
        socket->abort();
        socket->deleteLater();
    }
    m_clients.clear();
    if (!m_server)
        return;
    m_server->close();
    delete m_server;
    m_server = nullptr;
    // Qt removes its socket file on close; a file that is still there and still a socket is ours.
    struct stat st {};
    const QByteArray native = QFile::encodeName(m_path);
    if (::lstat(native.constData(), &st) == 0 && S_ISSOCK(st.st_mode))
        ::unlink(native.constData());
}

void SimCameraServer::accept()
{
    while (QLocalSocket* socket = m_server->nextPendingConnection()) {
        if (static_cast<int>(m_clients.size()) >= kMaxClients) {
            const std::string bytes = encodeSimWire(wireError(0, "busy", "too many cameras connected"));
            socket->write(bytes.data(), static_cast<qint64>(bytes.size()));
            socket->disconnectFromServer();
            connect(socket, &QLocalSocket::disconnected, socket, &QObject::deleteLater);
            continue;
        }
        auto client = std::make_unique<Client>();
        client->socket = socket;
        m_clients.emplace(socket, std::move(client));
        connect(socket, &QLocalSocket::readyRead, this, [this, socket] { read(socket); });
        connect(socket, &QLocalSocket::disconnected, this, [this, socket] { drop(socket); });
        SimWireHello hello;
        hello.specimen = specimenName(m_settings.specimen);
        hello.seed = m_settings.seed;
        hello.geometry = m_settings.geometry;
        send(socket, encodeSimWire(hello), false);
    }
}

void SimCameraServer::drop(QLocalSocket* socket)
{
    const auto it = m_clients.find(socket);
    if (it == m_clients.end())
        return;
    m_clients.erase(it);
    socket->disconnect(this);
    socket->deleteLater();
}

void SimCameraServer::read(QLocalSocket* socket)
{
    const auto it = m_clients.find(socket);
    if (it == m_clients.end())
        return;
    Client& c = *it->second;
    const QByteArray bytes = socket->readAll();
    if (c.reader.broken())
        return;  // hanging up already
    c.reader.feed(bytes.constData(), static_cast<std::size_t>(bytes.size()));
    for (;;) {
        SimWireMessage message;
        motion::msg::Message why;
        const auto r = c.reader.next(&message, &why);
        if (r == SimWireReader::Result::NeedMore)
            return;
        if (r == SimWireReader::Result::Broken) {
            // Nothing after this can be read in step: say why and hang up.
            send(socket, encodeSimWire(wireError(0, "bad_request", m::debugString(why))), false);
            socket->disconnectFromServer();
            return;
        }
        const auto* capture = std::get_if<SimWireCapture>(&message);
        if (!capture)
            continue;  // the reader's server side gives captures only
        if (c.inFlight >= kMaxInFlight) {
            send(socket, encodeSimWire(wireError(capture->id, "busy", "more than 4 captures asked at once")), false);
            continue;
        }
        // The exposure starts now: the work point is where the stage is at this moment.
        const auto at = m_workPoint ? m_workPoint() : std::nullopt;
        if (!at) {
            send(socket, encodeSimWire(wireError(capture->id, "no_stage", "the simulator has no stage to look at")), false);
            continue;
        }
        ++c.inFlight;
        render(socket, *capture, *at);
    }
}

void SimCameraServer::render(QLocalSocket* socket, const SimWireCapture& capture, const WorkPoint& at)
{
    const std::int64_t startedUs = serverNowUs();
    const auto specimen = m_specimen;
    const SimOptics optics = m_settings.optics;
    const CameraGeometry geometry = capture.geometry.value_or(m_settings.geometry);
    const std::uint64_t seed = m_settings.seed;
    const SimTrueGeometry trueGeometry = m_settings.trueGeometry;
    const std::uint64_t sequence = ++m_sequence;
    const double exposureMs = capture.exposureMs;
    const std::uint64_t id = capture.id;
    QPointer<QLocalSocket> to(socket);
    m_pool.start([this, specimen, optics, geometry, trueGeometry, at, exposureMs, seed, sequence, startedUs, id, to] {
        SimWireFrame answer;
        answer.id = id;
        answer.frame = renderSimFrame(*specimen.get(), trueGeometryOf(geometry, trueGeometry), optics, at.xMm, at.yMm, exposureMs, seed);
        answer.frame.pixelUm = geometry.pixelUm;  // what it was asked to be, as a real camera says
        answer.frame.deviceTimeUs = at.deviceTimeUs;
        answer.frame.sequence = sequence;
        answer.trueXMm = at.xMm;
        answer.trueYMm = at.yMm;
        auto bytes = std::make_shared<std::string>(encodeSimWire(answer));
        // Back on the server's thread; the destructor waits for this task, and a queued call
        // to a deleted object is dropped with it.
        QMetaObject::invokeMethod(this, [this, bytes, to, exposureMs, startedUs] {
            const auto leftMs = static_cast<int>(std::ceil(exposureMs - static_cast<double>(serverNowUs() - startedUs) / 1000.0));
            auto deliver = [this, bytes, to] {
                if (to)
                    send(to, *bytes, true);
            };
            if (leftMs > 0)
                QTimer::singleShot(leftMs, Qt::PreciseTimer, this, deliver);
            else
                deliver();
        }, Qt::QueuedConnection);
    });
}

void SimCameraServer::send(QLocalSocket* socket, const std::string& bytes, bool answersCapture)
{
    const auto it = m_clients.find(socket);
    if (it == m_clients.end())
        return;  // gone while its frame was rendered
    if (answersCapture)
        --it->second->inFlight;
    socket->write(bytes.data(), static_cast<qint64>(bytes.size()));
}

} // namespace dev::camera
