#include "control_lease.h"

#include <QUuid>

namespace app::api {

QString ControlLease::reasonKey(EndReason r)
{
    switch (r) {
    case EndReason::Released: return QStringLiteral("released");
    case EndReason::TakenBack: return QStringLiteral("taken_back");
    case EndReason::ConnectionClosed: return QStringLiteral("connection_closed");
    case EndReason::HeartbeatLost: return QStringLiteral("heartbeat_lost");
    case EndReason::CallEnded: return QStringLiteral("call_ended");
    }
    return QStringLiteral("released");
}

ControlLease::ControlLease(QObject* parent) : QObject(parent)
{
    m_heartbeat.setSingleShot(true);
    m_heartbeat.setTimerType(Qt::PreciseTimer);
    m_heartbeat.setInterval(kHeartbeatTimeoutMs);
    connect(&m_heartbeat, &QTimer::timeout, this, &ControlLease::onTimeout);
}

bool ControlLease::accepts(quint64 clientId, const QString& token) const
{
    return m_holder && m_holder->clientId == clientId && !token.isEmpty() && m_holder->token == token;
}

std::optional<QString> ControlLease::acquire(quint64 clientId, const QString& clientName, bool forOneCall)
{
    if (m_holder) {
        if (m_holder->clientId != clientId)
            return std::nullopt;
        if (m_holder->forOneCall && !forOneCall) {  // a held call's lease becomes a standing one
            m_holder->forOneCall = false;
            emit changed();
        }
        touch(clientId);
        return m_holder->token;
    }
    Holder h;
    h.clientId = clientId;
    h.clientName = clientName;
    h.token = QUuid::createUuid().toString(QUuid::WithoutBraces);
    h.since = QDateTime::currentDateTime();
    h.forOneCall = forOneCall;
    m_holder = h;
    if (!forOneCall)
        m_heartbeat.start();
    emit changed();
    return h.token;
}

bool ControlLease::release(quint64 clientId, const QString& token)
{
    if (!accepts(clientId, token))
        return false;
    end(EndReason::Released);
    return true;
}

bool ControlLease::touch(quint64 clientId)
{
    if (!isHeldBy(clientId))
        return false;
    if (!m_holder->forOneCall)
        m_heartbeat.start();
    return true;
}

void ControlLease::takeBack()
{
    if (m_holder)
        end(EndReason::TakenBack);
}

void ControlLease::clientGone(quint64 clientId)
{
    if (isHeldBy(clientId))
        end(EndReason::ConnectionClosed);
}

void ControlLease::endOneCallLease(quint64 clientId)
{
    if (isHeldBy(clientId) && m_holder->forOneCall)
        end(EndReason::CallEnded);
}

void ControlLease::onTimeout()
{
    if (!m_holder || m_holder->forOneCall)
        return;
    const quint64 id = m_holder->clientId;
    if (m_beforeExpiry)
        m_beforeExpiry(id);  // may touch() the lease, restarting the timer
    if (!m_holder || m_holder->clientId != id || m_heartbeat.isActive())
        return;
    // Waiting for its own call: alive. The timer stays off; callAnswered() restarts it.
    if (m_callInProgress && m_callInProgress(id))
        return;
    end(EndReason::HeartbeatLost);
}

void ControlLease::end(EndReason reason)
{
    m_heartbeat.stop();
    const Holder was = *m_holder;
    m_holder.reset();
    emit ended(was, reason);
    emit changed();
}

} // namespace app::api
