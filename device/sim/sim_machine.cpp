#include "device/sim/sim_machine.h"

#include "motion/jerk_limited.h"
#include "motion/seed_scurve.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace sim {
namespace {
constexpr std::uint16_t kMaxEvents = 256;  // bounded: oldest events are dropped first
}

SimMachine::SimMachine(const MachineConfig& config) : m_cfg(config)
{
    m_ticksPerControl = std::max(1, static_cast<int>(std::lround(config.controlPeriodS / kTickS)));
    std::uint64_t seed = config.seed;
    for (const auto& ac : config.axes) {
        AxisState s;
        s.plant = std::make_unique<SimAxis>(ac, config.closedLoop, seed++);
        s.offset = s.plant->reference();  // power-up: the counters read zero wherever the axis is
        s.softMin = 0;
        s.softMax = ac.travel;
        s.plant->holdHere();
        m_axes.push_back(std::move(s));
    }
}

SimMachine::~SimMachine() = default;

double SimMachine::scale(int i) const
{
    return st(i).plant->config().unit == proto::AxisUnit::Microlitre ? 1e3 : 1e6;
}

std::string SimMachine::fmt(int axis, double value) const
{
    char buf[64];
    const bool ul = st(axis).plant->config().unit == proto::AxisUnit::Microlitre;
    std::snprintf(buf, sizeof buf, ul ? "%.2f µL" : "%.3f mm", value);
    return buf;
}

proto::ErrorReply SimMachine::error(proto::ErrorCode code, int axis, double value, const std::string& text) const
{
    proto::ErrorReply e;
    e.code = code;
    e.axis = axis < 0 ? proto::kNoAxis : static_cast<std::uint8_t>(axis);
    e.value = axis < 0 ? static_cast<std::int32_t>(value) : static_cast<std::int32_t>(std::lround(value * scale(axis)));
    e.message = text;
    return e;
}

proto::HelloReply SimMachine::hello(std::uint32_t linkBaud) const
{
    proto::HelloReply h;
    h.kind = m_cfg.kind;
    h.capabilities = proto::CapHoming | proto::CapTelemetry | proto::CapJogVelocity;
    if (m_cfg.closedLoop)
        h.capabilities |= proto::CapGrating | proto::CapClosedLoopPid;
    else
        h.capabilities |= proto::CapEncoder;
    if (m_cfg.zAfterXy)
        h.capabilities |= proto::CapCoupledXyThenZ;
    for (const auto& a : m_cfg.axes)
        if (a.unit == proto::AxisUnit::Microlitre)
            h.capabilities |= proto::CapPump;
    h.controlPeriodUs = static_cast<std::uint32_t>(std::lround(m_cfg.controlPeriodS * 1e6));
    h.maxTelemetryRateHz = static_cast<std::uint32_t>(std::lround(1.0 / kTickS));
    h.jogWatchdogMs = proto::kJogWatchdogMs;
    h.linkBaud = linkBaud;
    h.model = m_cfg.model;
    h.firmware = "benchpilot-sim 1.0";
    for (int i = 0; i < axisCount(); ++i) {
        const auto& c = st(i).plant->config();
        proto::AxisInfo a;
        a.letter = c.letter;
        a.unit = c.unit;
        a.travelMin = 0;
        a.travelMax = static_cast<std::int32_t>(std::lround(c.travel * scale(i)));
        a.maxSpeed = static_cast<std::uint32_t>(std::lround(c.maxSpeed * scale(i)));
        a.resolution = static_cast<std::uint32_t>(std::lround(c.resolution * scale(i)));
        h.axes.push_back(a);
    }
    return h;
}

void SimMachine::raiseEvent(proto::EventKind kind, int axis, const std::string& text)
{
    proto::EventMsg e;
    e.kind = kind;
    e.axis = axis < 0 ? proto::kNoAxis : static_cast<std::uint8_t>(axis);
    e.deviceTimeUs = timeUs();
    if (axis >= 0)
        e.position = static_cast<std::int32_t>(std::lround((st(axis).plant->measured() - st(axis).offset) * scale(axis)));
    e.text = text;
    if (m_events.size() >= kMaxEvents)
        m_events.erase(m_events.begin());
    m_events.push_back(std::move(e));
}

