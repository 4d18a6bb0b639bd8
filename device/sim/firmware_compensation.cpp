// The reference firmware's dispatch of the compensation requests (docs/protocol.md,
// "Compensation"); the behaviour is in sim_compensation.cpp.
#include "device/sim/firmware.h"

namespace dev::sim {

bool Firmware::executeCompensation(const dev::proto::Frame& f, std::vector<std::uint8_t>& reply)
{
    const char* name = dev::proto::compensationTypeName(f.type);
    if (!name)
        return false;
    const std::uint8_t ok = static_cast<std::uint8_t>(f.type | dev::proto::kReplyFlag);
    SimCompensation& c = m_machine.compensation();
    auto answer = [&](const SimCompensation::Result& r, const dev::proto::Bytes& payload) {
        if (r)
            sendError(f.seq, *r, reply);
        else
            sendFrame(ok, f.seq, payload, reply);
    };
    switch (f.type) {
    case 0x1B:
        if (const auto r = dev::proto::decodeCompUploadRequest(f.payload)) {
            dev::proto::CompUploadReply out;
            const auto e = c.upload(*r, out);
            answer(e, e ? dev::proto::Bytes{} : dev::proto::encode(out));
            return true;
        }
        break;
    case 0x1C:
        if (const auto r = dev::proto::decodeCompGetRequest(f.payload)) {
            dev::proto::CompGetReply out;
            const auto e = c.get(*r, out);
            answer(e, e ? dev::proto::Bytes{} : dev::proto::encode(out));
            return true;
        }
        break;
    case 0x1D:
        if (const auto r = dev::proto::decodeCompEnableRequest(f.payload)) {
            answer(c.enable(*r), {});
            return true;
        }
        break;
    default: return false;
    }
    sendMalformed(f.seq, name, reply);
    return true;
}

} // namespace dev::sim
