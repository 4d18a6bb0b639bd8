#include "device/backends/benchpilot/event_reason.h"

#include "device/client/path_client.h"
#include "device/protocol/event_reasons.h"
#include "device/protocol/messages_compensation.h"
#include "device/protocol/messages_tuning.h"

#include <vector>

namespace dev {
namespace {

using dev::proto::EventKind;
namespace why = dev::proto::reason;

struct Reading {
    const dev::proto::EventReason& r;
    double at(std::size_t i) const { return i < r.values.size() ? r.values[i] : 0.0; }
    bool has(std::size_t n) const { return r.values.size() >= n; }
};

const char* testTerm(double kind) { return kind == why::kRelayTest ? "request.relay_test" : "request.step_test"; }

motion::msg::Message tuning(EventKind kind, const Reading& v, const std::vector<motion::msg::Arg>& who, motion::msg::Unit len)
{
    std::vector<motion::msg::Arg> a = who;
    if (!v.has(1))
        return {};
    a.push_back(motion::msg::term("test", testTerm(v.at(0))));
    auto with = [&](const char* id, std::initializer_list<motion::msg::Arg> more) {
        a.insert(a.end(), more);
        return motion::msg::make(id, a);
    };
    if (kind == dev::proto::kEvTestEnded && v.has(2)) {
        if (v.r.code == why::kSettled)
            return with("device.why.test_settled", {motion::msg::real("seconds", v.at(1), motion::msg::Unit::S)});
        if (v.r.code == why::kCompleted)
            return with("device.why.test_completed", {motion::msg::real("seconds", v.at(1), motion::msg::Unit::S)});
    }
    if (kind == dev::proto::kEvTestTripped) {
        if ((v.r.code == why::kExcursion || v.r.code == why::kFollowingError) && v.has(5))
            return with(v.r.code == why::kExcursion ? "device.why.test_excursion" : "device.why.test_following_error",
                        {motion::msg::real("limit", v.at(1), len), motion::msg::real("value", v.at(2), len), motion::msg::real("seconds", v.at(3), motion::msg::Unit::S),
                         motion::msg::real("at", v.at(4), len)});
        if (v.r.code == why::kDuration && v.has(3))
            return with("device.why.test_duration", {motion::msg::real("limit", v.at(1), motion::msg::Unit::S), motion::msg::real("at", v.at(2), len)});
    }
    if (kind == dev::proto::kEvTestAborted) {
        switch (v.r.code) {
        case why::kOnRequest: return with("device.why.test_on_request", {});
        case why::kByEStop: return with("device.why.test_estop", {});
        case why::kByFault: return with("device.why.test_fault", {});
        case why::kHostSilent:
            if (v.has(2))
                return with("device.why.test_host_silent", {motion::msg::real("seconds", v.at(1), motion::msg::Unit::S)});
            break;
        default: break;
        }
    }
    return {};
}

motion::msg::Message gains(const Reading& v, const std::vector<motion::msg::Arg>& who)
{
    if (!v.has(3))
        return {};
    std::vector<motion::msg::Arg> a = who;
    a.push_back(motion::msg::real("kp", v.at(0)));
    a.push_back(motion::msg::real("ki", v.at(1)));
    a.push_back(motion::msg::real("kd", v.at(2)));
    if (v.r.code == why::kGainsFellBack)
        return motion::msg::make("device.why.gains_fell_back", a);
    if (v.r.code != why::kGainsSet)
        return {};
    return motion::msg::make(v.at(3) != 0 ? "device.why.gains_set_kept" : "device.why.gains_set", a);
}

motion::msg::Message compensation(const Reading& v, const std::vector<motion::msg::Arg>& who)
{
    std::vector<motion::msg::Arg> a = who;
    const bool kept = v.at(0) != 0;
    switch (v.r.code) {
    case why::kInstalled:
        if (v.at(0) == 2 && v.has(4)) {
            a.insert(a.end(), {motion::msg::integer("order", static_cast<long long>(v.at(1))), motion::msg::real("from", v.at(2), motion::msg::Unit::Mm),
                               motion::msg::real("to", v.at(3), motion::msg::Unit::Mm)});
            return motion::msg::make("device.why.comp_installed_polynomial", a);
        }
        if (v.at(0) == 1 && v.has(3)) {
            a.push_back(motion::msg::integer("points", static_cast<long long>(v.at(1))));
            return motion::msg::make(v.at(2) != 0 ? "device.why.comp_installed_table_per_direction" : "device.why.comp_installed_table", a);
        }
        return {};
    case why::kEnabled: return motion::msg::make(kept ? "device.why.comp_enabled_kept" : "device.why.comp_enabled", a);
    case why::kDisabled: return motion::msg::make(kept ? "device.why.comp_disabled_kept" : "device.why.comp_disabled", a);
    default: return {};
    }
}

motion::msg::Message path(EventKind kind, std::uint8_t code)
{
    if (code == why::kPathRan)
        return kind == EventKind::PathUnderrun ? motion::msg::make("device.why.path_underrun") : motion::msg::Message{};
    if (code > static_cast<std::uint8_t>(dev::proto::PathReason::Cleared))
        return {};
    const motion::msg::Arg reason = motion::msg::term("reason", pathReasonTerm(static_cast<dev::proto::PathReason>(code)));
    if (kind == EventKind::PathHeld)
        return motion::msg::make("device.why.path_held", {reason});
    if (kind == EventKind::PathAborted)
        return motion::msg::make("device.why.path_ended", {reason});
    return {};
}

motion::msg::Message worded(EventKind kind, const dev::proto::EventReason& r, const std::string& letter, dev::proto::AxisUnit unit)
{
    const Reading v{r};
    const motion::msg::Unit len = unit == dev::proto::AxisUnit::Microlitre ? motion::msg::Unit::Ul : motion::msg::Unit::Mm;
    const std::vector<motion::msg::Arg> who = letter.empty() ? std::vector<motion::msg::Arg>{} : std::vector<motion::msg::Arg>{motion::msg::verbatim("axis", letter)};
    auto axisSentence = [&](const char* id) { return letter.empty() ? motion::msg::Message{} : motion::msg::make(id, who); };
    switch (kind) {
    case EventKind::MotionDone:
    case EventKind::HomeDone:
        if (r.code == why::kAlreadyThere)
            return motion::msg::make("device.why.already_there");
        if (r.code == why::kOutsideWindow)
            return motion::msg::make("device.why.outside_window");
        return {};
    case EventKind::LimitHit:
        if (r.code == why::kHomeSwitch)
            return axisSentence("device.why.home_switch");
        if (r.code == why::kLimitSwitch)
            return axisSentence("device.why.limit_switch");
        return {};
    case EventKind::Fault: return r.code == why::kHomeSwitchNotFound ? axisSentence("device.why.home_switch_not_found") : motion::msg::Message{};
    case EventKind::EStop: return r.code == why::kAllHalted ? motion::msg::make("device.why.all_halted") : motion::msg::Message{};
    case EventKind::JogExpired:
        if (r.code == why::kNotRefreshed && v.has(1) && !letter.empty())
            return motion::msg::make("device.why.jog_not_refreshed", {motion::msg::verbatim("axis", letter), motion::msg::real("seconds", v.at(0), motion::msg::Unit::S)});
        return {};
    case EventKind::Stopped:
        switch (r.code) {
        case why::kStopRequest: return motion::msg::make("device.why.stop_request");
        case why::kWithCoupledAxis: return motion::msg::make("device.why.with_coupled_axis");
        case why::kHomingOtherFailed: return motion::msg::make("device.why.homing_other_failed");
        case why::kHomingEarlierFailed: return motion::msg::make("device.why.homing_earlier_failed");
        case why::kHomingStopped: return motion::msg::make("device.why.homing_stopped");
        case why::kWaitedMoveStopped: return motion::msg::make("device.why.waited_move_stopped");
        case why::kWaitedMoveHitSwitch: return motion::msg::make("device.why.waited_move_hit_switch");
        default: return {};
        }
    case EventKind::LostSteps:
        if (r.code == why::kOffCommand && v.has(1) && !letter.empty())
            return motion::msg::make("device.why.off_command", {motion::msg::verbatim("axis", letter), motion::msg::real("error", v.at(0), len)});
        return {};
    case EventKind::Reset: return r.code == why::kCleared ? motion::msg::make("device.why.cleared") : motion::msg::Message{};
    case EventKind::PathStarted:
    case EventKind::PathSegmentDone:
    case EventKind::PathUnderrun:
    case EventKind::PathDone:
    case EventKind::PathHeld:
    case EventKind::PathAborted: return path(kind, r.code);
    default: break;
    }
    if (letter.empty())
        return {};
    if (kind == dev::proto::kEvTestEnded || kind == dev::proto::kEvTestTripped || kind == dev::proto::kEvTestAborted)
        return tuning(kind, v, who, len);
    if (kind == dev::proto::kEvGainsChanged)
        return gains(v, who);
    if (kind == dev::proto::kEvCompChanged)
        return compensation(v, who);
    return {};
}

} // namespace

std::optional<motion::msg::Message> eventReasonMessage(EventKind kind, const dev::proto::EventReason& r, const std::string& letter,
                                               dev::proto::AxisUnit unit)
{
    motion::msg::Message m = worded(kind, r, letter, unit);
    const bool pathAsPlanned = r.code == why::kPathRan && kind >= EventKind::PathStarted && kind <= EventKind::PathAborted;
    if (m.empty() && !pathAsPlanned)
        return std::nullopt;
    return m;
}

} // namespace dev
