// GrblClient, part 1: construction, the link and its state, the handshake that identifies the
// controller, and reading (the answers and pushes every line kind gets). Writing — the
// character-counted queue, realtime bytes, soft resets: grbl_client_write.cpp; identity and
// coordinates: grbl_client_identity.cpp; status and events: grbl_client_status.cpp; commands:
// grbl_client_commands.cpp; continuous jog: grbl_client_jog.cpp.
#include "device/backends/grbl/client/grbl_client.h"

#include "device/backends/grbl/client/grbl_path_client.h"
#include "device/backends/grbl/grbl_codes.h"


#include <cmath>
#include <utility>

namespace dev {

namespace {
/// Unknown lines noted one by one up to this, then every kUnknownNoteEvery-th: a flood of
/// garbage (a wrong baud rate) must not bury the event log.
constexpr quint64 kUnknownNotedFirst = 3;
constexpr quint64 kUnknownNoteEvery = 100;
} // namespace

GrblClient::GrblClient(const dev::files::MachineProfile& profile, bool lenient, QObject* parent)
    : Instrument(parent), m_profile(profile), m_lenient(lenient), m_paths(new GrblPathClient(this, this))
{
    m_clock.start();
    m_pollTimer.setInterval(std::max(20, static_cast<int>(std::lround(1000.0 / std::max(1.0, m_profile.statusPollHz)))));
    m_pollTimer.setTimerType(Qt::PreciseTimer);
    connect(&m_pollTimer, &QTimer::timeout, this, &GrblClient::poll);
    m_linkTimer.setInterval(50);
    connect(&m_linkTimer, &QTimer::timeout, this, &GrblClient::checkLink);
    m_jogTimer.setInterval(std::max(5, static_cast<int>(std::lround(m_profile.jog.refreshS * 1000))));
    m_jogTimer.setTimerType(Qt::PreciseTimer);
    connect(&m_jogTimer, &QTimer::timeout, this, &GrblClient::topUpJog);
}

GrblClient::~GrblClient()
{
    // A program that ends without closing the link (a CLI run) leaves where the machine stands.
    if (m_phase == Phase::Ready)
        keepHomeOnLeave();
    // Callbacks may refer to objects already gone: drop them unanswered.
    m_lines.pending.clear();
    m_waiters.status.clear();
    m_waiters.stop.clear();
    m_waiters.reset.clear();
    for (const auto& c : m_transportConnections)
        disconnect(c);
}

quint64 GrblClient::nowUs() const { return static_cast<quint64>(m_clock.nsecsElapsed() / 1000); }

void GrblClient::setTransport(Transport* transport)
{
    if (m_transport) {
        disconnectLink();
        for (const auto& c : m_transportConnections)
            disconnect(c);
        m_transportConnections.clear();
    }
    m_transport = transport;
    if (!transport)
        return;
    m_transportConnections << connect(transport, &Transport::bytesReceived, this, &GrblClient::onBytes);
    m_transportConnections << connect(transport, &Transport::opened, this, [this] {
        if (m_state == LinkState::Connecting && m_phase == Phase::Closed)
            onOpened();
    });
    m_transportConnections << connect(transport, &Transport::failed, this, [this](const motion::msg::Message& why) {
        if (m_state != LinkState::Connecting)
            return;
        failConnect(why);
    });
    m_transportConnections << connect(transport, &Transport::lost, this, [this](const motion::msg::Message& why) { linkGone(why); });
}

QString GrblClient::linkDescription() const { return m_transport ? m_transport->describe() : tr("no link"); }

LinkStats GrblClient::stats() const
{
    LinkStats s;
    s.framesIn = m_wire.bytesIn;
    s.malformed = m_wire.unknownLines;
    s.oversize = m_wire.garbageLines;
    s.droppedBytes = m_wire.reader.droppedBytes();
    s.lateReplies = m_lines.streamer.strayAcks();
    s.telemetrySamples = m_sampleIndex;
    s.telemetryBatches = m_sampleIndex;
    return s;
}

void GrblClient::setState(LinkState s)
{
    if (m_state == s)
        return;
    m_state = s;
    emit stateChanged(s);
}

void GrblClient::note(motion::msg::Message m) { emit noted(m); }

// ---- connecting ---------------------------------------------------------------------------

void GrblClient::connectLink()
{
    if (!m_transport) {
        emit linkError(motion::msg::make("link.no_connection_chosen"));
        return;
    }
    if (m_state == LinkState::Connecting || m_state == LinkState::Identified || m_state == LinkState::Ready)
        return;
    // A new connection: nothing is known of the controller at the other end, not even that it
    // is the one of last time. The conversation, what the controller is, what it reported and
    // its alarm state start afresh. Every way to Disconnected answered the lines and waiters
    // already, so none are left to answer. Kept: the E-stop latch (only reset() clears it), and
    // the instrument's shape and status until the controller is identified again, so a screen
    // goes on showing them while it reconnects.
    m_phase = Phase::Closed;
    m_wire = Wire{};
    m_wire.restartHeard = std::exchange(m_restartHeardBeforeConnect, false);
    dropLines(motion::msg::make("link.disconnected"));
    m_controller = Controller{};
    m_reports = Reports{};
    m_machine = Machine{};
    m_stop = Stop{};
    setState(LinkState::Connecting);
    if (m_transport->isOpen())
        QTimer::singleShot(0, this, [this] {
            if (m_state == LinkState::Connecting && m_phase == Phase::Closed)
                onOpened();
        });
    else
        m_transport->open();
}

void GrblClient::onOpened()
{
    m_phase = Phase::Syncing;
    m_wire.connectStartMs = m_clock.elapsed();
    m_wire.lastRxMs = m_wire.connectStartMs;
    m_wire.syncAttempts = 1;
    m_wire.syncSentMs = m_clock.elapsed();
    writeSync();
    m_linkTimer.start();
}

void GrblClient::writeSync()
{
    // Where this host's conversation begins: "\n" ends whatever someone left in GRBL's line
    // buffer (answered ok, or an error for the leftovers), then $G, answered "[GC:…]" and ok.
    // Answers before the [GC:] line are stale (another program's, or the leftovers'); the first
    // after it belongs to $G, and every later answer pairs with a line of ours. The '?' is
    // answered at once by a GRBL that is up.
    m_wire.syncSawParserState = false;
    m_transport->write(QByteArray("\n$G\n?", 5));
}

void GrblClient::failConnect(const motion::msg::Message& why)
{
    endLink(why);
    emit linkError(why);
    setState(LinkState::Disconnected);
}

void GrblClient::disconnectLink()
{
    if (m_state == LinkState::Ready && (m_jogs.run || m_jogs.cancelling) && m_transport) {
        // A jog queued ahead would run out by itself; cancel it rather than leave it to do so.
        m_transport->write(QByteArray(1, static_cast<char>(dev::grbl::rt::kJogCancel)));
    }
    endLink(motion::msg::make("link.disconnected"));
    setState(LinkState::Disconnected);
}

void GrblClient::linkGone(const motion::msg::Message& why)
{
    if (m_state == LinkState::Disconnected || m_state == LinkState::Lost)
        return;
    endLink(why);
    emit linkError(motion::msg::make("link.lost", {motion::msg::nested("cause", why)}));
    setState(LinkState::Lost);
}

void GrblClient::endLink(const motion::msg::Message& why)
{
    // Nothing more will be answered: every line and every waiter is answered now with `why`,
    // and nothing is owed any more — no motion, no stop, no jog (a jog GRBL still runs ends
    // with its short segments). What the controller is and reported stays until the next
    // connection, for the screens to show.
    if (m_phase == Phase::Ready)
        keepHomeOnLeave();
    m_pollTimer.stop();
    m_linkTimer.stop();
    m_jogTimer.stop();
    m_jogs.forget();
    LostLines lost = dropLines(why);
    answerLost(lost);
    RequestError e;
    e.kind = RequestError::Kind::LinkDown;
    e.message = why;
    Waiters waiters = std::move(m_waiters);
    m_waiters = Waiters{};
    for (auto& w : waiters.status)
        if (w.done)
            w.done(e, m_status);
    for (auto& d : waiters.stop)
        if (d)
            d(e);
    for (auto& d : waiters.reset)
        if (d)
            d(e);
    m_stop = Stop{};
    m_motion = Motion{};
    m_reports.querySent.clear();
    m_reports.queryAgain = false;
    m_phase = Phase::Closed;
    if (m_transport)
        m_transport->close();
}

GrblClient::LostLines GrblClient::dropLines(const motion::msg::Message& why, std::vector<std::string>* inFlight)
{
    auto [acks, waiting] = m_lines.reset(why);
    if (inFlight)
        for (auto& a : acks)
            inFlight->push_back(std::move(a.line));
    // The lines motion and jogs count are gone with the queue; GRBL will answer none of them.
    m_motion.linesOpen = 0;
    m_jogs.lines = Jogs::Lines{};
    return std::move(waiting);
}

void GrblClient::answerLost(LostLines& waiting)
{
    auto answering = std::move(waiting);
    waiting.clear();
    for (auto& [tag, p] : answering)
        if (p.done)
            p.done(std::nullopt);
}

void GrblClient::checkLink()
{
    const qint64 now = m_clock.elapsed();
    if (m_phase == Phase::Syncing) {
        if (m_wire.syncAttempts < 2 && now - m_wire.syncSentMs > std::min(kResyncMs, m_connectTimeoutMs / 2) && m_transport) {
            // A board that resets when its port opens (an Arduino's DTR) ate the first line
            // while its bootloader ran: say it again.
            ++m_wire.syncAttempts;
            m_wire.syncSentMs = now;
            writeSync();
        }
        if (now - m_wire.connectStartMs > m_connectTimeoutMs) {
            const motion::msg::Arg link = motion::msg::verbatim("link", linkDescription().toStdString());
            const motion::msg::Arg seconds = motion::msg::real("seconds", m_connectTimeoutMs / 1000.0, motion::msg::Unit::S);
            if (m_wire.bytesIn == 0)
                failConnect(motion::msg::make("grbl.connect.no_answer", {link, seconds}));
            else if (!m_wire.sawGrblLine)
                failConnect(motion::msg::make("grbl.connect.no_grbl_line",
                                      {link, motion::msg::integer("bytes", static_cast<long long>(m_wire.bytesIn)), seconds}));
            else
                failConnect(motion::msg::make("grbl.connect.never_acknowledged", {link, seconds}));
        }
        return;
    }
    if (m_phase == Phase::Identifying) {
        if (now - m_wire.lastRxMs > m_connectTimeoutMs)
            failConnect(motion::msg::make("grbl.connect.identify_silent", {motion::msg::verbatim("link", linkDescription().toStdString())}));
        return;
    }
    if (m_phase != Phase::Ready)
        return;
    // GRBL 1.1 does not answer '?' while homing, nor in a critical alarm: silence is expected then.
    if (!m_machine.homing && !m_machine.critical && now - m_wire.lastRxMs > kSilenceMs) {
        const motion::msg::Arg seconds = motion::msg::real("seconds", kSilenceMs / 1000.0, motion::msg::Unit::S);
        linkGone(m_wire.unknownLines > 0
                     ? motion::msg::make("grbl.silent_with_noise", {seconds, motion::msg::integer("count", static_cast<long long>(m_wire.unknownLines))})
                     : motion::msg::make("grbl.silent", {seconds}));
        return;
    }
    if (m_stop.active && now - m_stop.startMs > kStopMs) {
        RequestError e;
        e.kind = RequestError::Kind::Timeout;
        e.message = motion::msg::make("grbl.stop_timeout", {motion::msg::real("seconds", kStopMs / 1000.0, motion::msg::Unit::S)});
        finishStop(e);
    }
    if (!m_jogs.stick.empty() && now > m_jogs.stickDeadlineMs) {
        // The caller stopped renewing the joystick's velocities: stop as a watchdog would.
        m_jogs.stick.clear();
        updateJog();
    }
}

void GrblClient::startIdentify()
{
    m_phase = Phase::Identifying;
    const QPointer<GrblClient> self(this);
    auto fail = [self](const std::string& command, const std::optional<dev::grbl::Streamer::Ack>& a) {
        if (!self || self->m_phase != Phase::Identifying)
            return;
        if (!a) {
            self->failConnect(motion::msg::make("grbl.identify.not_answered",
                                        {motion::msg::verbatim("command", command), motion::msg::nested("cause", self->m_lines.lostReason)}));
            return;
        }
        self->failConnect(motion::msg::make("grbl.identify.refused", {motion::msg::verbatim("command", command), motion::msg::integer("code", a->errorCode, motion::msg::Unit::None)}));
    };
    queueLine("$I", [fail](const auto& a) {
        if (!a || !a->ok)
            fail("$I", a);
    });
    queueLine("$$", [fail](const auto& a) {
        if (!a || !a->ok)
            fail("$$", a);
    });
    queueLine("$#", [self, fail](const auto& a) {
        if (!self || self->m_phase != Phase::Identifying)
            return;
        if (!a)
            return fail("$#", a);
        // An old GRBL without $# still works: its work offset comes in the reports.
        self->finishIdentify();
    });
}

void GrblClient::finishIdentify()
{
    motion::msg::Message why;
    if (!buildIdentity(&why)) {
        failConnect(why);
        return;
    }
    m_phase = Phase::Ready;
    setState(LinkState::Identified);
    emit identified(m_identity);
    emit limitsChanged();
    m_pollTimer.start();
    sendQuery();  // Ready with the first report
}

// ---- bytes and lines ----------------------------------------------------------------------

void GrblClient::onBytes(const QByteArray& bytes)
{
    if (m_phase == Phase::Closed)
        return;
    m_wire.bytesIn += static_cast<quint64>(bytes.size());
    std::vector<dev::grbl::LineReader::Line> lines;
    m_wire.reader.feed(std::string_view(bytes.constData(), static_cast<std::size_t>(bytes.size())), lines);
    for (const auto& l : lines) {
        onLine(l);
        if (m_phase == Phase::Closed)
            return;  // the connection failed on this line
    }
}

void GrblClient::onLine(const dev::grbl::LineReader::Line& raw)
{
    if (raw.truncated) {
        ++m_wire.garbageLines;
        if (m_wire.garbageLines == 1)
            note(motion::msg::make("grbl.line_too_long", {motion::msg::integer("limit", static_cast<long long>(dev::grbl::LineReader::kMaxLineBytes),
                                                                motion::msg::Unit::Byte)}));
        return;
    }
    const dev::grbl::Line l = dev::grbl::classifyLine(raw.text);
    if (l.kind == dev::grbl::LineKind::Unknown) {
        ++m_wire.unknownLines;
        if (m_wire.unknownLines <= kUnknownNotedFirst || m_wire.unknownLines % kUnknownNoteEvery == 0)
            note(motion::msg::make("grbl.unknown_line", {motion::msg::verbatim("line", raw.text.substr(0, 120)),
                                                 motion::msg::integer("count", static_cast<long long>(m_wire.unknownLines))}));
        return;
    }
    if (l.kind == dev::grbl::LineKind::Empty)
        return;
    m_wire.sawGrblLine = true;
    m_wire.lastRxMs = m_clock.elapsed();
    switch (l.kind) {
    case dev::grbl::LineKind::Ok:
    case dev::grbl::LineKind::Error:
        if (m_phase == Phase::Syncing) {
            if (m_wire.syncSawParserState)
                startIdentify();  // $G's answer: from here on, answers pair with lines
            return;
        }
        onAck(l.kind == dev::grbl::LineKind::Ok, l.code);
        return;
    case dev::grbl::LineKind::Alarm: onAlarm(l.code); return;
    case dev::grbl::LineKind::Status: {
        const dev::grbl::StatusParse p = dev::grbl::parseStatusReport(l.payload);
        if (!p.report) {
            note(p.problem);
            return;
        }
        if (m_phase == Phase::Ready)
            onStatusReport(*p.report);
        return;
    }
    case dev::grbl::LineKind::Banner:
        if (const auto b = dev::grbl::parseBanner(raw.text))
            onBanner(*b);
        return;
    case dev::grbl::LineKind::Message: onDeviceMessage(std::string(l.payload)); return;
    case dev::grbl::LineKind::Version:
    case dev::grbl::LineKind::Options: dev::grbl::addBuildInfoLine(m_controller.build, l); return;
    case dev::grbl::LineKind::Bracketed:
        if (!dev::grbl::addBuildInfoLine(m_controller.build, l))
            applyParameters(l);
        return;
    case dev::grbl::LineKind::Setting:
        if (const auto s = dev::grbl::parseSettingLine(raw.text))
            m_controller.settings.add(*s);
        return;
    case dev::grbl::LineKind::ParserState:
        if (m_phase == Phase::Syncing) {
            m_wire.syncSawParserState = true;
            return;
        }
        note(motion::msg::make("grbl.device_line", {motion::msg::verbatim("line", raw.text.substr(0, 120))}));
        return;
    case dev::grbl::LineKind::Probe:
        return;  // the last line of every $# answer; this host does not probe
    default:
        return;  // help, echo, startup blocks: nothing to act on
    }
}

void GrblClient::onAck(bool ok, int code)
{
    const auto ack = m_lines.streamer.acknowledge(ok, code);
    if (!ack) {
        // An answer with nothing in flight: a second answer to a sync, or a line someone else
        // sent. Counted (stats().lateReplies); it is never matched to a later line.
        return;
    }
    const auto it = m_lines.pending.find(ack->tag);
    LineDone done;
    if (it != m_lines.pending.end()) {
        if (it->second.alone)
            m_lines.aloneInFlight = false;
        done = std::move(it->second.done);
        m_lines.pending.erase(it);
    }
    if (done)
        done(ack);
    // After an error the streamer holds back what follows; each command decides for itself
    // (a pattern stops its own job), so the others go on.
    m_lines.streamer.resume();
    pump();
}

void GrblClient::onBanner(const dev::grbl::Banner& banner)
{
    if (m_controller.firmware == dev::grbl::Firmware::Unknown || banner.firmware == dev::grbl::Firmware::GrblHal)
        m_controller.firmware = banner.firmware;
    m_controller.bannerVersion = banner.version;
    m_wire.sawGrblLine = true;
    m_lines.modalReady = false;
    if (m_phase != Phase::Ready)
        m_wire.restartHeard = true;
    if (m_phase == Phase::Syncing) {
        // The controller just started (an Arduino resets when its port opens). If the sync line
        // came before the reset it was lost: ask again soon unless its answer arrives.
        m_wire.syncSentMs = std::min(m_wire.syncSentMs, m_clock.elapsed() - kResyncMs + 300);
        m_wire.syncAttempts = std::min(m_wire.syncAttempts, 1);
        return;
    }
    ++m_wire.resets;
    const bool expected = m_wire.expectedBanners > 0;
    if (expected) {
        --m_wire.expectedBanners;
    } else {
        // Nobody here asked for it: a power glitch, another program, a watchdog. Everything in
        // flight is gone, nothing moves, and no position can be trusted any more.
        std::vector<std::string> lost;
        LostLines waiting = dropLines(motion::msg::make("grbl.reset_by_itself"), &lost);
        loseEstablished();
        m_motion = Motion{};
        m_jogs.forget();
        const motion::msg::Message detail = motion::msg::make(
            "grbl.controller_reset", {motion::msg::integer("lost", static_cast<long long>(lost.size())),
                                      motion::msg::verbatim("first", lost.empty() ? std::string() : lost.front())});
        emitEvent(dev::proto::EventKind::Fault, -1, 0, detail);
        answerLost(waiting);
    }
    // Any reset: GRBL tells its state and offsets afresh, and no longer homes or holds a limit alarm.
    m_reports.sinceReset();
    m_machine.sinceReset();
    if (m_phase == Phase::Identifying) {
        // A reset in the middle of identification: start again from the sync.
        m_phase = Phase::Syncing;
        m_wire.syncAttempts = 1;
        m_wire.syncSentMs = m_clock.elapsed();
        writeSync();
        return;
    }
    // The offsets may have changed with the reset (G92 is forgotten): read them again.
    queueLine("$#", {});
    emit controllerReset(expected);
    if (m_stop.active)
        finishStop(std::nullopt);
    auto resets = std::exchange(m_waiters.reset, {});
    for (auto& d : resets)
        if (d)
            d(std::nullopt);
    sendQuery();
}

void GrblClient::onDeviceMessage(const std::string& text)
{
    if (text == "Reset to continue")
        m_machine.critical = true;  // GRBL now hears nothing but 0x18
    note(motion::msg::make("grbl.device_message", {motion::msg::verbatim("text", text.substr(0, 200))}));
}

} // namespace dev
