#pragma once
// One connected client of the scripting API: its transport (the Unix socket, or a
// WebSocket), the lines it sent and not yet handled, what is written back to it, and
// who it says it is.
//
// Overflow policies (docs/api.md, "Bad input and slow clients"):
//  - A line over 1 MiB is answered with −32600 and skipped to its newline.
//  - At most kMaxQueuedLines requests wait to be handled; a client that sends more
//    without waiting for answers is disconnected. Each event-loop turn handles at most
//    kLinesPerTurn of them, so a flood never holds up the GUI.
//  - Subscription updates are not written while more than kUpdateBackpressureBytes wait
//    to go out (the subscription keeps only the newest values and counts what it folded
//    or dropped); answers are always written, and a client with more than kMaxPendingBytes
//    unread is disconnected: it has stopped reading.
#include <QDateTime>
#include <QObject>
#include <QPointer>
#include <QString>

#include <deque>

#include "json_rpc.h"

class QLocalSocket;

namespace app::api {

/// A transport carrying lines: the Unix socket (a byte stream, split at newlines) or
/// a WebSocket (each text message is one line).
class Channel : public QObject {
    Q_OBJECT
public:
    using QObject::QObject;
    virtual void write(const QByteArray& line) = 0;
    virtual qint64 pendingBytes() const = 0;  ///< written and not yet taken by the peer
    virtual void close() = 0;
    virtual QString transport() const = 0;    ///< "unix", "websocket"
    virtual qint64 peerPid() const { return -1; }
    /// Reads what has arrived now, without waiting for the event loop (see ControlLease).
    virtual void poll() {}

signals:
    /// Bytes of the stream (`framed` false) or one whole message (`framed` true).
    void received(const QByteArray& bytes, bool framed);
    void closed();
};

class LocalChannel final : public Channel {
    Q_OBJECT
public:
    explicit LocalChannel(QLocalSocket* socket, QObject* parent = nullptr);  ///< takes the socket
    void write(const QByteArray& line) override;
    qint64 pendingBytes() const override;
    void close() override;
    QString transport() const override { return QStringLiteral("unix"); }
    qint64 peerPid() const override { return m_pid; }
    qint64 peerUid() const { return m_uid; }
    void poll() override;

private:
    QLocalSocket* m_socket;
    qint64 m_pid = -1;
    qint64 m_uid = -1;
};

class ApiClient : public QObject {
    Q_OBJECT
public:
    static constexpr int kMaxQueuedLines = 256;
    static constexpr int kLinesPerTurn = 32;
    static constexpr qint64 kUpdateBackpressureBytes = 256 * 1024;
    static constexpr qint64 kMaxPendingBytes = 8 * 1024 * 1024;

    enum class Priority { Answer, Update };

    ApiClient(quint64 id, Channel* channel, QObject* parent = nullptr);  ///< takes the channel
    ~ApiClient() override;

    quint64 id() const { return m_id; }
    /// The name it gave (client.hello, control.acquire) or "pid N (program)".
    QString name() const { return m_name; }
    void setName(const QString& name);
    qint64 pid() const { return m_pid; }
    QString cwd() const { return m_cwd; }
    void setCwd(const QString& cwd) { m_cwd = cwd; }
    QDateTime connectedAt() const { return m_since; }
    QString transport() const { return m_channel ? m_channel->transport() : QString(); }
    bool isOpen() const { return m_open; }

    /// Writes one line; an Update is not written (false) while the client is behind.
    bool send(const QByteArray& line, Priority priority = Priority::Answer);
    bool canTakeUpdates() const;
    /// Closes the connection, saying why on stderr-like channels (the log).
    void disconnectBecause(const QString& why);
    /// Reads and handles what the peer already sent (the lease's last look before expiry).
    void drain();

    int callsInFlight() const { return m_callsInFlight; }
    void callStarted() { ++m_callsInFlight; }
    void callEnded() { --m_callsInFlight; }

signals:
    /// One request line to handle (in order, at most kLinesPerTurn per event-loop turn).
    void lineReady(const QByteArray& line);
    /// A line too long: answer it with an error.
    void overlongLine();
    void closed(const QString& why);
    void nameChanged();

private:
    void onReceived(const QByteArray& bytes, bool framed);
    void handleQueued();
    void scheduleHandling();

    quint64 m_id;
    QPointer<Channel> m_channel;
    LineSplitter m_splitter;
    std::deque<QByteArray> m_queue;
    bool m_handlingScheduled = false;
    bool m_open = true;
    QString m_name;
    qint64 m_pid = -1;
    QString m_cwd;
    QDateTime m_since;
    int m_callsInFlight = 0;
};

} // namespace app::api
