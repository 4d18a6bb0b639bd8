#pragma once
// The number an ERROR reply carries (docs/protocol.md, "Errors"), as a message argument
// in the unit its code gives it, so a refusal is worded from the code, the axis and this
// value in the operator's language rather than from the firmware's English.
#include "device/client/instrument_types.h"
#include "device/protocol/messages.h"
#include "motion/message.h"

#include <optional>

namespace dev {

/// "value": the limit of a SoftLimit refusal in the axis' unit,
/// the rate that fits for OverCapacity, an index or count for the path, capture,
/// gains and compensation codes; nullopt where the code's value says nothing to a
/// person (0, device-specific, or a value of unknown unit). `axis`: the axis at
/// fault, or nullptr.
std::optional<motion::msg::Arg> refusalValue(const dev::proto::ErrorReply& e, const AxisDescriptor* axis);

} // namespace dev
