#pragma once
// The GRBL backend (docs/grbl.md): a GRBL 1.1 or grblHAL controller behind dev::Instrument,
// over any byte transport. What it keeps:
//  - Connection: a sync ("\n" then $G: the answer after its [GC:] line marks where this host's
//    conversation begins, whatever was left in the buffers), then $I (firmware, planner blocks,
//    receive buffer), $$ (rates, accelerations, travel, homing, inches) and $# (the G54 work
//    offset); Ready after the first status report. A board that is still booting (an Arduino
//    resets when its port opens) is given a second sync; one that never answers, or sends only
//    bytes that are not GRBL lines, is refused within kConnectMs with a sentence that says so.
//  - Status: '?' at the machine profile's rate (one query outstanding at a time), every field
//    of the report read (grbl_status.h); positions in the instrument's work coordinates (G54),
//    the pump's µL from its axis' mm. No byte for kSilenceMs while polling (homing and a
//    critical alarm excepted, when GRBL does not answer) means the link is lost.
//  - Lines: character counting against the receive buffer $I reported (grbl_streamer.h); realtime
//    bytes outside the count; lines that write EEPROM (G10) sent alone. Every error:N and
//    ALARM:N becomes a RequestError / DeviceEvent carrying grbl.error{code, line} /
//    grbl.alarm{code} with its documented meaning; [MSG:], [GC:], [PRB:] and unknown lines are
//    noted (Instrument::noted), never fatal.
//  - Motion: absolute moves in G54 work coordinates (the analyzer's Z after X and Y), refused by
//    the host beyond the machine travel (GRBL would answer with ALARM:2 and need a reset);
//    MotionDone once the lines are acknowledged and a status report asked for afterwards shows
//    Idle. Step jogs as $J=G91 G21 …; continuous jogs and the joystick as short $J segments kept
//    a little ahead (grbl_jog.h), cancelled with 0x85 on release — and once more after a jog line
//    that was still in GRBL's buffer when the cancel came, which GRBL runs after the cancel.
//  - Homing with $H; where homing is disabled ($22=0, error:5), setZero() takes the present
//    position as home (G10 L20 P1) on the operator's word. An alarm that loses the position
//    (reset in motion, hard limit, homing failure) needs homing or unlock() ($X).
//  - stop(): 0x85 for a jog; otherwise a feed hold, and once GRBL holds at rest (Hold:0) a soft
//    reset that forgets the queue but keeps the position. estop(): feed hold and soft reset at
//    once: GRBL stops dead and, if it was moving, loses its position (ALARM:3).
//
// Device time: GRBL has no clock; status().deviceTimeUs is the host's monotonic clock at the
// arrival of the report.
//
// Only app/ and tests name this class; screens and runners see dev::Instrument.
#include "device/backends/grbl/grbl_build_info.h"
#include "device/backends/grbl/grbl_jog.h"
#include "device/backends/grbl/grbl_lines.h"
#include "device/backends/grbl/grbl_settings.h"
#include "device/backends/grbl/grbl_status.h"
#include "device/backends/grbl/grbl_streamer.h"
#include "device/client/instrument.h"
#include "device/files/machine_profile_file.h"
#include "device/link/transport.h"

#include <QElapsedTimer>
#include <QHash>
#include <QPointer>
#include <QTimer>

#include <deque>
#include <functional>
#include <map>
#include <set>
#include <optional>

namespace dev {

class GrblPathClient;

class GrblClient : public Instrument {
    Q_OBJECT
public:
    static constexpr int kConnectMs = 5000;   ///< no GRBL line within this: the connection fails
    static constexpr int kResyncMs = 2000;    ///< a first sync unanswered (a board still booting): once more
    static constexpr int kSilenceMs = 2500;   ///< no byte for this long while polling: the link is lost
    static constexpr int kQueryRetryMs = 1000;  ///< a '?' unanswered this long is sent again
    static constexpr int kStopMs = 5000;      ///< a stop or reset not confirmed within this is reported

    /// `profile`: the wiring (docs/grbl.md). `lenient`: the profile is the default one, so a
    /// pump axis the controller lacks is dropped rather than refused.
    explicit GrblClient(const dev::files::MachineProfile& profile, bool lenient = false, QObject* parent = nullptr);
    ~GrblClient() override;

    /// How long a connection may take before it is refused (kConnectMs unless a test is in a hurry).
    void setConnectTimeoutMs(int ms) { m_connectTimeoutMs = ms; }

