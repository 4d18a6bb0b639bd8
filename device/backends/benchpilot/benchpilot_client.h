#pragma once
// The BenchPilot protocol backend (docs/protocol.md): one instrument over any byte
// transport. Connection state machine, sequence-numbered requests with timeouts and
// retransmission, realtime requests that overtake the queue, jog refreshes, the status
// poll and the telemetry stream, all behind dev::Instrument. Its parts: the device's
// path queue (ProtocolPathClient), its tuning (ProtocolTuningClient) and its axis error
// compensation (ProtocolCompensationClient), all built on request().
//
// Only app/ and tests name this class; screens and runners see dev::Instrument.
#include "device/client/instrument.h"
#include "device/link/transport.h"
#include "device/protocol/frame_codec.h"

#include <QElapsedTimer>
#include <QHash>
#include <QPointer>
#include <QTimer>

#include <array>
#include <deque>
#include <map>

namespace dev {

class ProtocolCompensationClient;
class ProtocolCompensation2dClient;
class ProtocolPathClient;
class ProtocolTuningClient;

class BenchPilotClient : public Instrument {
    Q_OBJECT
public:
    /// Patience on a noisy line (docs/protocol.md, "Retries and silence"): a request is sent
    /// again, with the same sequence number, each time its per-attempt reply timeout passes,
    /// until it is answered. The timeout follows the measured round trip (srtt + 4·rttvar,
    /// bounded below and above); before the first measurement it is kInitialReplyTimeoutMs.
    static constexpr int kInitialReplyTimeoutMs = 100;
    static constexpr int kMinReplyTimeoutMs = 40;
    static constexpr int kMaxReplyTimeoutMs = 1000;
    /// The link is lost (and a connect fails) only when a request is waiting and no good
    /// frame at all has come from the device for longer than this.
    static constexpr int kSilenceLimitMs = 2000;
    /// A request the device never answers although it keeps talking fails (Timeout) after
    /// this long; the link stays up.
    static constexpr int kRequestGiveUpMs = 5000;
    /// While connecting, frames that arrive damaged also show a device answering: the
    /// handshake then goes on for up to this long before it says the device does not answer.
    static constexpr int kConnectGiveUpMs = 10000;
    /// Timeouts are checked this often; a check this much later than the last one (twice
    /// the period) finds the event loop was held up.
    static constexpr int kCheckPeriodMs = 20;
    static constexpr int kStallMs = 40;
    static constexpr int kStatusPollMs = 50;
    static constexpr int kJogRefreshMs = 50;   ///< 20 Hz, four refreshes per device watchdog period
    static constexpr int kDefaultTelemetryHz = 100;

    explicit BenchPilotClient(QObject* parent = nullptr);
    ~BenchPilotClient() override;

    /// Not owned. Replacing the transport disconnects the old one first.
    void setTransport(Transport* transport);
    Transport* transport() const { return m_transport; }

    // dev::Instrument
    void connectLink() override;
    void disconnectLink() override;
    LinkState state() const override { return m_state; }
    LinkStats stats() const override;
    /// Events and telemetry batches that arrived twice and were dropped.
    quint64 duplicateFrames() const { return m_duplicateFrames; }
    /// The reply timeout of the next attempt (ms), from the measured round trip.
    int replyTimeoutMs() const;
    QString linkDescription() const override;
    const DeviceIdentity& identity() const override { return m_identity; }
    const InstrumentStatus& status() const override { return m_status; }
    const QVector<SoftLimits>& softLimits() const override { return m_limits; }
    Capabilities capabilities() const override;
    void home(quint8 axisMask, Callback done = {}) override;
    void move(const QVector<QPair<int, double>>& targets, bool relative, double speed = 0, Callback done = {}) override;
    void archMove(const ArchMove& move, Callback done = {}) override;
    void jogStep(int axis, double delta, double speed = 0, Callback done = {}) override;
    void startJog(int axis, double velocity) override;
    void stopJog(int axis) override;
    void stopAllJogs() override;
    bool isJogging(int axis) const override { return m_jogs.contains(axis); }
    void setJogVelocities(const std::map<int, double>& velocities, Callback done = {}) override;
    int jogRefreshMs() const override { return kJogRefreshMs; }
    void stop(quint8 axisMask = 0, Callback done = {}) override;
    void estop(Callback done = {}) override;
    void reset(Callback done = {}) override;
    void setZero(quint8 axisMask, Callback done = {}) override;
    void setSoftLimits(int axis, double min, double max, Callback done = {}) override;
    void readStatus(StatusCallback done) override;
    void dwell(double seconds, Callback done) override;
    void pulseTrigger(double widthS, Callback done = {}) override;
    void subscribe(const QVector<dev::proto::ChannelRef>& channels, int rateHz, SubscribeCallback done = {}) override;
    const QVector<dev::proto::ChannelRef>& subscribedChannels() const override { return m_channels; }
    int subscribedRateHz() const override { return m_rateHz; }
    double toAxisUnits(const dev::proto::ChannelRef& channel, std::int32_t value) const override;
    PathClient* paths() override;
    TuningClient* tuning() override;
    CompensationClient* compensation() override;
    Compensation2dClient* compensation2d() override;

