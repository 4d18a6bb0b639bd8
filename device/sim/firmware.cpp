#include "device/sim/firmware.h"

#include "device/sim/sim_tuning.h"
#include "device/sim/path_queue.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace dev::sim {

namespace {

dev::proto::ErrorReply firmwareUnknownType(std::uint8_t type)
{
    dev::proto::ErrorReply e;
    e.code = dev::proto::ErrorCode::UnknownCommand;
    e.value = type;
    const char* hex = "0123456789ABCDEF";
    e.message = std::string("unknown request type 0x") + hex[(type >> 4) & 15] + hex[type & 15];
    return e;
}

} // namespace

namespace {
constexpr double kLinkHeadroom = 0.9;        // telemetry may use 90% of the wire; replies and events get the rest
constexpr double kBatchLatencyS = 0.02;      // a batch holds at most this much time unless capacity needs more
constexpr double kBusyLinkBatchS = 0.1;      // longest a batch may hold when the link is the limit
}

Firmware::Firmware(const MachineConfig& config, std::uint32_t linkBaud, const NonVolatile& powerUp)
    : m_machine(config, powerUp), m_linkBaud(linkBaud)
{
}

void Firmware::receive(const std::uint8_t* data, std::size_t size)
{
    m_frames.clear();
    m_decoder.feed(data, size, m_frames);
    if (!m_frames.empty()) {
        m_machine.tuning().hostHeard();  // feeds the tuning tests' host-silence watchdog
        m_lastHostFrameS = m_machine.timeS();  // and the path queue's
    }
    // Realtime requests act first: a stop or E-stop decoded in the same chunk as
    // queued requests must not wait behind them.
    for (const auto& f : m_frames)
        if (dev::proto::isRealtimeType(f.type))
            handle(f);
    for (const auto& f : m_frames)
        if (!dev::proto::isRealtimeType(f.type))
            handle(f);
    flushEvents();
}

void Firmware::advance(double dtS)
{
    // A NaN would poison the clock for good and stop the machine's time (and its
    // watchdog) forever; time never runs backwards either.
    if (!(dtS > 0) || !std::isfinite(dtS))
        return;
    m_pendingS += dtS;
    while (m_pendingS >= SimMachine::kTickS * 0.999999) {
        m_pendingS -= SimMachine::kTickS;
        m_machine.tick();
        ++m_tickCount;
        checkHostSilence();
        sampleTelemetry();
        flushEvents();
    }
}

void Firmware::drainOutput(std::vector<std::uint8_t>& out)
{
    out.insert(out.end(), m_out.begin(), m_out.end());
    m_out.clear();
}

void Firmware::sendFrame(std::uint8_t type, std::uint16_t seq, const dev::proto::Bytes& payload, std::vector<std::uint8_t>& out)
{
    dev::proto::encodeFrame(type, seq, payload.data(), payload.size(), out);
}

void Firmware::sendError(std::uint16_t seq, const dev::proto::ErrorReply& e, std::vector<std::uint8_t>& out)
{
    sendFrame(static_cast<std::uint8_t>(dev::proto::MsgType::Error), seq, dev::proto::encode(e), out);
}

void Firmware::flushEvents()
{
    for (auto& e : m_machine.takeEvents()) {
        if (!m_eventReasons)
            e.reason.reset();  // a host that did not ask reads the text alone (docs/protocol.md, "Event reasons")
        if (m_journalOn) {
            JournalEntry j;
            j.timeS = static_cast<double>(e.deviceTimeUs) * 1e-6;
            j.type = static_cast<std::uint8_t>(dev::proto::MsgType::Event);
            j.seq = m_eventSeq;
            j.payload = dev::proto::encode(e);
            m_journal.push_back(std::move(j));
        }
        sendFrame(static_cast<std::uint8_t>(dev::proto::MsgType::Event), m_eventSeq++, dev::proto::encode(e), m_out);
    }
}

