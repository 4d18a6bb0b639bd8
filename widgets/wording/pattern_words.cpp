// Words for the pattern.*, segment.* ids (docs/patterns.md): one row per id, the
// English source with %1, %2 … for the arguments named beside it (word_table.h).
#include "widgets/wording/areas.h"
#include "widgets/wording/word_table.h"

#include <QCoreApplication>

namespace ui::words::areas {
namespace {

// clang-format off
const Row kRows[] = {
    {"pattern.not_a_number", QT_TRANSLATE_NOOP3("ui::words::PatternWords", "must be a number", "pattern.not_a_number")},
    {"pattern.not_a_point", QT_TRANSLATE_NOOP3("ui::words::PatternWords", "must be two numbers [x, y]", "pattern.not_a_point")},
    {"pattern.not_above", QT_TRANSLATE_NOOP3("ui::words::PatternWords", "must be above %1 (got %2)", "pattern.not_above"), "min,value"},
    {"pattern.out_of_range", QT_TRANSLATE_NOOP3("ui::words::PatternWords", "must be from %1 to %2 (got %3)", "pattern.out_of_range"), "min,max,value"},
    {"pattern.line_has_no_length", QT_TRANSLATE_NOOP3("ui::words::PatternWords", "must differ from start_mm: the line has no length", "pattern.line_has_no_length")},
    {"pattern.too_many_chords", QT_TRANSLATE_NOOP3("ui::words::PatternWords", "gives %1 chords, more than %2: loosen it or shorten the wave", "pattern.too_many_chords"), "count,max"},
    {"pattern.not_half_turns", QT_TRANSLATE_NOOP3("ui::words::PatternWords", "must be a whole or half number of turns (got %1)", "pattern.not_half_turns"), "value"},
    {"pattern.too_many_passes", QT_TRANSLATE_NOOP3("ui::words::PatternWords", "gives %1 passes: too many (at most %2), widen the spacing", "pattern.too_many_passes"), "count,max"},
    {"pattern.segment_above_limit", QT_TRANSLATE_NOOP3("ui::words::PatternWords", "segment %1 (%2) reaches %3 = %4, beyond the upper soft limit %5", "pattern.segment_above_limit"), "segment,kind,axis,value,limit"},
    {"pattern.segment_below_limit", QT_TRANSLATE_NOOP3("ui::words::PatternWords", "segment %1 (%2) reaches %3 = %4, beyond the lower soft limit %5", "pattern.segment_below_limit"), "segment,kind,axis,value,limit"},
    {"pattern.run.replaced", QT_TRANSLATE_NOOP3("ui::words::PatternWords", "The instrument was replaced by another connection.", "pattern.run.replaced")},
    {"pattern.run.underrun", QT_TRANSLATE_NOOP3("ui::words::PatternWords", "The instrument ran out of queued segments and waited for more: the link is slower than the pattern.", "pattern.run.underrun")},
    {"pattern.run.done", QT_TRANSLATE_NOOP3("ui::words::PatternWords", "Pattern done in %1: contour error max %2, RMS %3 (%4 samples at %5).", "pattern.run.done"), "duration,max,rms,samples,rate"},
    {"pattern.run.held", QT_TRANSLATE_NOOP3("ui::words::PatternWords", "The instrument paused the pattern: %1. Press Resume to go on.", "pattern.run.held"), "reason"},
    {"pattern.run.aborted", QT_TRANSLATE_NOOP3("ui::words::PatternWords", "Pattern aborted at segment %1 of %2.", "pattern.run.aborted"), "segment,total"},
    {"pattern.run.stopped_by_instrument", QT_TRANSLATE_NOOP3("ui::words::PatternWords", "The instrument stopped the pattern at segment %1 (%2). Press Resume to continue from there.", "pattern.run.stopped_by_instrument"), "segment,reason"},
    {"pattern.run.no_path_queue", QT_TRANSLATE_NOOP3("ui::words::PatternWords", "The instrument is not connected or cannot run paths.", "pattern.run.no_path_queue")},
    {"pattern.run.no_segments", QT_TRANSLATE_NOOP3("ui::words::PatternWords", "The pattern has no segments.", "pattern.run.no_segments")},
    {"pattern.run.estop_active", QT_TRANSLATE_NOOP3("ui::words::PatternWords", "The E-stop is active: reset it first.", "pattern.run.estop_active")},
    {"pattern.run.still_moving", QT_TRANSLATE_NOOP3("ui::words::PatternWords", "The instrument is still moving: wait until it is at rest.", "pattern.run.still_moving")},
    {"pattern.run.not_homed", QT_TRANSLATE_NOOP3("ui::words::PatternWords", "Axis %1 is not homed: home it first.", "pattern.run.not_homed"), "axis"},
    {"pattern.run.no_z", QT_TRANSLATE_NOOP3("ui::words::PatternWords", "This instrument has no Z axis to work at a height.", "pattern.run.no_z")},
    {"pattern.run.z_outside_limits", QT_TRANSLATE_NOOP3("ui::words::PatternWords", "Z %1 is outside its soft limits %2 … %3.", "pattern.run.z_outside_limits"), "value,min,max"},
    {"pattern.run.feed_too_high", QT_TRANSLATE_NOOP3("ui::words::PatternWords", "Segment %1: feed %2 is above the instrument's %3.", "pattern.run.feed_too_high"), "segment,feed,max"},
    {"pattern.run.approach_refused", QT_TRANSLATE_NOOP3("ui::words::PatternWords", "Cannot move to the pattern's start: %1", "pattern.run.approach_refused"), "cause"},
    {"pattern.run.approach_stopped", QT_TRANSLATE_NOOP3("ui::words::PatternWords", "The move to the pattern's start was stopped before it arrived. Press Resume to try again.", "pattern.run.approach_stopped")},
    {"pattern.run.refused", QT_TRANSLATE_NOOP3("ui::words::PatternWords", "The instrument refused the pattern: %1", "pattern.run.refused"), "cause"},
    {"pattern.run.link_lost", QT_TRANSLATE_NOOP3("ui::words::PatternWords", "The link to the instrument was lost at segment %1 of %2. The instrument holds the path by itself within a second. Reconnect, then press Resume to continue from segment %1.", "pattern.run.link_lost"), "segment,total"},
    {"pattern.run.reconnect_first", QT_TRANSLATE_NOOP3("ui::words::PatternWords", "Reconnect the instrument first.", "pattern.run.reconnect_first")},
    {"pattern.run.continuing", QT_TRANSLATE_NOOP3("ui::words::PatternWords", "Continuing from segment %1.", "pattern.run.continuing"), "segment"},
};

const TermRow kTerms[] = {
    {"segment.line", QT_TRANSLATE_NOOP3("ui::words::PatternWords", "LINE", "segment.line")},
    {"segment.arc_cw", QT_TRANSLATE_NOOP3("ui::words::PatternWords", "ARC CW", "segment.arc_cw")},
    {"segment.arc_ccw", QT_TRANSLATE_NOOP3("ui::words::PatternWords", "ARC CCW", "segment.arc_ccw")},
    {"pattern.state.idle", QT_TRANSLATE_NOOP3("ui::words::PatternWords", "ready", "pattern.state.idle")},
    {"pattern.state.approaching", QT_TRANSLATE_NOOP3("ui::words::PatternWords", "moving to the start", "pattern.state.approaching")},
    {"pattern.state.running", QT_TRANSLATE_NOOP3("ui::words::PatternWords", "running", "pattern.state.running")},
    {"pattern.state.paused", QT_TRANSLATE_NOOP3("ui::words::PatternWords", "paused", "pattern.state.paused")},
    {"pattern.state.done", QT_TRANSLATE_NOOP3("ui::words::PatternWords", "done", "pattern.state.done")},
    {"pattern.state.aborted", QT_TRANSLATE_NOOP3("ui::words::PatternWords", "aborted", "pattern.state.aborted")},
    {"pattern.state.interrupted", QT_TRANSLATE_NOOP3("ui::words::PatternWords", "interrupted", "pattern.state.interrupted")},
    {"pattern.state.failed", QT_TRANSLATE_NOOP3("ui::words::PatternWords", "refused", "pattern.state.failed")},
};
// clang-format on

} // namespace

QString pattern(const motion::msg::Message& m) { return fromRows("ui::words::PatternWords", kRows, m); }
QString patternTerm(const std::string& id) { return fromTerms("ui::words::PatternWords", kTerms, id); }

} // namespace ui::words::areas