std::vector<proto::EventMsg> SimMachine::takeEvents()
{
    std::vector<proto::EventMsg> out;
    out.swap(m_events);
    return out;
}

// ---- commands ---------------------------------------------------------------

SimMachine::Result SimMachine::checkAxes(std::uint8_t mask, bool mustBeIdle) const
{
    if (m_estop)
        return error(proto::ErrorCode::EStopActive, -1, 0, "E-stop is active: send reset before moving");
    for (int b = 0; b < 8; ++b) {
        if (!(mask & (1u << b)))
            continue;
        if (b >= axisCount())
            return error(proto::ErrorCode::BadAxis, -1, b, "axis index " + std::to_string(b) + " does not exist");
        if (mustBeIdle && st(b).mode != Mode::Idle)
            return error(proto::ErrorCode::Busy, b, 0,
                         std::string("axis ") + st(b).plant->config().letter + " is still moving");
    }
    return std::nullopt;
}

SimMachine::Result SimMachine::planSegment(const std::vector<int>& axes, const std::vector<double>& targets,
                                           double speed, int after, proto::EventKind doneEvent, int* idOut)
{
    Segment seg;
    seg.id = m_nextSegmentId++;
    seg.after = after;
    seg.doneEvent = doneEvent;
    double len2 = 0;
    for (std::size_t k = 0; k < axes.size(); ++k) {
        const int i = axes[k];
        // A segment that waits starts from where the earlier one leaves this axis,
        // which for disjoint axes is where it is now.
        const double from = st(i).plant->reference();
        seg.axes.push_back(i);
        seg.start.push_back(from);
        seg.dir.push_back(targets[k] - from);
        len2 += (targets[k] - from) * (targets[k] - from);
    }
    const double len = std::sqrt(len2);
    if (len < 1e-9) {
        for (int i : axes)
            raiseEvent(doneEvent, i, "already there");
        if (idOut)
            *idOut = -1;
        return std::nullopt;
    }
    // Path limits: each axis' share of the path speed must stay inside its own limit.
    double vPath = speed, aPath = 1e300, jPath = 1e300, accelTime = 0;
    for (std::size_t k = 0; k < axes.size(); ++k) {
        seg.dir[k] /= len;
        const auto& c = st(axes[k]).plant->config();
        const double u = std::abs(seg.dir[k]);
        if (u < 1e-12)
            continue;
        vPath = std::min(vPath, c.maxSpeed / u);
        aPath = std::min(aPath, c.maxAccel / u);
        jPath = std::min(jPath, c.maxJerk / u);
        accelTime = std::max(accelTime, c.accelTimeS);
    }
    if (m_cfg.profile == ProfileKind::SeedSCurve) {
        // The seed's curve peaks at 1.5·v/t_acc: stretch t_acc until every axis can follow.
        accelTime = std::max(accelTime, 1.5 * vPath / aPath);
        auto p = motion::SeedSCurve::plan(len, vPath, accelTime);
        if (!p)
            return error(proto::ErrorCode::OutOfRange, -1, 0, "cannot plan an S-curve for this move");
        seg.profile = std::make_shared<motion::SeedSCurve>(*p);
    } else {
        auto p = motion::JerkLimitedProfile::plan(len, motion::JerkLimits{vPath, aPath, jPath});
        if (!p)
            return error(proto::ErrorCode::OutOfRange, -1, 0, "cannot plan a jerk-limited move");
        seg.profile = std::make_shared<motion::JerkLimitedProfile>(*p);
    }
    for (int i : axes) {
        st(i).mode = Mode::Segment;
        st(i).segment = seg.id;
        st(i).doneEvent = doneEvent;
        st(i).lostReported = false;
    }
    if (m_cfg.closedLoop && axes.size() == 2) {
        m_xyLineStart = seg.start;
        m_xyLineDir = seg.dir;
    }
    if (idOut)
        *idOut = seg.id;
    m_segments.push_back(std::move(seg));
    return std::nullopt;
}

