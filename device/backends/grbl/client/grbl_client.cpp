// GrblClient, part 1: construction, the link and its state, the handshake that identifies the
// controller, and reading (the answers and pushes every line kind gets). Writing — the
// character-counted queue, realtime bytes, soft resets: grbl_client_write.cpp; identity and
// coordinates: grbl_client_identity.cpp; status and events: grbl_client_status.cpp; commands:
// grbl_client_commands.cpp; continuous jog: grbl_client_jog.cpp.
#include "device/backends/grbl/client/grbl_client.h"

#include "device/backends/grbl/client/grbl_path_client.h"
#include "device/backends/grbl/grbl_codes.h"


#include <cmath>

namespace dev {

namespace {
/// Unknown lines noted one by one up to this, then every kUnknownNoteEvery-th: a flood of
/// garbage (a wrong baud rate) must not bury the event log.
constexpr quint64 kUnknownNotedFirst = 3;
constexpr quint64 kUnknownNoteEvery = 100;
} // namespace

GrblClient::GrblClient(const files::MachineProfile& profile, bool lenient, QObject* parent)
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
    // Callbacks may refer to objects already gone: drop them unanswered.
    m_pending.clear();
    m_statusWaiters.clear();
    m_stopDone.clear();
    m_resetDone.clear();
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
    m_transportConnections << connect(transport, &Transport::failed, this, [this](const msg::Message& why) {
        if (m_state != LinkState::Connecting)
            return;
        failConnect(why);
    });
    m_transportConnections << connect(transport, &Transport::lost, this, [this](const msg::Message& why) { linkGone(why); });
}

QString GrblClient::linkDescription() const { return m_transport ? m_transport->describe() : tr("no link"); }