    /// Where a home set here (setZero, with homing disabled) is remembered between connections
    /// (GrblHomeMemory), and the port this controller is on. Without it every connection to a
    /// controller without homing starts unestablished. The home is kept at the next connection
    /// only when the controller can be told not to have restarted since: no start-up banner as
    /// the port opened, no alarm, and the G54 offset and machine position this host last saw.
    void rememberHomesIn(const QString& file, const QString& port)
    {
        m_homeFile = file;
        m_homePort = port;
    }
    /// The probe that opened the port heard the controller's start-up banner (ProbeResult::grblBanner):
    /// it restarted as the port opened. For the next connectLink().
    void setRestartHeardBeforeConnect(bool heard) { m_restartHeardBeforeConnect = heard; }

    /// Not owned. Replacing the transport disconnects the old one first. A transport that is
    /// already open (a protocol probe opened it) is used as it is: no second open.
    void setTransport(Transport* transport);
    Transport* transport() const { return m_transport; }
    const dev::files::MachineProfile& profile() const { return m_profile; }

    // What the controller said about itself.
    dev::grbl::Firmware firmware() const { return m_controller.firmware; }
    const dev::grbl::BuildInfo& buildInfo() const { return m_controller.build; }
    const dev::grbl::Settings& settings() const { return m_controller.settings; }
    const dev::grbl::MachineLimits& machineLimits() const { return m_controller.limits; }
    dev::grbl::MachineState machineState() const { return m_reports.tracker.state(); }
    int alarmCode() const { return m_machine.alarm; }
    double pollHz() const { return m_profile.statusPollHz; }
    /// The jog plan for a continuous jog of one axis at `speed` (axis units/s): what the GUI
    /// quotes for the release stop and the overrun of a lost host.
    dev::grbl::JogPlan jogPlan(int axis, double speed) const;

    // dev::Instrument
    void connectLink() override;
    void disconnectLink() override;
    LinkState state() const override { return m_state; }
    LinkStats stats() const override;
    QString linkDescription() const override;
    const DeviceIdentity& identity() const override { return m_identity; }
    const InstrumentStatus& status() const override { return m_status; }
    const QVector<SoftLimits>& softLimits() const override { return m_softLimits; }
    Capabilities capabilities() const override;
    void home(quint8 axisMask, Callback done = {}) override;
    void move(const QVector<QPair<int, double>>& targets, bool relative, double speed = 0, Callback done = {}) override;
    void jogStep(int axis, double delta, double speed = 0, Callback done = {}) override;
    void startJog(int axis, double velocity) override;
    void stopJog(int axis) override;
    void stopAllJogs() override;
    bool isJogging(int axis) const override;
    void setJogVelocities(const std::map<int, double>& velocities, Callback done = {}) override;
    int jogRefreshMs() const override;
    void stop(quint8 axisMask = 0, Callback done = {}) override;
    void estop(Callback done = {}) override;
    void reset(Callback done = {}) override;
    void setZero(quint8 axisMask, Callback done = {}) override;
    void unlock(Callback done = {}) override;
    void setSoftLimits(int axis, double min, double max, Callback done = {}) override;
    void readStatus(StatusCallback done) override;
    void dwell(double seconds, Callback done) override;
    void pulseTrigger(double widthS, Callback done = {}) override;
    void subscribe(const QVector<dev::proto::ChannelRef>& channels, int rateHz, SubscribeCallback done = {}) override;
    const QVector<dev::proto::ChannelRef>& subscribedChannels() const override { return m_channels; }
    int subscribedRateHz() const override { return m_rateHz; }
    double toAxisUnits(const dev::proto::ChannelRef& channel, std::int32_t value) const override;
    PathClient* paths() override;
    TuningClient* tuning() override { return nullptr; }