SimMachine::Result SimMachine::move(const proto::MoveRequest& r)
{
    if (auto e = checkAxes(r.axisMask, true))
        return e;
    std::vector<int> axes;
    std::vector<double> targets;
    double speed = 1e300;
    std::size_t k = 0;
    for (int b = 0; b < axisCount(); ++b) {
        if (!(r.axisMask & (1u << b)))
            continue;
        const AxisState& s = st(b);
        const auto& c = s.plant->config();
        const double value = r.targets[k++] / scale(b);
        if (!r.relative && !s.homed)
            return error(proto::ErrorCode::NotHomed, b, value,
                         std::string("axis ") + c.letter + " is not homed: home it before an absolute move");
        const double logicalNow = s.plant->reference() - s.offset;
        const double targetLogical = r.relative ? logicalNow + value : value;
        const double targetMachine = targetLogical + s.offset;
        if (s.homed && (targetMachine < s.softMin - 1e-9 || targetMachine > s.softMax + 1e-9)) {
            const bool low = targetMachine < s.softMin;
            const double lim = (low ? s.softMin : s.softMax) - s.offset;
            return error(proto::ErrorCode::SoftLimit, b, lim,
                         std::string("axis ") + c.letter + " target " + fmt(b, targetLogical) + " is beyond the "
                             + (low ? "lower" : "upper") + " soft limit " + fmt(b, lim));
        }
        if (r.speed != 0) {
            const double v = r.speed / scale(b);
            if (v > c.maxSpeed + 1e-9)
                return error(proto::ErrorCode::OutOfRange, b, v,
                             std::string("speed ") + fmt(b, v) + "/s is above axis " + c.letter + "'s maximum "
                                 + fmt(b, c.maxSpeed) + "/s");
            speed = std::min(speed, v);
        } else {
            speed = std::min(speed, c.defaultSpeed);
        }
        axes.push_back(b);
        targets.push_back(targetMachine);
    }
    // Analyzer: X and Y move together on a straight line, the pump on its own,
    // and Z only once XY has arrived (the seed's cross-coupled XY, Z following).
    std::vector<int> xy, z, other;
    std::vector<double> txy, tz, tother;
    for (std::size_t n = 0; n < axes.size(); ++n) {
        const char l = st(axes[n]).plant->config().letter;
        if (l == 'X' || l == 'Y') {
            xy.push_back(axes[n]);
            txy.push_back(targets[n]);
        } else if (l == 'Z' && m_cfg.zAfterXy) {
            z.push_back(axes[n]);
            tz.push_back(targets[n]);
        } else {
            other.push_back(axes[n]);
            tother.push_back(targets[n]);
        }
    }
    int xyId = -1;
    if (!xy.empty())
        if (auto e = planSegment(xy, txy, speed, -1, proto::EventKind::MotionDone, &xyId))
            return e;
    if (!z.empty()) {
        const double zSpeed = r.speed ? r.speed / scale(z[0]) : st(z[0]).plant->config().defaultSpeed;
        if (auto e = planSegment(z, tz, zSpeed, xyId, proto::EventKind::MotionDone, nullptr))
            return e;
    }
    for (std::size_t n = 0; n < other.size(); ++n) {
        const double s = r.speed ? r.speed / scale(other[n]) : st(other[n]).plant->config().defaultSpeed;
        if (auto e = planSegment({other[n]}, {tother[n]}, s, -1, proto::EventKind::MotionDone, nullptr))
            return e;
    }
    return std::nullopt;
}

SimMachine::Result SimMachine::jogStep(const proto::JogStepRequest& r)
{
    if (r.axis >= axisCount())
        return error(proto::ErrorCode::BadAxis, -1, r.axis, "axis index " + std::to_string(r.axis) + " does not exist");
    proto::MoveRequest m;
    m.relative = true;
    m.speed = r.speed;
    m.axisMask = static_cast<std::uint8_t>(1u << r.axis);
    m.targets = {r.delta};
    return move(m);
}

