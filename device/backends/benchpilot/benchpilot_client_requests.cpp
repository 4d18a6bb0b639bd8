// BenchPilotClient, part 2 of 5: the request machinery. Sequence numbers, the
// one-in-flight queue beside the realtime requests that overtake it, per-attempt
// timeouts with retransmission, and matching incoming frames to the requests
// they answer (events and telemetry are handed on as signals). The other parts:
// benchpilot_client.cpp (connection, handshake), benchpilot_client_status.cpp,
// benchpilot_client_commands.cpp.
#include "device/backends/benchpilot/benchpilot_client.h"
#include "device/backends/benchpilot/event_reason.h"
#include "device/backends/benchpilot/refusal_value.h"

#include <algorithm>
#include <cmath>

namespace dev {
namespace {
QString typeName(dev::proto::MsgType t)
{
    switch (t) {
    case dev::proto::MsgType::Hello: return QStringLiteral("HELLO");
    case dev::proto::MsgType::Status: return QStringLiteral("STATUS");
    case dev::proto::MsgType::Home: return QStringLiteral("HOME");
    case dev::proto::MsgType::Move: return QStringLiteral("MOVE");
    case dev::proto::MsgType::JogStep: return QStringLiteral("JOG_STEP");
    case dev::proto::MsgType::SetZero: return QStringLiteral("SET_ZERO");
    case dev::proto::MsgType::GetLimits: return QStringLiteral("GET_LIMITS");
    case dev::proto::MsgType::SetLimits: return QStringLiteral("SET_LIMITS");
    case dev::proto::MsgType::Subscribe: return QStringLiteral("SUBSCRIBE");
    case dev::proto::MsgType::Reset: return QStringLiteral("RESET");
    case dev::proto::MsgType::JogVelocity: return QStringLiteral("JOG_VELOCITY");
    case dev::proto::MsgType::Stop: return QStringLiteral("STOP");
    case dev::proto::MsgType::EStop: return QStringLiteral("ESTOP");
    case dev::proto::MsgType::PathBegin: return QStringLiteral("PATH_BEGIN");
    case dev::proto::MsgType::PathAppend: return QStringLiteral("PATH_APPEND");
    case dev::proto::MsgType::PathStatus: return QStringLiteral("PATH_STATUS");
    case dev::proto::MsgType::ArchMove: return QStringLiteral("ARCH_MOVE");
    case dev::proto::MsgType::PathHold: return QStringLiteral("PATH_HOLD");
    case dev::proto::MsgType::PathResume: return QStringLiteral("PATH_RESUME");
    case dev::proto::MsgType::PathClear: return QStringLiteral("PATH_CLEAR");
    default: break;
    }
    // The tuning and compensation requests are numbered in their own headers.
    switch (static_cast<int>(t)) {
    case 0x0B: return QStringLiteral("GET_GAINS");
    case 0x0C: return QStringLiteral("SET_GAINS");
    case 0x0D: return QStringLiteral("STEP_TEST");
    case 0x0E: return QStringLiteral("RELAY_TEST");
    case 0x0F: return QStringLiteral("GET_CAPTURE");
    case 0x23: return QStringLiteral("TEST_ABORT");
    case 0x1B: return QStringLiteral("COMP_UPLOAD");
    case 0x1C: return QStringLiteral("COMP_GET");
    case 0x1D: return QStringLiteral("COMP_ENABLE");
    default: return QStringLiteral("0x%1").arg(static_cast<int>(t), 2, 16, QLatin1Char('0'));
    }
}
} // namespace

// ---- requests -------------------------------------------------------------------

void BenchPilotClient::send(dev::proto::MsgType type, const dev::proto::Bytes& payload, RawDone done)
{
    Request r;
    r.type = type;
    r.realtime = dev::proto::isRealtimeType(static_cast<std::uint8_t>(type));
    r.done = std::move(done);
    if (!m_transport || !m_transport->isOpen()) {
        RequestError e;
        e.kind = RequestError::Kind::LinkDown;
        e.message = motion::msg::make("request.not_sent", {motion::msg::verbatim("request", typeName(type).toStdString())});
        if (r.done)
            r.done(e, {});
        return;
    }
    r.seq = m_nextSeq++;
    if (m_nextSeq == 0)
        m_nextSeq = 1;
    std::vector<std::uint8_t> wire;
    dev::proto::encodeFrame(static_cast<std::uint8_t>(type), r.seq, payload.data(), payload.size(), wire);
    r.wire = QByteArray(reinterpret_cast<const char*>(wire.data()), static_cast<qsizetype>(wire.size()));
    if (r.realtime) {
        // Realtime requests overtake anything queued: they go out at once.
        const std::uint16_t seq = r.seq;
        transmit(r);
        m_realtime.emplace(seq, std::move(r));
        if (type == dev::proto::MsgType::JogVelocity || type == dev::proto::MsgType::Stop || type == dev::proto::MsgType::EStop)
            dropSupersededJogs(seq);
        return;
    }
    m_queue.push_back(std::move(r));
    pumpQueue();
}

void BenchPilotClient::addRttSample(double ms)
{
    if (m_srttMs < 0) {
        m_srttMs = ms;
        m_rttVarMs = ms / 2;
    } else {
        m_rttVarMs = 0.75 * m_rttVarMs + 0.25 * std::abs(m_srttMs - ms);
        m_srttMs = 0.875 * m_srttMs + 0.125 * ms;
    }
}

int BenchPilotClient::replyTimeoutMs() const
{
    if (m_srttMs < 0)
        return kInitialReplyTimeoutMs;
    // RFC 6298's retransmission timeout, with a floor for an event loop that hiccups
    // (a retry costs a few bytes; the device answers a repeat from its cache).
    const double rto = m_srttMs + std::max(10.0, 4 * m_rttVarMs);
    return std::clamp(static_cast<int>(std::lround(rto)), kMinReplyTimeoutMs, kMaxReplyTimeoutMs);
}

void BenchPilotClient::transmit(Request& r)
{
    ++r.attempts;
    if (r.attempts > 1)
        ++m_stats.retransmits;
    else
        r.firstSentMs = nowMs();
    r.deadlineMs = nowMs() + replyTimeoutMs();
    if (m_transport)
        m_transport->write(r.wire);
}

void BenchPilotClient::pumpQueue()
{
    if (m_inFlight || m_queue.empty())
        return;
    m_inFlight = true;
    transmit(m_queue.front());
}

void BenchPilotClient::complete(Request r, const std::optional<RequestError>& err, const dev::proto::Bytes& payload)
{
    if (r.done)
        r.done(err, payload);
}

void BenchPilotClient::dropSupersededJogs(std::uint16_t newerSeq)
{
    // A velocity command still unanswered when a newer velocity, stop or E-stop goes out
    // is no longer wanted: retrying it could set an old velocity after the newer one
    // (an axis restarted after its stop). Its caller hears it was accepted; what it
    // asked for was replaced by what came after.
    std::vector<Request> superseded;
    for (auto it = m_realtime.begin(); it != m_realtime.end();) {
        if (it->second.type == dev::proto::MsgType::JogVelocity && it->first != newerSeq) {
            superseded.push_back(std::move(it->second));
            it = m_realtime.erase(it);
        } else {
            ++it;
        }
    }
    // Called back only once the map is consistent: a callback may send again.
    for (auto& r : superseded)
        complete(std::move(r), std::nullopt, {});
}

void BenchPilotClient::checkTimeouts()
{
    const qint64 now = nowMs();
    // After the event loop was held up (a busy GUI thread, a slow machine) the device's
    // answers of that time wait in the queue behind this tick; the in-process simulator
    // has not even run yet. Time the host spent held up is not time the device took:
    // every waiting request's clocks move on by the hold-up, so nothing is resent and no
    // device is called silent for it. A loop that is always late still gains 20 ms a tick.
    const qint64 heldMs = m_lastCheckMs > 0 ? now - m_lastCheckMs - kCheckPeriodMs : 0;
    m_lastCheckMs = now;
    if (heldMs > kStallMs - kCheckPeriodMs) {
        ++m_stats.stalls;
        auto postpone = [heldMs](Request& r) {
            r.deadlineMs += heldMs;
            r.firstSentMs += heldMs;
            r.heldUp = true;
        };
        if (m_inFlight && !m_queue.empty())
            postpone(m_queue.front());
        for (auto& [seq, r] : m_realtime)
            postpone(r);
        if (m_lastFrameMs >= 0)
            m_lastFrameMs = std::min(m_lastFrameMs + heldMs, now);
        if (m_lastDamagedFrameMs >= 0)
            m_lastDamagedFrameMs = std::min(m_lastDamagedFrameMs + heldMs, now);
        m_connectStartedMs += heldMs;
    }
    // The device is silent when a request has waited longer than kSilenceLimitMs and no
    // good frame (reply, event, telemetry) came in that time. Corrupted frames do not
    // count: a line at the wrong baud rate is all garbage.
    qint64 oldestWaitingMs = -1;
    if (m_inFlight && !m_queue.empty())
        oldestWaitingMs = m_queue.front().firstSentMs;
    for (const auto& [seq, r] : m_realtime)
        if (oldestWaitingMs < 0 || r.firstSentMs < oldestWaitingMs)
            oldestWaitingMs = r.firstSentMs;
    bool silent = oldestWaitingMs >= 0 && now - std::max(m_lastFrameMs, oldestWaitingMs) > kSilenceLimitMs;
    if (m_state == LinkState::Connecting && oldestWaitingMs >= 0) {
        // The HELLO reply is the longest frame (~300 bytes with its limits): at 1 % of bytes
        // damaged it arrives whole one time in twenty. Frames that arrive damaged show a
        // device answering on a noisy line, so the handshake goes on trying for up to
        // kConnectGiveUpMs; a line that is all garbage (a wrong baud rate) ends there too.
        const qint64 lastSign = std::max({m_lastFrameMs, m_lastDamagedFrameMs, oldestWaitingMs});
        silent = now - lastSign > kSilenceLimitMs || now - m_connectStartedMs > kConnectGiveUpMs;
    }
    if (silent && (m_state == LinkState::Ready || m_state == LinkState::Identified)) {
        ++m_stats.timeouts;
        linkGone(motion::msg::make("link.stopped_answering"));
        return;
    }
    auto timeoutError = [now](const Request& r) {
        RequestError e;
        e.kind = RequestError::Kind::Timeout;
        e.message = motion::msg::make("request.no_reply", {motion::msg::verbatim("request", typeName(r.type).toStdString()),
                                                   motion::msg::integer("attempts", r.attempts),
                                                   motion::msg::real("seconds", (now - r.firstSentMs) / 1000.0, motion::msg::Unit::S)});
        return e;
    };
    // Given up: everything while connecting to a silent device; otherwise a request the
    // device has ignored for kRequestGiveUpMs while it kept talking. While connecting the
    // handshake's own patience (kConnectGiveUpMs, in `silent`) rules: the 5 s of a request
    // cut a HELLO short on a noisy line whose device was answering.
    auto givenUp = [&](const Request& r) {
        return silent || (m_state != LinkState::Connecting && now - r.firstSentMs > kRequestGiveUpMs);
    };
    std::vector<Request> expired;
    if (m_inFlight && !m_queue.empty()) {
        Request& r = m_queue.front();
        if (givenUp(r)) {
            expired.push_back(std::move(r));
            m_queue.pop_front();
            m_inFlight = false;
        } else if (r.deadlineMs <= now) {
            transmit(r);  // same seq, same bytes: the device answers a repeat from its cache
        }
    }
    for (auto it = m_realtime.begin(); it != m_realtime.end();) {
        if (givenUp(it->second)) {
            expired.push_back(std::move(it->second));
            it = m_realtime.erase(it);
            continue;
        }
        if (it->second.deadlineMs <= now)
            transmit(it->second);
        ++it;
    }
    for (auto& r : expired) {
        ++m_stats.timeouts;
        const RequestError e = timeoutError(r);
        complete(std::move(r), e, {});
    }
    pumpQueue();
}

void BenchPilotClient::failAll(RequestError::Kind kind, const motion::msg::Message& why)
{
    std::deque<Request> queue;
    queue.swap(m_queue);
    std::map<std::uint16_t, Request> rt;
    rt.swap(m_realtime);
    m_inFlight = false;
    m_statusPending = false;
    RequestError e;
    e.kind = kind;
    for (auto& r : queue) {
        e.message = motion::msg::make("request.abandoned", {motion::msg::verbatim("request", typeName(r.type).toStdString()), motion::msg::nested("cause", why)});
        if (r.done)
            r.done(e, {});
    }
    for (auto& [seq, r] : rt) {
        e.message = motion::msg::make("request.abandoned", {motion::msg::verbatim("request", typeName(r.type).toStdString()), motion::msg::nested("cause", why)});
        if (r.done)
            r.done(e, {});
    }
}

// ---- incoming -------------------------------------------------------------------

void BenchPilotClient::onBytes(const QByteArray& bytes)
{
    m_frames.clear();
    const auto& ds = m_decoder.stats();
    const quint64 damagedBefore = ds.crcErrors + ds.malformed;
    m_decoder.feed(reinterpret_cast<const std::uint8_t*>(bytes.constData()), static_cast<std::size_t>(bytes.size()), m_frames);
    if (!m_frames.empty())
        m_lastFrameMs = nowMs();  // garbage alone does not show the device is alive
    if (ds.crcErrors + ds.malformed > damagedBefore)
        m_lastDamagedFrameMs = nowMs();  // but while connecting, a frame damaged on the way may
    for (const auto& f : m_frames)
        onFrame(f);
}

RequestError BenchPilotClient::deviceError(const dev::proto::ErrorReply& e) const
{
    RequestError r;
    r.kind = RequestError::Kind::Device;
    r.code = e.code;
    r.axis = e.axis == dev::proto::kNoAxis ? -1 : e.axis;
    r.value = (r.axis >= 0 && r.axis < m_identity.axes.size()) ? e.value / m_identity.axes[r.axis].wireScale() : e.value;
    // The device's own words (firmware text, English) stay beside the code, which is
    // what the wording layer words.
    std::vector<motion::msg::Arg> args{motion::msg::term("code", dev::proto::errorCodeTerm(e.code)), motion::msg::verbatim("detail", e.message)};
    const bool onAxis = r.axis >= 0 && r.axis < m_identity.axes.size();
    if (onAxis)
        args.push_back(motion::msg::verbatim("axis", QString(m_identity.axes[r.axis].letter).toStdString()));
    if (auto v = refusalValue(e, onAxis ? &m_identity.axes[r.axis] : nullptr))
        args.push_back(std::move(*v));
    r.message = motion::msg::make("device.refused", std::move(args));
    return r;
}

void BenchPilotClient::onFrame(const dev::proto::Frame& f)
{
    if (f.type == static_cast<std::uint8_t>(dev::proto::MsgType::Event)) {
        // A frame repeated on the line is one event, not two (a MotionDone counted twice
        // would finish the next move early).
        if (seenEvent(f.seq)) {
            ++m_duplicateFrames;
            return;
        }
        if (auto e = dev::proto::decodeEvent(f.payload)) {
            DeviceEvent ev;
            ev.kind = e->kind;
            ev.axis = e->axis == dev::proto::kNoAxis ? -1 : e->axis;
            // Instrument-wide events keep the number as sent (path events carry a segment index there).
            ev.position = (ev.axis >= 0 && ev.axis < m_identity.axes.size()) ? e->position / m_identity.axes[ev.axis].wireScale()
                                                                              : e->position;
            ev.deviceTimeUs = e->deviceTimeUs;
            ev.text = QString::fromStdString(e->text);
            ev.hostTime = QDateTime::currentDateTime();
            if (e->reason) {
                const bool onAxis = ev.axis >= 0 && ev.axis < m_identity.axes.size();
                const std::string letter = onAxis ? QString(m_identity.axes[ev.axis].letter).toStdString() : std::string();
                const auto unit = onAxis ? m_identity.axes[ev.axis].unit : dev::proto::AxisUnit::Millimetre;
                if (auto m = eventReasonMessage(ev.kind, *e->reason, letter, unit)) {
                    ev.detail = std::move(*m);
                    ev.worded = true;
                }
            }
            // Homing moves the coordinate origin, and with it the limits' numbers.
            if (ev.kind == dev::proto::EventKind::HomeDone)
                refreshLimits();
            emit eventReceived(ev);
        }
        return;
    }
    if (f.type == static_cast<std::uint8_t>(dev::proto::MsgType::TelemetryBatch)) {
        auto b = dev::proto::decodeTelemetryBatch(f.payload);
        if (!b)
            return;
        // A batch from before the next expected sample is a repeat of one already had.
        if (m_haveSampleIndex && m_nextSampleIndex - b->firstSampleIndex - 1u < 0x80000000u) {
            ++m_duplicateFrames;
            return;
        }
        ++m_stats.telemetryBatches;
        m_stats.telemetrySamples += b->sampleCount;
        // The sample counter runs on across batches: a jump is samples the wire lost.
        if (m_haveSampleIndex && b->firstSampleIndex != m_nextSampleIndex) {
            const std::uint32_t gap = b->firstSampleIndex - m_nextSampleIndex;
            if (gap < 0x80000000u) {
                m_stats.lostSamples += gap;
                emit samplesLost(m_stats.lostSamples);
            }
        }
        m_haveSampleIndex = true;
        m_nextSampleIndex = b->firstSampleIndex + b->sampleCount;
        emit telemetryReceived(*b);
        return;
    }
    const bool isError = f.type == static_cast<std::uint8_t>(dev::proto::MsgType::Error);
    if (!isError && !dev::proto::isReplyType(f.type))
        return;
    auto matches = [&](const Request& r) {
        return r.seq == f.seq && (isError || f.type == dev::proto::replyTypeOf(r.type));
    };
    Request r;
    if (m_inFlight && !m_queue.empty() && matches(m_queue.front())) {
        r = std::move(m_queue.front());
        m_queue.pop_front();
        m_inFlight = false;
    } else if (auto it = m_realtime.find(f.seq); it != m_realtime.end() && matches(it->second)) {
        r = std::move(it->second);
        m_realtime.erase(it);
    } else {
        ++m_stats.lateReplies;  // an answer to a retransmission we already had, or to a forgotten request
        for (auto rt = m_retried.begin(); rt != m_retried.end(); ++rt)
            if (rt->seq == f.seq) {
                addRttSample(static_cast<double>(rt->answeredMs - rt->firstSentMs));
                m_retried.erase(rt);
                break;
            }
        return;
    }
    if (r.heldUp) {
        // Its clocks were moved on by a hold-up of the host: no measure of the line.
    } else if (r.attempts == 1) {
        // Karn's rule: only a request sent once gives an unambiguous round trip.
        addRttSample(static_cast<double>(nowMs() - r.firstSentMs));
    } else {
        // Retried: if a second answer comes later, the retries were early and the first
        // answer was to the first attempt (a timeout shorter than the round trip).
        m_retried.push_back({r.seq, r.firstSentMs, nowMs()});
        if (m_retried.size() > 16)
            m_retried.pop_front();
    }
    if (isError) {
        const auto e = dev::proto::decodeErrorReply(f.payload);
        RequestError err;
        if (e) {
            err = deviceError(*e);
        } else {
            err.kind = RequestError::Kind::Device;
            err.message = motion::msg::make("request.unreadable_error", {motion::msg::verbatim("request", typeName(r.type).toStdString())});
        }
        complete(std::move(r), err, {});
    } else {
        complete(std::move(r), std::nullopt, f.payload);
    }
    pumpQueue();
}

bool BenchPilotClient::seenEvent(std::uint16_t seq)
{
    const std::size_t n = std::min(m_recentEventCount, m_recentEvents.size());
    for (std::size_t i = 0; i < n; ++i)
        if (m_recentEvents[i] == seq)
            return true;
    m_recentEvents[m_recentEventNext] = seq;
    m_recentEventNext = (m_recentEventNext + 1) % m_recentEvents.size();
    ++m_recentEventCount;
    return false;
}

// ---- replies handed to callers ---------------------------------------------------

BenchPilotClient::RawDone BenchPilotClient::wrap(Callback done, const std::string& what)
{
    return [this, done = std::move(done), what](const std::optional<RequestError>& e, const dev::proto::Bytes&) {
        if (e) {
            RequestError err = *e;
            if (!what.empty() && err.kind == RequestError::Kind::Device)
                err.message = motion::msg::make("request.refused", {motion::msg::term("action", what), motion::msg::nested("cause", err.message)});
            emit requestFailed(err);
            if (done)
                done(err);
        } else if (done) {
            done(std::nullopt);
        }
    };
}

void BenchPilotClient::request(dev::proto::MsgType type, const dev::proto::Bytes& payload, ReplyCallback done, const std::string& what)
{
    send(type, payload, [this, done = std::move(done), what](const std::optional<RequestError>& e, const dev::proto::Bytes& reply) {
        if (e) {
            RequestError err = *e;
            if (!what.empty() && err.kind == RequestError::Kind::Device)
                err.message = motion::msg::make("request.refused", {motion::msg::term("action", what), motion::msg::nested("cause", err.message)});
            emit requestFailed(err);
            if (done)
                done(err, reply);
        } else if (done) {
            done(std::nullopt, reply);
        }
    });
}

} // namespace dev
