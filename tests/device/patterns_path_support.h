#pragma once
// What the path-queue tests share: building paths in mm, queuing them on a homed simulated
// machine in flow-controlled appends (as the host does), and running it while the contour
// tracker judges every tick's measured position against the geometric path.
#include "device/backends/benchpilot/path_wire.h"
#include "device/sim/path_queue.h"
#include "motion/path/contour_tracker.h"
#include "sim_test_support.h"

#include <cmath>
#include <functional>
#include <vector>

namespace pathtest {

using motion::path::Segment;
using motion::path::SegmentKind;
using motion::path::Vec2;

inline Segment line(Vec2 a, Vec2 b, double feed)
{
    Segment s;
    s.start = a;
    s.end = b;
    s.feedMmS = feed;
    return s;
}
inline Segment arc(Vec2 a, Vec2 b, Vec2 c, bool ccw, double feed)
{
    Segment s;
    s.kind = ccw ? SegmentKind::ArcCcw : SegmentKind::ArcCw;
    s.start = a;
    s.end = b;
    s.center = c;
    s.feedMmS = feed;
    return s;
}
/// A circle as four quarter arcs from centre + (r, 0).
inline std::vector<Segment> circle(Vec2 c, double r, bool ccw, double feed)
{
    std::vector<Segment> out;
    const Vec2 pts[5] = {{c.x + r, c.y}, {c.x, c.y + (ccw ? r : -r)}, {c.x - r, c.y}, {c.x, c.y - (ccw ? r : -r)}, {c.x + r, c.y}};
    for (int k = 0; k < 4; ++k)
        out.push_back(arc(pts[k], pts[k + 1], c, ccw, feed));
    return out;
}

inline dev::proto::PathAppendRequest appendOf(const std::vector<Segment>& path, std::size_t from, std::size_t count,
                                         std::uint32_t firstIndex, std::uint8_t flags)
{
    dev::proto::PathAppendRequest r;
    r.firstIndex = firstIndex;
    r.flags = flags;
    for (std::size_t k = from; k < from + count && k < path.size(); ++k)
        r.segments.push_back(dev::toWire(path[k]));
    return r;
}

/// Streams a path into a machine's queue the way a host does: fill what is free, then top up
/// as segments complete; runs until the path ends. `eachTick` sees every tick.
struct PathRun {
    dev::sim::SimMachine& m;
    simtest::Runner& r;
    std::vector<Segment> path;
    std::size_t sent = 0;
    double maxSpeedSeen = 0;

    std::optional<dev::proto::ErrorReply> begin(std::uint32_t firstIndex = 0)
    {
        dev::proto::PathBeginRequest b;
        b.firstIndex = firstIndex;
        return m.paths().begin(b);
    }
    std::optional<dev::proto::ErrorReply> topUp(std::uint32_t firstIndex = 0)
    {
        const auto st = m.paths().status();
        const std::size_t n = std::min<std::size_t>(st.freeSlots, path.size() - sent);
        if (n == 0)
            return std::nullopt;
        const bool last = sent + n == path.size();
        auto e = m.paths().append(appendOf(path, sent, n, firstIndex + static_cast<std::uint32_t>(sent),
                                           static_cast<std::uint8_t>(dev::proto::PathAppendStart | (last ? dev::proto::PathAppendLast : 0))));
        if (!e)
            sent += n;
        return e;
    }
    /// Runs until the path is done or aborted (or timeoutS); tops the queue up every 10 ms.
    bool run(double timeoutS, const std::function<void()>& eachTick = {})
    {
        const auto ticks = static_cast<long>(timeoutS / dev::sim::SimMachine::kTickS);
        for (long k = 0; k < ticks; ++k) {
            if (k % 100 == 0 && sent < path.size())
                topUp();
            m.tick();
            maxSpeedSeen = std::max(maxSpeedSeen, m.paths().speedMmS());
            if (eachTick)
                eachTick();
            r.take();
            const auto s = m.paths().state();
            if (s == dev::proto::PathState::Done || s == dev::proto::PathState::Aborted)
                return s == dev::proto::PathState::Done;
        }
        return false;
    }
};

/// Measured XY (host coordinates, mm).
inline Vec2 measuredXy(const dev::sim::SimMachine& m) { return {m.measuredLogical(0), m.measuredLogical(1)}; }

} // namespace pathtest
