// Homing of the simulated instruments: seek the home switch fast, back off,
// re-approach slowly, latch, then move to logical zero. The analyzer homes Z
// first so the needle is clear of the plate before X and Y sweep.
#include "device/sim/sim_machine.h"

#include <algorithm>
#include <cmath>

namespace dev::sim {

SimMachine::Result SimMachine::home(std::uint8_t mask)
{
    if (mask == 0)
        mask = static_cast<std::uint8_t>((1u << axisCount()) - 1);
    if (auto e = checkAxes(mask, true))
        return e;
    // One homing sequence at a time: a second one would drop the stages of the
    // first that have not started yet.
    if (!m_homeStages.empty())
        return error(dev::proto::ErrorCode::Busy, -1, 0, "a homing sequence is still running");
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
            raiseEvent(dev::proto::EventKind::Fault, i, std::string("axis ") + c.letter + " home switch not found over the whole travel",
                       dev::proto::reason::kHomeSwitchNotFound);
            cancelHoming("homing cancelled: another axis failed to find its switch", dev::proto::reason::kHomingOtherFailed);
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
            // give or take the switch's repeatability. Then travel to logical zero;
            // HomeDone (finishAxis) zeroes the counters there once more.
            const double noise = c.switchRepeatability > 0 ? s.plant->uniform(-c.switchRepeatability, c.switchRepeatability) : 0;
            zeroCounters(i, c.homeSwitchAt - noise);
            s.mode = Mode::Idle;  // homed only once zero is reached (finishAxis, HomeDone)
            planSegment({i}, {s.offset}, c.homeFastSpeed, -1, dev::proto::EventKind::HomeDone, nullptr);
        }
        break;
    }
}

bool SimMachine::awaitingHoming(int i) const
{
    if (st(i).mode != Mode::Idle || st(i).homed)
        return false;
    for (std::uint8_t stage : m_homeStages)
        if (stage & (1u << i))
            return true;
    return false;
}

void SimMachine::advanceHomingStages()
{
    // Stages run in order: the next begins when every axis of this one is homed and at rest.
    if (m_homeStages.empty())
        return;
    const std::uint8_t mask = m_homeStages.front();
    bool allHomed = true;
    for (int i = 0; i < axisCount(); ++i) {
        if (!(mask & (1u << i)))
            continue;
        if (st(i).mode != Mode::Idle)
            return;
        allHomed = allHomed && st(i).homed;
    }
    m_homeStages.erase(m_homeStages.begin());
    // An axis of this stage came to rest unhomed (stopped by a switch, say): the
    // later stages must not run, nor stay pending and block every later homing.
    if (!allHomed)
        cancelHoming("homing cancelled: an axis homed before this one did not reach home", dev::proto::reason::kHomingEarlierFailed);
    startHomingStage();
}

void SimMachine::cancelHoming(const char* why, std::uint8_t code)
{
    // Axes still waiting for their stage never moved: tell the host they will not home.
    for (int i = 0; i < axisCount(); ++i)
        if (awaitingHoming(i))
            raiseEvent(dev::proto::EventKind::Stopped, i, why, code);
    m_homeStages.clear();
}

} // namespace dev::sim
