#pragma once
// The reasons an instrument gives for a missing capability (dev::Instrument::whyNot,
// ids capability.*) in the operator's language: what a disabled control's tooltip or a
// screen's note says. It moves into the wording layer (widgets/wording/) when that lands.
#include "motion/message.h"

#include <QString>

namespace ui {

/// An empty Message gives an empty string; an id this file does not know, the id itself.
QString capabilityText(const msg::Message& reason);

} // namespace ui
