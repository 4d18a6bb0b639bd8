#include "device/backends/grbl/grbl_streamer.h"

#include <algorithm>

namespace dev::grbl {

namespace {
/// The device's ring buffer keeps one slot empty, so a 128-byte buffer holds 127 (the
/// interface document: "stores up to 127 characters"). Never less than one line's worth.
std::size_t usable(std::size_t rxBufferBytes) { return std::max<std::size_t>(rxBufferBytes, 2) - 1; }
} // namespace

Streamer::Streamer(std::size_t rxBufferBytes) : m_capacity(usable(rxBufferBytes)) {}

void Streamer::setRxBufferBytes(std::size_t bytes) { m_capacity = usable(bytes); }

Streamer::Queued Streamer::enqueue(std::string line, std::uint64_t tag)
{
    if (line.empty())
        return Queued::Empty;  // GRBL answers an empty line with ok; sending one only costs a round trip
    for (const char c : line) {
        const auto b = static_cast<std::uint8_t>(c);
        if (c == '\n' || c == '\r' || rt::isRealtime(b) || b < 0x20)
            return Queued::BadByte;
    }
    if (line.size() > kMaxLineChars || line.size() + 1 > m_capacity)
        return Queued::TooLong;
    line.push_back('\n');
    m_queue.push_back({std::move(line), tag});
    return Queued::Ok;
}

bool Streamer::enqueueRealtime(std::uint8_t byte)
{
    if (!rt::isRealtime(byte))
        return false;
    m_realtime.push_back(static_cast<char>(byte));
    return true;
}

std::string Streamer::takeOutput()
{
    std::string out;
    out.swap(m_realtime);
    while (!m_stopped && !m_queue.empty() && m_inFlightBytes + m_queue.front().line.size() <= m_capacity) {
        Entry e = std::move(m_queue.front());
        m_queue.pop_front();
        out += e.line;
        m_inFlightBytes += e.line.size();
        m_inFlight.push_back(std::move(e));
        ++m_linesSent;
    }
    return out;
}

std::optional<Streamer::Ack> Streamer::acknowledge(bool ok, int errorCode)
{
    if (m_inFlight.empty()) {
        ++m_strayAcks;
        return std::nullopt;
    }
    Entry e = std::move(m_inFlight.front());
    m_inFlight.pop_front();
    m_inFlightBytes -= e.line.size();
    e.line.pop_back();  // the '\n'
    if (!ok && m_stopOnError)
        m_stopped = true;
    return Ack{std::move(e.line), e.tag, ok, ok ? 0 : errorCode};
}

std::vector<std::uint64_t> Streamer::removeQueued(const std::function<bool(std::uint64_t tag)>& drop)
{
    std::vector<std::uint64_t> removed;
    std::deque<Entry> kept;
    for (auto& e : m_queue) {
        if (drop(e.tag))
            removed.push_back(e.tag);
        else
            kept.push_back(std::move(e));
    }
    m_queue.swap(kept);
    return removed;
}

std::vector<Streamer::Ack> Streamer::softReset(bool dropQueue)
{
    std::vector<Ack> lost;
    for (auto& e : m_inFlight) {
        e.line.pop_back();
        lost.push_back({std::move(e.line), e.tag, false, 0});
    }
    m_inFlight.clear();
    m_inFlightBytes = 0;
    if (dropQueue)
        m_queue.clear();
    m_stopped = false;
    return lost;
}

} // namespace dev::grbl