SimMachine::Result SimMachine::jogVelocity(const proto::JogVelocityRequest& r)
{
    if (auto e = checkAxes(r.axisMask, false))
        return e;
    std::size_t k = 0;
    for (int b = 0; b < axisCount(); ++b) {
        if (!(r.axisMask & (1u << b)))
            continue;
        const double v = r.velocities[k++] / scale(b);
        const AxisState& s = st(b);
        const auto& c = s.plant->config();
        if (s.mode != Mode::Idle && s.mode != Mode::Jog)
            return error(proto::ErrorCode::Busy, b, 0, std::string("axis ") + c.letter + " is busy with a move or homing");
        if (std::abs(v) > c.maxSpeed + 1e-9)
            return error(proto::ErrorCode::OutOfRange, b, v,
                         std::string("jog speed ") + fmt(b, v) + "/s is above axis " + c.letter + "'s maximum "
                             + fmt(b, c.maxSpeed) + "/s");
    }
    k = 0;
    for (int b = 0; b < axisCount(); ++b) {
        if (!(r.axisMask & (1u << b)))
            continue;
        AxisState& s = st(b);
        const double v = r.velocities[k++] / scale(b);
        if (s.mode == Mode::Idle) {
            if (v == 0)
                continue;
            s.mode = Mode::Jog;
            s.v = 0;
            s.lostReported = false;
        }
        s.vTarget = v;
        s.accel = s.plant->config().maxAccel;
        s.lastRefreshS = timeS();
        s.expired = false;
    }
    return std::nullopt;
}

SimMachine::Result SimMachine::stop(std::uint8_t mask)
{
    if (mask == 0)
        mask = 0xFF;
    std::vector<int> segIds;
    for (int i = 0; i < axisCount(); ++i) {
        if (!(mask & (1u << i)))
            continue;
        AxisState& s = st(i);
        if (s.mode == Mode::Segment)
            segIds.push_back(s.segment);
        if (s.mode == Mode::Jog || s.mode == Mode::Homing) {
            s.mode = Mode::Decel;
            s.v = s.plant->referenceVelocity();
            s.vTarget = 0;
            s.accel = s.plant->config().maxAccel;
        }
    }
    m_homeStages.clear();
    // Axes of one segment slow down together, so a coupled XY move stops on its line.
    for (int id : segIds) {
        auto it = std::find_if(m_segments.begin(), m_segments.end(), [&](const Segment& g) { return g.id == id; });
        if (it == m_segments.end())
            continue;
        double speed = 0, aPath = 1e300;
        for (std::size_t k = 0; k < it->axes.size(); ++k) {
            const double vk = st(it->axes[k]).plant->referenceVelocity();
            speed += vk * vk;
            if (std::abs(it->dir[k]) > 1e-12)
                aPath = std::min(aPath, st(it->axes[k]).plant->config().maxAccel / std::abs(it->dir[k]));
        }
        speed = std::sqrt(speed);
        const double stopTime = speed > 0 ? speed / aPath : 0;
        for (int i : it->axes) {
            AxisState& s = st(i);
            s.mode = Mode::Decel;
            s.v = s.plant->referenceVelocity();
            s.vTarget = 0;
            s.accel = stopTime > 0 ? std::abs(s.v) / stopTime : 1.0;
            s.segment = -1;
        }
        m_segments.erase(it);
    }
    // Segments still waiting for a stopped one are dropped with it.
    m_segments.erase(std::remove_if(m_segments.begin(), m_segments.end(),
                                    [&](const Segment& g) {
                                        if (g.started)
                                            return false;
                                        for (int i : g.axes)
                                            if (mask & (1u << i)) {
                                                for (int a : g.axes)
                                                    if (st(a).segment == g.id) {
                                                        st(a).mode = Mode::Idle;
                                                        st(a).segment = -1;
                                                        raiseEvent(proto::EventKind::Stopped, a, "cancelled before it started");
                                                    }
                                                return true;
                                            }
                                        return false;
                                    }),
                     m_segments.end());
    return std::nullopt;
}

SimMachine::Result SimMachine::estop()
{
    m_estop = true;
    m_segments.clear();
    m_homeStages.clear();
    for (int i = 0; i < axisCount(); ++i) {
        AxisState& s = st(i);
        s.plant->freeze();
        s.mode = Mode::Idle;
        s.segment = -1;
        s.v = s.vTarget = 0;
    }
    raiseEvent(proto::EventKind::EStop, -1, "emergency stop: all motion halted");
    return std::nullopt;
}

SimMachine::Result SimMachine::reset()
{
    if (m_estop) {
        m_estop = false;
        for (int i = 0; i < axisCount(); ++i)
            st(i).plant->holdHere();
    }
    for (int i = 0; i < axisCount(); ++i)
        st(i).fault = false;
    raiseEvent(proto::EventKind::Reset, -1, "E-stop and faults cleared");
    return std::nullopt;
}

