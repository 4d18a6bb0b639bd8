// The reference firmware's dispatch of the tuning requests (docs/protocol.md,
// "Tuning"); the behaviour is in sim_tuning.cpp.
#include "device/sim/firmware.h"
#include "device/sim/sim_tuning.h"

namespace dev::sim {

bool Firmware::executeTuning(const dev::proto::Frame& f, std::vector<std::uint8_t>& reply)
{
    const std::uint8_t ok = static_cast<std::uint8_t>(f.type | dev::proto::kReplyFlag);
    const char* name = dev::proto::tuningTypeName(f.type);
    if (!name)
        return false;
    SimTuning& t = m_machine.tuning();
    auto bad = [&] {
        dev::proto::ErrorReply e;
        e.code = dev::proto::ErrorCode::BadPayload;
        e.message = std::string("malformed ") + name + " request";
        sendError(f.seq, e, reply);
    };
    auto answer = [&](const SimTuning::Result& r, const dev::proto::Bytes& payload = {}) {
        if (r)
            sendError(f.seq, *r, reply);
        else
            sendFrame(ok, f.seq, payload, reply);
    };
    switch (f.type) {
    case 0x0B:
        if (auto r = dev::proto::decodeAxisRequest(f.payload)) {
            dev::proto::GainsReply g;
            const auto e = t.getGains(r->axis, g);
            answer(e, e ? dev::proto::Bytes{} : dev::proto::encode(g));
        } else {
            bad();
        }
        return true;
    case 0x0C:
        if (auto r = dev::proto::decodeSetGainsRequest(f.payload))
            answer(t.setGains(*r));
        else
            bad();
        return true;
    case 0x0D:
        if (auto r = dev::proto::decodeStepTestRequest(f.payload))
            answer(t.stepTest(*r));
        else
            bad();
        return true;
    case 0x0E:
        if (auto r = dev::proto::decodeRelayTestRequest(f.payload))
            answer(t.relayTest(*r));
        else
            bad();
        return true;
    case 0x0F:
        if (auto r = dev::proto::decodeCaptureRequest(f.payload)) {
            dev::proto::CaptureReply c;
            const auto e = t.capture(*r, c);
            answer(e, e ? dev::proto::Bytes{} : dev::proto::encode(c));
        } else {
            bad();
        }
        return true;
    case 0x23:
        // Realtime, like STOP: acted on whatever else is queued, never refused.
        // A malformed payload aborts every axis: the safe reading of a garbled abort.
        answer(t.abort(f.payload.size() == 1 ? f.payload[0] : 0, motion::control::EndReason::Stopped));
        return true;
    default: return false;
    }
}

} // namespace dev::sim
