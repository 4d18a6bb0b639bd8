// The GRBL personality's line handling: '$' system commands, jogs and G-code, each answered
// with one ok or error:N — at once, or when what the line waits for is done (room in the
// planner, the motion before a G4 or an M8, the end of homing).
#include "device/sim/grbl_firmware.h"
#include "motion/numbers.h"

#include "device/backends/grbl/grbl_protocol.h"

#include <cmath>
#include <cstdlib>

namespace dev::sim {

namespace err = dev::grbl::err;

namespace {

using motion::kPi;

std::string upper(std::string s)
{
    for (char& c : s)
        if (c >= 'a' && c <= 'z')
            c = static_cast<char>(c - 'a' + 'A');
    return s;
}

/// GRBL's mc_arc: chords of the arc whose sagitta stays within the arc tolerance $12; the
/// last point is the exact target. Axes past X and Y move linearly (a helix).
std::vector<std::vector<double>> arcPoints(const std::vector<double>& start, const GrblBlock& b, double toleranceMm)
{
    const double cx = b.centreMm[0], cy = b.centreMm[1];
    const double r0x = start[0] - cx, r0y = start[1] - cy;
    const double r1x = b.targetMm[0] - cx, r1y = b.targetMm[1] - cy;
    const double radius = std::hypot(r0x, r0y);
    double travel = std::atan2(r0x * r1y - r0y * r1x, r0x * r1x + r0y * r1y);
    // A full circle (end on start) is a whole turn, the way round the arc says.
    if (b.clockwise) {
        if (travel >= -5e-7)
            travel -= 2 * kPi;
    } else if (travel <= 5e-7) {
        travel += 2 * kPi;
    }
    const double chord = std::sqrt(std::max(1e-12, toleranceMm * (2 * radius - toleranceMm)));
    const auto segments = static_cast<int>(std::floor(std::fabs(0.5 * travel * radius) / chord));
    std::vector<std::vector<double>> out;
    for (int k = 1; k < segments; ++k) {
        const double a = travel * k / segments;
        std::vector<double> p = start;
        p[0] = cx + r0x * std::cos(a) - r0y * std::sin(a);
        p[1] = cy + r0x * std::sin(a) + r0y * std::cos(a);
        for (std::size_t i = 2; i < p.size(); ++i)
            p[i] = start[i] + (b.targetMm[i] - start[i]) * k / segments;
        out.push_back(std::move(p));
    }
    out.push_back(b.targetMm);
    return out;
}

} // namespace

void GrblFirmware::executeLine(const std::string& raw)
{
    if (raw.empty()) {
        answer(0);  // an empty line is a valid line that does nothing
        return;
    }
    const std::string line = upper(raw);
    int error = 0;
    if (line[0] == '$') {
        error = systemCommand(line);
    } else if (m_state == State::Alarm || m_state == State::Jog) {
        error = err::kSystemGcLock;
    } else {
        error = gcodeLine(line);
    }
    if (error >= 0 && !m_pending.active)
        answer(error);
}

int GrblFirmware::systemCommand(const std::string& line)
{
    const bool idleOrAlarm = m_state == State::Idle || m_state == State::Alarm;
    if (line == "$") {
        send(m_dialect == Dialect::Grbl ? "[HLP:$$ $# $G $I $N $x=val $Nx=line $J=line $SLP $C $X $H ~ ! ? ctrl-x]"
                                        : "[HLP:$$ $# $G $I $N $x=val $Nx=line $J=line $SLP $C $X $H $B ~ ! ? ctrl-x]");
        return 0;
    }
    if (line.rfind("$J=", 0) == 0)
        return jogLine(line.substr(3));
    if (line == "$$") {
        if (!idleOrAlarm)
            return err::kIdleError;
        m_out += m_settings.printout();
        return 0;
    }
    if (line == "$I") {
        buildInfo();
        return 0;
    }
    if (line == "$G") {
        parserState();
        return 0;
    }
    if (line == "$#") {
        parameters();
        return 0;
    }
    if (line == "$N") {
        send("$N0=");
        send("$N1=");
        return 0;
    }
    if (line == "$X") {
        if (m_state == State::Alarm) {
            m_state = State::Idle;
            m_alarm = 0;
            send("[MSG:Caution: Unlocked]");
        }
        return 0;
    }
    if (line == "$H") {
        if (!m_settings.homingEnabled())
            return err::kHomingDisabled;
        if (!idleOrAlarm)
            return err::kIdleError;
        if (m_machine.home(0))
            return err::kIdleError;
        m_state = State::Home;
        m_pending = Pending{};
        m_pending.active = true;
        m_pending.homing = true;
        return 0;
    }
    // $N=V: a setting.
    const std::size_t eq = line.find('=');
    if (eq != std::string::npos && eq > 1) {
        char* end = nullptr;
        const long id = std::strtol(line.c_str() + 1, &end, 10);
        if (end != line.c_str() + eq)
            return err::kInvalidStatement;
        const std::string value = line.substr(eq + 1);
        char* vend = nullptr;
        const double v = std::strtod(value.c_str(), &vend);
        if (value.empty() || vend != value.c_str() + value.size())
            return err::kBadNumberFormat;
        if (!idleOrAlarm)
            return err::kIdleError;
        return m_settings.write(static_cast<int>(id), v);
    }
    return err::kInvalidStatement;  // $C, $SLP, $RST=…, $N0=… are not simulated
}

int GrblFirmware::jogLine(const std::string& command)
{
    if (m_state != State::Idle && m_state != State::Jog)
        return err::kIdleError;
    GrblParse p = parseGrblJog(command, m_modal, m_motion.plannedEndMm(), m_letters, m_workOffset);
    if (p.error)
        return p.error;
    // A jog beyond the travel is refused, not alarmed: the document's rule for jogs.
    if (m_settings.softLimits() && !withinTravel(p.block.targetMm))
        return err::kTravelExceeded;
    m_state = State::Jog;
    m_pending = Pending{};
    m_pending.active = true;
    m_pending.points = {p.block.targetMm};
    m_pending.feedMmS = p.block.feedMmMin / 60;
    m_pending.jog = true;
    return 0;  // queued by the next tick's continuePending(), which also answers
}

int GrblFirmware::gcodeLine(const std::string& line)
{
    GrblModalState modal = m_modal;
    GrblParse p = parseGrblLine(line, modal, m_motion.plannedEndMm(), m_letters, m_dialect == Dialect::GrblHal, m_workOffset);
    if (p.error)
        return p.error;
    const GrblBlock& b = p.block;
    if (b.kind == GrblBlock::Kind::SetWorkOffset) {
        m_modal = modal;
        m_workOffset = b.targetMm;
        m_reportCount = 0;  // GRBL reports a changed WCO in the next status report
        return 0;
    }
    std::vector<std::vector<double>> points;
    if (b.kind == GrblBlock::Kind::Line)
        points = {b.targetMm};
    else if (b.kind == GrblBlock::Kind::Arc)
        points = arcPoints(m_motion.plannedEndMm(), b, m_settings.arcToleranceMm());
    if (m_settings.softLimits()) {
        for (const auto& pt : points) {
            if (withinTravel(pt))
                continue;
            // A G-code target beyond the travel: GRBL holds what is moving, then alarms and
            // waits for a reset (ALARM:2). The line gets no answer; the reset follows.
            m_modal = modal;
            m_softLimitHold = true;
            m_motion.hold();
            if (m_state == State::Run)
                m_state = State::Hold;
            return -1;
        }
    }
    m_modal = modal;
    m_pending = Pending{};
    m_pending.line = b.lineNumber;
    m_pending.feedMmS = b.rapid ? 0 : b.feedMmMin / 60;
    if (b.kind == GrblBlock::Kind::Dwell) {
        m_pending.active = true;
        m_pending.dwellS = b.dwellS;
        return 0;
    }
    // Outputs: M62/M63 go with the next motion of this block (or at once without one);
    // M64/M65 at once; coolant waits for the planner to empty (GRBL's coolant_sync).
    std::vector<GrblBlock::Output> withMotion, now, synced;
    for (const auto& o : b.outputs) {
        if (o.port < 0)
            synced.push_back(o);
        else if (o.synchronized && !points.empty())
            withMotion.push_back(o);
        else
            now.push_back(o);
    }
    fireOutputs(now);
    if (!synced.empty()) {
        m_pending.active = true;
        m_pending.syncOutputs = true;
        m_pending.outputs = synced;
        return 0;
    }
    if (points.empty())
        return 0;
    m_pending.active = true;
    m_pending.points = std::move(points);
    m_pending.outputs = std::move(withMotion);
    if (m_state == State::Idle)
        m_state = State::Run;
    return 0;
}

void GrblFirmware::continuePending()
{
    if (m_softLimitHold) {
        if (!m_motion.moving() || m_motion.holdComplete()) {
            m_softLimitHold = false;
            m_motion.flush();
            raiseAlarm(dev::grbl::alarm::kSoftLimit, true);
        }
        return;
    }
    if (!m_pending.active)
        return;
    if (m_pending.homing) {
        bool done = true;
        const dev::proto::StatusReply status = m_machine.status();
        for (const dev::proto::AxisStatus& a : status.axes) {
            if (!(a.flags & dev::proto::AxisHomed) || (a.flags & (dev::proto::AxisMoving | dev::proto::AxisHoming)))
                done = false;
            if (a.flags & dev::proto::AxisFault) {
                // No switch found: GRBL alarms, resets, and the $H line is never answered.
                m_machine.stop(0);
                m_state = State::Idle;
                raiseAlarm(dev::grbl::alarm::kHomingFailApproach, false);
                return;
            }
        }
        if (!done)
            return;
        // Homing forces the origin: where the cycle ends is machine position 0.
        for (int i = 0; i < m_machine.axisCount(); ++i)
            m_origin[static_cast<std::size_t>(i)] = m_machine.axis(i).reference();
        m_motion.resetTo(std::vector<double>(static_cast<std::size_t>(m_axes), 0.0));
        m_homed = true;
        m_alarm = 0;
        m_state = State::Idle;
        m_pending = Pending{};
        answer(0);
        return;
    }
    if (m_state == State::Hold && m_pending.points.empty())
        return;  // a held sync waits for the resume
    const GrblMotion::Limits lim = limits();
    while (!m_pending.points.empty()) {
        std::vector<GrblBlock::Output> firedNow;
        if (!m_motion.push(m_pending.points.front(), m_pending.feedMmS, m_pending.jog, m_pending.line, m_pending.outputs,
                           lim, &firedNow))
            return;  // the planner is full: the line waits, and so does everything behind it
        fireOutputs(firedNow);
        m_pending.outputs.clear();
        m_pending.points.erase(m_pending.points.begin());
    }
    if (m_pending.syncOutputs || m_pending.dwellS >= 0) {
        if (m_motion.moving())
            return;
        if (m_pending.syncOutputs) {
            fireOutputs(m_pending.outputs);
            m_pending.syncOutputs = false;
        }
        if (m_pending.dwellS >= 0) {
            if (m_pending.dwellUntilS < 0)
                m_pending.dwellUntilS = m_machine.timeS() + m_pending.dwellS;
            if (m_machine.timeS() < m_pending.dwellUntilS - 1e-9)
                return;
        }
    }
    m_pending = Pending{};
    answer(0);
}

} // namespace dev::sim
