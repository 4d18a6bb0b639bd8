#pragma once
// Which protocol a port speaks: the BenchPilot protocol (a HELLO answered) or GRBL 1.1 /
// grblHAL (a banner, a status report, an ok). The session asks before it picks a backend
// (app/gui/instrument_session.*, app/cli/cli_session.*).
//
// GRBL first, because it is the one that can be hurt: a BenchPilot frame sent to GRBL could
// hold bytes GRBL acts on at once (a feed hold '!', a reset 0x18, a safety door 0x84, feed
// overrides 0x90–0x9D). So:
//   1. '?' — GRBL answers with a status report at once (a BenchPilot device's frame decoder
//      drops the byte as noise before its next frame delimiter);
//   2. after kGrblFirstMs of silence, a BenchPilot HELLO whose bytes hold nothing GRBL reads
//      as a realtime command nor a line end (the sequence number is chosen so): a GRBL that
//      was still booting (an Arduino resets when its port opens) keeps it as the start of a
//      line, which the GRBL client's first "\n" ends and GRBL answers with one error;
//   3. '?' and HELLO again now and then until kTotalMs, then a message that says what was
//      (not) heard.
// The transport is left open for the backend when a protocol answered, closed otherwise.
#include "device/link/transport.h"
#include "device/protocol/frame_codec.h"
#include "device/protocol/messages.h"
#include "device/backends/grbl/grbl_lines.h"
#include "motion/message.h"

#include <QElapsedTimer>
#include <QPointer>
#include <QTimer>

namespace dev {

struct ProbeResult {
    enum class Protocol { None, BenchPilot, Grbl };
    Protocol protocol = Protocol::None;
    bool kindKnown = false;                            ///< a HELLO said which instrument
    dev::proto::DeviceKind kind = dev::proto::DeviceKind::Analyzer;
    /// What answered (grbl.probe.found_grbl{firmware, version}, grbl.probe.found_grbl_unnamed,
    /// grbl.probe.found_benchpilot{version, instrument}); ui::words::text words it.
    motion::msg::Message found;
    /// When protocol is None: why (grbl.probe.no_answer, grbl.probe.unreadable, link.*).
    motion::msg::Message error;
    /// GRBL's start-up banner came while probing: the controller restarted since the port was
    /// opened (GrblClient::setRestartHeardBeforeConnect).
    bool grblBanner = false;
};

class ProtocolProbe : public QObject {
    Q_OBJECT
public:
    static constexpr int kGrblFirstMs = 300;
    static constexpr int kRepeatMs = 1000;
    static constexpr int kTotalMs = 4000;
    /// Once BenchPilot frames arrive, even damaged ones (bad CRC or broken COBS: a noisy
    /// line), HELLO is asked again this often and for up to kNoisyTotalMs in all, as the
    /// client's own connect does (docs/protocol.md, "Retries and silence"). A wrong baud
    /// rate can look like damaged frames too: it is then reported after kNoisyTotalMs.
    static constexpr int kNoisyRepeatMs = 100;
    static constexpr int kNoisyTotalMs = 10000;
    /// The longest a probe takes before it finishes by itself: what a caller waiting on
    /// it must allow, or it gives up on a noisy line the probe would still have read.
    static constexpr int kLongestMs = kNoisyTotalMs > kTotalMs ? kNoisyTotalMs : kTotalMs;

    explicit ProtocolProbe(Transport* transport, QObject* parent = nullptr);
    ~ProtocolProbe() override;

    /// Opens the transport if it is not open, then asks. finished() follows exactly once.
    void start();
    const ProbeResult& result() const { return m_result; }
    bool done() const { return m_done; }

    /// The HELLO the probe sends: a sequence number whose frame has no byte GRBL acts on
    /// ('?', '!', '~', 0x18, 0x80–0xFF) and no line end. Exposed for the test that checks it.
    static QByteArray safeHello(std::uint16_t* seq = nullptr);

signals:
    void finished(const dev::ProbeResult& result);

private:
    void begin();
    void tick();
    void onBytes(const QByteArray& bytes);
    void finish(ProbeResult r);

    QPointer<Transport> m_transport;
    QList<QMetaObject::Connection> m_connections;
    QTimer m_timer;
    QElapsedTimer m_clock;
    dev::grbl::LineReader m_lines;
    dev::proto::FrameDecoder m_frames;
    std::uint16_t m_helloSeq = 0;
    qint64 m_lastQueryMs = 0, m_lastHelloMs = -1;
    quint64 m_bytes = 0;
    bool m_started = false, m_done = false;
    bool m_heardFrames = false;  ///< a BenchPilot frame arrived, whole or with a bad CRC
    ProbeResult m_result;
};

} // namespace dev

Q_DECLARE_METATYPE(dev::ProbeResult)
