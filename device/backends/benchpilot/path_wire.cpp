#include "device/backends/benchpilot/path_wire.h"

#include <cmath>

namespace dev {

namespace {
dev::proto::WireUnits nm(double mm) { return static_cast<dev::proto::WireUnits>(std::llround(mm * 1e6)); }
}

dev::proto::PathSegmentWire toWire(const motion::path::Segment& s)
{
    dev::proto::PathSegmentWire w;
    switch (s.kind) {
    case motion::path::SegmentKind::Line: w.kind = dev::proto::PathSegmentKind::Line; break;
    case motion::path::SegmentKind::ArcCw: w.kind = dev::proto::PathSegmentKind::ArcCw; break;
    case motion::path::SegmentKind::ArcCcw: w.kind = dev::proto::PathSegmentKind::ArcCcw; break;
    }
    w.feed = static_cast<std::uint32_t>(std::llround(std::max(0.0, s.feedMmS) * 1e6));
    w.x = nm(s.end.x);
    w.y = nm(s.end.y);
    if (s.isArc()) {
        w.cx = nm(s.center.x);
        w.cy = nm(s.center.y);
    }
    if (s.zMm) {
        w.hasZ = true;
        w.z = nm(*s.zMm);
    }
    return w;
}

std::vector<dev::proto::PathSegmentWire> toWire(const std::vector<motion::path::Segment>& path)
{
    std::vector<dev::proto::PathSegmentWire> out;
    out.reserve(path.size());
    for (const auto& s : path)
        out.push_back(toWire(s));
    return out;
}

motion::path::Segment fromWire(const dev::proto::PathSegmentWire& w, motion::path::Vec2 startMm)
{
    motion::path::Segment s;
    s.kind = w.kind == dev::proto::PathSegmentKind::Line    ? motion::path::SegmentKind::Line
             : w.kind == dev::proto::PathSegmentKind::ArcCw ? motion::path::SegmentKind::ArcCw
                                                       : motion::path::SegmentKind::ArcCcw;
    s.start = startMm;
    s.end = {w.x / 1e6, w.y / 1e6};
    s.center = {w.cx / 1e6, w.cy / 1e6};
    s.feedMmS = w.feed / 1e6;
    if (w.hasZ)
        s.zMm = w.z / 1e6;
    return s;
}

} // namespace dev