SimMachine::Result SimMachine::setZero(std::uint8_t mask)
{
    if (auto e = checkAxes(mask, true))
        return e;
    for (int i = 0; i < axisCount(); ++i)
        if (mask & (1u << i))
            st(i).offset = st(i).plant->reference();
    return std::nullopt;
}

SimMachine::Result SimMachine::setLimits(const proto::SetLimitsRequest& r)
{
    if (r.axis >= axisCount())
        return error(proto::ErrorCode::BadAxis, -1, r.axis, "axis index " + std::to_string(r.axis) + " does not exist");
    AxisState& s = st(r.axis);
    const auto& c = s.plant->config();
    const double lo = r.limits.min / scale(r.axis) + s.offset;
    const double hi = r.limits.max / scale(r.axis) + s.offset;
    if (!(lo < hi))
        return error(proto::ErrorCode::OutOfRange, r.axis, lo - s.offset,
                     std::string("axis ") + c.letter + " lower soft limit must be below the upper one");
    if (lo < -1e-9 || hi > c.travel + 1e-9)
        return error(proto::ErrorCode::OutOfRange, r.axis, lo < -1e-9 ? lo - s.offset : hi - s.offset,
                     std::string("axis ") + c.letter + " soft limits must lie inside the travel " + fmt(r.axis, -s.offset)
                         + " … " + fmt(r.axis, c.travel - s.offset));
    s.softMin = lo;
    s.softMax = hi;
    return std::nullopt;
}

proto::LimitsReply SimMachine::limits() const
{
    proto::LimitsReply r;
    for (int i = 0; i < axisCount(); ++i) {
        const AxisState& s = st(i);
        r.axes.push_back({static_cast<std::int32_t>(std::lround((s.softMin - s.offset) * scale(i))),
                          static_cast<std::int32_t>(std::lround((s.softMax - s.offset) * scale(i)))});
    }
    return r;
}

SimMachine::Result SimMachine::home(std::uint8_t mask)
{
    if (mask == 0)
        mask = static_cast<std::uint8_t>((1u << axisCount()) - 1);
    if (auto e = checkAxes(mask, true))
        return e;
    m_homeStages.clear();
    // The analyzer lifts Z clear of the plate before X and Y sweep to their switches.
    std::uint8_t zMask = 0;
    for (int i = 0; i < axisCount(); ++i)
        if ((mask & (1u << i)) && m_cfg.zAfterXy && st(i).plant->config().letter == 'Z')
            zMask = static_cast<std::uint8_t>(zMask | (1u << i));
    if (zMask)
        m_homeStages.push_back(zMask);
    if (mask & ~zMask)
        m_homeStages.push_back(static_cast<std::uint8_t>(mask & ~zMask));
    for (int i = 0; i < axisCount(); ++i)
        if (mask & (1u << i))
            st(i).homed = false;
    startHomingStage();
    return std::nullopt;
}

void SimMachine::startHomingStage()
{
    if (m_homeStages.empty())
        return;
    const std::uint8_t mask = m_homeStages.front();
    for (int i = 0; i < axisCount(); ++i) {
        if (!(mask & (1u << i)))
            continue;
        AxisState& s = st(i);
        s.mode = Mode::Homing;
        s.phase = s.plant->homeSwitch() ? HomePhase::BackOff : HomePhase::SeekFast;
        s.phaseStart = s.plant->reference();
        s.v = 0;
        s.accel = s.plant->config().maxAccel;
        s.vTarget = s.phase == HomePhase::SeekFast ? -s.plant->config().homeFastSpeed : s.plant->config().homeSlowSpeed * 2;
    }
}

// ---- the tick -----------------------------------------------------------------

void SimMachine::finishAxis(int i, proto::EventKind kind, const std::string& text)
{
    AxisState& s = st(i);
    s.mode = Mode::Idle;
    s.segment = -1;
    s.v = s.vTarget = 0;
    raiseEvent(kind, i, text);
    if (!m_cfg.closedLoop && !s.lostReported) {
        const double err = s.plant->measured() - s.plant->reference();
        if (std::abs(err) > m_cfg.lostStepTolerance) {
            s.lostReported = true;
            raiseEvent(proto::EventKind::LostSteps, i,
                 std::string("axis ") + s.plant->config().letter + " encoder is " + fmt(i, err) + " off the command");
        }
    }
}

