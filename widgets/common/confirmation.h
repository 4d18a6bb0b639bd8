#pragma once
// One rule for what asks first, on every screen: a long move
// (further than kLongMoveShare of an axis's travel) and a destructive action
// (Abort a run, Disconnect during one, quitting with unsaved edits or a running
// job) are confirmed. Screens raise the question through their Confirm hook;
// app/ shows it (long moves may offer "don't ask again for this session").
#include "motion/long_move.h"

namespace ui::confirmation {

/// The long-move rule itself lives below the widgets, where the jobs can apply it too.
using motion::isLongMove;
using motion::kLongMoveShare;

} // namespace ui::confirmation