    // ---- for the parts (GrblPathClient) ----------------------------------------------------
    /// What became of one line: acknowledged (ack->ok, or error:N), or lost (nullopt) to a
    /// reset or a dropped link.
    using LineDone = std::function<void(const std::optional<dev::grbl::Streamer::Ack>& ack)>;
    /// Queues a line; false (and nothing queued) when the streamer refuses it (too long, a
    /// control byte) or the link is not ready.
    bool sendLine(const std::string& line, LineDone done);
    void sendRealtime(std::uint8_t byte);
    /// Feed hold, then once GRBL holds at rest a soft reset that flushes every queued line and
    /// keeps the position; `done` when the controller is back (its banner), or with an error.
    void holdThenFlush(Callback done);
    /// Instrument position of GRBL's axes `gx` (mm), from the last report.
    double instrumentValue(int axis, const std::vector<double>& workMm) const;
    int grblIndexOf(int axis) const;
    /// The controller's letter for instrument axis `axis` ('X', 'A', …); 0 when unmapped.
    char grblLetterOf(int axis) const;
    std::optional<double> feedMmMin() const { return m_reports.tracker.feedMmMin(); }
    const std::vector<double>& workPositionMm() const { return m_reports.workMm; }
    /// True when the streamer holds no line in flight or queued.
    bool linesIdle() const;
    quint64 nowUs() const;
    /// A GRBL error answering `line`: grbl.error{code, line, request} where `request` is the term
    /// of the command it refused ("request.home").
    static RequestError errorOf(int code, const std::string& line, const std::string& request);
    /// The unit an instrument axis' values carry in messages (mm, or µL for the pump).
    motion::msg::Unit unitOf(int axis) const;

signals:
    /// A status report was applied (after statusChanged): for the parts.
    void reportApplied(quint64 querySentUs);
    /// The controller reset (its banner): everything queued was lost. `expected`: this host asked.
    void controllerReset(bool expected);
    /// ALARM:N arrived.
    void alarmRaised(int code);

protected:
    motion::msg::Message missingReason(Capability c) const override;

private:
    enum class Phase { Closed, Syncing, Identifying, Ready };
    struct PendingLine {
        LineDone done;
        bool alone = false;  ///< writes EEPROM: nothing else in flight while it is
    };

    // grbl_client.cpp: link, handshake, lines.
    void setState(LinkState s);
    void onOpened();
    void writeSync();
    void onBytes(const QByteArray& bytes);
    void onLine(const dev::grbl::LineReader::Line& line);
    void onAck(bool ok, int code);
    void onBanner(const dev::grbl::Banner& banner);
    void onAlarm(int code);
    void onDeviceMessage(const std::string& text);
    void checkLink();
    void startIdentify();
    void finishIdentify();
    void failConnect(const motion::msg::Message& why);
    void linkGone(const motion::msg::Message& why);
    /// The link ended (closed, lost, or a connection that failed): the reset path they share.
    void endLink(const motion::msg::Message& why);
    using LostLines = std::map<std::uint64_t, PendingLine>;
    /// Empties the line queue and the counts of the lines motion and jogs own; the waiters are
    /// returned for the caller to answer (answerLost) once its own state is consistent.
    LostLines dropLines(const motion::msg::Message& why, std::vector<std::string>* inFlight = nullptr);
    static void answerLost(LostLines& waiting);
    /// The line's tag, or 0 when it cannot be sent.
    std::uint64_t queueLine(const std::string& line, LineDone done, bool alone = false);
    void pump();
    void softReset(bool expected);
    void note(motion::msg::Message m);
    // grbl_client_identity.cpp: identity, capabilities, coordinates.
    bool buildIdentity(motion::msg::Message* why);
    void updateTravel();
    std::string axisLettersOfController() const;
    double scaleOf(int axis) const;
    // grbl_client_status.cpp: polling, status, events, telemetry.
    void poll();
    void sendQuery();
    void onStatusReport(const dev::grbl::StatusReport& r);
    void applyParameters(const dev::grbl::Line& l);
    /// `detail`: what happened (grbl.*, or empty when the kind says it all); `text`: the line the
    /// controller sent, where it sent one ("ALARM:1").
    void emitEvent(dev::proto::EventKind kind, int axis, double position, motion::msg::Message detail = {}, const QString& text = {});
    void settleMotion(quint64 askedUs, dev::grbl::MachineState state);
    void emitTelemetry(const std::vector<double>& workMm);
    // grbl_client_commands.cpp: helpers.
    void sendMotionLines(const std::vector<std::string>& lines, quint8 axes, const std::string& request, Callback done);
    bool established(int axis) const { return (m_positions.established >> axis) & 1u; }
    std::optional<RequestError> checkTarget(int axis, double target) const;
    void finishStop(const std::optional<RequestError>& e);
    // grbl_client_home.cpp: the home set here, across connections.
    std::string controllerKey() const;
    /// At the first report of a connection to a controller without homing: the axes whose home,
    /// set here before, still holds.
    quint32 recallHome(dev::grbl::MachineState state);
    void rememberHome();
    /// When the link ends: where the machine was last seen, for the next connection to compare.
    void keepHomeOnLeave();
    /// The positions are no longer trusted (an alarm, a restart): nor is the home remembered.
    void loseEstablished();
    // grbl_client_jog.cpp: continuous jog.
    void updateJog();
    void topUpJog();
    void cancelJog();
    void sendJogLines(const std::vector<std::string>& lines);
    std::map<int, double> wantedJogVelocities() const;