void SimMachine::stopAxisHard(int i)
{
    AxisState& s = st(i);
    s.plant->holdHere();
    s.v = s.vTarget = 0;
    if (s.mode == Mode::Segment) {
        // The whole coupled segment halts so the other axes do not run on alone.
        const int id = s.segment;
        auto it = std::find_if(m_segments.begin(), m_segments.end(), [&](const Segment& g) { return g.id == id; });
        if (it != m_segments.end()) {
            for (int a : it->axes)
                if (a != i) {
                    st(a).plant->holdHere();
                    finishAxis(a, proto::EventKind::Stopped, "stopped with its coupled axis");
                }
            m_segments.erase(it);
        }
        m_segments.erase(std::remove_if(m_segments.begin(), m_segments.end(),
                                        [&](const Segment& g) { return g.after == id; }),
                         m_segments.end());
    }
    s.mode = Mode::Idle;
    s.segment = -1;
}

void SimMachine::checkSwitches(int i)
{
    AxisState& s = st(i);
    if (s.mode == Mode::Homing || s.mode == Mode::Idle)
        return;
    const double v = s.plant->referenceVelocity();
    const auto& c = s.plant->config();
    if (s.plant->homeSwitch() && v < 0) {
        stopAxisHard(i);
        raiseEvent(proto::EventKind::LimitHit, i, std::string("axis ") + c.letter + " hit its home switch");
    } else if (s.plant->limitSwitch() && v > 0) {
        stopAxisHard(i);
        raiseEvent(proto::EventKind::LimitHit, i, std::string("axis ") + c.letter + " hit its limit switch");
    }
}

void SimMachine::tickSegments()
{
    std::vector<int> finished;
    for (auto& g : m_segments) {
        if (!g.started) {
            const bool waiting = g.after >= 0
                && std::any_of(m_segments.begin(), m_segments.end(), [&](const Segment& o) { return o.id == g.after; });
            if (waiting)
                continue;
            g.started = true;
        }
        g.t += kTickS;
        const motion::ProfileSample p = g.profile->at(g.t);
        for (std::size_t k = 0; k < g.axes.size(); ++k)
            st(g.axes[k]).plant->setReference(g.start[k] + g.dir[k] * p.s, g.dir[k] * p.v);
        if (g.t >= g.profile->duration())
            finished.push_back(g.id);
    }
    for (int id : finished) {
        auto it = std::find_if(m_segments.begin(), m_segments.end(), [&](const Segment& g) { return g.id == id; });
        if (it == m_segments.end())
            continue;
        const Segment g = std::move(*it);
        m_segments.erase(it);
        for (std::size_t k = 0; k < g.axes.size(); ++k) {
            const int i = g.axes[k];
            st(i).plant->setReference(g.start[k] + g.dir[k] * g.profile->distance(), 0);
            if (m_cfg.closedLoop) {
                st(i).mode = Mode::Settling;
                st(i).settleStartS = timeS();
                st(i).settledS = 0;
            } else {
                finishAxis(i, g.doneEvent);
            }
        }
    }
}

