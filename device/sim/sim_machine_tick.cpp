// The simulated controller's realtime loop: one fixed tick advances segments,
// velocity modes (jog, stop ramps, homing), the stage's PID, the plants, and
// checks settling and switches.
#include "device/sim/sim_machine.h"

#include "device/sim/sim_compensation.h"
#include "device/sim/sim_compensation_2d.h"
#include "device/sim/sim_tuning.h"

#include "device/sim/path_queue.h"
#include "motion/profile.h"

#include <algorithm>
#include <cmath>

namespace dev::sim {

void SimMachine::finishAxis(int i, dev::proto::EventKind kind, const std::string& text, std::uint8_t why)
{
    AxisState& s = st(i);
    s.mode = Mode::Idle;
    s.segment = -1;
    s.v = s.vTarget = 0;
    if (kind == dev::proto::EventKind::HomeDone) {
        zeroCounters(i, commandedLogical(i));  // the encoder agrees with the step counter at home
        s.homeOffset = s.offset;               // soft limits are relative to home
        s.homed = true;
    }
    raiseEvent(kind, i, text, why);
    if (!m_cfg.closedLoop && !s.lostReported) {
        const double err = measuredLogical(i) - commandedLogical(i);
        if (std::abs(err) > m_cfg.lostStepTolerance) {
            s.lostReported = true;
            raiseEvent(dev::proto::EventKind::LostSteps, i,
                       std::string("axis ") + s.plant->config().letter + " encoder is " + fmt(i, err) + " off the command",
                       dev::proto::reason::kOffCommand, {err});
        }
    }
}

void SimMachine::stopAxisHard(int i)
{
    AxisState& s = st(i);
    s.plant->holdHere();
    s.v = s.vTarget = 0;
    if (s.mode == Mode::Path)
        m_path->abortNow(dev::proto::PathReason::LimitSwitch, std::string("axis ") + s.plant->config().letter + " hit a switch");
    if (s.mode == Mode::Segment) {
        // The whole coupled segment halts so the other axes do not run on alone.
        const int id = s.segment;
        auto it = std::find_if(m_segments.begin(), m_segments.end(), [&](const Segment& g) { return g.id == id; });
        if (it != m_segments.end()) {
            for (int a : it->axes)
                if (a != i) {
                    st(a).plant->holdHere();
                    finishAxis(a, dev::proto::EventKind::Stopped, "stopped with its coupled axis", dev::proto::reason::kWithCoupledAxis);
                }
            const int arch = it->arch;
            m_segments.erase(it);
            cancelArchRest(arch, "cancelled: the move it waited for was stopped by a switch", dev::proto::reason::kWaitedMoveHitSwitch);
        }
        s.mode = Mode::Idle;
        s.segment = -1;
        // A Z that waited for this XY move to arrive must not start, nor stay busy.
        cancelSegmentsAfter(id, "cancelled: the move it waited for was stopped by a switch", dev::proto::reason::kWaitedMoveHitSwitch);
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
        raiseEvent(dev::proto::EventKind::LimitHit, i, std::string("axis ") + c.letter + " hit its home switch", dev::proto::reason::kHomeSwitch);
    } else if (s.plant->limitSwitch() && v > 0) {
        stopAxisHard(i);
        raiseEvent(dev::proto::EventKind::LimitHit, i, std::string("axis ") + c.letter + " hit its limit switch", dev::proto::reason::kLimitSwitch);
    }
}

void SimMachine::tickSegments()
{
    std::vector<int> finished;
    for (auto& g : m_segments) {
        if (!g.started) {
            // Waiting for the segment it hangs on to end, or (afterS ≥ 0) to have run that long.
            const bool waiting = g.after >= 0 && std::any_of(m_segments.begin(), m_segments.end(), [&](const Segment& o) {
                return o.id == g.after && (g.afterS < 0 || !o.started || o.t < g.afterS - 1e-12);
            });
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
            if (g.handsOver) {
                // An arched move's rise: Z goes on down with the arch's next part, if it is still there.
                const auto next = std::find_if(m_segments.begin(), m_segments.end(), [&](const Segment& o) {
                    return o.arch == g.arch && std::find(o.axes.begin(), o.axes.end(), i) != o.axes.end();
                });
                if (next != m_segments.end()) {
                    st(i).segment = next->id;
                    continue;
                }
            }
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
        if (s.mode == Mode::Jog && !s.expired && timeS() - s.lastRefreshS > m_jogWatchdogTripS) {
            // The host went quiet (frozen GUI, pulled cable): stop within the budget.
            s.expired = true;
            s.vTarget = 0;
            s.accel = std::max(c.maxAccel, std::abs(s.v) / kJogStopBudgetS);
            raiseEvent(dev::proto::EventKind::JogExpired, i, std::string("axis ") + c.letter + " jog not refreshed: stopped", dev::proto::reason::kNotRefreshed,
                       {m_jogWatchdogTripS});
        }
        double target = s.vTarget;
        const double pos = s.plant->reference();
        if (s.mode == Mode::Jog && s.homed) {
            // Never coast through a soft limit: the speed is capped by the distance left.
            // Room ahead in the direction of travel, or of the request when at rest:
            // an axis parked on a limit must still be able to jog away from it.
            const bool up = s.v != 0 ? s.v > 0 : target > 0;
            const double room = up ? softMaxMachine(i) - pos : pos - softMinMachine(i);
            const double vCap = std::sqrt(2.0 * s.accel * std::max(0.0, room));
            if (target > 0 && up)
                target = std::min(target, vCap);
            if (target < 0 && !up)
                target = std::max(target, -vCap);
        }
        const double dv = s.accel * kTickS;
        if (s.v < target)
            s.v = std::min(target, s.v + dv);
        else if (s.v > target)
            s.v = std::max(target, s.v - dv);
        double next = pos + s.v * kTickS;
        if (s.mode == Mode::Jog && s.homed) {
            // Clamp only ahead of the axis: one parked outside limits set narrower
            // than where it stands must drive back in, not jump there in one tick.
            if (s.v > 0)
                next = std::min(next, std::max(pos, softMaxMachine(i)));
            else if (s.v < 0)
                next = std::max(next, std::min(pos, softMinMachine(i)));
        }
        s.plant->setReference(next, s.v);
        if (s.mode == Mode::Homing) {
            tickHoming(i);
            continue;
        }
        if (s.v == 0 && s.vTarget == 0) {
            if (m_cfg.closedLoop) {
                s.doneEvent = s.mode == Mode::Decel ? dev::proto::EventKind::Stopped : dev::proto::EventKind::MotionDone;
                s.mode = Mode::Settling;
                s.settleStartS = timeS();
                s.settledS = 0;
            } else {
                if (s.mode == Mode::Decel)
                    finishAxis(i, dev::proto::EventKind::Stopped, {}, dev::proto::reason::kStopRequest);
                else
                    finishAxis(i, dev::proto::EventKind::MotionDone);
            }
        }
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
        finishAxis(i, s.doneEvent, {}, s.doneEvent == dev::proto::EventKind::Stopped ? dev::proto::reason::kStopRequest : 0);
    } else if (timeS() - s.settleStartS > 2.0) {
        finishAxis(i, s.doneEvent, "arrived outside the in-position window", dev::proto::reason::kOutsideWindow);
    }
}

void SimMachine::tick()
{
    ++m_ticks;
    m_comp->reconcile();  // a compensation takes effect once its axis is homed and at rest
    m_path->tick();
    tickSegments();
    tickVelocityModes();
    m_comp2d->follow();  // the 2D table's corrections at the references just set
    for (int i = 0; i < axisCount(); ++i) {
        if (m_cfg.closedLoop && m_ticks % static_cast<std::uint64_t>(m_ticksPerControl) == 0
            && !m_tuning->controlStep(i, m_ticksPerControl))  // a tuning test, or the PID with the axis' gains
            st(i).plant->controlStep(m_tuning->gains(i), m_ticksPerControl, m_cfg.loop);
        st(i).plant->tick(kTickS);
        if (st(i).mode == Mode::Settling)
            tickSettling(i);
        checkSwitches(i);
    }
    advanceHomingStages();
    m_tuning->tick();
}

} // namespace dev::sim
