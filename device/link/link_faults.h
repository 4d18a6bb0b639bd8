#pragma once
// What a bad cable does to bytes, as one seeded generator per direction: shared by the
// in-process loopback (LoopbackPair) and the fault-injecting pty proxy (bp-faultline), so
// a seed means the same line on both paths and a failing seed is replayed exactly.
#include <QByteArray>

#include <cstdint>
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
    qint64 damagedBytes() const { return corruptedBytes + droppedBytes + duplicatedBytes; }
};

/// One direction of a bad cable: turns each write into what arrives, and says how late.
class FaultyLine {
public:
    void setFaults(const LinkFaults& faults)
    {
        m_faults = faults;
        m_rng.seed(faults.seed);
    }
    const LinkFaults& faults() const { return m_faults; }
    const LinkFaultCounts& counts() const { return m_counts; }

    /// What `write` becomes on the wire (empty: nothing arrives) and, in `delayNs`, the
    /// latency to add to it. The draws' order is part of a seed's meaning: keep it.
    QByteArray spoil(const QByteArray& write, std::int64_t* delayNs);

private:
    LinkFaults m_faults;
    LinkFaultCounts m_counts;
    std::mt19937_64 m_rng{1};
};

} // namespace dev
