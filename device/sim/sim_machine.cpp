#include "device/sim/sim_machine.h"

#include "device/sim/sim_tuning.h"

#include "device/sim/path_queue.h"
#include "device/sim/sim_compensation_2d.h"
#include "motion/jerk_limited.h"
#include "motion/seed_scurve.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace dev::sim {
namespace {
constexpr std::uint16_t kMaxEvents = 256;  // bounded: oldest events are dropped first
}

SimMachine::SimMachine(const MachineConfig& config, const NonVolatile& powerUp) : m_cfg(config)
{
    m_ticksPerControl = std::max(1, static_cast<int>(std::lround(config.controlPeriodS / kTickS)));
    std::uint64_t seed = config.seed;
    for (const auto& ac : config.axes) {
        AxisState s;
        s.plant = std::make_unique<SimAxis>(ac, config.closedLoop, seed++, config.driveLagS, config.rotorLagS);
        s.plant->holdHere();
        s.softMin = 0;
        s.softMax = ac.travel;
        m_axes.push_back(std::move(s));
        zeroCounters(axisCount() - 1, 0.0);  // power-up: the counters read zero wherever the axis is
    }
    m_tuning = std::make_unique<SimTuning>(*this);
    m_path = std::make_unique<PathQueue>(*this);
    m_comp = std::make_unique<SimCompensation>(*this, powerUp);
    m_comp2d = std::make_unique<SimCompensation2d>(*this, powerUp);
}

SimMachine::~SimMachine() = default;

void SimMachine::setGains(const PidGains& g) { m_tuning->setAllGains(g); }

double SimMachine::commandedLogical(int i) const { return st(i).plant->reference() - st(i).offset; }
double SimMachine::measuredLogical(int i) const { return st(i).plant->reportedMeasured() - st(i).measuredOffset; }
double SimMachine::workPointLogical(int i) const
{
    if (i < 2 && hasStageErrors())
        return stageWorkPointMachine(i, st(0).plant->carriage(), st(1).plant->carriage()) - st(i).measuredOffset;
    return st(i).plant->workPoint() - st(i).measuredOffset;
}

bool SimMachine::hasStageErrors() const { return m_cfg.stageErrors.has_value() && axisCount() >= 2; }

double SimMachine::stageWorkPointMachine(int i, double carriageX, double carriageY) const
{
    const auto& e = *m_cfg.stageErrors;
    const double own = i == 0 ? carriageX : carriageY;
    const auto& cfg = st(i).plant->config();
    // The pitch is the axis' own work-point error (abbeErrorPolyUm, which the file's
    // pitch polynomial set); the cross terms and the lost motion come from the model.
    const auto v = motion::metrology::stageErrorUm(e, carriageX, carriageY, st(0).plant->approach(), st(1).plant->approach());
    const double pitch = motion::metrology::polynomialUm(cfg.abbeErrorPolyUm, own);
    const double ownPitchInModel = motion::metrology::polynomialUm(i == 0 ? e.x.pitchPolyUm : e.y.pitchPolyUm, own);
    return own + (pitch + (i == 0 ? v.xUm : v.yUm) - ownPitchInModel) * 1e-3;
}

SimMachine::WorkPointMm SimMachine::trueWorkPoint() const
{
    if (axisCount() < 2)
        return {};
    return {workPointLogical(0), workPointLogical(1)};
}

SimMachine::WorkPointMm SimMachine::trueWorkPointAt(double gratingXMm, double gratingYMm) const
{
    if (axisCount() < 2)
        return {};
    // The grating reads the carriage through its own scale error (SimAxis::measured).
    const double cx = (gratingXMm + st(0).measuredOffset) / (1.0 + st(0).plant->config().scaleErrorPerUnit);
    const double cy = (gratingYMm + st(1).measuredOffset) / (1.0 + st(1).plant->config().scaleErrorPerUnit);
    if (!hasStageErrors()) {
        auto single = [&](int i, double c) {
            return c + motion::metrology::polynomialUm(st(i).plant->config().abbeErrorPolyUm, c) * 1e-3 - st(i).measuredOffset;
        };
        return {single(0, cx), single(1, cy)};
    }
    return {stageWorkPointMachine(0, cx, cy) - st(0).measuredOffset, stageWorkPointMachine(1, cx, cy) - st(1).measuredOffset};
}

