#include "device/client/path_client.h"

#include <QCoreApplication>

namespace dev {

QString pathStateText(proto::PathState s)
{
    switch (s) {
    case proto::PathState::Idle: return QCoreApplication::translate("dev::PathClient", "idle");
    case proto::PathState::Filling: return QCoreApplication::translate("dev::PathClient", "filling");
    case proto::PathState::Running: return QCoreApplication::translate("dev::PathClient", "running");
    case proto::PathState::Starved: return QCoreApplication::translate("dev::PathClient", "waiting for segments");
    case proto::PathState::Holding: return QCoreApplication::translate("dev::PathClient", "holding");
    case proto::PathState::Held: return QCoreApplication::translate("dev::PathClient", "held");
    case proto::PathState::Done: return QCoreApplication::translate("dev::PathClient", "done");
    case proto::PathState::Aborted: return QCoreApplication::translate("dev::PathClient", "aborted");
    }
    return {};
}

QString pathReasonText(proto::PathReason r)
{
    switch (r) {
    case proto::PathReason::None: return {};
    case proto::PathReason::HostHold: return QCoreApplication::translate("dev::PathClient", "paused from BenchPilot");
    case proto::PathReason::HostSilent:
        return QCoreApplication::translate("dev::PathClient", "the instrument heard nothing from BenchPilot for a second");
    case proto::PathReason::Stop: return QCoreApplication::translate("dev::PathClient", "a stop");
    case proto::PathReason::EStop: return QCoreApplication::translate("dev::PathClient", "the E-stop");
    case proto::PathReason::LimitSwitch: return QCoreApplication::translate("dev::PathClient", "a limit switch");
    case proto::PathReason::NewSession: return QCoreApplication::translate("dev::PathClient", "a new connection to the instrument");
    case proto::PathReason::Cleared: return QCoreApplication::translate("dev::PathClient", "abort");
    }
    return {};
}

} // namespace dev