void SimMachine::tickVelocityModes()
{
    for (int i = 0; i < axisCount(); ++i) {
        AxisState& s = st(i);
        if (s.mode != Mode::Jog && s.mode != Mode::Decel && s.mode != Mode::Homing)
            continue;
        const auto& c = s.plant->config();
        if (s.mode == Mode::Jog && !s.expired && timeS() - s.lastRefreshS > kJogWatchdogTripS) {
            // The host went quiet (frozen GUI, pulled cable): stop within the budget.
            s.expired = true;
            s.vTarget = 0;
            s.accel = std::max(c.maxAccel, std::abs(s.v) / kJogStopBudgetS);
            raiseEvent(proto::EventKind::JogExpired, i, std::string("axis ") + c.letter + " jog not refreshed: stopped");
        }
        double target = s.vTarget;
        const double pos = s.plant->reference();
        if (s.mode == Mode::Jog && s.homed) {
            // Never coast through a soft limit: the speed is capped by the distance left.
            const double room = s.v >= 0 ? s.softMax - pos : pos - s.softMin;
            const double vCap = std::sqrt(2.0 * s.accel * std::max(0.0, room));
            if (target > 0 && s.v >= 0)
                target = std::min(target, vCap);
            if (target < 0 && s.v <= 0)
                target = std::max(target, -vCap);
        }
        const double dv = s.accel * kTickS;
        if (s.v < target)
            s.v = std::min(target, s.v + dv);
        else if (s.v > target)
            s.v = std::max(target, s.v - dv);
        double next = pos + s.v * kTickS;
        if (s.mode == Mode::Jog && s.homed)
            next = std::clamp(next, s.softMin, s.softMax);
        s.plant->setReference(next, s.v);
        if (s.mode == Mode::Homing) {
            tickHoming(i);
            continue;
        }
        if (s.v == 0 && s.vTarget == 0) {
            if (m_cfg.closedLoop) {
                s.doneEvent = s.mode == Mode::Decel ? proto::EventKind::Stopped : proto::EventKind::MotionDone;
                s.mode = Mode::Settling;
                s.settleStartS = timeS();
                s.settledS = 0;
            } else {
                finishAxis(i, s.mode == Mode::Decel ? proto::EventKind::Stopped : proto::EventKind::MotionDone);
            }
        }
    }
}

void SimMachine::tickHoming(int i)
{
    AxisState& s = st(i);
    const auto& c = s.plant->config();
    const double pos = s.plant->reference();
    switch (s.phase) {
    case HomePhase::SeekFast:
        if (s.plant->homeSwitch()) {
            s.plant->holdHere();
            s.v = 0;
            s.phase = HomePhase::BackOff;
            s.phaseStart = s.plant->reference();
            s.vTarget = c.homeSlowSpeed * 2;
        } else if (s.phaseStart - pos > c.travel + c.limitSwitchMargin + 2 * c.hardStopMargin) {
            s.mode = Mode::Idle;
            s.fault = true;
            s.plant->holdHere();
            m_homeStages.clear();
            raiseEvent(proto::EventKind::Fault, i, std::string("axis ") + c.letter + " home switch not found over the whole travel");
        }
        break;
    case HomePhase::BackOff:
        if (!s.plant->homeSwitch() && pos - s.phaseStart > c.homeBackoff) {
            s.vTarget = -c.homeSlowSpeed;
            s.v = 0;
            s.phase = HomePhase::SeekSlow;
        }
        break;
    case HomePhase::SeekSlow:
        if (s.plant->homeSwitch()) {
            s.plant->holdHere();
            s.v = s.vTarget = 0;
            // Latch: the switch edge becomes homeSwitchAt in the new coordinates,
            // give or take the switch's repeatability.
            const double noise = c.switchRepeatability > 0 ? s.plant->uniform(-c.switchRepeatability, c.switchRepeatability) : 0;
            s.offset = s.plant->reference() - c.homeSwitchAt + noise;
            s.homed = true;
            s.mode = Mode::Idle;
            planSegment({i}, {s.offset}, c.homeFastSpeed, -1, proto::EventKind::HomeDone, nullptr);
        }
        break;
    }
}

void SimMachine::tickSettling(int i)
{
    AxisState& s = st(i);
    if (std::abs(s.plant->followingError()) <= m_cfg.inPositionWindow)
        s.settledS += kTickS;
    else
        s.settledS = 0;
    if (s.settledS >= m_cfg.settleTimeS) {
        finishAxis(i, s.doneEvent);
    } else if (timeS() - s.settleStartS > 2.0) {
        finishAxis(i, s.doneEvent, "arrived outside the in-position window");
    }
}

void SimMachine::tick()
{
    ++m_ticks;
    tickSegments();
    tickVelocityModes();
    for (int i = 0; i < axisCount(); ++i) {
        if (m_cfg.closedLoop && m_ticks % static_cast<std::uint64_t>(m_ticksPerControl) == 0)
            st(i).plant->controlStep(m_cfg.gains, m_ticksPerControl);
        st(i).plant->tick(kTickS);
        if (st(i).mode == Mode::Settling)
            tickSettling(i);
        checkSwitches(i);
    }
    // Homing stages run in order: the next begins when every axis of this one is homed.
    if (!m_homeStages.empty()) {
        const std::uint8_t mask = m_homeStages.front();
        bool done = true;
        for (int i = 0; i < axisCount(); ++i)
            if ((mask & (1u << i)) && (st(i).mode != Mode::Idle || !st(i).homed))
                done = false;
        if (done) {
            m_homeStages.erase(m_homeStages.begin());
            startHomingStage();
        }
    }
}

