#pragma once
// An EVENT's reason (docs/protocol.md, "Event reasons") as a message the wording layer
// words in the operator's language, so no firmware English reaches the event log, a
// banner or a job's stop message.
#include "device/protocol/messages.h"
#include "motion/message.h"

#include <optional>
#include <string>

namespace dev {

/// The sentence for `why` on an event of `kind` about axis `letter` (empty for an
/// instrument-wide event), whose positions are in `unit`: nullopt for a code this host
/// does not know (the device's text is shown instead), an empty message when the
/// reason adds nothing to the kind (a path that started or finished as planned).
std::optional<motion::msg::Message> eventReasonMessage(dev::proto::EventKind kind, const dev::proto::EventReason& why, const std::string& letter,
                                               dev::proto::AxisUnit unit);

} // namespace dev
