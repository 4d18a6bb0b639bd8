// GrblClient, part 2: writing. Lines go through a backlog (an EEPROM write waits there until
// nothing else is in flight, and nothing follows it until it is answered) into the
// character-counting streamer; realtime bytes go out ahead of any line; a soft reset empties
// both and answers every line in flight as lost. And the sentence a GRBL refusal becomes.
#include "device/backends/grbl/client/grbl_client.h"

#include "device/backends/grbl/grbl_codes.h"


namespace dev {

// ---- writing ------------------------------------------------------------------------------

std::uint64_t GrblClient::queueLine(const std::string& line, LineDone done, bool alone)
{
    if (!m_transport || !m_transport->isOpen() || m_phase == Phase::Closed)
        return 0;
    if (line.empty() || line.size() > dev::grbl::kMaxLineChars || line.size() + 1 > m_lines.streamer.capacityBytes())
        return 0;
    for (const char c : line) {
        const auto b = static_cast<std::uint8_t>(c);
        if (b < 0x20 || dev::grbl::rt::isRealtime(b))
            return 0;
    }
    // Motion lines rely on the modal state this host set (G54 work coordinates, XY plane, feed
    // per minute); a reset or another program may have changed it.
    if (!m_lines.modalReady && (line[0] == 'G' || line[0] == 'M')) {
        m_lines.modalReady = true;
        const std::uint64_t tag = m_nextTag++;
        m_lines.backlog.emplace_back("G54 G17 G94", tag);
        m_lines.pending[tag] = PendingLine{[this](const std::optional<dev::grbl::Streamer::Ack>& a) {
                                         if (!a || !a->ok)
                                             m_lines.modalReady = false;
                                     },
                                     false};
    }
    const std::uint64_t tag = m_nextTag++;
    m_lines.backlog.emplace_back(line, tag);
    m_lines.pending[tag] = PendingLine{std::move(done), alone};
    pump();
    return tag;
}

bool GrblClient::sendLine(const std::string& line, LineDone done)
{
    if (m_phase != Phase::Ready)
        return false;
    return queueLine(line, std::move(done)) != 0;
}

void GrblClient::sendRealtime(std::uint8_t byte)
{
    if (!m_lines.streamer.enqueueRealtime(byte))
        return;
    pump();
}

bool GrblClient::linesIdle() const { return m_lines.backlog.empty() && m_lines.streamer.idle(); }

void GrblClient::pump()
{
    if (!m_transport || !m_transport->isOpen())
        return;
    while (!m_lines.backlog.empty() && !m_lines.aloneInFlight) {
        const auto& [line, tag] = m_lines.backlog.front();
        const auto it = m_lines.pending.find(tag);
        const bool alone = it != m_lines.pending.end() && it->second.alone;
        if (alone && !(m_lines.streamer.inFlightLines() == 0 && m_lines.streamer.queuedLines() == 0))
            break;  // an EEPROM write goes out only when nothing else is in flight
        m_lines.streamer.enqueue(line, tag);
        m_lines.backlog.pop_front();
        if (alone)
            m_lines.aloneInFlight = true;
    }
    const std::string out = m_lines.streamer.takeOutput();
    if (!out.empty())
        m_transport->write(QByteArray(out.data(), static_cast<qsizetype>(out.size())));
}

void GrblClient::softReset(bool expected)
{
    if (!m_transport || !m_transport->isOpen())
        return;
    // Realtime bytes still waiting (a feed hold) go first, then the reset itself.
    std::string out = m_lines.streamer.takeOutput();
    out.push_back(static_cast<char>(dev::grbl::rt::kSoftReset));
    m_transport->write(QByteArray(out.data(), static_cast<qsizetype>(out.size())));
    // GRBL forgets every line it holds, and half a line it was sending is garbage now.
    if (expected)
        ++m_wire.expectedBanners;
    m_wire.reader.clear();
    LostLines lost = dropLines(motion::msg::make("grbl.reset_flushed"));
    answerLost(lost);
}

// ---- refusals ----------------------------------------------------------------

RequestError GrblClient::errorOf(int code, const std::string& line, const std::string& request)
{
    RequestError e;
    e.kind = RequestError::Kind::Device;
    switch (code) {
    case dev::grbl::err::kTravelExceeded: e.code = dev::proto::ErrorCode::SoftLimit; break;
    case dev::grbl::err::kIdleError:
    case dev::grbl::err::kSystemGcLock: e.code = dev::proto::ErrorCode::Busy; break;
    case dev::grbl::err::kHomingDisabled: e.code = dev::proto::ErrorCode::UnknownCommand; break;
    default: e.code = dev::proto::ErrorCode::BadPayload; break;
    }
    e.message = dev::grbl::errorMessage(code, line);
    e.message.args.push_back(motion::msg::term("request", request));
    return e;
}

} // namespace dev
