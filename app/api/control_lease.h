#pragma once
// Who is in control of the bench (docs/api.md, "Control"): at most one client of the
// API at a time holds the lease; the operator at the GUI can always take it back.
//
//  - control.acquire gives the lease to a client when nobody holds it (and no job the
//    operator started is running); the token it returns goes with every call that moves,
//    pumps, changes gains or starts a job.
//  - It ends when the client releases it, when the operator takes it back, when the
//    client's connection closes, or when neither a heartbeat nor a call has come from
//    the holder for kHeartbeatTimeoutMs. A call of the holder's still in progress on its
//    open connection is proof of life too (a script that homes for seconds without a
//    heartbeat thread keeps its lease): the silence is counted from its answer. Then
//    whatever keeps velocity motion going for the holder stops (lostControl
//    listeners): as when a jog key is released.
//  - E-stop and stop never need it.
#include <QDateTime>
#include <QObject>
#include <QString>
#include <QTimer>

#include <functional>
#include <optional>

namespace app::api {

class ControlLease : public QObject {
    Q_OBJECT
public:
    /// The longest silence a holder may keep (no heartbeat, no call) before the lease ends.
    static constexpr int kHeartbeatTimeoutMs = 500;

    enum class EndReason { Released, TakenBack, ConnectionClosed, HeartbeatLost, CallEnded };
    static QString reasonKey(EndReason r);  ///< "released", "taken_back", … (in notifications and the log)

    struct Holder {
        quint64 clientId = 0;
        QString clientName;
        QString token;
        QDateTime since;
        bool forOneCall = false;  ///< taken for a single cli.run (benchpilot-cli --attach): no heartbeats needed
    };

    explicit ControlLease(QObject* parent = nullptr);

    const std::optional<Holder>& holder() const { return m_holder; }
    bool isHeldBy(quint64 clientId) const { return m_holder && m_holder->clientId == clientId; }
    /// The client holds it and `token` is its token.
    bool accepts(quint64 clientId, const QString& token) const;

    /// Gives the lease to the client; nullopt when someone else holds it. The holder
    /// asking again gets its own token back (and the heartbeat restarts).
    std::optional<QString> acquire(quint64 clientId, const QString& clientName, bool forOneCall = false);
    bool release(quint64 clientId, const QString& token);
    /// A heartbeat or any call from the holder; false if it does not hold the lease.
    bool touch(quint64 clientId);
    /// The operator's Take back.
    void takeBack();
    void clientGone(quint64 clientId);
    void endOneCallLease(quint64 clientId);

    /// Called just before a heartbeat timeout ends the lease: lets the server read what
    /// the holder already sent (a busy event loop must not cost a live client its lease).
    void setBeforeExpiry(std::function<void(quint64 clientId)> drain) { m_beforeExpiry = std::move(drain); }
    /// Whether the holder waits for a call of its own that is still running: while it
    /// does, its silence does not end the lease.
    void setCallInProgress(std::function<bool(quint64 clientId)> waiting) { m_callInProgress = std::move(waiting); }
    /// A call of the client's was answered: the holder's silence is counted from now.
    void callAnswered(quint64 clientId) { touch(clientId); }

signals:
    void changed();
    /// After the lease ended; `holder` is the one it was.
    void ended(const app::api::ControlLease::Holder& holder, app::api::ControlLease::EndReason reason);

private:
    void end(EndReason reason);
    void onTimeout();

    std::optional<Holder> m_holder;
    QTimer m_heartbeat;
    std::function<void(quint64)> m_beforeExpiry;
    std::function<bool(quint64)> m_callInProgress;
};

} // namespace app::api
