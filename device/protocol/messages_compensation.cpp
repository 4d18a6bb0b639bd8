#include "device/protocol/messages_compensation.h"

#include "device/protocol/bytes.h"

#include <cstring>

namespace dev::proto {
namespace {

void putF64(ByteWriter& w, double v)
{
    std::uint64_t u;
    std::memcpy(&u, &v, 8);
    w.u64(u);
}

double getF64(ByteReader& r)
{
    const std::uint64_t u = r.u64();
    double v;
    std::memcpy(&v, &u, 8);
    return v;
}

bool validKind(std::uint8_t k, bool noneAllowed)
{
    return (noneAllowed && k == 0) || (k >= 1 && k <= 3);
}

bool isTable(CompKind k) { return k == CompKind::Table || k == CompKind::TablePerDirection; }

void putPoint(ByteWriter& w, const CompPoint& p)
{
    w.i32(p.nominal);
    w.i32(p.correctionUp);
    w.i32(p.correctionDown);
}

CompPoint getPoint(ByteReader& r)
{
    CompPoint p;
    p.nominal = r.i32();
    p.correctionUp = r.i32();
    p.correctionDown = r.i32();
    return p;
}

} // namespace

Bytes encode(const CompUploadRequest& m)
{
    Bytes out;
    ByteWriter w(out);
    w.u8(m.axis);
    w.u8(static_cast<std::uint8_t>(m.kind));
    w.i32(m.backlash);
    w.u16(m.total);
    w.u16(m.first);
    if (m.kind == CompKind::Polynomial) {
        w.u8(static_cast<std::uint8_t>(m.coefficients.size()));
        w.i32(m.validFrom);
        w.i32(m.validTo);
        for (double c : m.coefficients)
            putF64(w, c);
    } else {
        w.u8(static_cast<std::uint8_t>(m.points.size()));
        for (const CompPoint& p : m.points)
            putPoint(w, p);
    }
    return out;
}

std::optional<CompUploadRequest> decodeCompUploadRequest(const Bytes& b)
{
    ByteReader r(b);
    CompUploadRequest m;
    m.axis = r.u8();
    const std::uint8_t kind = r.u8();
    m.backlash = r.i32();
    m.total = r.u16();
    m.first = r.u16();
    const std::uint8_t count = r.u8();
    if (!r.ok() || !validKind(kind, false))
        return std::nullopt;
    m.kind = static_cast<CompKind>(kind);
    if (m.kind == CompKind::Polynomial) {
        // One part holds the whole polynomial: a count that says otherwise is malformed.
        if (count != m.total || m.first != 0 || count > kMaxCompCoefficients)
            return std::nullopt;
        m.validFrom = r.i32();
        m.validTo = r.i32();
        for (int i = 0; i < count && r.ok(); ++i)
            m.coefficients.push_back(getF64(r));
    } else {
        if (count > kMaxCompPointsPerFrame)
            return std::nullopt;
        for (int i = 0; i < count && r.ok(); ++i)
            m.points.push_back(getPoint(r));
    }
    return finish(r, std::move(m));
}

Bytes encode(const CompUploadReply& m)
{
    Bytes out;
    ByteWriter w(out);
    w.u8(m.axis);
    w.u16(m.received);
    w.u8(m.installed);
    return out;
}

std::optional<CompUploadReply> decodeCompUploadReply(const Bytes& b)
{
    ByteReader r(b);
    CompUploadReply m;
    m.axis = r.u8();
    m.received = r.u16();
    m.installed = r.u8();
    return finish(r, std::move(m));
}

Bytes encode(const CompGetRequest& m)
{
    Bytes out;
    ByteWriter w(out);
    w.u8(m.axis);
    w.u16(m.first);
    w.u8(m.maxCount);
    return out;
}

std::optional<CompGetRequest> decodeCompGetRequest(const Bytes& b)
{
    ByteReader r(b);
    CompGetRequest m;
    m.axis = r.u8();
    m.first = r.u16();
    m.maxCount = r.u8();
    return finish(r, std::move(m));
}

Bytes encode(const CompGetReply& m)
{
    Bytes out;
    ByteWriter w(out);
    w.u8(m.axis);
    w.u8(static_cast<std::uint8_t>(m.kind));
    w.u8(m.flags);
    w.i32(m.backlash);
    w.u16(m.total);
    w.u16(m.first);
    if (m.kind == CompKind::Polynomial) {
        w.u8(static_cast<std::uint8_t>(m.coefficients.size()));
        w.i32(m.validFrom);
        w.i32(m.validTo);
        for (double c : m.coefficients)
            putF64(w, c);
    } else if (isTable(m.kind)) {
        w.u8(static_cast<std::uint8_t>(m.points.size()));
        for (const CompPoint& p : m.points)
            putPoint(w, p);
    } else {
        w.u8(0);
    }
    return out;
}

std::optional<CompGetReply> decodeCompGetReply(const Bytes& b)
{
    ByteReader r(b);
    CompGetReply m;
    m.axis = r.u8();
    const std::uint8_t kind = r.u8();
    m.flags = r.u8();
    m.backlash = r.i32();
    m.total = r.u16();
    m.first = r.u16();
    const std::uint8_t count = r.u8();
    if (!r.ok() || !validKind(kind, true))
        return std::nullopt;
    m.kind = static_cast<CompKind>(kind);
    if (m.kind == CompKind::Polynomial) {
        if (count != m.total || count > kMaxCompCoefficients)
            return std::nullopt;
        m.validFrom = r.i32();
        m.validTo = r.i32();
        for (int i = 0; i < count && r.ok(); ++i)
            m.coefficients.push_back(getF64(r));
    } else if (isTable(m.kind)) {
        if (count > kMaxCompPointsPerFrame)
            return std::nullopt;
        for (int i = 0; i < count && r.ok(); ++i)
            m.points.push_back(getPoint(r));
    } else if (count != 0) {
        return std::nullopt;
    }
    return finish(r, std::move(m));
}

Bytes encode(const CompEnableRequest& m)
{
    Bytes out;
    ByteWriter w(out);
    w.u8(m.axisMask);
    w.u8(m.flags);
    return out;
}

std::optional<CompEnableRequest> decodeCompEnableRequest(const Bytes& b)
{
    ByteReader r(b);
    CompEnableRequest m;
    m.axisMask = r.u8();
    m.flags = r.u8();
    return finish(r, std::move(m));
}

const char* compensationTypeName(std::uint8_t type)
{
    switch (type) {
    case 0x1B: return "COMP_UPLOAD";
    case 0x1C: return "COMP_GET";
    case 0x1D: return "COMP_ENABLE";
    default: return nullptr;
    }
}

} // namespace dev::proto