void Firmware::handle(const dev::proto::Frame& f)
{
    if (f.type >= 0x80)
        return;  // replies, events and errors: only a device sends those, a device ignores them
    const bool hello = f.type == static_cast<std::uint8_t>(dev::proto::MsgType::Hello);
    const bool repeatOfLast = m_lastQueued.valid && m_lastQueued.type == f.type && m_lastQueued.seq == f.seq
        && m_lastQueued.payload == f.payload;
    if (hello && !repeatOfLast) {
        // A HELLO that is not a repeat of the last queued request starts a new
        // session: a host that restarted numbers its requests afresh, and its
        // first move must not be taken for a retransmission of the previous
        // session's move with the same seq and bytes.
        for (auto& c : m_cache)
            c.valid = false;
        m_haveMotionSeq = false;
        // The host that started a test is gone; a new one has not asked for it.
        m_machine.tuning().abort(0, motion::control::EndReason::Stopped);
        m_machine.paths().sessionStarted();
    }
    for (const auto& c : m_cache) {
        if (c.valid && c.seq == f.seq && c.type == f.type && c.payload == f.payload) {
            ++m_duplicates;
            m_out.insert(m_out.end(), c.reply.begin(), c.reply.end());
            return;
        }
    }
    const bool velocity = f.type == static_cast<std::uint8_t>(dev::proto::MsgType::JogVelocity);
    const bool motionCommand = velocity || f.type == static_cast<std::uint8_t>(dev::proto::MsgType::Stop)
        || f.type == static_cast<std::uint8_t>(dev::proto::MsgType::EStop);
    if (velocity && m_haveMotionSeq && static_cast<std::int16_t>(f.seq - m_lastMotionSeq) < 0) {
        // Sequence numbers rise in the order a host sends: this velocity was sent before
        // the last one acted on, and reaches us late (a retry that lost the race).
        ++m_staleVelocities;
        sendFrame(static_cast<std::uint8_t>(f.type | dev::proto::kReplyFlag), f.seq, {}, m_out);
        return;
    }
    if (motionCommand) {
        m_haveMotionSeq = true;
        m_lastMotionSeq = f.seq;
    }
    CachedReply& slot = m_cache[m_cacheNext];
    m_cacheNext = (m_cacheNext + 1) % m_cache.size();
    slot.valid = true;
    slot.type = f.type;
    slot.seq = f.seq;
    slot.payload = f.payload;
    slot.reply.clear();
    if (!dev::proto::isRealtimeType(f.type))
        m_lastQueued = slot;
    ++m_executed;
    if (m_journalOn) {
        JournalEntry j;
        j.timeS = m_machine.timeS();
        j.type = f.type;
        j.seq = f.seq;
        j.payload = f.payload;
        for (int i = 0; i < m_machine.axisCount(); ++i)
            j.commanded.push_back(m_machine.commandedLogical(i));
        m_journal.push_back(std::move(j));
    }
    execute(f, slot.reply);
    m_out.insert(m_out.end(), slot.reply.begin(), slot.reply.end());
}

void Firmware::sendMalformed(std::uint16_t seq, const char* what, std::vector<std::uint8_t>& out)
{
    dev::proto::ErrorReply e;
    e.code = dev::proto::ErrorCode::BadPayload;
    e.message = std::string("malformed ") + what + " request";
    sendError(seq, e, out);
}

