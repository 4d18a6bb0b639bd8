#pragma once
// An in-process pair of connected transports. Bytes written at one end arrive
// at the other, paced like a UART at the chosen baud rate (8N1: ten bit times a
// byte), with optional faults so tests and benchmarks can see what a bad cable does.
#include "device/link/transport.h"

#include <QElapsedTimer>
#include <QTimer>

#include <deque>
#include <functional>
#include <random>

namespace dev {

/// What a bad cable does to the bytes one side sends. Every figure is a probability per
/// write (chunk) or per byte; all draws come from one generator seeded with `seed`, so a
/// run is repeatable. Bytes are never reordered: a UART does not reorder.
struct LinkFaults {
    double dropChunkProbability = 0;     ///< a whole write vanishes
    double corruptByteProbability = 0;   ///< each byte has one bit flipped
    double dropByteProbability = 0;      ///< each byte vanishes (an overrun)
    double duplicateByteProbability = 0; ///< each byte arrives twice
    double duplicateChunkProbability = 0;///< a whole write arrives twice, back to back
    int extraDelayMs = 0;                ///< latency added to every write
    int jitterMs = 0;                    ///< and up to this much more, drawn per write (order kept)
    /// Applied to every write before the faults above (tests that lose one kind of frame).
    std::function<QByteArray(const QByteArray&)> filter;
    std::uint64_t seed = 1;

    bool any() const
    {
        return dropChunkProbability > 0 || corruptByteProbability > 0 || dropByteProbability > 0
            || duplicateByteProbability > 0 || duplicateChunkProbability > 0 || extraDelayMs > 0 || jitterMs > 0 || filter;
    }
    /// The same rate of each byte fault (corrupted, dropped, duplicated), as the hostile
    /// campaign uses: `rate` = 0.01 gives 1 % of bytes damaged one way or another.
    static LinkFaults bytes(double rate, std::uint64_t seed)
    {
        LinkFaults f;
        f.corruptByteProbability = rate / 3;
        f.dropByteProbability = rate / 3;
        f.duplicateByteProbability = rate / 3;
        f.seed = seed;
        return f;
    }
};

/// What the line has done so far, per direction.
struct LinkFaultCounts {
    qint64 droppedChunks = 0, duplicatedChunks = 0;
    qint64 corruptedBytes = 0, droppedBytes = 0, duplicatedBytes = 0, filteredWrites = 0;
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
    const LinkFaults& faults(Side from) const { return m_faults[from]; }
    const LinkFaultCounts& faultCounts(Side from) const { return m_counts[from]; }
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
    void deliverDue();
    void schedule();

    qint32 m_baud;
    Transport* m_ends[2];
    LinkFaults m_faults[2];
    LinkFaultCounts m_counts[2];
    qint64 m_hungUntilNs = 0;
    qint64 m_lastDueNs[2] = {0, 0};   ///< jitter never lets a write overtake the one before
    std::mt19937_64 m_rng[2];
    qint64 m_lineFreeNs[2] = {0, 0};  ///< when the wire from each side is next idle
    qint64 m_carried[2] = {0, 0};
    std::deque<Pending> m_pending;    ///< in due order per direction
    QElapsedTimer m_clock;
    QTimer m_timer;
    bool m_unplugged = false;
};

} // namespace dev
