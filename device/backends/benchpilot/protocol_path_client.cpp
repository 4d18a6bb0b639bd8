#include "device/backends/benchpilot/protocol_path_client.h"

#include "device/backends/benchpilot/benchpilot_client.h"
#include "device/backends/benchpilot/path_wire.h"

#include <QCoreApplication>

#include <algorithm>

namespace dev {

ProtocolPathClient::ProtocolPathClient(BenchPilotClient* client, QObject* parent) : PathClient(parent), m_client(client)
{
    connect(client, &BenchPilotClient::eventReceived, this, &ProtocolPathClient::onEvent);
    connect(client, &BenchPilotClient::identified, this, [this] { m_haveLimits = false; });
}

bool ProtocolPathClient::available() const
{
    return m_client && m_client->isReady() && m_client->hasProtocolCapability(dev::proto::CapPathQueue);
}

motion::path::PathLimits ProtocolPathClient::limits() const
{
    motion::path::PathLimits l;
    if (m_haveLimits) {
        l.accelMmS2 = m_last.accelMmS2;
        l.junctionDeviationMm = m_last.junctionDeviationMm;
    }
    if (m_client && m_client->identity().axes.size() >= 2)
        l.maxSpeedMmS = std::min(m_client->identity().axes[0].maxSpeed, m_client->identity().axes[1].maxSpeed);
    return l;
}

void ProtocolPathClient::refreshLimits(Callback done)
{
    queryStatus([done](const std::optional<RequestError>& e, const PathQueueState&) {
        if (done)
            done(e);
    });
}

PathQueueState ProtocolPathClient::fromWire(const dev::proto::PathStatusReply& s)
{
    PathQueueState q;
    q.state = s.state;
    q.capacity = s.capacity;
    q.freeSlots = s.freeSlots;
    q.nextIndex = s.nextIndex;
    q.executingIndex = s.executingIndex;
    q.speedMmS = s.speed / 1e6;
    q.underruns = s.underruns;
    q.reason = s.reason;
    q.accelMmS2 = s.accel / 1e6;
    q.junctionDeviationMm = s.junctionDeviation / 1e6;
    return q;
}

BenchPilotClient::ReplyCallback ProtocolPathClient::statusReply(Reply done)
{
    // The reply may come after this client is gone (a run dropped mid-request).
    const QPointer<ProtocolPathClient> self(this);
    return [this, self, done = std::move(done)](const std::optional<RequestError>& e, const dev::proto::Bytes& payload) {
        if (!self)
            return;
        if (e) {
            if (done)
                done(e, m_last);
            return;
        }
        const auto s = dev::proto::decodePathStatusReply(payload);
        if (!s) {
            RequestError err;
            err.kind = RequestError::Kind::Device;
            err.message = motion::msg::make("request.path_unreadable");
            if (done)
                done(err, m_last);
            return;
        }
        m_last = fromWire(*s);
        m_haveLimits = m_last.accelMmS2 > 0;
        if (done)
            done(std::nullopt, m_last);
    };
}

namespace {
std::optional<RequestError> notConnected()
{
    RequestError e;
    e.kind = RequestError::Kind::LinkDown;
    e.message = motion::msg::make("request.instrument_not_connected");
    return e;
}
} // namespace

void ProtocolPathClient::begin(quint32 firstIndex, Reply done)
{
    if (!m_client)
        return done(notConnected(), m_last);
    dev::proto::PathBeginRequest r;
    r.firstIndex = firstIndex;
    m_client->request(dev::proto::MsgType::PathBegin, dev::proto::encode(r), statusReply(std::move(done)), "request.path");
}

void ProtocolPathClient::append(quint32 firstIndex, const std::vector<motion::path::Segment>& segments, bool start,
                                bool last, Reply done)
{
    if (!m_client)
        return done(notConnected(), m_last);
    dev::proto::PathAppendRequest r;
    r.firstIndex = firstIndex;
    r.flags = static_cast<std::uint8_t>((start ? dev::proto::PathAppendStart : 0) | (last ? dev::proto::PathAppendLast : 0));
    r.segments = toWire(segments);
    m_client->request(dev::proto::MsgType::PathAppend, dev::proto::encode(r), statusReply(std::move(done)), "request.path_segments");
}

void ProtocolPathClient::queryStatus(Reply done)
{
    if (!m_client)
        return done(notConnected(), m_last);
    // No `what`: a status query that fails is the caller's business, not a banner.
    m_client->request(dev::proto::MsgType::PathStatus, {}, statusReply(std::move(done)));
}

void ProtocolPathClient::hold(Callback done)
{
    if (!m_client)
        return done ? done(notConnected()) : void();
    m_client->request(dev::proto::MsgType::PathHold, {}, [done](const auto& e, const auto&) { if (done) done(e); }, "request.pause");
}

void ProtocolPathClient::resume(Callback done)
{
    if (!m_client)
        return done ? done(notConnected()) : void();
    m_client->request(dev::proto::MsgType::PathResume, {}, [done](const auto& e, const auto&) { if (done) done(e); }, "request.resume");
}

void ProtocolPathClient::clear(Callback done)
{
    if (!m_client)
        return done ? done(notConnected()) : void();
    m_client->request(dev::proto::MsgType::PathClear, {}, [done](const auto& e, const auto&) { if (done) done(e); }, "request.abort");
}

void ProtocolPathClient::onEvent(const DeviceEvent& e)
{
    if (e.axis != -1)
        return;
    const auto index = static_cast<quint32>(std::max(0.0, e.position));
    switch (e.kind) {
    case dev::proto::EventKind::PathStarted:
        emit startedAt(e.deviceTimeUs);
        emit started(index);
        break;
    case dev::proto::EventKind::PathSegmentDone: emit segmentDone(index); break;
    case dev::proto::EventKind::PathUnderrun: emit underrun(index); break;
    case dev::proto::EventKind::PathDone: emit finished(index, e.deviceTimeUs); break;
    case dev::proto::EventKind::PathHeld: emit held(index, e.text); break;
    case dev::proto::EventKind::PathAborted: emit aborted(index, e.text); break;
    default: break;
    }
}

} // namespace dev