    dev::files::MachineProfile m_profile;
    bool m_lenient;
    QPointer<Transport> m_transport;
    QList<QMetaObject::Connection> m_transportConnections;
    LinkState m_state = LinkState::Disconnected;
    Phase m_phase = Phase::Closed;
    QElapsedTimer m_clock;
    QTimer m_pollTimer, m_linkTimer, m_jogTimer;
    int m_connectTimeoutMs = kConnectMs;
    std::uint64_t m_nextTag = 1;  ///< line tags are never reused, across resets and connections
    QString m_homeFile, m_homePort;
    bool m_restartHeardBeforeConnect = false;

    // ---- State, grouped by what it belongs to ---------------------------------------------
    // Each group is reset as a whole — assigned afresh, or by its own reset() — so a field
    // added to a group is reset by every path that resets the group. The paths, and the groups
    // each one resets (the functions say why):
    //   connectLink()        Wire, Lines, Controller, Reports, Machine, Stop
    //   identified           the instrument's shape (m_identity, m_map, m_softLimits, m_status)
    //   endLink()            Lines, Waiters (answered), Stop, Motion, Jog, Reports' queries
    //   controller reset     Lines, Reports.sinceReset(), Machine.sinceReset(); unexpected:
    //   (its banner)         also Motion, Jog, Positions
    //   softReset() sent     Lines
    //   estop()              Jog, Motion.axes, then softReset()
    //   ALARM:N              Jog, Motion.axes, Positions (unless it keeps them)
    // m_estopLatched is no group: the operator's latch outlives every reset but reset().

    /// This connection's conversation: reading bytes into lines, the sync, what came in.
    struct Wire {
        dev::grbl::LineReader reader;
        quint64 bytesIn = 0, garbageLines = 0, unknownLines = 0, resets = 0;
        qint64 lastRxMs = -1, connectStartMs = 0, syncSentMs = 0;
        int syncAttempts = 0;
        bool syncSawParserState = false;
        bool sawGrblLine = false;
        bool restartHeard = false;  ///< a start-up banner came before the controller was identified
        int expectedBanners = 0;  ///< soft resets this host sent whose banner has not come yet
    } m_wire;

    /// The lines on their way to the controller and what waits for their answers. Whenever
    /// the controller forgets its buffers or the link ends they are all lost at once
    /// (dropLines(): every waiter answered with nullopt).
    struct Lines {
        dev::grbl::Streamer streamer;  ///< its receive-buffer size ($I) outlives the resets
        std::deque<std::pair<std::string, std::uint64_t>> backlog;  ///< waiting for the streamer (behind an EEPROM line)
        std::map<std::uint64_t, PendingLine> pending;               ///< by streamer tag
        bool aloneInFlight = false;
        bool modalReady = false;  ///< "G54 G17 G94" sent since the last reset
        motion::msg::Message lostReason;  ///< why lines in flight were lost, for the commands that owned them
        /// Empties the queue; the lines in flight (for the message) and the waiters (to answer).
        std::pair<std::vector<dev::grbl::Streamer::Ack>, std::map<std::uint64_t, PendingLine>> reset(const motion::msg::Message& why)
        {
            auto lost = streamer.softReset(true);
            backlog.clear();
            aloneInFlight = false;
            modalReady = false;
            lostReason = why;
            auto waiting = std::move(pending);
            pending.clear();
            return {std::move(lost), std::move(waiting)};
        }
    } m_lines;

    /// What the controller said it is: read afresh at every connection.
    struct Controller {
        dev::grbl::Firmware firmware = dev::grbl::Firmware::Unknown;
        std::string bannerVersion;
        dev::grbl::BuildInfo build;
        dev::grbl::Settings settings;
        dev::grbl::MachineLimits limits;
        std::vector<double> g54Mm, g92Mm;  ///< $#
        double tloMm = 0;
        bool haveParameters = false;
    } m_controller;

