#pragma once
// An in-process pair of connected transports. Bytes written at one end arrive
// at the other, paced like a UART at the chosen baud rate (8N1: ten bit times a
// byte), with optional faults so tests and benchmarks can see what a bad cable does.
#include "device/link/link_faults.h"
#include "device/link/transport.h"

#include <QElapsedTimer>
#include <QTimer>

#include <deque>

namespace dev {

class LoopbackPair : public QObject {
    Q_OBJECT
public:
    enum Side { A = 0, B = 1 };
    /// baud 0 = no pacing (bytes arrive on the next event-loop turn).
    explicit LoopbackPair(qint32 baud = 0, QObject* parent = nullptr);
    ~LoopbackPair() override;

    Transport* end(Side side);
    qint32 baud() const { return m_baud; }
    /// Wire seconds per wall-clock second: a simulator whose clock runs `scale` times
    /// faster than the wall gets a wire that carries `scale` times the bytes, so what
    /// the firmware budgets per second of its link still fits (SimulatorHost::setTimeScale).
    void setTimeScale(double scale) { m_timeScale = scale > 0 ? scale : 1.0; }
    double timeScale() const { return m_timeScale; }
    /// Faults applied to what `from` sends.
    void setFaults(Side from, const LinkFaults& faults) { m_lines[from].setFaults(faults); }
    const LinkFaults& faults(Side from) const { return m_lines[from].faults(); }
    const LinkFaultCounts& faultCounts(Side from) const { return m_lines[from].counts(); }
    /// The line goes quiet for `ms` in both directions without either port noticing
    /// (a hung adapter): everything written meanwhile is lost.
    void hang(int ms);
    bool hung() const { return m_hungUntilNs > m_clock.nsecsElapsed(); }
    /// Pulls the cable: both open ends report the link lost; opening fails until replug().
    void unplug();
    void replug() { m_unplugged = false; }
    bool unplugged() const { return m_unplugged; }
    /// Bytes that crossed the wire from `from` (after drops).
    qint64 bytesCarried(Side from) const { return m_carried[from]; }
    /// Injects raw bytes as if `from` had sent them (line noise).
    void inject(Side from, const QByteArray& bytes) { transmit(from, bytes, false); }

private:
    friend class LoopbackEnd;
    struct Pending {
        qint64 dueNs;
        int to;
        QByteArray bytes;
    };
    void transmit(int from, const QByteArray& bytes, bool applyFaults);
    void peerOpenedBy(int side);
    void deliverDue();
    void schedule();

    qint32 m_baud;
    double m_timeScale = 1.0;
    Transport* m_ends[2];
    FaultyLine m_lines[2];            ///< what each side's writes suffer
    qint64 m_hungUntilNs = 0;
    qint64 m_lastDueNs[2] = {0, 0};   ///< jitter never lets a write overtake the one before
    qint64 m_lineFreeNs[2] = {0, 0};  ///< when the wire from each side is next idle
    qint64 m_carried[2] = {0, 0};
    std::deque<Pending> m_pending;    ///< in due order per direction
    QElapsedTimer m_clock;
    QTimer m_timer;
    bool m_unplugged = false;
};

} // namespace dev
