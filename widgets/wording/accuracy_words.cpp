// Words for the accuracy.*, compensation.*, direction.*, rotation.* ids (docs/accuracy.md): one row per id, the
// English source with %1, %2 … for the arguments named beside it (word_table.h).
#include "widgets/wording/areas.h"
#include "widgets/wording/word_table.h"

#include <QCoreApplication>

namespace ui::words::areas {
namespace {

// clang-format off
const Row kRows[] = {
    {"accuracy.value_not_finite", QT_TRANSLATE_NOOP3("ui::words::AccuracyWords", "must be a number (not NaN or infinite)", "accuracy.value_not_finite")},
    {"accuracy.value_below", QT_TRANSLATE_NOOP3("ui::words::AccuracyWords", "is %1, below the least allowed %2", "accuracy.value_below"), "value,min"},
    {"accuracy.value_above", QT_TRANSLATE_NOOP3("ui::words::AccuracyWords", "is %1, above the most allowed %2", "accuracy.value_above"), "value,max"},
    {"accuracy.value_not_positive", QT_TRANSLATE_NOOP3("ui::words::AccuracyWords", "must be above 0 (is %1)", "accuracy.value_not_positive"), "value"},
    {"accuracy.axis_name_invalid", QT_TRANSLATE_NOOP3("ui::words::AccuracyWords", "\"%1\" is not an axis name: one capital letter, such as X", "accuracy.axis_name_invalid"), "axis"},
    {"accuracy.no_targets", QT_TRANSLATE_NOOP3("ui::words::AccuracyWords", "no targets: give a list of targets or a start, end and count", "accuracy.no_targets")},
    {"accuracy.targets_and_grid", QT_TRANSLATE_NOOP3("ui::words::AccuracyWords", "give either a list of targets or a grid, not both", "accuracy.targets_and_grid")},
    {"accuracy.too_few_targets", QT_TRANSLATE_NOOP3("ui::words::AccuracyWords", "%1 targets: a positioning test needs at least %2", "accuracy.too_few_targets"), "count,min"},
    {"accuracy.fewer_targets_than_iso", QT_TRANSLATE_NOOP3("ui::words::AccuracyWords", "%1 targets: ISO 230-2 recommends at least %2", "accuracy.fewer_targets_than_iso"), "count,recommended"},
    {"accuracy.targets_not_increasing", QT_TRANSLATE_NOOP3("ui::words::AccuracyWords", "target %1 does not come after %2: targets must increase", "accuracy.targets_not_increasing"), "value,previous"},
    {"accuracy.target_below_limit", QT_TRANSLATE_NOOP3("ui::words::AccuracyWords", "target %1 is below the soft limit %2", "accuracy.target_below_limit"), "value,limit"},
    {"accuracy.target_above_limit", QT_TRANSLATE_NOOP3("ui::words::AccuracyWords", "target %1 is above the soft limit %2", "accuracy.target_above_limit"), "value,limit"},
    {"accuracy.grid_end_not_after_start", QT_TRANSLATE_NOOP3("ui::words::AccuracyWords", "the grid ends at %1, not after its start %2", "accuracy.grid_end_not_after_start"), "end,start"},
    {"accuracy.grid_spacing_too_small", QT_TRANSLATE_NOOP3("ui::words::AccuracyWords", "targets %1 apart are too close: at least %2", "accuracy.grid_spacing_too_small"), "spacing,min"},
    {"accuracy.no_overrun", QT_TRANSLATE_NOOP3("ui::words::AccuracyWords", "no overrun: the drive reverses at the end targets, so their readings include the reversal", "accuracy.no_overrun")},
    {"accuracy.overrun_below_limit", QT_TRANSLATE_NOOP3("ui::words::AccuracyWords", "the overrun goes to %1, below the soft limit %2", "accuracy.overrun_below_limit"), "position,limit"},
    {"accuracy.overrun_above_limit", QT_TRANSLATE_NOOP3("ui::words::AccuracyWords", "the overrun goes to %1, above the soft limit %2", "accuracy.overrun_above_limit"), "position,limit"},
    {"accuracy.too_few_cycles", QT_TRANSLATE_NOOP3("ui::words::AccuracyWords", "%1 cycles: at least %2 are needed to see a spread", "accuracy.too_few_cycles"), "count,min"},
    {"accuracy.fewer_cycles_than_iso", QT_TRANSLATE_NOOP3("ui::words::AccuracyWords", "%1 cycles: ISO 230-2 recommends %2", "accuracy.fewer_cycles_than_iso"), "count,recommended"},
    {"accuracy.settle_timeout_below_window", QT_TRANSLATE_NOOP3("ui::words::AccuracyWords", "the settle timeout %1 is shorter than its window %2", "accuracy.settle_timeout_below_window"), "timeout,window"},
    {"accuracy.duplicate_reading", QT_TRANSLATE_NOOP3("ui::words::AccuracyWords", "a second reading at %1 %2 in cycle %3 (the first is reading %4)", "accuracy.duplicate_reading"), "target,direction,cycle,first"},
    {"accuracy.direction_missing", QT_TRANSLATE_NOOP3("ui::words::AccuracyWords", "no %1 readings at %2, though other targets have them", "accuracy.direction_missing"), "direction,target"},
    {"accuracy.cycle_counts_differ", QT_TRANSLATE_NOOP3("ui::words::AccuracyWords", "%1 readings at %2 %3, where the others have %4", "accuracy.cycle_counts_differ"), "count,target,direction,expected"},
    {"accuracy.statistics_incomplete", QT_TRANSLATE_NOOP3("ui::words::AccuracyWords", "the table's row for %1 lacks a mean or a standard deviation", "accuracy.statistics_incomplete"), "target"},
    {"accuracy.reading_count_wrong", QT_TRANSLATE_NOOP3("ui::words::AccuracyWords", "%1 readings, where the test has %2", "accuracy.reading_count_wrong"), "count,expected"},
    {"accuracy.reading_not_in_plan", QT_TRANSLATE_NOOP3("ui::words::AccuracyWords", "a reading at %1 %2 in cycle %3, which the test does not have", "accuracy.reading_not_in_plan"), "target,direction,cycle"},
    {"accuracy.reading_missing", QT_TRANSLATE_NOOP3("ui::words::AccuracyWords", "no reading at %1 %2 in cycle %3", "accuracy.reading_missing"), "target,direction,cycle"},
    {"accuracy.xy.point_off_line", QT_TRANSLATE_NOOP3("ui::words::AccuracyWords", "this target is %1 off the line through the first and last (at most %2)", "accuracy.xy.point_off_line"), "distance,max"},
    {"accuracy.xy.no_such_point", QT_TRANSLATE_NOOP3("ui::words::AccuracyWords", "reading for target %1, but the line has %2 targets", "accuracy.xy.no_such_point"), "index,count"},
    {"accuracy.xy.axis_does_not_move", QT_TRANSLATE_NOOP3("ui::words::AccuracyWords", "%1 does not move along this line: it is not evaluated", "accuracy.xy.axis_does_not_move"), "axis"},
    {"accuracy.circle.axes_invalid", QT_TRANSLATE_NOOP3("ui::words::AccuracyWords", "\"%1\" is not a plane: two different axis letters, such as XY", "accuracy.circle.axes_invalid"), "axes"},
    {"accuracy.circle.below_limit", QT_TRANSLATE_NOOP3("ui::words::AccuracyWords", "the circle reaches %1 = %2, below the soft limit %3", "accuracy.circle.below_limit"), "axis,value,limit"},
    {"accuracy.circle.above_limit", QT_TRANSLATE_NOOP3("ui::words::AccuracyWords", "the circle reaches %1 = %2, above the soft limit %3", "accuracy.circle.above_limit"), "axis,value,limit"},
    {"accuracy.circle.no_direction", QT_TRANSLATE_NOOP3("ui::words::AccuracyWords", "choose clockwise, counter-clockwise or both", "accuracy.circle.no_direction")},
    {"accuracy.circle.no_runs", QT_TRANSLATE_NOOP3("ui::words::AccuracyWords", "no circle was sampled", "accuracy.circle.no_runs")},
    {"accuracy.circle.direction_twice", QT_TRANSLATE_NOOP3("ui::words::AccuracyWords", "two %1 runs: one of each direction", "accuracy.circle.direction_twice"), "rotation"},
    {"accuracy.circle.too_few_samples", QT_TRANSLATE_NOOP3("ui::words::AccuracyWords", "%1 samples of a circle: at least %2", "accuracy.circle.too_few_samples"), "count,min"},
    {"accuracy.circle.incomplete_revolution", QT_TRANSLATE_NOOP3("ui::words::AccuracyWords", "the samples leave a gap of %1 in the revolution (at most %2)", "accuracy.circle.incomplete_revolution"), "gap,max"},
    {"accuracy.circle.no_circle", QT_TRANSLATE_NOOP3("ui::words::AccuracyWords", "the %1 samples do not lie on a circle", "accuracy.circle.no_circle"), "rotation"},
    {"accuracy.result.figure_disagrees", QT_TRANSLATE_NOOP3("ui::words::AccuracyWords", "%1 is written as %2, but the file's own table gives %3", "accuracy.result.figure_disagrees"), "figure,value,computed"},
    {"accuracy.result.needs_down_statistics", QT_TRANSLATE_NOOP3("ui::words::AccuracyWords", "needs mean_down_mm and s_down_mm in a bidirectional result", "accuracy.result.needs_down_statistics")},
    {"accuracy.csv.missing_column", QT_TRANSLATE_NOOP3("ui::words::AccuracyWords", "the header has no %1 column", "accuracy.csv.missing_column"), "column"},
    {"accuracy.csv.unknown_unit", QT_TRANSLATE_NOOP3("ui::words::AccuracyWords", "cannot read the unit of column %1: use one of %2", "accuracy.csv.unknown_unit"), "column,units"},
    {"accuracy.csv.duplicate_column", QT_TRANSLATE_NOOP3("ui::words::AccuracyWords", "a second column for the same quantity: %1", "accuracy.csv.duplicate_column"), "column"},
    {"accuracy.certificate.no_schema", QT_TRANSLATE_NOOP3("ui::words::AccuracyWords", "the first line must be '# %1 1': this is not a scale certificate", "accuracy.certificate.no_schema"), "schema"},
    {"accuracy.certificate.version", QT_TRANSLATE_NOOP3("ui::words::AccuracyWords", "a certificate of version %1; this BenchPilot reads version %2", "accuracy.certificate.version"), "version,supported"},
    {"accuracy.certificate.outside_scale", QT_TRANSLATE_NOOP3("ui::words::AccuracyWords", "graduation %1 is outside the scale, which is graduated from 0 to %2: a certificate of another scale", "accuracy.certificate.outside_scale"), "graduation,length"},
    {"accuracy.certificate.off_pitch", QT_TRANSLATE_NOOP3("ui::words::AccuracyWords", "graduation %1 is not on the scale's pitch of %2: a certificate of another scale", "accuracy.certificate.off_pitch"), "graduation,pitch"},
    {"accuracy.certificate.not_increasing", QT_TRANSLATE_NOOP3("ui::words::AccuracyWords", "graduation %1 does not come after %2: a certificate's graduations increase", "accuracy.certificate.not_increasing"), "graduation,previous"},
    {"accuracy.csv.no_readings", QT_TRANSLATE_NOOP3("ui::words::AccuracyWords", "the file has no readings", "accuracy.csv.no_readings")},
    {"accuracy.csv.wrong_cell_count", QT_TRANSLATE_NOOP3("ui::words::AccuracyWords", "%1 cells where the header has %2", "accuracy.csv.wrong_cell_count"), "count,expected"},
    {"accuracy.csv.not_a_number", QT_TRANSLATE_NOOP3("ui::words::AccuracyWords", "\"%1\" is not a number", "accuracy.csv.not_a_number"), "text"},
    {"accuracy.csv.unknown_direction", QT_TRANSLATE_NOOP3("ui::words::AccuracyWords", "\"%1\" is not a direction: up or down", "accuracy.csv.unknown_direction"), "text"},
    {"accuracy.csv.not_a_cycle", QT_TRANSLATE_NOOP3("ui::words::AccuracyWords", "\"%1\" is not a cycle: a whole number from 1", "accuracy.csv.not_a_cycle"), "text"},
    {"compensation.too_few_points", QT_TRANSLATE_NOOP3("ui::words::AccuracyWords", "%1 points: a fit needs at least %2 different positions", "compensation.too_few_points"), "count,min"},
    {"compensation.order_out_of_range", QT_TRANSLATE_NOOP3("ui::words::AccuracyWords", "order %1: choose %2 to %3", "compensation.order_out_of_range"), "order,min,max"},
    {"compensation.order_needs_more_points", QT_TRANSLATE_NOOP3("ui::words::AccuracyWords", "order %1 needs at least %2 points; there are %3", "compensation.order_needs_more_points"), "order,min,count"},
    {"compensation.no_coefficients", QT_TRANSLATE_NOOP3("ui::words::AccuracyWords", "the polynomial has no coefficients", "compensation.no_coefficients")},
    {"compensation.too_many_coefficients", QT_TRANSLATE_NOOP3("ui::words::AccuracyWords", "%1 coefficients: at most %2 (order 5)", "compensation.too_many_coefficients"), "count,max"},
    {"compensation.range_too_short", QT_TRANSLATE_NOOP3("ui::words::AccuracyWords", "the range %1 to %2 is shorter than %3", "compensation.range_too_short"), "from,to,min"},
    {"compensation.curve_too_large", QT_TRANSLATE_NOOP3("ui::words::AccuracyWords", "the curve reaches %1 at %2, beyond ±%3", "compensation.curve_too_large"), "value,position,max"},
    {"compensation.curve_too_steep", QT_TRANSLATE_NOOP3("ui::words::AccuracyWords", "the curve's slope is %1 µm/mm at %2, beyond %3", "compensation.curve_too_steep"), "value,position,max"},
    {"compensation.too_few_table_points", QT_TRANSLATE_NOOP3("ui::words::AccuracyWords", "%1 table points: at least %2", "compensation.too_few_table_points"), "count,min"},
    {"compensation.too_many_table_points", QT_TRANSLATE_NOOP3("ui::words::AccuracyWords", "%1 table points: a device keeps at most %2", "compensation.too_many_table_points"), "count,max"},
    {"compensation.nominals_not_increasing", QT_TRANSLATE_NOOP3("ui::words::AccuracyWords", "nominal %1 does not come after %2", "compensation.nominals_not_increasing"), "value,previous"},
    {"compensation.nominals_too_close", QT_TRANSLATE_NOOP3("ui::words::AccuracyWords", "nominals %1 and %2 are closer than %3", "compensation.nominals_too_close"), "previous,value,min"},
    {"compensation.backlash_with_directions", QT_TRANSLATE_NOOP3("ui::words::AccuracyWords", "a backlash of %1 beside per-direction columns: put it in the columns", "compensation.backlash_with_directions"), "value"},
    {"compensation.linuxcnc.not_a_triplet", QT_TRANSLATE_NOOP3("ui::words::AccuracyWords", "%1 values on a line where LinuxCNC expects three (nominal, forward, reverse); LinuxCNC would stop reading here", "compensation.linuxcnc.not_a_triplet"), "count"},
};

const TermRow kTerms[] = {
    {"direction.up", QT_TRANSLATE_NOOP3("ui::words::AccuracyWords", "up", "direction.up")},
    {"direction.down", QT_TRANSLATE_NOOP3("ui::words::AccuracyWords", "down", "direction.down")},
    {"rotation.cw", QT_TRANSLATE_NOOP3("ui::words::AccuracyWords", "clockwise", "rotation.cw")},
    {"rotation.ccw", QT_TRANSLATE_NOOP3("ui::words::AccuracyWords", "counter-clockwise", "rotation.ccw")},
};
// clang-format on

/// Sentences that say more when the message carries more (an XY line names the axis
/// of a limit, a result file the target and direction of a short cycle count): the
/// bench words those forms, the table the plain ones.
bool hasLongerForm(const motion::msg::Message& m)
{
    const std::string& id = m.id;
    if (id == "accuracy.target_below_limit" || id == "accuracy.target_above_limit" || id == "accuracy.overrun_below_limit"
        || id == "accuracy.overrun_above_limit")
        return m.arg("axis") != nullptr;
    return id == "accuracy.too_few_cycles" && m.arg("target") != nullptr;
}

} // namespace

QString accuracy(const motion::msg::Message& m)
{
    if (hasLongerForm(m))
        return accuracyBench(m);
    const QString t = fromRows("ui::words::AccuracyWords", kRows, m);
    if (!t.isNull())
        return t;
    return m.id.rfind("compensation.", 0) == 0 ? compensationBench(m) : accuracyBench(m);
}
QString accuracyTerm(const std::string& id)
{
    const QString t = fromTerms("ui::words::AccuracyWords", kTerms, id);
    return t.isNull() ? accuracyBenchTerm(id) : t;
}

} // namespace ui::words::areas