void SimMachine::zeroCounters(int i, double logicalHere)
{
    AxisState& s = st(i);
    s.offset = s.plant->reference() - logicalHere;
    if (m_cfg.closedLoop) {
        // The servo compares command and grating in one frame, so they share the
        // offset; a grating counter only holds whole counts, so zero is one too.
        const double res = s.plant->config().resolution;
        s.offset = std::round(s.offset / res) * res;
        s.measuredOffset = s.offset;
        return;
    }
    // The encoder counter is loaded with the same value, rounded to whole counts
    // so it keeps reading multiples of its resolution.
    const double res = s.plant->config().resolution;
    s.measuredOffset = s.plant->measured() - std::round(logicalHere / res) * res;
}

double SimMachine::scale(int i) const
{
    return st(i).plant->config().unit == dev::proto::AxisUnit::Microlitre ? 1e3 : 1e6;
}

std::string SimMachine::fmt(int axis, double value) const
{
    char buf[64];
    const bool ul = st(axis).plant->config().unit == dev::proto::AxisUnit::Microlitre;
    std::snprintf(buf, sizeof buf, ul ? "%.2f µL" : "%.3f mm", value);
    return buf;
}

std::int32_t SimMachine::wireInt32(double value)
{
    // An error names the value it refused, which can be anything the host sent (a
    // target of 2.3e9 nm, a speed of 4e9): the wire field says "at least this much"
    // instead of a wrapped number, and a double outside int32 is never cast (undefined).
    if (std::isnan(value))
        return 0;
    constexpr double lo = std::numeric_limits<std::int32_t>::min(), hi = std::numeric_limits<std::int32_t>::max();
    return static_cast<std::int32_t>(std::clamp(value, lo, hi));  // truncates, as the cast did
}

dev::proto::ErrorReply SimMachine::error(dev::proto::ErrorCode code, int axis, double value, const std::string& text) const
{
    dev::proto::ErrorReply e;
    e.code = code;
    e.axis = axis < 0 ? dev::proto::kNoAxis : static_cast<std::uint8_t>(axis);
    e.value = wireInt32(axis < 0 ? value : std::round(value * scale(axis)));
    e.message = text;
    return e;
}

void SimMachine::raiseEvent(dev::proto::EventKind kind, int axis, const std::string& text, std::uint8_t why, std::vector<double> values)
{
    dev::proto::EventMsg e;
    e.kind = kind;
    e.axis = axis < 0 ? dev::proto::kNoAxis : static_cast<std::uint8_t>(axis);
    e.deviceTimeUs = timeUs();
    if (axis >= 0)
        e.position = wireInt32(std::round(measuredLogical(axis) * scale(axis)));
    e.text = text;
    if (why != 0)
        e.reason = dev::proto::EventReason{why, std::move(values)};
    if (m_events.size() >= kMaxEvents)
        m_events.erase(m_events.begin());
    m_events.push_back(std::move(e));
}

std::vector<dev::proto::EventMsg> SimMachine::takeEvents()
{
    std::vector<dev::proto::EventMsg> out;
    out.swap(m_events);
    return out;
}

// ---- commands ---------------------------------------------------------------

SimMachine::Result SimMachine::checkAxes(std::uint8_t mask, bool mustBeIdle) const
{
    if (m_estop)
        return error(dev::proto::ErrorCode::EStopActive, -1, 0, "E-stop is active: send reset before moving");
    for (int b = 0; b < 8; ++b) {
        if (!(mask & (1u << b)))
            continue;
        if (b >= axisCount())
            return error(dev::proto::ErrorCode::BadAxis, -1, b, "axis index " + std::to_string(b) + " does not exist");
        if (mustBeIdle && (st(b).mode != Mode::Idle || awaitingHoming(b)))
            return error(dev::proto::ErrorCode::Busy, b, 0,
                         std::string("axis ") + st(b).plant->config().letter + " is still moving");
    }
    return std::nullopt;
}

