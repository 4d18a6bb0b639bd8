#include "device/link/link_faults.h"

namespace dev {

QByteArray FaultyLine::spoil(const QByteArray& write, std::int64_t* delayNs)
{
    const LinkFaults& f = m_faults;
    LinkFaultCounts& n = m_counts;
    *delayNs = 0;
    QByteArray bytes = write;
    if (f.filter) {
        bytes = f.filter(write);
        if (bytes != write)
            ++n.filteredWrites;
        if (bytes.isEmpty())
            return {};
    }
    std::uniform_real_distribution<double> u(0, 1);
    if (f.dropChunkProbability > 0 && u(m_rng) < f.dropChunkProbability) {
        ++n.droppedChunks;
        return {};
    }
    if (f.corruptByteProbability > 0 || f.dropByteProbability > 0 || f.duplicateByteProbability > 0) {
        QByteArray out;
        out.reserve(bytes.size() + 8);
        for (char c : bytes) {
            if (f.dropByteProbability > 0 && u(m_rng) < f.dropByteProbability) {
                ++n.droppedBytes;
                continue;
            }
            if (f.corruptByteProbability > 0 && u(m_rng) < f.corruptByteProbability) {
                c = static_cast<char>(c ^ (1 << std::uniform_int_distribution<int>(0, 7)(m_rng)));
                ++n.corruptedBytes;
            }
            out.append(c);
            if (f.duplicateByteProbability > 0 && u(m_rng) < f.duplicateByteProbability) {
                out.append(c);
                ++n.duplicatedBytes;
            }
        }
        bytes = out;
    }
    if (f.duplicateChunkProbability > 0 && u(m_rng) < f.duplicateChunkProbability) {
        bytes += bytes;
        ++n.duplicatedChunks;
    }
    // Drawn even when every byte was dropped, so the sequence does not depend on that.
    std::int64_t extra = std::int64_t(f.extraDelayMs) * 1000000;
    if (f.jitterMs > 0)
        extra += static_cast<std::int64_t>(u(m_rng) * f.jitterMs * 1e6);
    *delayNs = extra;
    return bytes;
}

} // namespace dev
