// Words for the accuracy bench's runs that the table in accuracy_words.cpp does
// not word: ids accuracy.*, compensation.*, file.* and gauge.* (context ui::words::AccuracyBenchWords),
// and the terms direction.* and rotation.* (docs/accuracy.md, appendix).
#include "widgets/wording/areas.h"
#include "widgets/wording/wording.h"

#include <QCoreApplication>

namespace ui::words::areas {
namespace {

class AccuracyBenchWords {
    Q_DECLARE_TR_FUNCTIONS(ui::words::AccuracyBenchWords)
public:
    static QString accuracy(const motion::msg::Message& m);
    static QString run(const motion::msg::Message& m);
    static QString files(const motion::msg::Message& m);
    static QString compensation(const motion::msg::Message& m);
    static QString gauge(const motion::msg::Message& m);
    static QString source(const motion::msg::Message& m);
    static QString term(const std::string& id);
};

QString benchArg(const motion::msg::Message& m, const char* name) { return ui::words::arg(m, name); }
bool benchHas(const motion::msg::Message& m, const char* name) { return m.arg(name) != nullptr; }

QString AccuracyBenchWords::accuracy(const motion::msg::Message& m)
{
    const std::string& id = m.id;
    if (id.rfind("accuracy.run.", 0) == 0)
        return run(m);
    if (id.rfind("accuracy.csv.", 0) == 0 || id.rfind("accuracy.import.", 0) == 0 || id.rfind("accuracy.log.", 0) == 0)
        return files(m);
    if (id.rfind("accuracy.source.", 0) == 0)
        return source(m);
    if (id == "accuracy.value_not_finite")
        return tr("must be a number (not NaN or infinite)");
    if (id == "accuracy.value_below")
        return tr("is %1, below the least allowed %2").arg(benchArg(m, "value"), benchArg(m, "min"));
    if (id == "accuracy.value_above")
        return tr("is %1, above the most allowed %2").arg(benchArg(m, "value"), benchArg(m, "max"));
    if (id == "accuracy.value_not_positive")
        return tr("must be above 0 (is %1)").arg(benchArg(m, "value"));
    if (id == "accuracy.axis_name_invalid")
        return tr("\"%1\" is not an axis name: one capital letter, such as X").arg(benchArg(m, "axis"));
    if (id == "accuracy.no_targets")
        return tr("no targets: give a list of targets or a start, end and count");
    if (id == "accuracy.targets_and_grid")
        return tr("give either a list of targets or a grid, not both");
    if (id == "accuracy.too_few_targets")
        return tr("%1 targets: a positioning test needs at least %2").arg(benchArg(m, "count"), benchArg(m, "min"));
    if (id == "accuracy.fewer_targets_than_iso")
        return tr("%1 targets: ISO 230-2 recommends at least %2").arg(benchArg(m, "count"), benchArg(m, "recommended"));
    if (id == "accuracy.targets_not_increasing")
        return tr("target %1 does not come after %2: targets must increase").arg(benchArg(m, "value"), benchArg(m, "previous"));
    if (id == "accuracy.target_below_limit")
        return benchHas(m, "axis") ? tr("target %1 of axis %2 is below the soft limit %3").arg(benchArg(m, "value"), benchArg(m, "axis"), benchArg(m, "limit"))
                              : tr("target %1 is below the soft limit %2").arg(benchArg(m, "value"), benchArg(m, "limit"));
    if (id == "accuracy.target_above_limit")
        return benchHas(m, "axis") ? tr("target %1 of axis %2 is above the soft limit %3").arg(benchArg(m, "value"), benchArg(m, "axis"), benchArg(m, "limit"))
                              : tr("target %1 is above the soft limit %2").arg(benchArg(m, "value"), benchArg(m, "limit"));
    if (id == "accuracy.grid_end_not_after_start")
        return tr("the grid ends at %1, not after its start %2").arg(benchArg(m, "end"), benchArg(m, "start"));
    if (id == "accuracy.grid_spacing_too_small")
        return tr("targets %1 apart are too close: at least %2").arg(benchArg(m, "spacing"), benchArg(m, "min"));
    if (id == "accuracy.no_overrun")
        return tr("no overrun: the drive reverses at the end targets, so their readings include the reversal");
    if (id == "accuracy.overrun_below_limit")
        return benchHas(m, "axis") ? tr("the overrun takes axis %1 to %2, below the soft limit %3").arg(benchArg(m, "axis"), benchArg(m, "position"), benchArg(m, "limit"))
                              : tr("the overrun goes to %1, below the soft limit %2").arg(benchArg(m, "position"), benchArg(m, "limit"));
    if (id == "accuracy.overrun_above_limit")
        return benchHas(m, "axis") ? tr("the overrun takes axis %1 to %2, above the soft limit %3").arg(benchArg(m, "axis"), benchArg(m, "position"), benchArg(m, "limit"))
                              : tr("the overrun goes to %1, above the soft limit %2").arg(benchArg(m, "position"), benchArg(m, "limit"));
    if (id == "accuracy.too_few_cycles")
        return benchHas(m, "target") ? tr("%1 cycles at %2 %3: at least %4 are needed to see a spread").arg(benchArg(m, "count"), benchArg(m, "target"), benchArg(m, "direction"), benchArg(m, "min"))
                                : tr("%1 cycles: at least %2 are needed to see a spread").arg(benchArg(m, "count"), benchArg(m, "min"));
    if (id == "accuracy.fewer_cycles_than_iso")
        return tr("%1 cycles: ISO 230-2 recommends %2").arg(benchArg(m, "count"), benchArg(m, "recommended"));
    if (id == "accuracy.settle_timeout_below_window")
        return tr("the settle timeout %1 is shorter than its window %2").arg(benchArg(m, "timeout"), benchArg(m, "window"));
    if (id == "accuracy.duplicate_reading")
        return tr("a second reading at %1 %2 in cycle %3 (the first is reading %4)").arg(benchArg(m, "target"), benchArg(m, "direction"), benchArg(m, "cycle"), benchArg(m, "first"));
    if (id == "accuracy.direction_missing")
        return tr("no %1 readings at %2, though other targets have them").arg(benchArg(m, "direction"), benchArg(m, "target"));
    if (id == "accuracy.cycle_counts_differ")
        return tr("%1 readings at %2 %3, where the others have %4").arg(benchArg(m, "count"), benchArg(m, "target"), benchArg(m, "direction"), benchArg(m, "expected"));
    if (id == "accuracy.statistics_incomplete")
        return tr("the table's row for %1 lacks a mean or a standard deviation").arg(benchArg(m, "target"));
    if (id == "accuracy.reading_count_wrong")
        return tr("%1 readings, where the test has %2").arg(benchArg(m, "count"), benchArg(m, "expected"));
    if (id == "accuracy.reading_not_in_plan")
        return tr("a reading at %1 %2 in cycle %3, which the test does not have").arg(benchArg(m, "target"), benchArg(m, "direction"), benchArg(m, "cycle"));
    if (id == "accuracy.reading_missing")
        return tr("no reading at %1 %2 in cycle %3").arg(benchArg(m, "target"), benchArg(m, "direction"), benchArg(m, "cycle"));
    if (id == "accuracy.xy.point_off_line")
        return tr("this target is %1 off the line through the first and last (at most %2)").arg(benchArg(m, "distance"), benchArg(m, "max"));
    if (id == "accuracy.xy.no_such_point")
        return tr("reading for target %1, but the line has %2 targets").arg(benchArg(m, "index"), benchArg(m, "count"));
    if (id == "accuracy.xy.axis_does_not_move")
        return tr("%1 does not move along this line: it is not evaluated").arg(benchArg(m, "axis"));
    if (id == "accuracy.circle.axes_invalid")
        return tr("\"%1\" is not a plane: two different axis letters, such as XY").arg(benchArg(m, "axes"));
    if (id == "accuracy.circle.below_limit")
        return tr("the circle reaches %1 = %2, below the soft limit %3").arg(benchArg(m, "axis"), benchArg(m, "value"), benchArg(m, "limit"));
    if (id == "accuracy.circle.above_limit")
        return tr("the circle reaches %1 = %2, above the soft limit %3").arg(benchArg(m, "axis"), benchArg(m, "value"), benchArg(m, "limit"));
    if (id == "accuracy.circle.no_direction")
        return tr("choose clockwise, counter-clockwise or both");
    if (id == "accuracy.circle.no_runs")
        return tr("no circle was sampled");
    if (id == "accuracy.circle.direction_twice")
        return tr("two %1 runs: one of each direction").arg(benchArg(m, "rotation"));
    if (id == "accuracy.circle.too_few_samples")
        return tr("%1 samples of a circle: at least %2").arg(benchArg(m, "count"), benchArg(m, "min"));
    if (id == "accuracy.circle.incomplete_revolution")
        return tr("the samples leave a gap of %1 in the revolution (at most %2)").arg(benchArg(m, "gap"), benchArg(m, "max"));
    if (id == "accuracy.circle.no_circle")
        return tr("the %1 samples do not lie on a circle").arg(benchArg(m, "rotation"));
    if (id == "accuracy.result.figure_disagrees")
        return tr("%1 is written as %2, but the file's own table gives %3").arg(benchArg(m, "figure"), benchArg(m, "value"), benchArg(m, "computed"));
    return {};
}

QString AccuracyBenchWords::run(const motion::msg::Message& m)
{
    const std::string& id = m.id;
    if (id == "accuracy.run.busy")
        return tr("A run is in progress: pause or abort it first.");
    if (id == "accuracy.run.not_connected")
        return tr("The instrument is not connected.");
    if (id == "accuracy.run.no_such_axis")
        return tr("The instrument has no axis %1 for this test.").arg(benchArg(m, "axis"));
    if (id == "accuracy.run.not_homed")
        return benchArg(m, "axis").isEmpty() ? tr("The test's axes are not homed: home them first.")
                                      : tr("Axis %1 is not homed: home it first.").arg(benchArg(m, "axis"));
    if (id == "accuracy.run.estop")
        return tr("E-stop is active: the run stopped; reset the E-stop and resume.");
    if (id == "accuracy.run.no_source")
        return tr("Choose where the readings come from.");
    if (id == "accuracy.run.source_axes")
        return tr("The %1 reads %2 axis at a time; this test reads %3.").arg(benchArg(m, "source"), benchArg(m, "max"), benchArg(m, "count"));
    if (id == "accuracy.run.gauge_one_axis")
        return tr("The gauge on %1 reads one axis; this test reads two.").arg(benchArg(m, "port"));
    if (id == "accuracy.run.folder_failed")
        return tr("Cannot use the folder %1: cannot create it.").arg(benchArg(m, "folder"));
    if (id == "accuracy.run.other_log")
        return tr("%1 holds the run log of another test (%2): choose another folder, or start afresh to keep it aside.")
            .arg(benchArg(m, "file"), benchArg(m, "test"));
    if (id == "accuracy.run.log_unreadable")
        return tr("The run log %1 cannot be continued (line %2): %3.").arg(benchArg(m, "file"), benchArg(m, "line"), benchArg(m, "detail"));
    if (id == "accuracy.run.log_not_kept_aside")
        return tr("Cannot write the run log %1: cannot keep the old log aside as %2.").arg(benchArg(m, "file"), benchArg(m, "aside"));
    if (id == "accuracy.run.log_write_failed")
        return tr("Cannot write the run log %1: %2. The run stopped; no reading was lost.").arg(benchArg(m, "file"), benchArg(m, "detail"));
    if (id == "accuracy.run.move_refused")
        return tr("The instrument refused the move: %1").arg(benchArg(m, "detail"));
    if (id == "accuracy.run.link_lost")
        return tr("The link to the instrument was lost: the run stopped. Reconnect and resume: it goes on at the next reading.");
    if (id == "accuracy.run.aborted")
        return tr("The run was aborted. Resume goes on at the next reading.");
    if (id == "accuracy.run.axis_stopped")
        return tr("Axis %1 stopped (%2): %3. The run stopped.").arg(benchArg(m, "axis"), benchArg(m, "event"), benchArg(m, "detail"));
    if (id == "accuracy.run.status_failed")
        return tr("No position reading from the instrument: %1").arg(benchArg(m, "detail"));
    if (id == "accuracy.run.status_no_axis")
        return tr("No position reading from the instrument: its status has no axis %1.").arg(benchArg(m, "axis"));
    if (id == "accuracy.run.reading_incomplete")
        return tr("The reading has %1 values where the test reads %2 axes: the run stopped.").arg(benchArg(m, "count"), benchArg(m, "expected"));
    if (id == "accuracy.run.results_failed")
        return tr("Cannot write %1: %2").arg(benchArg(m, "file"), benchArg(m, "detail"));
    if (id == "accuracy.run.not_prepared")
        return tr("Define or open a test first.");
    if (id == "accuracy.run.finished_already")
        return tr("Every reading of this run is taken.");
    if (id == "accuracy.run.circle_elsewhere")
        return tr("A circular test runs as a circle, not as stops.");
    if (id == "accuracy.run.timed_out")
        return tr("The run took far longer than its estimate and was aborted.");
    if (id == "accuracy.run.path_aborted")
        // The controller's own words when it gave some (ALARM:2), else the plain fact.
        return m.text("detail").empty() ? tr("The circle's path was aborted.")
                                        : tr("The circle's path was aborted: %1").arg(benchArg(m, "detail"));
    return {};
}

QString AccuracyBenchWords::files(const motion::msg::Message& m)
{
    const std::string& id = m.id;
    if (id == "accuracy.csv.missing_column")
        return tr("the header has no %1 column").arg(benchArg(m, "column"));
    if (id == "accuracy.csv.unknown_unit")
        return tr("cannot read the unit of column %1: use one of %2").arg(benchArg(m, "column"), benchArg(m, "units"));
    if (id == "accuracy.csv.duplicate_column")
        return tr("a second column for the same quantity: %1").arg(benchArg(m, "column"));
    if (id == "accuracy.csv.no_readings")
        return tr("the file has no readings");
    if (id == "accuracy.csv.wrong_cell_count")
        return tr("%1 cells where the header has %2").arg(benchArg(m, "count"), benchArg(m, "expected"));
    if (id == "accuracy.csv.not_a_number")
        return tr("\"%1\" is not a number").arg(benchArg(m, "text"));
    if (id == "accuracy.csv.unknown_direction")
        return tr("\"%1\" is not a direction: up or down").arg(benchArg(m, "text"));
    if (id == "accuracy.csv.not_a_cycle")
        return tr("\"%1\" is not a cycle: a whole number from 1").arg(benchArg(m, "text"));
    if (id == "accuracy.import.count_differs")
        return tr("the export has %1 readings, where the run's sequence has %2 stops").arg(benchArg(m, "count"), benchArg(m, "expected"));
    if (id == "accuracy.import.direction_differs")
        return tr("reading %1 was taken %2, where the run's stop %1 (at %3) was approached %4")
            .arg(benchArg(m, "index"), benchArg(m, "direction"), benchArg(m, "target"), benchArg(m, "expected"));
    if (id == "accuracy.import.target_differs")
        return tr("reading %1 is for target %2, where the run's stop %1 is at %3").arg(benchArg(m, "index"), benchArg(m, "target"), benchArg(m, "expected"));
    if (id == "accuracy.import.not_this_test_count")
        return tr("the sequence has %1 stops, where the test \"%3\" makes %2: it is the run of another test")
            .arg(benchArg(m, "count"), benchArg(m, "expected"), benchArg(m, "test"));
    if (id == "accuracy.import.not_this_test_stop")
        return tr("the sequence's stop %1 is at %2, approached %3 in cycle %4, where the test \"%8\" goes to %5, approached %6 in "
                  "cycle %7: it is the run of another test")
            .arg(benchArg(m, "stop"), benchArg(m, "target"), benchArg(m, "direction"), benchArg(m, "cycle"), benchArg(m, "expected"),
                 benchArg(m, "expected_direction"), benchArg(m, "expected_cycle"), benchArg(m, "test"));
    if (id == "accuracy.import.index_out_of_order")
        return tr("index \"%1\": the sequence's rows are numbered from 1 in order (expected %2)").arg(benchArg(m, "text"), benchArg(m, "expected"));
    if (id == "accuracy.log.positions_not_numbers")
        return tr("must hold numbers (mm)");
    if (id == "accuracy.log.positions_count")
        return tr("must hold one position per axis read, one or two (mm)");
    if (id == "accuracy.log.stop_out_of_order")
        return tr("is %1 where the run's next stop is %2: a log's stops come in order, each once").arg(benchArg(m, "stop"), benchArg(m, "expected"));
    if (id == "accuracy.log.measured_count")
        return tr("must hold as many positions as target_mm");
    if (id == "file.unreadable")
        return tr("cannot read %1: %2").arg(benchArg(m, "file"), benchArg(m, "detail"));
    if (id == "file.json_syntax")
        return tr("not valid JSON: %1").arg(benchArg(m, "detail"));
    if (id == "file.json_field")
        return benchArg(m, "detail");
    if (id == "file.csv.unterminated_quote")
        return tr("a quoted field is not closed");
    if (id == "file.csv.text_after_quote")
        return tr("text after a closing quote");
    if (id == "file.csv.semicolons")
        return tr("the file is separated by semicolons; BenchPilot reads commas and '.' as the decimal point");
    return {};
}

QString AccuracyBenchWords::compensation(const motion::msg::Message& m)
{
    const std::string& id = m.id;
    if (id == "compensation.too_few_points")
        return tr("%1 points: a fit needs at least %2 different positions").arg(benchArg(m, "count"), benchArg(m, "min"));
    if (id == "compensation.order_out_of_range")
        return tr("order %1: choose %2 to %3").arg(benchArg(m, "order"), benchArg(m, "min"), benchArg(m, "max"));
    if (id == "compensation.order_needs_more_points")
        return tr("order %1 needs at least %2 points; there are %3").arg(benchArg(m, "order"), benchArg(m, "min"), benchArg(m, "count"));
    if (id == "compensation.no_coefficients")
        return tr("the polynomial has no coefficients");
    if (id == "compensation.too_many_coefficients")
        return tr("%1 coefficients: at most %2 (order 5)").arg(benchArg(m, "count"), benchArg(m, "max"));
    if (id == "compensation.range_too_short")
        return tr("the range %1 to %2 is shorter than %3").arg(benchArg(m, "from"), benchArg(m, "to"), benchArg(m, "min"));
    if (id == "compensation.curve_too_large")
        return tr("the curve reaches %1 at %2, beyond ±%3").arg(benchArg(m, "value"), benchArg(m, "position"), benchArg(m, "max"));
    if (id == "compensation.curve_too_steep")
        return tr("the curve's slope is %1 µm/mm at %2, beyond %3").arg(benchArg(m, "value"), benchArg(m, "position"), benchArg(m, "max"));
    if (id == "compensation.too_few_table_points")
        return tr("%1 table points: at least %2").arg(benchArg(m, "count"), benchArg(m, "min"));
    if (id == "compensation.too_many_table_points")
        return tr("%1 table points: a device keeps at most %2").arg(benchArg(m, "count"), benchArg(m, "max"));
    if (id == "compensation.nominals_not_increasing")
        return tr("nominal %1 does not come after %2").arg(benchArg(m, "value"), benchArg(m, "previous"));
    if (id == "compensation.nominals_too_close")
        return tr("nominals %1 and %2 are closer than %3").arg(benchArg(m, "previous"), benchArg(m, "value"), benchArg(m, "min"));
    if (id == "compensation.backlash_with_directions")
        return tr("a backlash of %1 beside per-direction columns: put it in the columns").arg(benchArg(m, "value"));
    if (id == "compensation.linuxcnc.not_a_triplet")
        return tr("%1 values on a line where LinuxCNC expects three (nominal, forward, reverse); LinuxCNC would stop reading here")
            .arg(benchArg(m, "count"));
    if (id == "compensation.axis_not_compensable")
        return tr("axis %1 cannot carry a compensation").arg(benchArg(m, "axis"));
    if (id == "compensation.not_supported")
        return tr("this instrument keeps no compensation of its own");
    if (id == "compensation.model_invalid")
        return tr("the compensation cannot be applied (%1): %2").arg(benchArg(m, "field"), benchArg(m, "detail"));
    if (id == "compensation.upload_unreadable")
        return tr("the device answered COMP_UPLOAD with something unreadable");
    if (id == "compensation.not_installed")
        return tr("the device took every part of the compensation but did not install it");
    if (id == "compensation.read_unreadable")
        return tr("the device answered COMP_GET with something unreadable");
    if (id == "compensation.device_refused")
        return tr("The instrument refused: %1").arg(benchArg(m, "detail"));
    if (id == "compensation.none_on_device")
        return tr("The instrument holds no compensation for axis %1.").arg(benchArg(m, "axis"));
    return {};
}

QString AccuracyBenchWords::gauge(const motion::msg::Message& m)
{
    const std::string& id = m.id;
    if (id == "gauge.not_a_reading")
        return tr("The gauge on %1 answered \"%2\", which is not a reading such as +012.3456 mm.").arg(benchArg(m, "port"), benchArg(m, "text"));
    if (id == "gauge.unknown_unit")
        return tr("The gauge on %1 answered \"%2\" in a unit BenchPilot does not read (%3); it reads mm, µm and in.")
            .arg(benchArg(m, "port"), benchArg(m, "text"), benchArg(m, "unit"));
    if (id == "gauge.no_answer")
        return benchHas(m, "port") ? tr("The gauge on %1 did not answer within %2, asked twice.").arg(benchArg(m, "port"), benchArg(m, "timeout"))
                              : tr("The gauge did not answer.");
    if (id == "gauge.port_failed")
        return tr("Cannot open the gauge's port %1: %2").arg(benchArg(m, "port"), benchArg(m, "detail"));
    if (id == "gauge.link_lost")
        return tr("The gauge's port %1 went away: %2").arg(benchArg(m, "port"), benchArg(m, "detail"));
    if (id == "gauge.busy")
        return tr("The gauge on %1 is still answering the last request.").arg(benchArg(m, "port"));
    if (id == "gauge.no_transport")
        return tr("The gauge on %1 has no port to talk through.").arg(benchArg(m, "port"));
    if (id == "gauge.not_open")
        return tr("The gauge's port %1 is not open.").arg(benchArg(m, "port"));
    return {};
}

QString AccuracyBenchWords::source(const motion::msg::Message& m)
{
    const std::string& id = m.id;
    if (id == "accuracy.source.readback")
        return tr("readback");
    if (id == "accuracy.source.stage_grating")
        return tr("the stage's grating (readback)");
    if (id == "accuracy.source.analyzer_encoder")
        return tr("the analyzer's encoder (readback)");
    if (id == "accuracy.source.gauge")
        return tr("gauge on %1").arg(benchArg(m, "port"));
    if (id == "accuracy.source.manual")
        return tr("manual entry");
    if (id == "accuracy.source.recorded")  // a finished run's own record of its source
        return tr("as recorded: %1").arg(benchArg(m, "reference"));
    if (id == "accuracy.source.interferometer")
        return tr("laser interferometer (imported after the run)");
    if (id == "accuracy.source.camera_scale")
        return tr("camera %1 reading the glass scale along %2").arg(benchArg(m, "camera"), benchArg(m, "axis"));
    if (id == "accuracy.source.camera_plate")
        return tr("camera %1 reading the grid plate's dots").arg(benchArg(m, "camera"));
    return {};
}

QString AccuracyBenchWords::term(const std::string& id)
{
    // What a reading source is, where a sentence names its kind ("The gauge reads 1 axis at a time").
    if (id == "accuracy.source_kind.readback")
        return tr("readback");
    if (id == "accuracy.source_kind.gauge")
        return tr("gauge");
    if (id == "accuracy.source_kind.interferometer")
        return tr("interferometer");
    if (id == "accuracy.source_kind.manual")
        return tr("manual entry");
    if (id == "accuracy.source_kind.camera")
        return tr("camera");
    // The compensation requests, where a request error names them ("no reply to upload compensation …").
    if (id == "compensation.request.upload")
        return tr("upload compensation");
    if (id == "compensation.request.read")
        return tr("read compensation");
    if (id == "compensation.request.enable")
        return tr("enable compensation");
    if (id == "compensation.request.disable")
        return tr("disable compensation");
    return {};
}

} // namespace

QString accuracyBench(const motion::msg::Message& m) { return AccuracyBenchWords::accuracy(m); }
QString compensationBench(const motion::msg::Message& m) { return AccuracyBenchWords::compensation(m); }
QString gauge(const motion::msg::Message& m) { return AccuracyBenchWords::gauge(m); }
QString accuracyBenchTerm(const std::string& id) { return AccuracyBenchWords::term(id); }

} // namespace ui::words::areas
