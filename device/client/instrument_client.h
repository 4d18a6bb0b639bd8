#pragma once
// Asynchronous client of one instrument (analyzer or stage) over any transport:
// connection state machine, sequence-numbered requests with timeouts and
// retransmission, typed signals for status, events and telemetry. Widgets use
// this API and never see the protocol.
#include "device/client/instrument_types.h"
#include "device/link/transport.h"
#include "device/protocol/frame_codec.h"

#include <QElapsedTimer>
#include <QHash>
#include <QObject>
#include <QPointer>
#include <QTimer>

#include <deque>
#include <functional>
#include <map>

namespace dev {

struct LinkStats {
    quint64 framesIn = 0, crcErrors = 0, malformed = 0, oversize = 0, droppedBytes = 0;
    quint64 retransmits = 0, timeouts = 0, lateReplies = 0;
    quint64 telemetryBatches = 0, telemetrySamples = 0, lostSamples = 0;
};

class InstrumentClient : public QObject {
    Q_OBJECT
public:
    /// Per-attempt reply timeout and attempts: a silent device is reported within
    /// kAttempts × kReplyTimeoutMs (under 2 s).
    static constexpr int kReplyTimeoutMs = 300;
    static constexpr int kAttempts = 3;
    static constexpr int kStatusPollMs = 50;
    static constexpr int kJogRefreshMs = 50;   ///< 20 Hz, four refreshes per device watchdog period
    static constexpr int kDefaultTelemetryHz = 100;

    explicit InstrumentClient(QObject* parent = nullptr);
    ~InstrumentClient() override;

    /// Not owned. Replacing the transport disconnects the old one first.
    void setTransport(Transport* transport);
    Transport* transport() const { return m_transport; }
    void connectLink();
    void disconnectLink();

    LinkState state() const { return m_state; }
    bool isReady() const { return m_state == LinkState::Ready; }
    const DeviceIdentity& identity() const { return m_identity; }
    const InstrumentStatus& status() const { return m_status; }
    const QVector<SoftLimits>& softLimits() const { return m_limits; }
    LinkStats stats() const;
    QString linkDescription() const;

    using Callback = std::function<void(const std::optional<RequestError>&)>;

    void home(quint8 axisMask, Callback done = {});              ///< 0 = every axis
    /// Absolute or relative move of several axes (axis index → target in axis
    /// units). speed: axis units per second along the path, 0 = the device default.
    void move(const QVector<QPair<int, double>>& targets, bool relative, double speed = 0, Callback done = {});
    void jogStep(int axis, double delta, double speed = 0, Callback done = {});
    /// Velocity move that lasts while it is refreshed: the client refreshes it
    /// every kJogRefreshMs until stopJog(); if the client or link dies, the device stops it.
    void startJog(int axis, double velocity);
    void stopJog(int axis);
    void stopAllJogs();
    bool isJogging(int axis) const { return m_jogs.contains(axis); }
    void stop(quint8 axisMask = 0, Callback done = {});
    void estop(Callback done = {});
    void reset(Callback done = {});
    void setZero(quint8 axisMask, Callback done = {});
    void setSoftLimits(int axis, double min, double max, Callback done = {});
    /// Replaces the telemetry subscription. rate 0 stops it.
    void subscribe(const QVector<proto::ChannelRef>& channels, int rateHz,
                   std::function<void(const std::optional<RequestError>&, const proto::SubscribeReply&)> done = {});
    const QVector<proto::ChannelRef>& subscribedChannels() const { return m_channels; }
    int subscribedRateHz() const { return m_rateHz; }
    /// Converts a wire value of a channel to axis units (mm, µL, per second, …).
    double toAxisUnits(const proto::ChannelRef& channel, std::int32_t value) const;

    /// Any request of the protocol, with its reply payload handed back: how the job
    /// clients (tuning, paths, …) talk to the device without this class growing a
    /// method per message. A device refusal is also emitted as requestFailed, its
    /// message prefixed with `what` ("set gains refused: …") when `what` is given.
    using ReplyCallback = std::function<void(const std::optional<RequestError>&, const proto::Bytes& payload)>;
    void request(proto::MsgType type, const proto::Bytes& payload, ReplyCallback done, const QString& what = {});

signals:
    void stateChanged(dev::LinkState state);
    void identified(const dev::DeviceIdentity& identity);
    void statusChanged(const dev::InstrumentStatus& status);
    void limitsChanged();
    void eventReceived(const dev::DeviceEvent& event);
    void telemetryReceived(const proto::TelemetryBatch& batch);
    /// Something went wrong on the link or with a request; for a status bar or log.
    void linkError(const QString& message);
    void requestFailed(const dev::RequestError& error);
    void samplesLost(quint64 totalLost);

private:
    using RawDone = std::function<void(const std::optional<RequestError>&, const proto::Bytes& payload)>;
    struct Request {
        proto::MsgType type;
        std::uint16_t seq = 0;
        QByteArray wire;
        int attempts = 0;
        qint64 firstSentMs = 0;
        qint64 deadlineMs = 0;
        RawDone done;
        bool realtime = false;
    };

    void setState(LinkState s);
    void send(proto::MsgType type, const proto::Bytes& payload, RawDone done);
    void transmit(Request& r);
    void pumpQueue();
    void onBytes(const QByteArray& bytes);
    void onFrame(const proto::Frame& f);
    void complete(Request r, const std::optional<RequestError>& err, const proto::Bytes& payload);
    void checkTimeouts();
    void failAll(RequestError::Kind kind, const QString& why);
    void onHello(const std::optional<RequestError>& err, const proto::Bytes& payload);
    void pollStatus();
    void applyStatus(const proto::Bytes& payload);
    void refreshLimits(std::function<void()> then = {});
    void refreshJogs();
    void linkGone(const QString& why);
    RequestError deviceError(const proto::ErrorReply& e) const;
    RawDone wrap(Callback done, const QString& what);
    qint64 nowMs() const;

    QPointer<Transport> m_transport;
    QList<QMetaObject::Connection> m_transportConnections;
    LinkState m_state = LinkState::Disconnected;
    DeviceIdentity m_identity;
    InstrumentStatus m_status;
    QVector<SoftLimits> m_limits;
    proto::FrameDecoder m_decoder;
    std::vector<proto::Frame> m_frames;
    std::uint16_t m_nextSeq = 1;
    std::deque<Request> m_queue;          ///< queued requests, front is in flight when m_inFlight
    bool m_inFlight = false;
    std::map<std::uint16_t, Request> m_realtime;  ///< realtime requests awaiting replies, by seq
    QTimer m_timeoutTimer, m_statusTimer, m_jogTimer;
    QElapsedTimer m_clock;
    bool m_statusPending = false;
    int m_consecutiveTimeouts = 0;
    qint64 m_lastFrameMs = -1;            ///< when a good frame (reply, event, telemetry) last arrived
    QHash<int, double> m_jogs;            ///< axis → velocity (axis units/s) while held
    QVector<proto::ChannelRef> m_channels;
    int m_rateHz = 0;
    std::uint32_t m_nextSampleIndex = 0;
    bool m_haveSampleIndex = false;
    LinkStats m_stats;
};

} // namespace dev
