#include "device/backends/benchpilot/refusal_value.h"

#include "device/protocol/messages_compensation.h"
#include "device/protocol/messages_tuning.h"

namespace dev {

std::optional<msg::Arg> refusalValue(const proto::ErrorReply& e, const AxisDescriptor* axis)
{
    using proto::ErrorCode;
    const auto code = e.code;
    // NotHomed's value is a target only for a move (0 for a test or a path): the sentence needs none.
    if (code == ErrorCode::SoftLimit) {
        if (!axis)
            return std::nullopt;
        const msg::Unit unit = axis->unit == proto::AxisUnit::Microlitre ? msg::Unit::Ul : msg::Unit::Mm;
        return msg::real("value", e.value / axis->wireScale(), unit);
    }
    if (code == ErrorCode::OverCapacity)
        return msg::real("value", e.value, msg::Unit::Hz);
    if (code == proto::kErrBadGains) {
        static const char* const names[] = {"kp", "ki", "kd"};
        return e.value >= 0 && e.value <= 2 ? std::optional<msg::Arg>(msg::verbatim("value", names[e.value])) : std::nullopt;
    }
    if (code == ErrorCode::UnknownCommand || code == ErrorCode::BadAxis || code == proto::kErrNoCapture
        || code == ErrorCode::PathQueueFull || code == ErrorCode::PathSequence || code == ErrorCode::PathGeometry
        || code == proto::kErrCompSequence)
        return msg::integer("value", e.value);
    if (code == proto::kErrCompInvalid && e.value >= 0)
        return msg::integer("value", e.value);
    return std::nullopt;
}

} // namespace dev