    /// Any request of the protocol, with its reply payload handed back: how the parts
    /// (tuning, paths) talk to the device without this class growing a method per message.
    /// A device refusal is also emitted as requestFailed, its message prefixed with `what`
    /// ("set gains refused: …") when `what` is given.
    using ReplyCallback = std::function<void(const std::optional<RequestError>&, const dev::proto::Bytes& payload)>;
    void request(dev::proto::MsgType type, const dev::proto::Bytes& payload, ReplyCallback done, const std::string& what = {});
    /// The HELLO capability bits (docs/protocol.md), for the parts.
    bool hasProtocolCapability(std::uint32_t bits) const { return (m_identity.protocolCapabilities & bits) == bits; }

protected:
    motion::msg::Message missingReason(Capability c) const override;

private:
    using RawDone = std::function<void(const std::optional<RequestError>&, const dev::proto::Bytes& payload)>;
    struct Request {
        dev::proto::MsgType type;
        std::uint16_t seq = 0;
        QByteArray wire;
        int attempts = 0;
        qint64 firstSentMs = 0;
        qint64 deadlineMs = 0;
        RawDone done;
        bool realtime = false;
        bool heldUp = false;  ///< waited through a hold-up of the host: its round trip is no measure
    };

    void setState(LinkState s);
    void send(dev::proto::MsgType type, const dev::proto::Bytes& payload, RawDone done);
    void transmit(Request& r);
    void pumpQueue();
    void onBytes(const QByteArray& bytes);
    void onFrame(const dev::proto::Frame& f);
    void complete(Request r, const std::optional<RequestError>& err, const dev::proto::Bytes& payload);
    void checkTimeouts();
    void failAll(RequestError::Kind kind, const motion::msg::Message& why);
    /// Superseded velocity commands stop being retried: a late copy must not undo a newer one.
    void dropSupersededJogs(std::uint16_t newerSeq);
    bool seenEvent(std::uint16_t seq);
    void addRttSample(double ms);
    void sayHello(bool readsExtensions);
    void onHello(const std::optional<RequestError>& err, const dev::proto::Bytes& payload, bool askedExtensions);
    motion::msg::Message connectUnanswered() const;
    void pollStatus();
    void applyStatus(const dev::proto::Bytes& payload);
    void refreshLimits(std::function<void()> then = {});
    void refreshJogs();
    /// Calls `then` once a status reading shows every axis at rest (polling until it does).
    void whenStill(Callback then);
    void linkGone(const motion::msg::Message& why);
    RequestError deviceError(const dev::proto::ErrorReply& e) const;
    RawDone wrap(Callback done, const std::string& what);
    qint64 nowMs() const;

    QPointer<Transport> m_transport;
    QList<QMetaObject::Connection> m_transportConnections;
    LinkState m_state = LinkState::Disconnected;
    DeviceIdentity m_identity;
    InstrumentStatus m_status;
    QVector<SoftLimits> m_limits;
    dev::proto::FrameDecoder m_decoder;
    std::vector<dev::proto::Frame> m_frames;
    std::uint16_t m_nextSeq = 1;
    std::deque<Request> m_queue;          ///< queued requests, front is in flight when m_inFlight
    bool m_inFlight = false;
    std::map<std::uint16_t, Request> m_realtime;  ///< realtime requests awaiting replies, by seq
    QTimer m_timeoutTimer, m_statusTimer, m_jogTimer;
    QElapsedTimer m_clock;
    bool m_statusPending = false;
    quint64 m_duplicateFrames = 0;
    double m_srttMs = -1;                 ///< smoothed round trip of requests answered at the first attempt; <0 = none yet
    double m_rttVarMs = 0;
    /// Requests answered after retries: a second answer to one shows the retries were
    /// early, and its first answer's round trip is a sample after all.
    struct Retried {
        std::uint16_t seq;
        qint64 firstSentMs, answeredMs;
    };
    std::deque<Retried> m_retried;
    std::array<std::uint16_t, 32> m_recentEvents{};  ///< sequence numbers of the last events, to drop a duplicated one
    std::size_t m_recentEventCount = 0, m_recentEventNext = 0;
    qint64 m_lastCheckMs = 0;              ///< when checkTimeouts() last ran
    qint64 m_lastFrameMs = -1;            ///< when a good frame (reply, event, telemetry) last arrived
    qint64 m_lastDamagedFrameMs = -1;     ///< when a frame with a bad CRC or shape last arrived
    qint64 m_connectStartedMs = 0;        ///< when the transport opened and HELLO went out
    quint64 m_damagedAtConnect = 0;       ///< the decoder's damaged frames when this connect began
    QHash<int, double> m_jogs;            ///< axis → velocity (axis units/s) while held
    QVector<dev::proto::ChannelRef> m_channels;
    int m_rateHz = 0;
    std::uint32_t m_nextSampleIndex = 0;
    bool m_haveSampleIndex = false;
    LinkStats m_stats;
    ProtocolPathClient* m_paths;
    ProtocolTuningClient* m_tuning;
    ProtocolCompensationClient* m_compensation;
    ProtocolCompensation2dClient* m_compensation2d;
};

} // namespace dev
