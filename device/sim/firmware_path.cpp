// The firmware's side of the path queue: decoding its requests, replying with the queue's fill
// state, and holding a running path when the host has gone quiet.
#include "device/sim/firmware.h"

#include "device/protocol/messages_path.h"
#include "device/sim/path_queue.h"

namespace dev::sim {

void Firmware::executePath(const dev::proto::Frame& f, std::vector<std::uint8_t>& reply)
{
    using dev::proto::MsgType;
    PathQueue& q = m_machine.paths();
    const std::uint8_t ok = static_cast<std::uint8_t>(f.type | dev::proto::kReplyFlag);
    auto bad = [&](const char* what) { sendMalformed(f.seq, what, reply); };
    // BEGIN, APPEND and STATUS answer with the queue's state: the host's flow control.
    auto withStatus = [&](const PathQueue::Result& r) {
        if (r)
            sendError(f.seq, *r, reply);
        else
            sendFrame(ok, f.seq, dev::proto::encode(q.status()), reply);
    };
    auto empty = [&](const PathQueue::Result& r) {
        if (r)
            sendError(f.seq, *r, reply);
        else
            sendFrame(ok, f.seq, {}, reply);
    };
    switch (static_cast<MsgType>(f.type)) {
    case MsgType::PathBegin:
        if (auto r = dev::proto::decodePathBeginRequest(f.payload))
            return withStatus(q.begin(*r));
        return bad("PATH_BEGIN");
    case MsgType::PathAppend:
        if (auto r = dev::proto::decodePathAppendRequest(f.payload))
            return withStatus(q.append(*r));
        return bad("PATH_APPEND");
    case MsgType::PathStatus:
        if (!f.payload.empty())
            return bad("PATH_STATUS");
        return withStatus(std::nullopt);
    // Realtime: acted on whatever the payload, like E-STOP — a hold must never be lost to a
    // stray byte.
    case MsgType::PathHold:
        return empty(q.hold());
    case MsgType::PathResume:
        return empty(q.resume());
    case MsgType::PathClear:
        return empty(q.clear());
    default:
        return bad("path");
    }
}

void Firmware::checkHostSilence()
{
    PathQueue& q = m_machine.paths();
    if (!q.moving() || q.state() == dev::proto::PathState::Holding)
        return;
    // BenchPilot polls STATUS every 50 ms: a second without any frame is a host that is gone.
    if (m_machine.timeS() - m_lastHostFrameS > m_hostSilenceLimitS)
        q.hold(dev::proto::PathReason::HostSilent);
}

} // namespace dev::sim
