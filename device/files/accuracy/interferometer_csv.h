#pragma once
// A laser interferometer's capture, imported after the run (docs/accuracy.md,
// "Interferometer import"). The interferometer's software captures on its own
// (usually when the beam has been still for a while); BenchPilot cannot read it
// live. So:
//
//  1. the run writes its target sequence with times (`*.targets.csv`):
//       index,target_mm,direction,cycle,time_s,settled
//     one row per stop in the order visited, time_s the device clock since the
//     run began when the axis had settled there;
//  2. the operator captures with the interferometer software and exports CSV;
//  3. the import matches the export's readings to the sequence in order: row k of
//     the export is stop k. The export needs a header and one value column:
//       measured_<unit> | position_<unit> | reading_<unit>   (where the axis is), or
//       deviation_<unit> | error_<unit>                       (measured − target);
//     units by suffix (mm, um, µm, nm, m, in). Optional columns are checked:
//       target_<unit>  must be the stop's target to 1 µm,
//       direction      up/down (also forward/backward, fwd/bwd, +/-) must be the stop's.
//     Other columns are ignored. A count that differs from the sequence's, or a
//     direction or target that does not match, is an error naming the file, line
//     and column, and nothing is imported.
//
// Plain C++ (fuzzed).
#include "device/files/accuracy/file_problem.h"
#include "motion/metrology/linear/axis_test.h"
#include "motion/metrology/readings.h"

#include <QString>

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace dev::files::accuracy {

/// One stop of a run, as the target sequence keeps it.
struct SequenceStop {
    int index = 0;           ///< 1-based, in the order visited
    double targetMm = 0;
    motion::metrology::Direction direction = motion::metrology::Direction::Up;
    int cycle = 1;
    double timeS = 0;        ///< device clock since the run began, when the axis had settled
    bool settled = true;
};

std::string targetSequenceCsv(const std::vector<SequenceStop>& stops);

struct SequenceRead {
    std::vector<SequenceStop> stops;
    motion::msg::Problems problems;
    bool ok() const { return !hasErrors(problems); }
};
SequenceRead targetSequenceFromCsv(std::string_view text, std::string_view fileName);

struct InterferometerImport {
    std::vector<motion::metrology::Reading> readings;  ///< one per stop, in the sequence's order
    motion::msg::Problems problems;
    bool ok() const { return !hasErrors(problems); }
};
/// The export matched to the sequence, all or nothing.
InterferometerImport importInterferometerCsv(std::string_view exportText, std::string_view fileName,
                                             const std::vector<SequenceStop>& sequence);

/// Whether `sequence` is the run of `test`: as many stops, each at the same target
/// (within the import's match of targets), direction and cycle. Empty when it is;
/// else why not (accuracy.import.not_this_test_count / not_this_test_stop, the first
/// stop that differs). A capture evaluated against another test would be filed
/// under that test's axis and tolerances.
std::optional<motion::msg::Message> sequenceMismatch(const std::vector<SequenceStop>& sequence, const motion::metrology::AxisTest& test);

SequenceRead loadTargetSequence(const QString& path);
bool saveTargetSequence(const QString& path, const std::vector<SequenceStop>& stops, motion::msg::Message* error);
InterferometerImport loadInterferometerExport(const QString& path, const std::vector<SequenceStop>& sequence);

} // namespace dev::files::accuracy