SimMachine::Result SimMachine::planSegment(const std::vector<int>& axes, const std::vector<double>& targets,
                                           double speed, int after, dev::proto::EventKind doneEvent, int* idOut,
                                           const std::vector<double>* fromMachine)
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
        const double from = fromMachine ? (*fromMachine)[k] : st(i).plant->reference();
        seg.axes.push_back(i);
        seg.start.push_back(from);
        seg.dir.push_back(targets[k] - from);
        len2 += (targets[k] - from) * (targets[k] - from);
    }
    const double len = std::sqrt(len2);
    if (len < 1e-9) {
        for (int i : axes)
            raiseEvent(doneEvent, i, "already there", dev::proto::reason::kAlreadyThere);
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
            return error(dev::proto::ErrorCode::OutOfRange, -1, 0, "cannot plan an S-curve for this move");
        seg.profile = std::make_shared<motion::SeedSCurve>(*p);
    } else {
        auto p = motion::JerkLimitedProfile::plan(len, motion::JerkLimits{vPath, aPath, jPath});
        if (!p)
            return error(dev::proto::ErrorCode::OutOfRange, -1, 0, "cannot plan a jerk-limited move");
        seg.profile = std::make_shared<motion::JerkLimitedProfile>(*p);
    }
    for (int i : axes) {
        st(i).mode = Mode::Segment;
        st(i).segment = seg.id;
        st(i).doneEvent = doneEvent;
        st(i).lostReported = false;
    }
    if (m_cfg.closedLoop && axisCount() >= 2) {
        // The contour channel measures against this segment's XY line; an axis the
        // segment does not move stays where its reference is.
        m_xyLineStart = {st(0).plant->reference(), st(1).plant->reference()};
        m_xyLineDir = {0.0, 0.0};
        for (std::size_t k = 0; k < seg.axes.size(); ++k)
            if (seg.axes[k] < 2)
                m_xyLineDir[static_cast<std::size_t>(seg.axes[k])] = seg.dir[k];
        const double norm = std::hypot(m_xyLineDir[0], m_xyLineDir[1]);
        if (norm < 1e-12) {
            m_xyLineDir.clear();
        } else {
            m_xyLineDir[0] /= norm;
            m_xyLineDir[1] /= norm;
        }
    }
    if (idOut)
        *idOut = seg.id;
    m_segments.push_back(std::move(seg));
    return std::nullopt;
}

