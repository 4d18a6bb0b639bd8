#include "api_client.h"

#include <QCoreApplication>
#include <QFile>
#include <QLocalSocket>
#include <QTimer>

#include <sys/socket.h>

namespace app::api {

namespace {
[[maybe_unused]] QString tr(const char* text) { return QCoreApplication::translate("app::api", text); }

QString programOf(qint64 pid)
{
    QFile comm(QStringLiteral("/proc/%1/comm").arg(pid));
    if (!comm.open(QIODevice::ReadOnly))
        return {};
    return QString::fromUtf8(comm.readAll()).trimmed();
}
} // namespace

LocalChannel::LocalChannel(QLocalSocket* socket, QObject* parent) : Channel(parent), m_socket(socket)
{
    m_socket->setParent(this);
    // Who is at the other end: the kernel says (SO_PEERCRED), whatever the client claims.
    ucred cred{};
    socklen_t len = sizeof(cred);
    if (::getsockopt(static_cast<int>(m_socket->socketDescriptor()), SOL_SOCKET, SO_PEERCRED, &cred, &len) == 0) {
        m_pid = cred.pid;
        m_uid = cred.uid;
    }
    connect(m_socket, &QLocalSocket::readyRead, this, &LocalChannel::poll);
    connect(m_socket, &QLocalSocket::disconnected, this, &Channel::closed);
}

void LocalChannel::poll()
{
    if (m_socket->bytesAvailable() > 0)
        emit received(m_socket->readAll(), false);
}

void LocalChannel::write(const QByteArray& line) { m_socket->write(line); }

qint64 LocalChannel::pendingBytes() const { return m_socket->bytesToWrite(); }

void LocalChannel::close()
{
    m_socket->abort();
}

ApiClient::ApiClient(quint64 id, Channel* channel, QObject* parent)
    : QObject(parent), m_id(id), m_channel(channel), m_since(QDateTime::currentDateTime())
{
    channel->setParent(this);
    m_pid = channel->peerPid();
    const QString program = m_pid > 0 ? programOf(m_pid) : QString();
    m_name = m_pid > 0 ? (program.isEmpty() ? tr("pid %1").arg(m_pid) : tr("%1 (pid %2)").arg(program).arg(m_pid))
                       : tr("client %1").arg(id);
    connect(channel, &Channel::received, this, &ApiClient::onReceived);
    connect(channel, &Channel::closed, this, [this] {
        if (!m_open)
            return;
        m_open = false;
        m_queue.clear();
        emit closed(tr("connection closed"));
    });
}

ApiClient::~ApiClient() = default;

void ApiClient::setName(const QString& name)
{
    const QString clean = name.simplified().left(80);
    if (clean.isEmpty() || clean == m_name)
        return;
    m_name = m_pid > 0 ? tr("%1 (pid %2)").arg(clean).arg(m_pid) : clean;
    emit nameChanged();
}

bool ApiClient::canTakeUpdates() const
{
    return m_open && m_channel && m_channel->pendingBytes() <= kUpdateBackpressureBytes;
}

bool ApiClient::send(const QByteArray& line, Priority priority)
{
    if (!m_open || !m_channel)
        return false;
    if (priority == Priority::Update && !canTakeUpdates())
        return false;
    if (m_channel->pendingBytes() + line.size() > kMaxPendingBytes) {
        disconnectBecause(tr("it stopped reading (more than %1 MiB of answers waiting)").arg(kMaxPendingBytes / (1024 * 1024)));
        return false;
    }
    m_channel->write(line);
    return true;
}

void ApiClient::disconnectBecause(const QString& why)
{
    if (!m_open)
        return;
    m_open = false;
    m_queue.clear();
    emit closed(why);
    if (m_channel)
        m_channel->close();
}

void ApiClient::drain()
{
    if (m_channel)
        m_channel->poll();
    // What is queued is handled now, in order: a heartbeat behind a few calls counts.
    while (m_open && !m_queue.empty()) {
        const QByteArray line = m_queue.front();
        m_queue.pop_front();
        emit lineReady(line);
    }
}

void ApiClient::onReceived(const QByteArray& bytes, bool framed)
{
    if (!m_open)
        return;
    auto take = [this](const QByteArray& line) {
        if (!m_open)
            return;
        if (static_cast<int>(m_queue.size()) >= kMaxQueuedLines) {
            disconnectBecause(tr("it flooded the server (more than %1 requests waiting)").arg(kMaxQueuedLines));
            return;
        }
        m_queue.push_back(line);
    };
    if (framed) {
        if (bytes.size() > kMaxLineBytes)
            emit overlongLine();
        else
            take(bytes);
    } else {
        m_splitter.feed(bytes, take, [this] { emit overlongLine(); });
    }
    scheduleHandling();
}

void ApiClient::scheduleHandling()
{
    if (m_handlingScheduled || m_queue.empty())
        return;
    m_handlingScheduled = true;
    QTimer::singleShot(0, this, &ApiClient::handleQueued);
}

void ApiClient::handleQueued()
{
    m_handlingScheduled = false;
    for (int n = 0; n < kLinesPerTurn && m_open && !m_queue.empty(); ++n) {
        const QByteArray line = m_queue.front();
        m_queue.pop_front();
        emit lineReady(line);
    }
    scheduleHandling();
}

} // namespace app::api
