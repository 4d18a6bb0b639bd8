// The GRBL personality's byte handling, clock and machine states: realtime bytes, the
// receive buffer, soft reset, alarms, hard limits, and the mapping of GRBL's machine
// position onto the simulated axes. Lines: grbl_firmware_lines.cpp; reports: grbl_firmware_report.cpp.
#include "device/sim/grbl_firmware.h"

#include "device/backends/grbl/grbl_protocol.h"

#include <algorithm>
#include <cmath>

namespace dev::sim {

namespace {

std::string lettersFor(const MachineConfig& c)
{
    std::string s;
    for (const auto& a : c.axes)
        s.push_back(a.letter == 'P' ? 'A' : a.letter);  // the pump is GRBL's fourth axis, A
    // GRBL always has X, Y and Z: a machine without Z gets one that moves nothing.
    while (s.size() < 3)
        s.push_back("XYZ"[s.size()]);
    return s;
}

} // namespace

GrblFirmware::GrblFirmware(const MachineConfig& config, Dialect dialect)
    : m_machine(config),
      m_dialect(dialect),
      m_letters(lettersFor(config)),
      m_axes(static_cast<int>(m_letters.size())),
      m_settings(config, m_axes),
      m_motion(m_axes, dialect == Dialect::Grbl ? dev::grbl::kGrblDefaultPlannerBlocks : 35),
      m_origin(static_cast<std::size_t>(m_axes), 0.0),
      m_workOffset(static_cast<std::size_t>(m_axes), 0.0),
      m_rxSize(dialect == Dialect::Grbl ? dev::grbl::kGrblDefaultRxBufferBytes : dev::grbl::kGrblHalDefaultRxBufferBytes)
{
    // Power-up: GRBL's step counters start at 0 wherever the axes stand.
    for (int i = 0; i < m_machine.axisCount(); ++i)
        m_origin[static_cast<std::size_t>(i)] = m_machine.axis(i).reference();
    if (m_settings.homingEnabled()) {
        m_state = State::Alarm;  // homing init lock: the position is not known yet
        m_alarm = 0;
    }
    welcome();
}

void GrblFirmware::welcome()
{
    m_out += "\r\n";
    send(m_dialect == Dialect::Grbl ? "Grbl 1.1h ['$' for help]" : "GrblHAL 1.1f ['$' or '$HELP' for help]");
    if (m_state == State::Alarm)
        send("[MSG:'$H'|'$X' to unlock]");
    m_reportCount = 0;
}

void GrblFirmware::send(const std::string& line) { m_out += line + "\r\n"; }

void GrblFirmware::answer(int error) { send(error ? "error:" + std::to_string(error) : std::string("ok")); }

void GrblFirmware::drainOutput(std::vector<std::uint8_t>& out)
{
    out.insert(out.end(), m_out.begin(), m_out.end());
    m_out.clear();
}

// ---- bytes in ---------------------------------------------------------------------------

void GrblFirmware::receive(const std::uint8_t* data, std::size_t size)
{
    for (std::size_t k = 0; k < size; ++k) {
        const std::uint8_t b = data[k];
        if (dev::grbl::rt::isRealtime(b)) {
            realtime(b);
            continue;
        }
        // The serial interrupt's ring buffer keeps one slot free; what does not fit is lost.
        if (m_rx.size() + 1 >= m_rxSize) {
            ++m_lostRx;
            continue;
        }
        m_rx.push_back(static_cast<char>(b));
        m_maxRx = std::max(m_maxRx, m_rx.size());
    }
}

void GrblFirmware::realtime(std::uint8_t b)
{
    if (b == dev::grbl::rt::kSoftReset) {
        softReset();
        return;
    }
    if (m_critical)
        return;  // a limit alarm waits for a reset; it does not even report status
    switch (b) {
    case dev::grbl::rt::kStatusQuery:
        m_statusRequested = true;  // several '?' before the report is made give one report
        break;
    case dev::grbl::rt::kFeedHold:
        if (m_state == State::Jog) {
            m_jogCancel = true;  // a feed hold cancels a jog, like 0x85
            m_motion.hold();
        } else if (m_state == State::Run || m_state == State::Idle) {
            m_state = State::Hold;
            m_motion.hold();
        }
        break;
    case dev::grbl::rt::kCycleStart:
        if (m_state == State::Hold && m_motion.holdComplete()) {
            m_motion.resume();
            m_state = m_motion.moving() || m_pending.active ? State::Run : State::Idle;
        }
        break;
    case dev::grbl::rt::kJogCancel:
        if (m_jogCancelsS.size() >= 64)
            m_jogCancelsS.erase(m_jogCancelsS.begin());
        m_jogCancelsS.push_back(m_machine.timeS());
        if (m_state == State::Jog && !m_jogCancel) {
            m_jogCancel = true;
            m_motion.hold();
        }
        break;
    default:
        break;  // overrides, safety door: accepted, not simulated (docs/grbl.md)
    }
}

// ---- reset and alarms ---------------------------------------------------------------------

void GrblFirmware::portOpened()
{
    if (m_restartsOnOpen)
        restart();
}

void GrblFirmware::restart()
{
    ++m_restarts;
    if (m_state == State::Home)
        m_machine.stop(0);
    for (int i = 0; i < m_machine.axisCount(); ++i) {
        m_machine.axis(i).holdHere();
        m_origin[static_cast<std::size_t>(i)] = m_machine.axis(i).reference();  // the counters start at 0 here
    }
    m_motion.resetTo(std::vector<double>(static_cast<std::size_t>(m_axes), 0.0));
    m_homed = false;
    m_alarm = 0;
    m_state = m_settings.homingEnabled() ? State::Alarm : State::Idle;
    m_critical = false;
    m_jogCancel = false;
    m_softLimitHold = false;
    m_pending = Pending{};
    m_rx.clear();
    m_line.clear();
    m_lineOverflow = false;
    m_statusRequested = false;
    m_modal = GrblModalState{};
    bool floodOn = false;
    for (const auto& e : m_outputs)
        if (e.port < 0)
            floodOn = e.on;
    if (floodOn)
        m_outputs.push_back({m_machine.timeS(), -1, false});
    m_out.clear();  // half a line it was sending dies with it
    welcome();
}

void GrblFirmware::softReset()
{
    const bool moving = (m_state == State::Run || m_state == State::Jog || m_state == State::Home)
                        || (m_state == State::Hold && !m_motion.holdComplete());
    if (m_state == State::Home)
        m_machine.stop(0);  // ends the homing sequence where it is
    // The steppers stop dead: what the step counters say is where GRBL believes it is.
    for (int i = 0; i < m_machine.axisCount(); ++i)
        m_machine.axis(i).holdHere();
    std::vector<double> pos = m_motion.positionMm();
    for (int i = 0; i < m_machine.axisCount(); ++i)
        pos[static_cast<std::size_t>(i)] = m_machine.axis(i).reference() - m_origin[static_cast<std::size_t>(i)];
    m_motion.resetTo(pos);
    if (moving) {
        m_alarm = m_state == State::Home ? dev::grbl::alarm::kHomingFailReset : dev::grbl::alarm::kAbortCycle;
        send("ALARM:" + std::to_string(m_alarm));
        m_state = State::Alarm;
        if (m_alarm == dev::grbl::alarm::kAbortCycle)
            m_homed = false;
    }
    // A reset keeps an alarm (position still unknown); otherwise GRBL comes back Idle.
    if (m_state != State::Alarm)
        m_state = State::Idle;
    m_critical = false;
    m_jogCancel = false;
    m_softLimitHold = false;
    m_pending = Pending{};
    m_rx.clear();
    m_line.clear();
    m_lineOverflow = false;
    m_statusRequested = false;
    m_modal = GrblModalState{};
    // Spindle and coolant are switched off by a reset; grblHAL's aux outputs keep their state.
    bool floodOn = false;
    for (const auto& e : m_outputs)
        if (e.port < 0)
            floodOn = e.on;
    if (floodOn)
        m_outputs.push_back({m_machine.timeS(), -1, false});
    welcome();
}

void GrblFirmware::raiseAlarm(int code, bool critical)
{
    m_alarm = code;
    m_state = State::Alarm;
    send("ALARM:" + std::to_string(code));
    if (critical) {
        send("[MSG:Reset to continue]");
        m_critical = true;
    }
    m_pending = Pending{};
}

bool GrblFirmware::withinTravel(const std::vector<double>& target) const
{
    // Homing sets the origin at the switch end (GRBL's homing-forces-origin build, [OPT:Z]),
    // so the machine space is [0, $13x] on every axis.
    for (int k = 0; k < m_axes; ++k) {
        const double t = target[static_cast<std::size_t>(k)];
        if (t < -1e-6 || t > m_settings.maxTravelMm(k) + 1e-6)
            return false;
    }
    return true;
}

GrblMotion::Limits GrblFirmware::limits() const
{
    GrblMotion::Limits l;
    for (int k = 0; k < m_axes; ++k) {
        l.maxRateMmS.push_back(m_settings.maxRateMmS(k));
        l.accelMmS2.push_back(m_settings.accelMmS2(k));
    }
    l.junctionDeviationMm = m_settings.junctionDeviationMm();
    return l;
}

bool GrblFirmware::checkHardLimits()
{
    if (!m_settings.hardLimits() || m_state == State::Home)
        return false;
    // A switch closing under a moving axis (GRBL's limit pins interrupt on the edge).
    for (int i = 0; i < m_machine.axisCount(); ++i) {
        const SimAxis& a = m_machine.axis(i);
        const bool hit = (a.homeSwitch() && a.referenceVelocity() < 0) || (a.limitSwitch() && a.referenceVelocity() > 0);
        if (!hit)
            continue;
        for (int j = 0; j < m_machine.axisCount(); ++j)
            m_machine.axis(j).holdHere();
        std::vector<double> pos = m_motion.positionMm();
        for (int j = 0; j < m_machine.axisCount(); ++j)
            pos[static_cast<std::size_t>(j)] = m_machine.axis(j).reference() - m_origin[static_cast<std::size_t>(j)];
        m_motion.resetTo(pos);
        m_homed = false;
        raiseAlarm(dev::grbl::alarm::kHardLimit, true);
        return true;
    }
    return false;
}

// ---- time ---------------------------------------------------------------------------------

void GrblFirmware::advance(double dtS)
{
    m_pendingS += dtS;
    while (m_pendingS >= SimMachine::kTickS * 0.999) {
        m_pendingS -= SimMachine::kTickS;
        tick();
    }
}

void GrblFirmware::fireOutputs(const std::vector<GrblBlock::Output>& outs)
{
    for (const auto& o : outs)
        m_outputs.push_back({m_machine.timeS(), o.port, o.on});
}

void GrblFirmware::applyPosition()
{
    if (m_state == State::Home)
        return;  // the machine's homing cycle drives the axes
    const std::vector<double>& pos = m_motion.positionMm();
    const std::vector<double> vel = m_motion.velocityMmS();
    for (int i = 0; i < m_machine.axisCount(); ++i) {
        const auto k = static_cast<std::size_t>(i);
        m_machine.axis(i).setReference(m_origin[k] + pos[k], vel[k]);
    }
}

void GrblFirmware::tick()
{
    if (m_state == State::Run || m_state == State::Jog || m_state == State::Hold) {
        std::vector<GrblBlock::Output> fired;
        m_motion.tick(SimMachine::kTickS, fired);
        fireOutputs(fired);
        if (m_jogCancel && m_motion.holdComplete()) {
            m_motion.flush();  // a cancelled jog forgets the rest of the jog queue
            m_jogCancel = false;
            m_state = State::Idle;
        }
    }
    applyPosition();
    const bool moving = m_motion.moving();
    if (m_wasMoving && !moving) {
        m_lastMotionEndS = m_machine.timeS();
        ++m_motionEnds;
    }
    m_wasMoving = moving;
    m_machine.tick();
    m_machine.takeEvents();  // the GRBL personality reports through its own lines
    if (!checkHardLimits()) {
        continuePending();
        // A dwell or a coolant change waiting for the planner to empty is not motion: Idle.
        if (m_state == State::Run && !m_motion.moving() && (!m_pending.active || m_pending.points.empty()))
            m_state = State::Idle;
        if (m_state == State::Jog && !m_motion.moving())
            m_state = State::Idle;
        readLines();
    }
    if (m_statusRequested) {
        m_statusRequested = false;
        statusReport();
    }
}

void GrblFirmware::readLines()
{
    // One line per tick (100 µs) at most: GRBL parses a line in about a millisecond, so this is
    // a faster GRBL, not a different one. A line waits while the one before it is not done,
    // and while a feed hold or a jog cancel suspends GRBL's main loop (protocol_exec_rt_suspend):
    // a line that arrives then is read once the machine is Idle again (or resumed) — so a jog
    // line still in the buffer when 0x85 arrives runs after the cancel, as on real GRBL.
    if (m_critical || m_pending.active || m_state == State::Hold || m_jogCancel)
        return;
    while (!m_rx.empty()) {
        const char c = m_rx.front();
        m_rx.pop_front();
        if (c == '\n' || c == '\r') {  // GRBL ends a line at either: "\r\n" is two lines
            const std::string line = m_line;
            const bool overflow = m_lineOverflow;
            m_line.clear();
            m_lineOverflow = false;
            if (overflow)
                answer(dev::grbl::err::kOverflow);
            else
                executeLine(line);
            return;
        }
        // GRBL's line buffer holds 79 characters after its pre-parser drops spaces and every other
        // control character (protocol.c: "c <= ' '").
        if (static_cast<unsigned char>(c) <= ' ')
            continue;
        if (m_line.size() >= dev::grbl::kMaxLineChars)
            m_lineOverflow = true;
        else
            m_line.push_back(c);
    }
}

} // namespace dev::sim