SimMachine::Result SimMachine::move(const dev::proto::MoveRequest& r)
{
    // The decoder guarantees one target per axis; a caller in-process may not.
    if (r.axisMask == 0 || r.targets.size() != static_cast<std::size_t>(dev::proto::popcount8(r.axisMask)))
        return error(dev::proto::ErrorCode::BadPayload, -1, static_cast<double>(r.targets.size()),
                     "a move needs at least one axis and exactly one target per axis in its mask");
    if (auto e = checkAxes(r.axisMask, true))
        return e;
    std::vector<int> axes;
    std::vector<double> targets, speeds;
    std::size_t k = 0;
    dev::proto::AxisUnit speedUnit = dev::proto::AxisUnit::Millimetre;
    for (int b = axisCount() - 1; b >= 0; --b)
        if (r.axisMask & (1u << b))
            speedUnit = st(b).plant->config().unit;
    for (int b = 0; b < axisCount(); ++b) {
        if (!(r.axisMask & (1u << b)))
            continue;
        const AxisState& s = st(b);
        const auto& c = s.plant->config();
        const double value = r.targets[k++] / scale(b);
        if (!r.relative && !s.homed)
            return error(dev::proto::ErrorCode::NotHomed, b, value,
                         std::string("axis ") + c.letter + " is not homed: home it before an absolute move");
        const double logicalNow = commandedLogical(b);
        const double targetLogical = r.relative ? logicalNow + value : value;
        const double targetMachine = targetLogical + s.offset;
        if (s.homed && (targetMachine < softMinMachine(b) - 1e-9 || targetMachine > softMaxMachine(b) + 1e-9)) {
            const bool low = targetMachine < softMinMachine(b);
            const double lim = (low ? softMinMachine(b) : softMaxMachine(b)) - s.offset;
            return error(dev::proto::ErrorCode::SoftLimit, b, lim,
                         std::string("axis ") + c.letter + " target " + fmt(b, targetLogical) + " is beyond the "
                             + (low ? "lower" : "upper") + " soft limit " + fmt(b, lim));
        }
        // One speed, one unit: it is in the unit of the first axis named (mm/s for
        // a move with any linear axis); axes in another unit (the pump beside X)
        // run at their own default speed rather than at a number meant for mm.
        if (r.speed != 0 && c.unit == speedUnit) {
            const double v = r.speed / scale(b);
            if (v > c.maxSpeed + 1e-9)
                return error(dev::proto::ErrorCode::OutOfRange, b, v,
                             std::string("speed ") + fmt(b, v) + "/s is above axis " + c.letter + "'s maximum "
                                 + fmt(b, c.maxSpeed) + "/s");
            speeds.push_back(v);
        } else {
            speeds.push_back(c.defaultSpeed);
        }
        axes.push_back(b);
        targets.push_back(targetMachine);
    }
    // Analyzer: X and Y move together on a straight line, the pump on its own,
    // and Z only once XY has arrived (the seed's cross-coupled XY, Z following).
    // Each group runs at its own axes' speed: the XY path is not slowed to Z's or
    // the pump's default just because they are part of the same request.
    std::vector<int> xy, z, other;
    std::vector<double> txy, tz, tother, sother;
    double vXy = 1e300, vZ = 1e300;
    for (std::size_t n = 0; n < axes.size(); ++n) {
        const char l = st(axes[n]).plant->config().letter;
        if (l == 'X' || l == 'Y') {
            xy.push_back(axes[n]);
            txy.push_back(targets[n]);
            vXy = std::min(vXy, speeds[n]);
        } else if (l == 'Z' && m_cfg.zAfterXy) {
            z.push_back(axes[n]);
            tz.push_back(targets[n]);
            vZ = std::min(vZ, speeds[n]);
        } else {
            other.push_back(axes[n]);
            tother.push_back(targets[n]);
            sother.push_back(speeds[n]);
        }
    }
    int xyId = -1;
    if (!xy.empty())
        if (auto e = planSegment(xy, txy, vXy, -1, dev::proto::EventKind::MotionDone, &xyId))
            return e;
    if (!z.empty())
        if (auto e = planSegment(z, tz, vZ, xyId, dev::proto::EventKind::MotionDone, nullptr))
            return e;
    for (std::size_t n = 0; n < other.size(); ++n)
        if (auto e = planSegment({other[n]}, {tother[n]}, sother[n], -1, dev::proto::EventKind::MotionDone, nullptr))
            return e;
    return std::nullopt;
}

SimMachine::Result SimMachine::jogStep(const dev::proto::JogStepRequest& r)
{
    if (r.axis >= axisCount())
        return error(dev::proto::ErrorCode::BadAxis, -1, r.axis, "axis index " + std::to_string(r.axis) + " does not exist");
    dev::proto::MoveRequest m;
    m.relative = true;
    m.speed = r.speed;
    m.axisMask = static_cast<std::uint8_t>(1u << r.axis);
    m.targets = {r.delta};
    return move(m);
}

