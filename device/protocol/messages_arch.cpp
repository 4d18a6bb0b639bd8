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
    if (m.pump) {
        w.i32(m.pump->delta);
        w.u32(m.pump->speed);
        w.i32(m.pump->liquidZ);
        w.i32(m.pump->leaveZ);
    }
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
    // Either the 32 bytes of the plain move or those and the pump block: nothing between.
    if (r.ok() && r.remaining() > 0) {
        ArchPump pump;
        pump.delta = r.i32();
        pump.speed = r.u32();
        pump.liquidZ = r.i32();
        pump.leaveZ = r.i32();
        m.pump = pump;
    }
    return finish(r, std::move(m));
}

} // namespace dev::proto
