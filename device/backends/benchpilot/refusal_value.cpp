#include "device/backends/benchpilot/refusal_value.h"

#include "device/protocol/messages_compensation.h"
#include "device/protocol/messages_tuning.h"

namespace dev {

std::optional<motion::msg::Arg> refusalValue(const dev::proto::ErrorReply& e, const AxisDescriptor* axis)
{
    using dev::proto::ErrorCode;
    const auto code = e.code;
    // NotHomed's value is a target only for a move (0 for a test or a path): the sentence needs none.
    if (code == ErrorCode::SoftLimit) {
        if (!axis)
            return std::nullopt;
        const motion::msg::Unit unit = axis->unit == dev::proto::AxisUnit::Microlitre ? motion::msg::Unit::Ul : motion::msg::Unit::Mm;
        return motion::msg::real("value", e.value / axis->wireScale(), unit);
    }
    if (code == ErrorCode::OverCapacity)
        return motion::msg::real("value", e.value, motion::msg::Unit::Hz);
    if (code == dev::proto::kErrBadGains) {
        static const char* const names[] = {"kp", "ki", "kd"};
        return e.value >= 0 && e.value <= 2 ? std::optional<motion::msg::Arg>(motion::msg::verbatim("value", names[e.value])) : std::nullopt;
    }
    if (code == ErrorCode::UnknownCommand || code == ErrorCode::BadAxis || code == dev::proto::kErrNoCapture
        || code == ErrorCode::PathQueueFull || code == ErrorCode::PathSequence || code == ErrorCode::PathGeometry
        || code == dev::proto::kErrCompSequence)
        return motion::msg::integer("value", e.value);
    if (code == dev::proto::kErrCompInvalid && e.value >= 0)
        return motion::msg::integer("value", e.value);
    return std::nullopt;
}

} // namespace dev
