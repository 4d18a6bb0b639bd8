#include "device/protocol/messages_compensation_2d.h"

#include "device/protocol/bytes.h"

namespace dev::proto {

Bytes encode(const Comp2dUploadRequest& m)
{
    Bytes out;
    ByteWriter w(out);
    w.u8(m.columns);
    w.u8(m.rows);
    w.i32(m.originX);
    w.i32(m.originY);
    w.i32(m.pitchX);
    w.i32(m.pitchY);
    w.u16(m.first);
    w.u8(static_cast<std::uint8_t>(m.nodes.size()));
    for (const Comp2dNode& n : m.nodes) {
        w.i32(n.correctionX);
        w.i32(n.correctionY);
    }
    return out;
}

Bytes encode(const Comp2dUploadReply& m)
{
    Bytes out;
    ByteWriter w(out);
    w.u16(m.received);
    w.u8(m.installed);
    return out;
}

Bytes encode(const Comp2dEnableRequest& m) { return Bytes{m.flags}; }

Bytes encode(const Comp2dEnableReply& m) { return Bytes{m.state, m.columns, m.rows}; }

std::optional<Comp2dUploadRequest> decodeComp2dUploadRequest(const Bytes& b)
{
    ByteReader r(b);
    Comp2dUploadRequest m;
    m.columns = r.u8();
    m.rows = r.u8();
    m.originX = r.i32();
    m.originY = r.i32();
    m.pitchX = r.i32();
    m.pitchY = r.i32();
    m.first = r.u16();
    const std::uint8_t count = r.u8();
    if (!r.ok() || count > kMaxComp2dNodesPerFrame)
        return std::nullopt;
    for (std::uint8_t i = 0; i < count; ++i) {
        Comp2dNode n;
        n.correctionX = r.i32();
        n.correctionY = r.i32();
        m.nodes.push_back(n);
    }
    if (!r.done())
        return std::nullopt;
    return m;
}

std::optional<Comp2dUploadReply> decodeComp2dUploadReply(const Bytes& b)
{
    ByteReader r(b);
    Comp2dUploadReply m;
    m.received = r.u16();
    m.installed = r.u8();
    if (!r.done() || m.installed > 1)
        return std::nullopt;
    return m;
}

std::optional<Comp2dEnableRequest> decodeComp2dEnableRequest(const Bytes& b)
{
    // Bits above the query flag are refused: a later flag must not be silently ignored.
    if (b.size() != 1 || (b[0] & ~0x07u) != 0)
        return std::nullopt;
    return Comp2dEnableRequest{b[0]};
}

std::optional<Comp2dEnableReply> decodeComp2dEnableReply(const Bytes& b)
{
    if (b.size() != 3 || (b[0] & ~0x0Fu) != 0)
        return std::nullopt;
    return Comp2dEnableReply{b[0], b[1], b[2]};
}

const char* compensation2dTypeName(std::uint8_t type)
{
    switch (type) {
    case 0x1E: return "COMP2D_UPLOAD";
    case 0x1F: return "COMP2D_ENABLE";
    default: return nullptr;
    }
}

} // namespace dev::proto
