#include "device/client/capabilities.h"

namespace dev {

const std::array<Capability, 18>& allCapabilities()
{
    static const std::array<Capability, 18> all = {
        Capability::Homing,        Capability::SetZero,       Capability::MeasuredPosition, Capability::ClosedLoop,
        Capability::Telemetry,     Capability::VelocityJog,   Capability::StopsOnHostLoss,  Capability::PathQueue,
        Capability::PathZFollow,   Capability::CoupledXyThenZ, Capability::SoftLimits,      Capability::PidGains,
        Capability::TuningTests,   Capability::Pump,          Capability::TriggerOutput,    Capability::MachineLimits,
        Capability::Compensation,  Capability::ArchedMove,
    };
    return all;
}

std::string capabilityKey(Capability c)
{
    switch (c) {
    case Capability::Homing: return "homing";
    case Capability::SetZero: return "set_zero";
    case Capability::MeasuredPosition: return "measured_position";
    case Capability::ClosedLoop: return "closed_loop";
    case Capability::Telemetry: return "telemetry";
    case Capability::VelocityJog: return "velocity_jog";
    case Capability::StopsOnHostLoss: return "stops_on_host_loss";
    case Capability::PathQueue: return "path_queue";
    case Capability::PathZFollow: return "path_z_follow";
    case Capability::CoupledXyThenZ: return "coupled_xy_then_z";
    case Capability::SoftLimits: return "soft_limits";
    case Capability::PidGains: return "pid_gains";
    case Capability::TuningTests: return "tuning_tests";
    case Capability::Pump: return "pump";
    case Capability::TriggerOutput: return "trigger_output";
    case Capability::MachineLimits: return "machine_limits";
    case Capability::Compensation: return "compensation";
    case Capability::ArchedMove: return "arched_move";
    }
    return "unknown";
}

std::string missingId(Capability c) { return "capability.no_" + capabilityKey(c); }

} // namespace dev
