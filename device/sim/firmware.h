#pragma once
// The reference firmware's protocol side: decodes frames, answers requests,
// never executes a retransmitted request twice, streams telemetry batches and
// events. Plain C++ on a virtual clock: the host decides how fast time runs.
#include "device/protocol/frame_codec.h"
#include "device/protocol/messages.h"
#include "device/protocol/messages_path.h"
#include "device/sim/serial_device.h"
#include "device/sim/sim_machine.h"

#include <array>
#include <cstdint>
#include <vector>

namespace dev::sim {

class Firmware : public SerialDevice {
public:
    /// Output not yet drained beyond which telemetry batches are dropped.
    static constexpr std::size_t kMaxPendingOutputBytes = 64 * 1024;

    /// `powerUp`: the flash the device powers up with (saved compensations).
    Firmware(const MachineConfig& config, std::uint32_t linkBaud, const NonVolatile& powerUp = {});

    /// Bytes from the host, in any chunking.
    void receive(const std::uint8_t* data, std::size_t size) override;
    /// Runs the machine for `dtS` of virtual time (whole ticks; the remainder carries).
    void advance(double dtS) override;
    /// Moves the bytes the device has sent since the last call to `out`.
    void drainOutput(std::vector<std::uint8_t>& out) override;

    SimMachine& machine() { return m_machine; }
    const SimMachine& machine() const { return m_machine; }
    const dev::proto::DecoderStats& decoderStats() const { return m_decoder.stats(); }
    std::uint64_t executedRequests() const { return m_executed; }
    std::uint64_t duplicateRequests() const { return m_duplicates; }
    /// Velocity commands that arrived after a newer velocity, stop or E-stop: answered, not executed.
    std::uint64_t staleVelocityRequests() const { return m_staleVelocities; }
    std::uint64_t droppedTelemetryBatches() const { return m_droppedBatches; }
    std::uint32_t linkBaud() const { return m_linkBaud; }
    void setLinkBaud(std::uint32_t baud) { m_linkBaud = baud; }
    /// Device time without any frame from the host after which a moving path is held
    /// (dev::proto::kPathHostSilenceMs). A simulator run K times faster than the wall clock judges
    /// the host by the host's clock: K times the limit (SimulatorHost::setTimeScale does that).
    void setHostSilenceLimitS(double seconds) { m_hostSilenceLimitS = seconds; }
    /// false: answer HELLO as protocol 1.0 firmware did, refusing a HELLO with a payload
    /// and never sending extension blocks (for trying a host against older firmware).
    void setHelloExtensions(bool on) { m_helloExtensions = on; }

    /// The firmware's own record of what it executed and the events it raised (type EVENT,
    /// no positions) (off unless asked for): how tests
    /// judge a run on a hostile line by what the device did, not by what the host believes.
    struct JournalEntry {
        double timeS = 0;                   ///< machine time of execution
        std::uint8_t type = 0;
        std::uint16_t seq = 0;
        dev::proto::Bytes payload;
        std::vector<double> commanded;      ///< each axis's commanded position before it ran (axis units)
    };
    void setJournal(bool on) { m_journalOn = on; }
    const std::vector<JournalEntry>& journal() const { return m_journal; }

    /// Bytes per second the link can carry (8N1: ten bit times per byte).
    double linkBytesPerSecond() const { return m_linkBaud / 10.0; }

private:
    void handle(const dev::proto::Frame& f);
    void execute(const dev::proto::Frame& f, std::vector<std::uint8_t>& reply);
    void sendFrame(std::uint8_t type, std::uint16_t seq, const dev::proto::Bytes& payload, std::vector<std::uint8_t>& out);
    void sendError(std::uint16_t seq, const dev::proto::ErrorReply& e, std::vector<std::uint8_t>& out);
    void sendMalformed(std::uint16_t seq, const char* what, std::vector<std::uint8_t>& out);  ///< BadPayload
    void subscribe(const dev::proto::Frame& f, std::vector<std::uint8_t>& reply);
    /// Tuning requests (firmware_tuning.cpp); false if `f` is not one.
    bool executeTuning(const dev::proto::Frame& f, std::vector<std::uint8_t>& reply);
    /// Compensation requests (firmware_compensation.cpp); false if `f` is not one.
    bool executeCompensation(const dev::proto::Frame& f, std::vector<std::uint8_t>& reply);
    void sampleTelemetry();
    void flushEvents();
    // Path queue (firmware_path.cpp): its requests, and the feed hold when the host goes quiet.
    void executePath(const dev::proto::Frame& f, std::vector<std::uint8_t>& reply);
    void checkHostSilence();

    SimMachine m_machine;
    std::uint32_t m_linkBaud;
    dev::proto::FrameDecoder m_decoder;
    std::vector<dev::proto::Frame> m_frames;
    std::vector<std::uint8_t> m_out;
    double m_pendingS = 0;
    std::uint16_t m_eventSeq = 0;
    std::uint64_t m_executed = 0, m_duplicates = 0, m_droppedBatches = 0;
    double m_lastHostFrameS = 0;  ///< machine time of the last good frame from the host
    double m_hostSilenceLimitS = dev::proto::kPathHostSilenceMs / 1000.0;
    bool m_helloExtensions = true;
    bool m_eventReasons = false;  ///< this session's host asked for each EVENT's reason
    bool m_journalOn = false;
    std::vector<JournalEntry> m_journal;

    /// Replies to the last requests, so a retransmission (same seq and bytes) is
    /// answered again without acting twice. Fixed ring: the oldest entry is overwritten.
    struct CachedReply {
        bool valid = false;
        std::uint8_t type = 0;
        std::uint16_t seq = 0;
        dev::proto::Bytes payload;
        std::vector<std::uint8_t> reply;
    };
    /// Large enough that a host retrying one request for its whole patience (docs/protocol.md:
    /// up to 5 s) while status polls and jog refreshes go on finds its answer still here.
    std::array<CachedReply, 256> m_cache;
    std::size_t m_cacheNext = 0;
    /// The latest velocity, stop or E-stop executed: a velocity command numbered before it
    /// is a late copy and must not set an old velocity again (restart a stopped axis).
    bool m_haveMotionSeq = false;
    std::uint16_t m_lastMotionSeq = 0;
    std::uint64_t m_staleVelocities = 0;
    CachedReply m_lastQueued;  ///< key of the latest queued request (reply not kept): tells a repeated HELLO from a new session

    // Telemetry subscription.
    std::vector<dev::proto::ChannelRef> m_channels;
    std::uint32_t m_rateHz = 0;
    std::uint32_t m_ticksPerSample = 0;
    std::uint16_t m_samplesPerBatch = 0;
    std::uint32_t m_sampleIndex = 0;
    std::uint64_t m_tickCount = 0;
    dev::proto::TelemetryBatch m_batch;
};

} // namespace dev::sim
