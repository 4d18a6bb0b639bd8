// What the simulated instrument reports: HELLO, status and telemetry channels,
// all in logical (host) coordinates and wire units.
#include "device/sim/sim_machine.h"

#include "device/protocol/messages_compensation.h"
#include "device/protocol/messages_compensation_2d.h"
#include "device/sim/sim_compensation_2d.h"
#include "device/protocol/messages_tuning.h"
#include "device/sim/path_queue.h"

#include <algorithm>
#include <cmath>

namespace dev::sim {

dev::proto::HelloReply SimMachine::hello(std::uint32_t linkBaud) const
{
    dev::proto::HelloReply h;
    h.kind = m_cfg.kind;
    h.capabilities = dev::proto::CapHoming | dev::proto::CapTelemetry | dev::proto::CapJogVelocity | dev::proto::CapPathQueue | dev::proto::CapCompensation;
    if (m_cfg.closedLoop)
        h.capabilities |= dev::proto::CapGrating | dev::proto::CapClosedLoopPid | dev::proto::CapGains | dev::proto::CapExperiments;
    else
        h.capabilities |= dev::proto::CapEncoder;
    if (m_cfg.zAfterXy)
        h.capabilities |= dev::proto::CapCoupledXyThenZ | dev::proto::CapPathZFollow | dev::proto::kCapArchMove;
    if (m_comp2d->available())
        h.capabilities |= dev::proto::CapCompensation2d;
    for (const auto& a : m_cfg.axes)
        if (a.unit == dev::proto::AxisUnit::Microlitre) {
            h.capabilities |= dev::proto::CapPump;
            if (m_cfg.zAfterXy)
                h.capabilities |= dev::proto::kCapArchPump;  // the plunger inside an arched move
        }
    h.controlPeriodUs = static_cast<std::uint32_t>(std::lround(m_cfg.controlPeriodS * 1e6));
    h.maxTelemetryRateHz = static_cast<std::uint32_t>(std::lround(1.0 / kTickS));
    h.jogWatchdogMs = dev::proto::kJogWatchdogMs;
    h.linkBaud = linkBaud;
    h.model = m_cfg.model;
    h.firmware = "benchpilot-sim 1.0";
    for (int i = 0; i < axisCount(); ++i) {
        const auto& c = st(i).plant->config();
        dev::proto::AxisInfo a;
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

dev::proto::MotionLimits SimMachine::motionLimits() const
{
    dev::proto::MotionLimits l;
    const bool seed = m_cfg.profile == ProfileKind::SeedSCurve;
    l.profile = seed ? dev::proto::MotionProfile::SeedSCurve : dev::proto::MotionProfile::JerkLimited;
    auto u32 = [](double v) { return static_cast<std::uint32_t>(std::clamp(std::llround(v), 0LL, 4294967295LL)); };
    for (int i = 0; i < axisCount(); ++i) {
        const AxisConfig& c = st(i).plant->config();
        dev::proto::AxisMotionLimits a;
        // Thousandths of the axis unit: µm/s² (nL/s² on the pump).
        a.maxAccel = u32(c.maxAccel * 1e3);
        if (seed) {
            // The seed's curve has jerk 6·v/t2² at its start, with t2 = max(accelTimeS,
            // 1.5·v/maxAccel) and v ≤ maxSpeed: largest at v = 2·maxAccel·accelTimeS/3,
            // where it is 4·maxAccel/accelTimeS. The planner bounds jerk only through t2,
            // so this is the most it ever commands, not a parameter it plans with.
            const double vPeak = std::min(c.maxSpeed, 2.0 * c.maxAccel * c.accelTimeS / 3.0);
            a.maxJerk = u32(6.0 * vPeak / (c.accelTimeS * c.accelTimeS) * 1e3);
            a.minAccelTimeUs = u32(c.accelTimeS * 1e6);
        } else {
            a.maxJerk = u32(c.maxJerk * 1e3);
        }
        a.defaultSpeed = u32(c.defaultSpeed * scale(i));
        l.axes.push_back(a);
    }
    return l;
}

dev::proto::StatusReply SimMachine::status() const
{
    dev::proto::StatusReply r;
    r.deviceFlags = static_cast<std::uint8_t>((m_estop ? dev::proto::DeviceEStop : 0));
    r.deviceTimeUs = timeUs();
    for (int i = 0; i < axisCount(); ++i) {
        const AxisState& s = st(i);
        dev::proto::AxisStatus a;
        a.commanded = static_cast<std::int32_t>(std::lround(commandedLogical(i) * scale(i)));
        a.measured = static_cast<std::int32_t>(std::lround(measuredLogical(i) * scale(i)));
        std::uint16_t f = 0;
        if (s.homed)
            f |= dev::proto::AxisHomed;
        if (s.mode != Mode::Idle && (s.mode != Mode::Path || m_path->moving()))
            f |= dev::proto::AxisMoving;  // a queued path at rest reserves its axes but moves nothing
        if (s.mode == Mode::Homing || (!m_homeStages.empty() && !s.homed && (m_homeStages.front() & (1u << i))))
            f |= dev::proto::AxisHoming;
        if (s.mode == Mode::Jog)
            f |= dev::proto::AxisJogging;
        if (s.plant->homeSwitch())
            f |= dev::proto::AxisHomeSwitch;
        if (s.plant->limitSwitch())
            f |= dev::proto::AxisLimitSwitch;
        if (s.fault) {
            f |= dev::proto::AxisFault;
            r.deviceFlags |= dev::proto::DeviceFault;
        }
        a.flags = f;
        r.axes.push_back(a);
    }
    // Axes waiting on a later homing stage are part of the homing too.
    for (std::size_t n = 1; n < m_homeStages.size(); ++n)
        for (int i = 0; i < axisCount(); ++i)
            if (m_homeStages[n] & (1u << i))
                r.axes[static_cast<std::size_t>(i)].flags |= dev::proto::AxisHoming | dev::proto::AxisMoving;
    return r;
}

double SimMachine::contourErrorMm() const
{
    if (axisCount() < 2)
        return 0;
    const double mx = st(0).plant->reportedMeasured(), my = st(1).plant->reportedMeasured();
    if (m_path->active())
        if (const auto e = m_path->contourErrorMm(mx, my))
            return std::abs(*e);  // against the queued path's lines and arcs
    if (m_xyLineDir.size() == 2) {
        // Distance from the last commanded XY line: what a stitched image would see as drift.
        const double dx = mx - m_xyLineStart[0], dy = my - m_xyLineStart[1];
        return std::abs(dx * m_xyLineDir[1] - dy * m_xyLineDir[0]);
    }
    return std::hypot(mx - st(0).plant->reference(), my - st(1).plant->reference());
}

bool SimMachine::channelExists(const dev::proto::ChannelRef& c) const
{
    if (c.kind == dev::proto::ChannelKind::ContourError)
        return c.axis == dev::proto::kNoAxis && m_cfg.closedLoop;
    if (c.kind == dev::proto::ChannelKind::ControllerU)
        return c.axis < axisCount() && m_cfg.closedLoop;
    return c.axis < axisCount();
}

std::int32_t SimMachine::channelValue(const dev::proto::ChannelRef& c) const
{
    if (c.kind == dev::proto::ChannelKind::ContourError)
        return static_cast<std::int32_t>(std::lround(contourErrorMm() * 1e6));
    const AxisState& s = st(c.axis);
    const SimAxis& p = *s.plant;
    const double k = scale(c.axis);
    double v = 0;
    switch (c.kind) {
    case dev::proto::ChannelKind::Commanded: v = commandedLogical(c.axis) * k; break;
    case dev::proto::ChannelKind::Measured: v = measuredLogical(c.axis) * k; break;
    case dev::proto::ChannelKind::Velocity: v = p.measuredVelocity() * k; break;
    case dev::proto::ChannelKind::FollowingError: v = (measuredLogical(c.axis) - commandedLogical(c.axis)) * k; break;
    case dev::proto::ChannelKind::ControllerOutput: v = p.controllerOutputStepsS(); break;
    case dev::proto::ChannelKind::Switches: v = (p.homeSwitch() ? 1 : 0) | (p.limitSwitch() ? 2 : 0); break;
    case dev::proto::ChannelKind::ContourError: break;
    case dev::proto::ChannelKind::ControllerU: v = p.controllerU() * k; break;
    }
    return static_cast<std::int32_t>(std::clamp(std::lround(v), -2147483647L, 2147483647L));
}

} // namespace dev::sim
