#pragma once
// An in-process pair of connected transports. Bytes written at one end arrive
// at the other, paced like a UART at the chosen baud rate (8N1: ten bit times a
// byte), with optional faults so tests and benchmarks can see what a bad cable does.
#include "device/link/transport.h"

#include <QElapsedTimer>
#include <QTimer>

#include <deque>
#include <random>

namespace dev {

struct LinkFaults {
    double dropChunkProbability = 0;   ///< a whole write vanishes
    double corruptByteProbability = 0; ///< each byte has one bit flipped
    int extraDelayMs = 0;              ///< latency added to every write
    std::uint64_t seed = 1;
};

class LoopbackPair : public QObject {
    Q_OBJECT
public:
    enum Side { A = 0, B = 1 };
    /// baud 0 = no pacing (bytes arrive on the next event-loop turn).
    explicit LoopbackPair(qint32 baud = 0, QObject* parent = nullptr);
    ~LoopbackPair() override;

    Transport* end(Side side);
    qint32 baud() const { return m_baud; }
    /// Faults applied to what `from` sends.
    void setFaults(Side from, const LinkFaults& faults);
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
    void deliverDue();
    void schedule();

    qint32 m_baud;
    Transport* m_ends[2];
    LinkFaults m_faults[2];
    std::mt19937_64 m_rng[2];
    qint64 m_lineFreeNs[2] = {0, 0};  ///< when the wire from each side is next idle
    qint64 m_carried[2] = {0, 0};
    std::deque<Pending> m_pending;    ///< in due order per direction
    QElapsedTimer m_clock;
    QTimer m_timer;
    bool m_unplugged = false;
};

} // namespace dev