LinkStats GrblClient::stats() const
{
    LinkStats s;
    s.framesIn = m_bytesIn;
    s.malformed = m_unknownLines;
    s.oversize = m_garbageLines;
    s.droppedBytes = m_reader.droppedBytes();
    s.lateReplies = m_streamer.strayAcks();
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

void GrblClient::note(msg::Message m) { emit noted(m); }

// ---- connecting ---------------------------------------------------------------------------

void GrblClient::connectLink()
{
    if (!m_transport) {
        emit linkError(msg::make("link.no_connection_chosen"));
        return;
    }
    if (m_state == LinkState::Connecting || m_state == LinkState::Identified || m_state == LinkState::Ready)
        return;
    m_phase = Phase::Closed;
    m_reader.clear();
    m_streamer.softReset(true);
    m_backlog.clear();
    m_pending.clear();
    m_aloneInFlight = false;
    m_expectedBanners = 0;
    m_bytesIn = m_garbageLines = m_unknownLines = 0;
    m_sawGrblLine = false;
    m_syncAttempts = 0;
    m_firmware = grbl::Firmware::Unknown;
    m_bannerVersion.clear();
    m_build = grbl::BuildInfo{};
    m_settings.clear();
    m_haveParameters = false;
    m_g54Mm.clear();
    m_g92Mm.clear();
    m_tloMm = 0;
    m_tracker = grbl::StatusTracker{};
    m_querySent.clear();
    m_alarm = 0;
    m_critical = m_homing = m_stopping = false;
    m_modalReady = false;
    m_firstReport = true;
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
    m_connectStartMs = m_clock.elapsed();
    m_lastRxMs = m_connectStartMs;
    m_syncAttempts = 1;
    m_syncSentMs = m_clock.elapsed();
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
    m_syncSawParserState = false;
    m_transport->write(QByteArray("\n$G\n?", 5));
}

void GrblClient::failConnect(const msg::Message& why)
{
    m_pollTimer.stop();
    m_linkTimer.stop();
    m_jogTimer.stop();
    failAllLines(why);
    m_phase = Phase::Closed;
    if (m_transport)
        m_transport->close();
    emit linkError(why);
    setState(LinkState::Disconnected);
}

void GrblClient::disconnectLink()
{
    if (m_state == LinkState::Ready && (m_jog || m_jogCancelling) && m_transport) {
        // A jog queued ahead would run out by itself; cancel it rather than leave it to do so.
        m_transport->write(QByteArray(1, static_cast<char>(grbl::rt::kJogCancel)));
    }
    m_heldJogs.clear();
    m_stickJogs.clear();
    m_jog.reset();
    m_jogCancelling = false;
    m_pollTimer.stop();
    m_linkTimer.stop();
    m_jogTimer.stop();
    failAllLines(msg::make("link.disconnected"));
    m_phase = Phase::Closed;
    if (m_transport)
        m_transport->close();
    setState(LinkState::Disconnected);
}

void GrblClient::linkGone(const msg::Message& why)
{
    if (m_state == LinkState::Disconnected || m_state == LinkState::Lost)
        return;
    m_heldJogs.clear();
    m_stickJogs.clear();
    m_jog.reset();
    m_jogCancelling = false;
    m_pollTimer.stop();
    m_linkTimer.stop();
    m_jogTimer.stop();
    failAllLines(why);
    m_phase = Phase::Closed;
    if (m_transport)
        m_transport->close();
    emit linkError(msg::make("link.lost", {msg::nested("cause", why)}));
    setState(LinkState::Lost);
}

void GrblClient::failAllLines(const msg::Message& why)
{
    m_streamer.softReset(true);
    m_backlog.clear();
    m_aloneInFlight = false;
    auto pending = std::move(m_pending);
    m_pending.clear();
    m_lostReason = why;
    for (auto& [tag, p] : pending)
        if (p.done)
            p.done(std::nullopt);
    RequestError e;
    e.kind = RequestError::Kind::LinkDown;
    e.message = why;
    auto waiters = std::move(m_statusWaiters);
    m_statusWaiters.clear();
    for (auto& w : waiters)
        if (w.done)
            w.done(e, m_status);
    auto stops = std::move(m_stopDone);
    m_stopDone.clear();
    for (auto& d : stops)
        if (d)
            d(e);
    auto resets = std::move(m_resetDone);
    m_resetDone.clear();
    for (auto& d : resets)
        if (d)
            d(e);
    m_stopping = false;
    m_motionAxes = 0;
    m_motionLinesOpen = 0;
    m_jogLinesOpen = 0;
    m_jogTags.clear();
    m_querySent.clear();
}

void GrblClient::checkLink()
{
    const qint64 now = m_clock.elapsed();
    if (m_phase == Phase::Syncing) {
        if (m_syncAttempts < 2 && now - m_syncSentMs > std::min(kResyncMs, m_connectTimeoutMs / 2) && m_transport) {
            // A board that resets when its port opens (an Arduino's DTR) ate the first line
            // while its bootloader ran: say it again.
            ++m_syncAttempts;
            m_syncSentMs = now;
            writeSync();
        }
        if (now - m_connectStartMs > m_connectTimeoutMs) {
            const msg::Arg link = msg::verbatim("link", linkDescription().toStdString());
            const msg::Arg seconds = msg::real("seconds", m_connectTimeoutMs / 1000.0, msg::Unit::S);
            if (m_bytesIn == 0)
                failConnect(msg::make("grbl.connect.no_answer", {link, seconds}));
            else if (!m_sawGrblLine)
                failConnect(msg::make("grbl.connect.no_grbl_line",
                                      {link, msg::integer("bytes", static_cast<long long>(m_bytesIn)), seconds}));
            else
                failConnect(msg::make("grbl.connect.never_acknowledged", {link, seconds}));
        }
        return;
    }
    if (m_phase == Phase::Identifying) {
        if (now - m_lastRxMs > m_connectTimeoutMs)
            failConnect(msg::make("grbl.connect.identify_silent", {msg::verbatim("link", linkDescription().toStdString())}));
        return;
    }
    if (m_phase != Phase::Ready)
        return;
    // GRBL 1.1 does not answer '?' while homing, nor in a critical alarm: silence is expected then.
    if (!m_homing && !m_critical && now - m_lastRxMs > kSilenceMs) {
        const msg::Arg seconds = msg::real("seconds", kSilenceMs / 1000.0, msg::Unit::S);
        linkGone(m_unknownLines > 0
                     ? msg::make("grbl.silent_with_noise", {seconds, msg::integer("count", static_cast<long long>(m_unknownLines))})
                     : msg::make("grbl.silent", {seconds}));
        return;
    }
    if (m_stopping && now - m_stopStartMs > kStopMs) {
        RequestError e;
        e.kind = RequestError::Kind::Timeout;
        e.message = msg::make("grbl.stop_timeout", {msg::real("seconds", kStopMs / 1000.0, msg::Unit::S)});
        finishStop(e);
    }
    if (!m_stickJogs.empty() && now > m_stickDeadlineMs) {
        // The caller stopped renewing the joystick's velocities: stop as a watchdog would.
        m_stickJogs.clear();
        updateJog();
    }
}

void GrblClient::startIdentify()
{
    m_phase = Phase::Identifying;
    const QPointer<GrblClient> self(this);
    auto fail = [self](const std::string& command, const std::optional<grbl::Streamer::Ack>& a) {
        if (!self || self->m_phase != Phase::Identifying)
            return;
        if (!a) {
            self->failConnect(msg::make("grbl.identify.not_answered",
                                        {msg::verbatim("command", command), msg::nested("cause", self->m_lostReason)}));
            return;
        }
        self->failConnect(msg::make("grbl.identify.refused", {msg::verbatim("command", command), msg::integer("code", a->errorCode, msg::Unit::None)}));
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
    msg::Message why;
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
    m_bytesIn += static_cast<quint64>(bytes.size());
    std::vector<grbl::LineReader::Line> lines;
    m_reader.feed(std::string_view(bytes.constData(), static_cast<std::size_t>(bytes.size())), lines);
    for (const auto& l : lines) {
        onLine(l);
        if (m_phase == Phase::Closed)
            return;  // the connection failed on this line
    }
}

void GrblClient::onLine(const grbl::LineReader::Line& raw)
{
    if (raw.truncated) {
        ++m_garbageLines;
        if (m_garbageLines == 1)
            note(msg::make("grbl.line_too_long", {msg::integer("limit", static_cast<long long>(grbl::LineReader::kMaxLineBytes),
                                                                msg::Unit::Byte)}));
        return;
    }
    const grbl::Line l = grbl::classifyLine(raw.text);
    if (l.kind == grbl::LineKind::Unknown) {
        ++m_unknownLines;
        if (m_unknownLines <= kUnknownNotedFirst || m_unknownLines % kUnknownNoteEvery == 0)
            note(msg::make("grbl.unknown_line", {msg::verbatim("line", raw.text.substr(0, 120)),
                                                 msg::integer("count", static_cast<long long>(m_unknownLines))}));
        return;
    }
    if (l.kind == grbl::LineKind::Empty)
        return;
    m_sawGrblLine = true;
    m_lastRxMs = m_clock.elapsed();
    switch (l.kind) {
    case grbl::LineKind::Ok:
    case grbl::LineKind::Error:
        if (m_phase == Phase::Syncing) {
            if (m_syncSawParserState)
                startIdentify();  // $G's answer: from here on, answers pair with lines
            return;
        }
        onAck(l.kind == grbl::LineKind::Ok, l.code);
        return;
    case grbl::LineKind::Alarm: onAlarm(l.code); return;
    case grbl::LineKind::Status: {
        const grbl::StatusParse p = grbl::parseStatusReport(l.payload);
        if (!p.report) {
            note(p.problem);
            return;
        }
        if (m_phase == Phase::Ready)
            onStatusReport(*p.report);
        return;
    }
    case grbl::LineKind::Banner:
        if (const auto b = grbl::parseBanner(raw.text))
            onBanner(*b);
        return;
    case grbl::LineKind::Message: onDeviceMessage(std::string(l.payload)); return;
    case grbl::LineKind::Version:
    case grbl::LineKind::Options: grbl::addBuildInfoLine(m_build, l); return;
    case grbl::LineKind::Bracketed:
        if (!grbl::addBuildInfoLine(m_build, l))
            applyParameters(l);
        return;
    case grbl::LineKind::Setting:
        if (const auto s = grbl::parseSettingLine(raw.text))
            m_settings.add(*s);
        return;
    case grbl::LineKind::ParserState:
        if (m_phase == Phase::Syncing) {
            m_syncSawParserState = true;
            return;
        }
        note(msg::make("grbl.device_line", {msg::verbatim("line", raw.text.substr(0, 120))}));
        return;
    case grbl::LineKind::Probe:
        return;  // the last line of every $# answer; this host does not probe
    default:
        return;  // help, echo, startup blocks: nothing to act on
    }
}

void GrblClient::onAck(bool ok, int code)
{
    const auto ack = m_streamer.acknowledge(ok, code);
    if (!ack) {
        // An answer with nothing in flight: a second answer to a sync, or a line someone else
        // sent. Counted (stats().lateReplies); it is never matched to a later line.
        return;
    }
    const auto it = m_pending.find(ack->tag);
    LineDone done;
    if (it != m_pending.end()) {
        if (it->second.alone)
            m_aloneInFlight = false;
        done = std::move(it->second.done);
        m_pending.erase(it);
    }
    if (done)
        done(ack);
    // After an error the streamer holds back what follows; each command decides for itself
    // (a pattern stops its own job), so the others go on.
    m_streamer.resume();
    pump();
}

void GrblClient::onBanner(const grbl::Banner& banner)
{
    if (m_firmware == grbl::Firmware::Unknown || banner.firmware == grbl::Firmware::GrblHal)
        m_firmware = banner.firmware;
    m_bannerVersion = banner.version;
    m_sawGrblLine = true;
    m_modalReady = false;
    if (m_phase == Phase::Syncing) {
        // The controller just started (an Arduino resets when its port opens). If the sync line
        // came before the reset it was lost: ask again soon unless its answer arrives.
        m_syncSentMs = std::min(m_syncSentMs, m_clock.elapsed() - kResyncMs + 300);
        m_syncAttempts = std::min(m_syncAttempts, 1);
        return;
    }
    ++m_resets;
    const bool expected = m_expectedBanners > 0;
    if (expected) {
        --m_expectedBanners;
    } else {
        // Nobody here asked for it: a power glitch, another program, a watchdog. Everything in
        // flight is gone and the position can no longer be trusted.
        std::vector<std::string> lost;
        for (const auto& a : m_streamer.softReset(true))
            lost.push_back(a.line);
        m_backlog.clear();
        m_aloneInFlight = false;
        m_lostReason = msg::make("grbl.reset_by_itself");
        auto pending = std::move(m_pending);
        m_pending.clear();
        m_established = 0;
        m_motionAxes = 0;
        m_motionLinesOpen = 0;
        m_jogLinesOpen = 0;
        m_jogTags.clear();
        m_jog.reset();
        m_heldJogs.clear();
        m_stickJogs.clear();
        m_jogCancelling = false;
        const msg::Message detail = msg::make(
            "grbl.controller_reset", {msg::integer("lost", static_cast<long long>(lost.size())),
                                      msg::verbatim("first", lost.empty() ? std::string() : lost.front())});
        emitEvent(proto::EventKind::Fault, -1, 0, detail);
        for (auto& [tag, p] : pending)
            if (p.done)
                p.done(std::nullopt);
    }
    m_tracker.reset();
    m_wcoMm.clear();
    m_querySent.clear();
    m_critical = false;
    m_homing = false;
    if (m_phase == Phase::Identifying) {
        // A reset in the middle of identification: start again from the sync.
        m_phase = Phase::Syncing;
        m_syncAttempts = 1;
        m_syncSentMs = m_clock.elapsed();
        writeSync();
        return;
    }
    // The offsets may have changed with the reset (G92 is forgotten): read them again.
    queueLine("$#", {});
    emit controllerReset(expected);
    if (m_stopping)
        finishStop(std::nullopt);
    auto resets = std::move(m_resetDone);
    m_resetDone.clear();
    for (auto& d : resets)
        if (d)
            d(std::nullopt);
    sendQuery();
}

void GrblClient::onDeviceMessage(const std::string& text)
{
    if (text == "Reset to continue")
        m_critical = true;  // GRBL now hears nothing but 0x18
    note(msg::make("grbl.device_message", {msg::verbatim("text", text.substr(0, 200))}));
}

} // namespace dev
