// Words for the profile.* ids (docs/motion.md): one row per id, the
// English source with %1, %2 … for the arguments named beside it (word_table.h).
#include "widgets/wording/areas.h"
#include "widgets/wording/word_table.h"

#include <QCoreApplication>

namespace ui::words::areas {
namespace {

// clang-format off
const Row kRows[] = {
    {"profile.not_finite", QT_TRANSLATE_NOOP3("ui::words::ProfileWords", "%1 = %2 must be finite", "profile.not_finite"), "field,value"},
    {"profile.axis_not_finite", QT_TRANSLATE_NOOP3("ui::words::ProfileWords", "axis %1: %2 = %3 must be finite", "profile.axis_not_finite"), "axis,field,value"},
    {"profile.not_positive", QT_TRANSLATE_NOOP3("ui::words::ProfileWords", "%1 = %2 must be finite and above 0 for %3", "profile.not_positive"), "field,value,kind"},
    {"profile.not_positive_plain", QT_TRANSLATE_NOOP3("ui::words::ProfileWords", "%1 = %2 must be finite and above 0", "profile.not_positive_plain"), "field,value"},
    {"profile.axis_not_positive", QT_TRANSLATE_NOOP3("ui::words::ProfileWords", "axis %1: %2 = %3 must be finite and above 0", "profile.axis_not_positive"), "axis,field,value"},
    {"profile.negative", QT_TRANSLATE_NOOP3("ui::words::ProfileWords", "%1 = %2 must be finite and not negative for %3", "profile.negative"), "field,value,kind"},
    {"profile.start_speed_above_max", QT_TRANSLATE_NOOP3("ui::words::ProfileWords", "%1 = %2 must be from 0 to vMaxMmS for %3", "profile.start_speed_above_max"), "field,value,kind"},
    {"profile.start_speed_for_plateau", QT_TRANSLATE_NOOP3("ui::words::ProfileWords", "%1 = %2 must be above 0 when plateauMm is above 0 for %3", "profile.start_speed_for_plateau"), "field,value,kind"},
    {"profile.unknown_kind", QT_TRANSLATE_NOOP3("ui::words::ProfileWords", "unknown profile kind", "profile.unknown_kind")},
    {"profile.axis_count", QT_TRANSLATE_NOOP3("ui::words::ProfileWords", "%1 axes: a move has 1 to %2", "profile.axis_count"), "count,max"},
    {"profile.path_limits_not_finite", QT_TRANSLATE_NOOP3("ui::words::ProfileWords", "path limits are not finite; check the per-axis limits", "profile.path_limits_not_finite")},
    {"profile.path_speed_not_finite", QT_TRANSLATE_NOOP3("ui::words::ProfileWords", "path speed is not finite; check the per-axis vMaxMmS", "profile.path_speed_not_finite")},
    {"profile.block_zero_duration", QT_TRANSLATE_NOOP3("ui::words::ProfileWords", "joint %1 block %2: t0 = 0 ms must be above 0", "profile.block_zero_duration"), "joint,block"},
    {"profile.block_too_fast", QT_TRANSLATE_NOOP3("ui::words::ProfileWords", "joint %1 block %2: |V2| = %3 microsteps/s exceeds vMax = %4", "profile.block_too_fast"), "joint,block,v2,max"},
    {"profile.block_unreachable", QT_TRANSLATE_NOOP3("ui::words::ProfileWords", "joint %1 block %2: S = %3 microsteps is not reachable from V1 = %4 to V2 = %5 microsteps/s in t0 = %6 (reachable %7 … %8)", "profile.block_unreachable"), "joint,block,steps,v1,v2,t0,from,to"},
};
// clang-format on

} // namespace

QString profile(const motion::msg::Message& m) { return fromRows("ui::words::ProfileWords", kRows, m); }

} // namespace ui::words::areas