SimMachine::Result SimMachine::jogVelocity(const dev::proto::JogVelocityRequest& r)
{
    if (r.axisMask == 0 || r.velocities.size() != static_cast<std::size_t>(dev::proto::popcount8(r.axisMask)))
        return error(dev::proto::ErrorCode::BadPayload, -1, static_cast<double>(r.velocities.size()),
                     "a jog needs at least one axis and exactly one velocity per axis in its mask");
    if (auto e = checkAxes(r.axisMask, false))
        return e;
    std::size_t k = 0;
    for (int b = 0; b < axisCount(); ++b) {
        if (!(r.axisMask & (1u << b)))
            continue;
        const double v = r.velocities[k++] / scale(b);
        const AxisState& s = st(b);
        const auto& c = s.plant->config();
        if ((s.mode != Mode::Idle && s.mode != Mode::Jog && s.mode != Mode::Settling) || awaitingHoming(b))
            return error(dev::proto::ErrorCode::Busy, b, 0, std::string("axis ") + c.letter + " is busy with a move or homing");
        if (std::abs(v) > c.maxSpeed + 1e-9)
            return error(dev::proto::ErrorCode::OutOfRange, b, v,
                         std::string("jog speed ") + fmt(b, v) + "/s is above axis " + c.letter + "'s maximum "
                             + fmt(b, c.maxSpeed) + "/s");
    }
    k = 0;
    for (int b = 0; b < axisCount(); ++b) {
        if (!(r.axisMask & (1u << b)))
            continue;
        AxisState& s = st(b);
        const double v = r.velocities[k++] / scale(b);
        if (s.mode == Mode::Settling) {
            // Stage: a new jog press right after a release must not be refused while
            // the loop settles; the earlier motion is reported done first.
            if (v == 0)
                continue;
            finishAxis(b, s.doneEvent);
        }
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
        if (b < 2)
            m_xyLineDir.clear();  // no path line while jogging: contour error is the XY tracking error
    }
    return std::nullopt;
}

SimMachine::Result SimMachine::stop(std::uint8_t mask)
{
    if (mask == 0)
        mask = 0xFF;
    m_tuning->abort(mask, motion::control::EndReason::Stopped);  // a test on these axes ends: the axis holds
    if (m_path->active() && (mask & m_path->axisMask()))
        m_path->stop();  // slows down along the path, not off it
    // Homing is one sequence: stopping any axis that takes part ends it for all
    // the stages that have not started yet.
    bool homingStopped = false;
    for (std::uint8_t stage : m_homeStages)
        if (stage & mask)
            homingStopped = true;
    std::vector<int> segIds;
    for (int i = 0; i < axisCount(); ++i) {
        if (!(mask & (1u << i)))
            continue;
        AxisState& s = st(i);
        if (s.mode == Mode::Segment && std::find(segIds.begin(), segIds.end(), s.segment) == segIds.end())
            segIds.push_back(s.segment);
        if (s.mode == Mode::Jog || s.mode == Mode::Homing) {
            s.mode = Mode::Decel;
            s.v = s.plant->referenceVelocity();
            s.vTarget = 0;
            s.accel = s.plant->config().maxAccel;
        }
    }
    if (homingStopped)
        cancelHoming("homing stopped before this axis' turn", dev::proto::reason::kHomingStopped);
    // Axes of one segment slow down together, so a coupled XY move stops on its
    // line. A segment that has not started yet stops at once (v = 0).
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
            s.v = it->started ? s.plant->referenceVelocity() : 0.0;
            s.vTarget = 0;
            s.accel = stopTime > 0 ? std::abs(s.v) / stopTime : 1.0;
            s.segment = -1;
        }
        const int arch = it->arch;
        m_segments.erase(it);
        // Z waited for this XY move to arrive; it never will.
        cancelSegmentsAfter(id, "cancelled: the move it waited for was stopped", dev::proto::reason::kWaitedMoveStopped);
        cancelArchRest(arch, "cancelled: the move it waited for was stopped", dev::proto::reason::kWaitedMoveStopped);
    }
    return std::nullopt;
}

void SimMachine::cancelSegmentsAfter(int id, const char* why, std::uint8_t code)
{
    auto waiting = [&](const Segment& g) { return !g.started && g.after == id; };
    for (const Segment& g : m_segments) {
        if (!waiting(g))
            continue;
        for (int a : g.axes) {
            if (st(a).segment != g.id)
                continue;
            st(a).mode = Mode::Idle;
            st(a).segment = -1;
            raiseEvent(dev::proto::EventKind::Stopped, a, why, code);
        }
    }
    m_segments.erase(std::remove_if(m_segments.begin(), m_segments.end(), waiting), m_segments.end());
}

