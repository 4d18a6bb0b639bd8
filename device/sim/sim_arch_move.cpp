// ARCH_MOVE on the simulated analyzer (docs/protocol.md): the reference firmware's
// blended Z-up, XY-across, Z-down. The three parts are ordinary segments whose starts
// hang on each other's progress, timed by motion::archTiming from the very profiles
// they run, so the host's plan (motion/plans/recipes) times the move as it runs.
#include "device/sim/sim_machine.h"

#include "motion/arch_timing.h"

#include <algorithm>
#include <cmath>

namespace dev::sim {

namespace {

int archAxisByLetter(const SimMachine& m, char letter)
{
    for (int i = 0; i < m.axisCount(); ++i)
        if (m.axis(i).config().letter == letter)
            return i;
    return -1;
}

} // namespace

SimMachine::Segment* SimMachine::segmentById(int id)
{
    auto it = std::find_if(m_segments.begin(), m_segments.end(), [&](const Segment& g) { return g.id == id; });
    return it == m_segments.end() ? nullptr : &*it;
}

void SimMachine::cancelArchRest(int arch, const char* why, std::uint8_t code)
{
    if (arch < 0)
        return;
    auto waiting = [&](const Segment& g) { return g.arch == arch && !g.started; };
    for (const Segment& g : m_segments) {
        if (!waiting(g))
            continue;
        for (int a : g.axes) {
            if (st(a).segment != g.id)
                continue;  // still driven by the arch's running part, which its own stop ends
            st(a).mode = Mode::Idle;
            st(a).segment = -1;
            raiseEvent(dev::proto::EventKind::Stopped, a, why, code);
        }
    }
    m_segments.erase(std::remove_if(m_segments.begin(), m_segments.end(), waiting), m_segments.end());
}

SimMachine::Result SimMachine::archMove(const dev::proto::ArchMoveRequest& r)
{
    const int ix = archAxisByLetter(*this, 'X'), iy = archAxisByLetter(*this, 'Y'), iz = archAxisByLetter(*this, 'Z');
    const int ip = archAxisByLetter(*this, 'P');
    if (ix < 0 || iy < 0 || iz < 0 || !m_cfg.zAfterXy)
        return error(dev::proto::ErrorCode::BadAxis, -1, 0, "an arched move needs X, Y and a Z that follows them");
    if (r.pump && ip < 0)
        return error(dev::proto::ErrorCode::BadAxis, -1, 0, "an arched move's pump block needs a plunger axis");
    std::uint8_t mask = static_cast<std::uint8_t>((1u << ix) | (1u << iy) | (1u << iz));
    if (r.pump)
        mask = static_cast<std::uint8_t>(mask | (1u << ip));
    if (auto e = checkAxes(mask, true))
        return e;
    std::vector<int> axes{ix, iy, iz};
    if (r.pump)
        axes.push_back(ip);
    for (int i : axes)
        if (!st(i).homed)
            return error(dev::proto::ErrorCode::NotHomed, i, 0,
                         std::string("axis ") + st(i).plant->config().letter + " is not homed: home it before an arched move");
    // Targets in machine coordinates, each inside its soft limits (the clearance too: Z goes there).
    auto machineOf = [&](int i, std::int32_t wire) { return wire / scale(i) + st(i).offset; };
    struct Target {
        int axis;
        std::int32_t wire;
    };
    std::vector<Target> targets{{ix, r.x}, {iy, r.y}, {iz, r.clearZ}, {iz, r.z}};
    if (r.pump) {
        targets.push_back({iz, r.pump->leaveZ});
        // The plunger's target: where it is commanded now plus the relative move, on the wire.
        const double pNow = st(ip).plant->reference() - st(ip).offset;
        targets.push_back({ip, wireInt32((pNow + r.pump->delta / scale(ip)) * scale(ip))});
    }
    for (const Target& t : targets) {
        const double m = machineOf(t.axis, t.wire);
        if (m < softMinMachine(t.axis) - 1e-9 || m > softMaxMachine(t.axis) + 1e-9) {
            const bool low = m < softMinMachine(t.axis);
            const double lim = (low ? softMinMachine(t.axis) : softMaxMachine(t.axis)) - st(t.axis).offset;
            return error(dev::proto::ErrorCode::SoftLimit, t.axis, lim,
                         std::string("axis ") + st(t.axis).plant->config().letter + " target " + fmt(t.axis, m - st(t.axis).offset)
                             + " is beyond the " + (low ? "lower" : "upper") + " soft limit " + fmt(t.axis, lim));
        }
    }
    auto speedOf = [&](int i, std::uint32_t wire, double* v) -> Result {
        const auto& c = st(i).plant->config();
        *v = wire == 0 ? c.defaultSpeed : wire / scale(i);
        if (*v > c.maxSpeed + 1e-9)
            return error(dev::proto::ErrorCode::OutOfRange, i, *v,
                         std::string("speed ") + fmt(i, *v) + "/s is above axis " + c.letter + "'s maximum " + fmt(i, c.maxSpeed) + "/s");
        return std::nullopt;
    };
    double vx = 0, vy = 0, vz = 0;
    if (auto e = speedOf(ix, r.xySpeed, &vx))
        return e;
    if (auto e = speedOf(iy, r.xySpeed, &vy))
        return e;
    if (auto e = speedOf(iz, r.zSpeed, &vz))
        return e;
    double vp = 0;
    if (r.pump)
        if (auto e = speedOf(ip, r.pump->speed, &vp))
            return e;

    // Z counts down from its home (the analyzer's): "above" is the smaller value.
    const double zNow = st(iz).plant->reference();
    const double zTop = std::min(zNow, machineOf(iz, r.clearZ));
    const double zEnd = machineOf(iz, r.z);
    const double xEnd = machineOf(ix, r.x), yEnd = machineOf(iy, r.y);
    const double xNow = st(ix).plant->reference(), yNow = st(iy).plant->reference();
    const bool rises = zNow - zTop > 1e-9, descends = std::abs(zEnd - zTop) > 1e-9;
    const bool crosses = std::hypot(xEnd - xNow, yEnd - yNow) > 1e-9;
    // The pump block: the plunger runs only while the tip is at or below the liquid height,
    // which the way down must therefore pass (or the tip already be below), and the rise
    // after it must start at the bottom (Z counts down: below is larger).
    const double zLiquid = r.pump ? machineOf(iz, r.pump->liquidZ) : 0.0;
    const double zLeave = r.pump ? machineOf(iz, r.pump->leaveZ) : zEnd;
    const double pTarget = r.pump ? st(ip).plant->reference() + r.pump->delta / scale(ip) : 0.0;
    const bool pumps = r.pump && r.pump->delta != 0;
    if (r.pump && (zLiquid > zEnd + 1e-9 || zLeave > zEnd + 1e-9))
        return error(dev::proto::ErrorCode::OutOfRange, iz, zLiquid - st(iz).offset,
                     "an arched move's liquid height and the height it leaves to must be at or above its Z target");
    if (pumps && (!descends || zLiquid < zTop - 1e-9))
        return error(dev::proto::ErrorCode::OutOfRange, iz, zLiquid - st(iz).offset,
                     "an arched move's plunger needs a way down that passes its liquid height");
    const bool leaves = r.pump && zEnd - zLeave > 1e-9;
    const int arch = m_nextArchId++;
    int idRise = -1, idXy = -1, idDown = -1;
    if (rises)
        if (auto e = planSegment({iz}, {zTop}, vz, -1, dev::proto::EventKind::MotionDone, &idRise))
            return e;
    if (crosses)
        if (auto e = planSegment({ix, iy}, {xEnd, yEnd}, std::min(vx, vy), -1, dev::proto::EventKind::MotionDone, &idXy))
            return e;
    if (descends) {
        const std::vector<double> from{zTop};
        if (auto e = planSegment({iz}, {zEnd}, vz, -1, dev::proto::EventKind::MotionDone, &idDown, &from))
            return e;
    }
    int idPump = -1, idLeave = -1;
    if (pumps)
        if (auto e = planSegment({ip}, {pTarget}, vp, -1, dev::proto::EventKind::MotionDone, &idPump))
            return e;
    if (leaves) {
        const std::vector<double> from{zEnd};
        if (auto e = planSegment({iz}, {zLeave}, vz, -1, dev::proto::EventKind::MotionDone, &idLeave, &from))
            return e;
    }
    Segment* rise = segmentById(idRise);
    Segment* xy = segmentById(idXy);
    Segment* down = segmentById(idDown);
    Segment* pump = segmentById(idPump);
    Segment* leave = segmentById(idLeave);
    motion::ArchPumpParts parts;
    parts.plunger = pump ? pump->profile.get() : nullptr;
    parts.liquidMm = std::max(0.0, zLiquid - zTop);
    parts.leave = leave ? leave->profile.get() : nullptr;
    parts.leaveLiquidMm = std::max(0.0, zEnd - zLiquid);
    const motion::ArchTiming t = motion::archTiming(rise ? rise->profile.get() : nullptr, xy ? xy->profile.get() : nullptr,
                                                    down ? down->profile.get() : nullptr, r.departRadius / scale(ix),
                                                    r.approachRadius / scale(ix), parts);
    for (Segment* g : {rise, xy, down, pump, leave})
        if (g)
            g->arch = arch;
    if (rise && xy) {
        xy->after = rise->id;
        xy->afterS = t.xyStartS;
    }
    if (down) {
        // The way down hangs on XY's progress (so it follows XY's true start to the tick),
        // and on the rise when there is no XY; Z stays with the rise until it ends.
        if (xy) {
            down->after = xy->id;
            down->afterS = t.downStartS - t.xyStartS;
        } else if (rise) {
            down->after = rise->id;
        }
        if (rise) {
            rise->handsOver = true;
            st(iz).segment = rise->id;
        }
    }
    if (pump && down) {
        // The plunger hangs on the way down's progress: it starts as the tip passes the liquid height.
        pump->after = down->id;
        pump->afterS = t.pumpStartS - t.downStartS;
    }
    if (leave) {
        // Back up once Z is down and, while the plunger still runs, no sooner than lets the
        // plunger stop before the tip is above the liquid height again.
        const double pumpEndS = pump ? t.pumpStartS + pump->profile->duration() : 0.0;
        if (pump && pumpEndS > t.leaveStartS - 1e-12 && t.leaveStartS >= t.pumpStartS) {
            leave->after = pump->id;
            leave->afterS = t.leaveStartS - t.pumpStartS;
        } else if (down) {
            leave->after = down->id;
        }
        Segment* zBefore = down ? down : rise;
        if (zBefore) {
            zBefore->handsOver = true;
            if (!rise || !down)
                st(iz).segment = zBefore->id;
        } else {
            st(iz).segment = leave->id;
        }
    }
    // A part of no length has nothing to report at its end: its axes have arrived now.
    if (!crosses)
        for (int i : {ix, iy})
            raiseEvent(dev::proto::EventKind::MotionDone, i, "already there", dev::proto::reason::kAlreadyThere);
    if (!rises && !descends && !leaves)
        raiseEvent(dev::proto::EventKind::MotionDone, iz, "already there", dev::proto::reason::kAlreadyThere);
    return std::nullopt;
}

} // namespace dev::sim