void Firmware::execute(const dev::proto::Frame& f, std::vector<std::uint8_t>& reply)
{
    using dev::proto::MsgType;
    const auto type = static_cast<MsgType>(f.type);
    const std::uint8_t ok = static_cast<std::uint8_t>(f.type | dev::proto::kReplyFlag);
    auto bad = [&](const char* what) { sendMalformed(f.seq, what, reply); };
    auto answer = [&](const SimMachine::Result& r) {
        if (r)
            sendError(f.seq, *r, reply);
        else
            sendFrame(ok, f.seq, {}, reply);
    };
    switch (type) {
    case MsgType::Hello: {
        // Protocol 1.0 firmware knew no HELLO payload and refused one; a host that asks
        // for the extension blocks then asks again without (docs/protocol.md, "HELLO").
        const auto r = dev::proto::decodeHelloRequest(f.payload);
        if (!r || (!m_helloExtensions && !f.payload.empty()))
            return bad("HELLO");
        dev::proto::HelloReply h = m_machine.hello(m_linkBaud);
        m_eventReasons = (r->flags & dev::proto::HelloReadsEventReasons) != 0;
        if (r->flags & dev::proto::HelloReadsExtensions)
            h.motionLimits = m_machine.motionLimits();
        sendFrame(ok, f.seq, dev::proto::encode(h), reply);
        return;
    }
    case MsgType::Status:
        if (!f.payload.empty())
            return bad("STATUS");
        sendFrame(ok, f.seq, dev::proto::encode(m_machine.status()), reply);
        return;
    case MsgType::Home:
        if (auto r = dev::proto::decodeHomeRequest(f.payload))
            return answer(m_machine.home(r->axisMask));
        return bad("HOME");
    case MsgType::Move:
        if (auto r = dev::proto::decodeMoveRequest(f.payload))
            return answer(m_machine.move(*r));
        return bad("MOVE");
    case MsgType::ArchMove:
        // Only a device that says so in HELLO takes it: to another it is an unknown type.
        if (!(m_machine.hello(m_linkBaud).capabilities & dev::proto::kCapArchMove))
            return sendError(f.seq, firmwareUnknownType(f.type), reply);
        if (auto r = dev::proto::decodeArchMoveRequest(f.payload)) {
            if (r->pump && !(m_machine.hello(m_linkBaud).capabilities & dev::proto::kCapArchPump))
                return bad("ARCH_MOVE");  // a pump block this device did not offer: a payload it cannot read
            return answer(m_machine.archMove(*r));
        }
        return bad("ARCH_MOVE");
    case MsgType::JogStep:
        if (auto r = dev::proto::decodeJogStepRequest(f.payload))
            return answer(m_machine.jogStep(*r));
        return bad("JOG_STEP");
    case MsgType::SetZero:
        if (auto r = dev::proto::decodeAxisMaskRequest(f.payload))
            return answer(m_machine.setZero(r->axisMask));
        return bad("SET_ZERO");
    case MsgType::GetLimits:
        if (!f.payload.empty())
            return bad("GET_LIMITS");
        sendFrame(ok, f.seq, dev::proto::encode(m_machine.limits()), reply);
        return;
    case MsgType::SetLimits:
        if (auto r = dev::proto::decodeSetLimitsRequest(f.payload))
            return answer(m_machine.setLimits(*r));
        return bad("SET_LIMITS");
    case MsgType::Subscribe:
        return subscribe(f, reply);
    case MsgType::Reset:
        return answer(m_machine.reset());
    case MsgType::JogVelocity:
        if (auto r = dev::proto::decodeJogVelocityRequest(f.payload))
            return answer(m_machine.jogVelocity(*r));
        return bad("JOG_VELOCITY");
    case MsgType::Stop:
        if (auto r = dev::proto::decodeAxisMaskRequest(f.payload))
            return answer(m_machine.stop(r->axisMask));
        return bad("STOP");
    case MsgType::EStop:
        return answer(m_machine.estop());
    case MsgType::PathBegin:
    case MsgType::PathAppend:
    case MsgType::PathStatus:
    case MsgType::PathHold:
    case MsgType::PathResume:
    case MsgType::PathClear:
        return executePath(f, reply);
    default: {
        if (executeTuning(f, reply) || executeCompensation(f, reply))
            return;
        sendError(f.seq, firmwareUnknownType(f.type), reply);
    }
    }
}