    // The instrument the controller is, replaced whole when identified (buildIdentity).
    DeviceIdentity m_identity;
    struct AxisMap {
        int grbl = -1;       ///< index into the controller's axes
        double scale = 1;    ///< instrument units per GRBL mm (µL per mm for the pump)
    };
    QVector<AxisMap> m_map;  ///< per instrument axis
    QVector<SoftLimits> m_softLimits;
    InstrumentStatus m_status;

    /// What the status reports said, and the queries that ask for them.
    struct Reports {
        dev::grbl::StatusTracker tracker;
        std::vector<double> machineMm, workMm, wcoMm;
        std::vector<double> lastWorkMm;  ///< the report before, for motion and velocity
        quint64 lastUs = 0;
        bool first = true;  ///< the first report of the connection decides what is established
        /// Send times of the '?' not answered yet, oldest first (a report answers the oldest:
        /// when GRBL folds two queries into one report, later reports are dated conservatively early).
        std::deque<quint64> querySent;
        bool queryAgain = false;
        /// The controller reset: its state and offsets come again in its next reports, and no
        /// query sent before is answered. The last positions stay on screen until then.
        void sinceReset()
        {
            tracker.reset();
            wcoMm.clear();
            querySent.clear();
            queryAgain = false;
        }
    } m_reports;

    /// What the controller is doing that the host must know to talk to it.
    struct Machine {
        int alarm = 0;
        bool critical = false;  ///< hard or soft limit alarm: GRBL hears nothing but a reset
        bool homing = false;    ///< $H running: GRBL answers no '?' until it ends
        /// A reset ends a critical alarm and a homing cycle; the alarm code stays (ALARM:3 may follow).
        void sinceReset() { critical = homing = false; }
    } m_machine;
    bool m_estopLatched = false;

    /// Which positions are trusted.
    struct Positions {
        quint32 established = 0;  ///< instrument axes whose position is trusted (homed, unlocked, set here)
    } m_positions;

    /// Motion the host commanded, owing MotionDone or Stopped.
    struct Motion {
        quint32 axes = 0;    ///< instrument axes owing MotionDone
        int linesOpen = 0;   ///< their lines not yet acknowledged
        quint64 ackUs = 0;   ///< when the last of them was acknowledged
        /// Axes owing HomeDone: told with the first report asked after $H was acknowledged, so
        /// that the event carries where homing left them, not where the last report before it saw them.
        quint32 homedAxes = 0;
        quint64 homedAckUs = 0;
    } m_motion;

    /// A stop in progress: feed hold, waiting for Hold:0, then the reset.
    struct Stop {
        bool active = false;
        bool resetSent = false;
        quint64 askedUs = 0;  ///< when the feed hold went out: reports asked later judge the hold
        qint64 startMs = 0;
    } m_stop;

    /// Callers waiting for something other than a line's answer; answered, never dropped, when the link ends.
    struct StatusWaiter {
        quint64 sinceUs;
        StatusCallback done;
    };
    struct Waiters {
        std::vector<StatusWaiter> status;
        std::vector<Callback> stop;
        std::vector<Callback> reset;  ///< reset()/estop()/unlock() waiting for the banner
    } m_waiters;

    /// Continuous jog: what is asked (held keys, the joystick), the jog running, and its lines.
    struct Jogs {
        /// The jog lines queued or in flight: they belong to the line queue and are dropped
        /// with it (dropLines()), not before — GRBL still answers each one.
        struct Lines {
            int open = 0;
            std::set<std::uint64_t> tags;
        } lines;
        QHash<int, double> held;        ///< startJog: axis → velocity
        std::map<int, double> stick;    ///< setJogVelocities: axis → velocity
        qint64 stickDeadlineMs = 0;
        std::optional<dev::grbl::ContinuousJog> run;
        std::vector<double> velocityMmS;  ///< per GRBL axis, the vector `run` runs
        bool cancelling = false;
        int linesAtCancel = 0;            ///< jog lines unacknowledged when 0x85 went out
        quint64 cancelSentUs = 0;
        bool refusedSaid = false;
        /// Nothing asked, nothing running: everything but the lines still in the queue.
        void forget()
        {
            Lines keep = std::move(lines);
            *this = Jogs{};
            lines = std::move(keep);
        }
    } m_jogs;

    // Telemetry from status reports: the subscription outlives the link.
    QVector<dev::proto::ChannelRef> m_channels;
    int m_rateHz = 0;
    std::uint32_t m_sampleIndex = 0;

    GrblPathClient* m_paths;
};

} // namespace dev
