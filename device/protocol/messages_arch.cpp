#include "device/protocol/messages_arch.h"

#include "device/protocol/bytes.h"

namespace dev::proto {

Bytes encode(const ArchMoveRequest& m)
{
    Bytes b;
    ByteWriter w(b);
    w.u32(m.xySpeed);
    w.u32(m.zSpeed);
    w.i32(m.x);
    w.i32(m.y);
    w.i32(m.clearZ);
    w.i32(m.z);
    w.u32(m.departRadius);
    w.u32(m.approachRadius);
    return b;
}

std::optional<ArchMoveRequest> decodeArchMoveRequest(const Bytes& p)
{
    ByteReader r(p);
    ArchMoveRequest m;
    m.xySpeed = r.u32();
    m.zSpeed = r.u32();
    m.x = r.i32();
    m.y = r.i32();
    m.clearZ = r.i32();
    m.z = r.i32();
    m.departRadius = r.u32();
    m.approachRadius = r.u32();
    return finish(r, std::move(m));
}

} // namespace dev::proto
