#include "pty_transport.h"

#include <QTimer>

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <termios.h>
#include <unistd.h>

namespace app::sim {
namespace {
// A host that stops reading must not make the simulator grow without bound:
// beyond this, the oldest unsent bytes are dropped (the host sees a sample gap).
constexpr qsizetype kMaxPendingBytes = 1 << 20;
}

PtyTransport::PtyTransport(QObject* parent) : dev::Transport(parent) {}

PtyTransport::~PtyTransport() { close(); }

bool PtyTransport::create()
{
    m_master = ::posix_openpt(O_RDWR | O_NOCTTY);
    if (m_master < 0 || ::grantpt(m_master) != 0 || ::unlockpt(m_master) != 0) {
        m_error = tr("cannot create a pseudo-terminal: %1").arg(QString::fromLocal8Bit(std::strerror(errno)));
        return false;
    }
    const char* name = ::ptsname(m_master);
    if (!name) {
        m_error = tr("cannot name the pseudo-terminal: %1").arg(QString::fromLocal8Bit(std::strerror(errno)));
        return false;
    }
    m_slavePath = QString::fromLocal8Bit(name);
    // Raw mode on the line so binary frames pass untouched (no echo, no CR/LF mapping).
    m_slaveKeepAlive = ::open(name, O_RDWR | O_NOCTTY);
    if (m_slaveKeepAlive >= 0) {
        termios t{};
        if (::tcgetattr(m_slaveKeepAlive, &t) == 0) {
            ::cfmakeraw(&t);
            ::tcsetattr(m_slaveKeepAlive, TCSANOW, &t);
        }
    }
    ::fcntl(m_master, F_SETFL, ::fcntl(m_master, F_GETFL) | O_NONBLOCK);
    m_readNotifier = new QSocketNotifier(m_master, QSocketNotifier::Read, this);
    connect(m_readNotifier, &QSocketNotifier::activated, this, &PtyTransport::onReadable);
    m_writeNotifier = new QSocketNotifier(m_master, QSocketNotifier::Write, this);
    m_writeNotifier->setEnabled(false);
    connect(m_writeNotifier, &QSocketNotifier::activated, this, &PtyTransport::flushPending);
    return true;
}

void PtyTransport::open()
{
    QTimer::singleShot(0, this, [this] {
        if (m_master >= 0)
            emit opened();
        else
            emit failed(motion::msg::make("link.cannot_open", {motion::msg::verbatim("port", "pty"), motion::msg::verbatim("detail", m_error.toStdString())}));
    });
}

void PtyTransport::close()
{
    delete m_readNotifier;
    m_readNotifier = nullptr;
    delete m_writeNotifier;
    m_writeNotifier = nullptr;
    if (m_master >= 0)
        ::close(m_master);
    if (m_slaveKeepAlive >= 0)
        ::close(m_slaveKeepAlive);
    m_master = m_slaveKeepAlive = -1;
}

void PtyTransport::onReadable()
{
    char buf[4096];
    for (;;) {
        const ssize_t n = ::read(m_master, buf, sizeof buf);
        if (n > 0) {
            emit bytesReceived(QByteArray(buf, static_cast<qsizetype>(n)));
            continue;
        }
        break;  // EAGAIN, or EIO while no host has the slave open: nothing to read
    }
}

void PtyTransport::write(const QByteArray& bytes)
{
    if (m_master < 0)
        return;
    m_pending += bytes;
    if (m_pending.size() > kMaxPendingBytes)
        m_pending.remove(0, m_pending.size() - kMaxPendingBytes);
    flushPending();
}

void PtyTransport::flushPending()
{
    while (!m_pending.isEmpty()) {
        const ssize_t n = ::write(m_master, m_pending.constData(), static_cast<size_t>(m_pending.size()));
        if (n <= 0)
            break;
        m_pending.remove(0, static_cast<qsizetype>(n));
    }
    if (m_writeNotifier)
        m_writeNotifier->setEnabled(!m_pending.isEmpty());
}

} // namespace app::sim