void Firmware::subscribe(const dev::proto::Frame& f, std::vector<std::uint8_t>& reply)
{
    const auto req = dev::proto::decodeSubscribeRequest(f.payload);
    dev::proto::ErrorReply e;
    if (!req) {
        e.code = dev::proto::ErrorCode::BadPayload;
        e.message = "malformed SUBSCRIBE request";
        return sendError(f.seq, e, reply);
    }
    if (req->rateHz == 0 || req->channels.empty()) {
        m_rateHz = 0;
        m_channels.clear();
        sendFrame(static_cast<std::uint8_t>(f.type | dev::proto::kReplyFlag), f.seq, dev::proto::encode(dev::proto::SubscribeReply{}), reply);
        return;
    }
    for (const auto& c : req->channels) {
        if (!m_machine.channelExists(c)) {
            e.code = dev::proto::ErrorCode::BadAxis;
            e.axis = c.axis;
            e.message = "telemetry channel " + std::to_string(static_cast<int>(c.kind)) + " on axis "
                + std::to_string(c.axis) + " does not exist on this instrument";
            return sendError(f.seq, e, reply);
        }
    }
    const std::uint32_t tickRate = static_cast<std::uint32_t>(std::lround(1.0 / SimMachine::kTickS));
    if (req->rateHz > tickRate) {
        e.code = dev::proto::ErrorCode::OutOfRange;
        e.value = static_cast<std::int32_t>(tickRate);
        e.message = "telemetry rate " + std::to_string(req->rateHz) + " Hz is above the device's " + std::to_string(tickRate)
            + " Hz sample clock";
        return sendError(f.seq, e, reply);
    }
    const std::size_t ch = req->channels.size();
    // The sample clock divides the tick rate. Round the period up so a subscription
    // never runs faster than asked (300 Hz gives 294 Hz, not 303 Hz, and 6000 Hz
    // gives 5000 Hz, not 10000 Hz): a rate the link was said to carry must fit.
    const std::uint32_t ticksPerSample = (tickRate + req->rateHz - 1) / req->rateHz;
    const double rate = double(tickRate) / ticksPerSample;
    const std::size_t maxFit = (dev::proto::kMaxPayloadBytes - dev::proto::telemetryHeaderBytes(ch)) / (4 * ch);
    if (maxFit == 0) {
        e.code = dev::proto::ErrorCode::OutOfRange;
        e.value = static_cast<std::int32_t>(ch);
        e.message = "too many telemetry channels for one batch";
        return sendError(f.seq, e, reply);
    }
    // Smallest batch that keeps latency low; grown if the wire needs fewer frames.
    const double capacity = linkBytesPerSecond() * kLinkHeadroom;
    auto bytesPerSecond = [&](std::size_t spb) {
        const double frame = double(dev::proto::wireBytesForPayload(dev::proto::telemetryHeaderBytes(ch) + 4 * ch * spb));
        return rate / double(spb) * frame;
    };
    std::size_t spb = std::clamp<std::size_t>(static_cast<std::size_t>(std::ceil(rate * kBatchLatencyS)), 1, maxFit);
    const std::size_t latencySpb = spb;
    while (spb < maxFit && bytesPerSecond(spb) > capacity)
        ++spb;
    if (spb > latencySpb) {
        // The wire is the bottleneck: spend what latency allows (100 ms) on fewer,
        // fuller frames, so framing overhead does not eat the link's margin.
        spb = std::max(spb, std::min(maxFit, static_cast<std::size_t>(std::floor(rate * kBusyLinkBatchS))));
    }
    if (bytesPerSecond(spb) > capacity) {
        const double perSampleFull = double(dev::proto::wireBytesForPayload(dev::proto::telemetryHeaderBytes(ch) + 4 * ch * maxFit)) / double(maxFit);
        // The fastest achievable rate (tick rate / whole ticks) that fits, as whole
        // Hz that get exactly that sample period when asked for again: rounded up
        // where that still maps to it (588.2 Hz → 589), else down (accepted, one
        // period slower) where periods are too close together for whole Hz.
        const double minTicks = std::max(1.0, std::ceil(double(tickRate) * perSampleFull / capacity));
        auto maxRate = static_cast<std::int32_t>(std::ceil(double(tickRate) / minTicks));
        if (std::ceil(double(tickRate) / maxRate) < minTicks)
            maxRate = static_cast<std::int32_t>(std::floor(double(tickRate) / minTicks));
        e.code = dev::proto::ErrorCode::OverCapacity;
        e.value = maxRate;
        e.message = std::to_string(static_cast<long>(rate)) + " Hz × " + std::to_string(ch) + " channels needs "
            + std::to_string(static_cast<long>(bytesPerSecond(spb))) + " B/s but the link carries "
            + std::to_string(static_cast<long>(capacity)) + " B/s at " + std::to_string(m_linkBaud)
            + " baud: at most " + std::to_string(maxRate) + " Hz with these channels";
        return sendError(f.seq, e, reply);
    }
    m_channels = req->channels;
    m_rateHz = static_cast<std::uint32_t>(std::lround(rate));
    m_ticksPerSample = ticksPerSample;
    m_samplesPerBatch = static_cast<std::uint16_t>(spb);
    m_sampleIndex = 0;
    m_batch = dev::proto::TelemetryBatch{};
    dev::proto::SubscribeReply r;
    r.rateHz = m_rateHz;
    r.samplesPerBatch = m_samplesPerBatch;
    sendFrame(static_cast<std::uint8_t>(f.type | dev::proto::kReplyFlag), f.seq, dev::proto::encode(r), reply);
}

void Firmware::sampleTelemetry()
{
    if (m_rateHz == 0 || m_tickCount % m_ticksPerSample != 0)
        return;
    if (m_batch.sampleCount == 0) {
        m_batch.firstSampleIndex = m_sampleIndex;
        m_batch.firstSampleTimeUs = m_machine.timeUs();
        m_batch.periodUs = static_cast<std::uint32_t>(m_ticksPerSample * 100);
        m_batch.channels = m_channels;
        m_batch.values.clear();
    }
    for (const auto& c : m_channels)
        m_batch.values.push_back(m_machine.channelValue(c));
    ++m_batch.sampleCount;
    ++m_sampleIndex;
    if (m_batch.sampleCount >= m_samplesPerBatch) {
        // Overflow policy: a host that stops reading loses telemetry, never replies
        // or events; the gap in firstSampleIndex tells it what it lost.
        if (m_out.size() < kMaxPendingOutputBytes)
            sendFrame(static_cast<std::uint8_t>(dev::proto::MsgType::TelemetryBatch), m_eventSeq++, dev::proto::encode(m_batch), m_out);
        else
            ++m_droppedBatches;
        m_batch.sampleCount = 0;
    }
}

} // namespace dev::sim
