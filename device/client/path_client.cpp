#include "device/client/path_client.h"

namespace dev {

const char* pathStateTerm(proto::PathState s)
{
    switch (s) {
    case proto::PathState::Idle: return "path.state.idle";
    case proto::PathState::Filling: return "path.state.filling";
    case proto::PathState::Running: return "path.state.running";
    case proto::PathState::Starved: return "path.state.starved";
    case proto::PathState::Holding: return "path.state.holding";
    case proto::PathState::Held: return "path.state.held";
    case proto::PathState::Done: return "path.state.done";
    case proto::PathState::Aborted: return "path.state.aborted";
    }
    return "path.state.idle";
}

const char* pathReasonTerm(proto::PathReason r)
{
    switch (r) {
    case proto::PathReason::None: return "path.reason.none";
    case proto::PathReason::HostHold: return "path.reason.host_hold";
    case proto::PathReason::HostSilent: return "path.reason.host_silent";
    case proto::PathReason::Stop: return "path.reason.stop";
    case proto::PathReason::EStop: return "path.reason.estop";
    case proto::PathReason::LimitSwitch: return "path.reason.limit_switch";
    case proto::PathReason::NewSession: return "path.reason.new_session";
    case proto::PathReason::Cleared: return "path.reason.cleared";
    }
    return "path.reason.none";
}

} // namespace dev