SimMachine::Result SimMachine::estop()
{
    m_tuning->abort(0xFF, motion::control::EndReason::EStop);
    m_estop = true;
    m_path->abortNow(dev::proto::PathReason::EStop, "E-stop");
    m_segments.clear();
    m_homeStages.clear();
    for (int i = 0; i < axisCount(); ++i) {
        AxisState& s = st(i);
        s.plant->freeze();
        s.mode = Mode::Idle;
        s.segment = -1;
        s.v = s.vTarget = 0;
    }
    raiseEvent(dev::proto::EventKind::EStop, -1, "emergency stop: all motion halted", dev::proto::reason::kAllHalted);
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
    raiseEvent(dev::proto::EventKind::Reset, -1, "E-stop and faults cleared", dev::proto::reason::kCleared);
    return std::nullopt;
}

SimMachine::Result SimMachine::setZero(std::uint8_t mask)
{
    if (mask == 0)
        mask = static_cast<std::uint8_t>((1u << axisCount()) - 1);  // AxisMaskRequest: 0 = all axes
    if (auto e = checkAxes(mask, true))
        return e;
    for (int i = 0; i < axisCount(); ++i)
        if (mask & (1u << i))
            zeroCounters(i, 0.0);
    return std::nullopt;
}

SimMachine::Result SimMachine::setLimits(const dev::proto::SetLimitsRequest& r)
{
    if (r.axis >= axisCount())
        return error(dev::proto::ErrorCode::BadAxis, -1, r.axis, "axis index " + std::to_string(r.axis) + " does not exist");
    AxisState& s = st(r.axis);
    const auto& c = s.plant->config();
    // Limits live in home coordinates; before homing the axis' coordinates are
    // wherever it was powered up, so a limit given in them would land anywhere.
    if (!s.homed)
        return error(dev::proto::ErrorCode::NotHomed, r.axis, r.limits.min / scale(r.axis),
                     std::string("axis ") + c.letter + " is not homed: soft limits are set in homed coordinates");
    // Requests are logical; the limits are kept in home coordinates.
    const double toHome = s.offset - s.homeOffset;
    const double minLogical = r.limits.min / scale(r.axis), maxLogical = r.limits.max / scale(r.axis);
    const double lo = minLogical + toHome, hi = maxLogical + toHome;
    if (!(lo < hi))
        return error(dev::proto::ErrorCode::OutOfRange, r.axis, minLogical,
                     std::string("axis ") + c.letter + " lower soft limit " + fmt(r.axis, minLogical)
                         + " must be below the upper one " + fmt(r.axis, maxLogical));
    if (lo < -1e-9 || hi > c.travel + 1e-9)
        return error(dev::proto::ErrorCode::OutOfRange, r.axis, lo < -1e-9 ? minLogical : maxLogical,
                     std::string("axis ") + c.letter + " soft limits must lie inside the travel " + fmt(r.axis, -toHome)
                         + " … " + fmt(r.axis, c.travel - toHome));
    s.softMin = lo;
    s.softMax = hi;
    return std::nullopt;
}

dev::proto::LimitsReply SimMachine::limits() const
{
    dev::proto::LimitsReply r;
    for (int i = 0; i < axisCount(); ++i) {
        const AxisState& s = st(i);
        // Unhomed, the firmware cannot place its limits in the power-up coordinates:
        // it reports them as configured, in the coordinates homing will establish.
        const double shift = s.homed ? s.offset - s.homeOffset : 0.0;
        r.axes.push_back({static_cast<std::int32_t>(std::lround((s.softMin - shift) * scale(i))),
                          static_cast<std::int32_t>(std::lround((s.softMax - shift) * scale(i)))});
    }
    return r;
}



} // namespace dev::sim
