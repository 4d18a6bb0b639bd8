#pragma once
// Character-counting streaming (the GRBL interface document's "character-counting
// protocol"), as a pure state machine: no clock, no I/O. The host queues lines and realtime
// bytes, writes what takeOutput() gives it, and feeds every ok / error:N back.
//
// The rule it keeps: the bytes of lines sent and not yet acknowledged never exceed what the
// device's receive buffer holds (capacityBytes(): the size $I reports — or 128 for GRBL,
// 1024 for grblHAL, the documented defaults — less the one slot a ring buffer keeps free).
//   - Lines end with '\n' only; the '\n' counts.
//   - Each ok or error:N acknowledges the OLDEST line in flight; an error names that line.
//   - Realtime bytes (?, !, ~, 0x18, 0x85, the override bytes) go out at once, ahead of
//     any line waiting, and are not counted: the firmware picks them off on arrival.
//   - A soft reset (0x18) empties the device's buffer: the count goes back to zero and the
//     lines in flight are reported lost (softReset()).
//   - After an error the streamer stops sending (GRBL keeps executing what is already in
//     its buffer: the document's reservation); the job decides to resume() or clearQueue().
#include "device/backends/grbl/grbl_protocol.h"

#include <cstdint>
#include <deque>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace dev::grbl {

class Streamer {
public:
    explicit Streamer(std::size_t rxBufferBytes = kGrblDefaultRxBufferBytes);

    /// The device's receive buffer size (from [OPT:]); takes effect for the next line sent.
    void setRxBufferBytes(std::size_t bytes);
    std::size_t capacityBytes() const { return m_capacity; }

    enum class Queued { Ok, Empty, TooLong, BadByte };
    /// Queues one line (without its '\n'). Refused: a line that could never fit the buffer or
    /// GRBL's line length, or that holds a line end or a realtime byte (which GRBL would pick
    /// off mid-line and act on). `tag` comes back with its acknowledgement.
    Queued enqueue(std::string line, std::uint64_t tag = 0);
    /// Queues a realtime byte to go out ahead of every waiting line. False if it is not one.
    bool enqueueRealtime(std::uint8_t byte);

    /// Bytes to write now: pending realtime bytes, then as many whole queued lines as fit.
    std::string takeOutput();

    struct Ack {
        std::string line;       ///< the line this answer belongs to
        std::uint64_t tag = 0;
        bool ok = true;
        int errorCode = 0;      ///< error:N
    };
    /// An "ok" (errorCode < 0 … pass ok = true) or "error:N" arrived. nullopt if nothing was in
    /// flight (a stray answer: counted in strayAcks(), never matched to a later line).
    std::optional<Ack> acknowledge(bool ok, int errorCode = 0);

    /// The device was reset (0x18 sent or a banner seen): nothing is in its buffer any more.
    /// Returns the lines that were in flight and will never be answered; queued lines stay
    /// queued unless `dropQueue`.
    std::vector<Ack> softReset(bool dropQueue = true);
    /// After an error: start sending again / forget what is still queued.
    void resume() { m_stopped = false; }
    void clearQueue() { m_queue.clear(); }
    /// Forgets the queued (not yet written) lines whose tag `drop` picks; returns their tags.
    /// Lines in flight stay: the device has them. (A jog cancel drops the segments not sent.)
    std::vector<std::uint64_t> removeQueued(const std::function<bool(std::uint64_t tag)>& drop);
    void setStopOnError(bool stop) { m_stopOnError = stop; }

    bool stopped() const { return m_stopped; }
    std::size_t inFlightBytes() const { return m_inFlightBytes; }
    std::size_t inFlightLines() const { return m_inFlight.size(); }
    std::size_t queuedLines() const { return m_queue.size(); }
    bool idle() const { return m_queue.empty() && m_inFlight.empty() && m_realtime.empty(); }
    std::uint64_t strayAcks() const { return m_strayAcks; }
    std::uint64_t linesSent() const { return m_linesSent; }

private:
    struct Entry {
        std::string line;  ///< with its '\n'
        std::uint64_t tag = 0;
    };
    std::size_t m_capacity;
    std::deque<Entry> m_queue;
    std::deque<Entry> m_inFlight;
    std::size_t m_inFlightBytes = 0;
    std::string m_realtime;
    bool m_stopOnError = true;
    bool m_stopped = false;
    std::uint64_t m_strayAcks = 0;
    std::uint64_t m_linesSent = 0;
};

} // namespace dev::grbl