// ---- readouts -------------------------------------------------------------------

proto::StatusReply SimMachine::status() const
{
    proto::StatusReply r;
    r.deviceFlags = static_cast<std::uint8_t>((m_estop ? proto::DeviceEStop : 0));
    r.deviceTimeUs = timeUs();
    for (int i = 0; i < axisCount(); ++i) {
        const AxisState& s = st(i);
        proto::AxisStatus a;
        a.commanded = static_cast<std::int32_t>(std::lround((s.plant->reference() - s.offset) * scale(i)));
        a.measured = static_cast<std::int32_t>(std::lround((s.plant->measured() - s.offset) * scale(i)));
        std::uint16_t f = 0;
        if (s.homed)
            f |= proto::AxisHomed;
        if (s.mode != Mode::Idle)
            f |= proto::AxisMoving;
        if (s.mode == Mode::Homing || (!m_homeStages.empty() && !s.homed && (m_homeStages.front() & (1u << i))))
            f |= proto::AxisHoming;
        if (s.mode == Mode::Jog)
            f |= proto::AxisJogging;
        if (s.plant->homeSwitch())
            f |= proto::AxisHomeSwitch;
        if (s.plant->limitSwitch())
            f |= proto::AxisLimitSwitch;
        if (s.fault) {
            f |= proto::AxisFault;
            r.deviceFlags |= proto::DeviceFault;
        }
        a.flags = f;
        r.axes.push_back(a);
    }
    // Axes waiting on a later homing stage are part of the homing too.
    for (std::size_t n = 1; n < m_homeStages.size(); ++n)
        for (int i = 0; i < axisCount(); ++i)
            if (m_homeStages[n] & (1u << i))
                r.axes[static_cast<std::size_t>(i)].flags |= proto::AxisHoming | proto::AxisMoving;
    return r;
}

double SimMachine::contourErrorMm() const
{
    if (axisCount() < 2)
        return 0;
    const double mx = st(0).plant->measured(), my = st(1).plant->measured();
    if (m_xyLineDir.size() == 2) {
        // Distance from the last commanded XY line: what a stitched image would see as drift.
        const double dx = mx - m_xyLineStart[0], dy = my - m_xyLineStart[1];
        return std::abs(dx * m_xyLineDir[1] - dy * m_xyLineDir[0]);
    }
    return std::hypot(mx - st(0).plant->reference(), my - st(1).plant->reference());
}

bool SimMachine::channelExists(const proto::ChannelRef& c) const
{
    if (c.kind == proto::ChannelKind::ContourError)
        return c.axis == proto::kNoAxis && m_cfg.closedLoop;
    return c.axis < axisCount();
}

std::int32_t SimMachine::channelValue(const proto::ChannelRef& c) const
{
    if (c.kind == proto::ChannelKind::ContourError)
        return static_cast<std::int32_t>(std::lround(contourErrorMm() * 1e6));
    const AxisState& s = st(c.axis);
    const SimAxis& p = *s.plant;
    const double k = scale(c.axis);
    double v = 0;
    switch (c.kind) {
    case proto::ChannelKind::Commanded: v = (p.reference() - s.offset) * k; break;
    case proto::ChannelKind::Measured: v = (p.measured() - s.offset) * k; break;
    case proto::ChannelKind::Velocity: v = p.measuredVelocity() * k; break;
    case proto::ChannelKind::FollowingError: v = p.followingError() * k; break;
    case proto::ChannelKind::ControllerOutput: v = p.controllerOutputStepsS(); break;
    case proto::ChannelKind::Switches: v = (p.homeSwitch() ? 1 : 0) | (p.limitSwitch() ? 2 : 0); break;
    case proto::ChannelKind::ContourError: break;
    }
    return static_cast<std::int32_t>(std::clamp(std::lround(v), -2147483647L, 2147483647L));
}

} // namespace sim
