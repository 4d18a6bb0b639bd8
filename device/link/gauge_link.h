#pragma once
// An external gauge on a serial port of its own (or any dev::Transport: the
// in-process simulated gauge, a pty): asks for one reading at a time in the
// dialect of gauge_dialect.h and hands back the value in mm or a message that
// names the port and what the gauge sent.
//
// Timing: an answer must be complete within timeoutMs of the request (wall clock:
// the gauge is a real instrument, not the simulator's clock); an unanswered request
// is sent once more before the read fails with gauge.no_answer. Lines that arrive
// when nothing was asked (a gauge with a data button, a reply that came too late)
// are dropped, so a late answer is never taken for the next reading.
#include "device/link/transport.h"
#include "motion/message.h"

#include <QObject>
#include <QPointer>
#include <QTimer>

#include <functional>
#include <optional>

namespace dev {

class GaugeLink : public QObject {
    Q_OBJECT
public:
    /// `transport` is not owned; `port` names it in messages ("/dev/ttyUSB1").
    GaugeLink(Transport* transport, QString port, QObject* parent = nullptr);
    ~GaugeLink() override;

    void setTimeoutMs(int ms) { m_timeoutMs = ms; }
    int timeoutMs() const { return m_timeoutMs; }
    /// Requests sent before a read gives up (the first and its retries).
    void setAttempts(int n) { m_attempts = n < 1 ? 1 : n; }
    QString port() const { return m_port; }

    using OpenDone = std::function<void(const motion::msg::Message& problem)>;  ///< empty problem: open
    /// Opens the transport (gauge.port_failed {port, detail} when it cannot be).
    void open(OpenDone done);
    void close();
    bool isOpen() const;

    using ReadDone = std::function<void(std::optional<double> valueMm, const motion::msg::Message& problem)>;
    /// One reading. Problems: gauge.not_a_reading, gauge.unknown_unit (what it sent),
    /// gauge.no_answer {port, timeout}, gauge.link_lost {port, detail}, gauge.busy (a read
    /// is already waiting), gauge.not_open. Every read is answered exactly once.
    void read(ReadDone done);
    /// Drops a read in progress without calling it back.
    void cancel();

private:
    void onBytes(const QByteArray& bytes);
    void sendRequest();
    void finish(std::optional<double> value, const motion::msg::Message& problem);

    QPointer<Transport> m_transport;
    QString m_port;
    int m_timeoutMs = 1000;
    int m_attempts = 2;
    int m_attemptsLeft = 0;
    QTimer m_timer;
    QByteArray m_line;
    bool m_overlong = false;
    ReadDone m_pending;
    OpenDone m_opening;
    QList<QMetaObject::Connection> m_connections;
};

} // namespace dev
