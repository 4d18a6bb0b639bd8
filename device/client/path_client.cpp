#include "device/client/path_client.h"

namespace dev {

const char* pathStateTerm(dev::proto::PathState s)
{
    switch (s) {
    case dev::proto::PathState::Idle: return "path.state.idle";
    case dev::proto::PathState::Filling: return "path.state.filling";
    case dev::proto::PathState::Running: return "path.state.running";
    case dev::proto::PathState::Starved: return "path.state.starved";
    case dev::proto::PathState::Holding: return "path.state.holding";
    case dev::proto::PathState::Held: return "path.state.held";
    case dev::proto::PathState::Done: return "path.state.done";
    case dev::proto::PathState::Aborted: return "path.state.aborted";
    }
    return "path.state.idle";
}

const char* pathReasonTerm(dev::proto::PathReason r)
{
    switch (r) {
    case dev::proto::PathReason::None: return "path.reason.none";
    case dev::proto::PathReason::HostHold: return "path.reason.host_hold";
    case dev::proto::PathReason::HostSilent: return "path.reason.host_silent";
    case dev::proto::PathReason::Stop: return "path.reason.stop";
    case dev::proto::PathReason::EStop: return "path.reason.estop";
    case dev::proto::PathReason::LimitSwitch: return "path.reason.limit_switch";
    case dev::proto::PathReason::NewSession: return "path.reason.new_session";
    case dev::proto::PathReason::Cleared: return "path.reason.cleared";
    }
    return "path.reason.none";
}

} // namespace dev
