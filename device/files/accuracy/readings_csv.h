#pragma once
// The readings of an accuracy test as CSV (docs/accuracy.md, "Readings CSV"):
//
//   target_mm,direction,cycle,measured_mm
//   10,up,1,10.0012
//
// A header names the columns; the four above are required in any order, other
// columns are allowed and ignored (a runner adds time_s, deviation_um, settled).
// target and measured may be in another length unit, said by the column name's
// suffix: _mm, _um (or _µm), _nm, _m, _in. direction is up or down (a
// unidirectional test has only up); cycle is a whole number from 1.
#include "device/files/accuracy/file_problem.h"
#include "motion/metrology/linear/iso230_2.h"
#include "motion/metrology/readings.h"

#include <QString>

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace dev::files::accuracy {

struct ReadingsRead {
    std::vector<motion::metrology::Reading> readings;
    std::vector<int> lines;   ///< the line of each reading, for placing later problems
    motion::msg::Problems problems;
    bool ok() const { return !hasErrors(problems); }
};

/// Plain C++: what the fuzzer drives. Every problem at once: a missing column, a
/// unit it cannot read, a row with the wrong number of cells, a number that is not
/// one or not finite, a direction other than up/down, a cycle that is not a whole
/// number from 1.
ReadingsRead readingsFromCsv(std::string_view text, std::string_view fileName);

/// The evaluation's own problems (paths "readings[k]…") placed at the line and
/// column of the reading they name: too few cycles, a duplicate, a missing direction.
motion::msg::Problems placeReadingProblems(const motion::msg::Problems& found, const ReadingsRead& read, std::string_view fileName);

/// Read and evaluate in one: what `benchpilot-cli accuracy analyze` does.
struct AnalyzedReadings {
    ReadingsRead read;
    motion::metrology::Evaluation evaluation;
    motion::msg::Problems problems;   ///< the reader's and the evaluation's, placed
    bool ok() const { return !hasErrors(problems); }
};
AnalyzedReadings analyzeReadingsCsv(std::string_view text, std::string_view fileName);

/// target_mm,direction,cycle,measured_mm,deviation_um with CRLF line ends; the
/// numbers as the shortest text that reads back to the same double.
std::string readingsToCsv(const std::vector<motion::metrology::Reading>& readings);

/// Whole files: read with the file's name in every problem; written all or nothing.
ReadingsRead loadReadingsCsv(const QString& path);
bool saveReadingsCsv(const QString& path, const std::vector<motion::metrology::Reading>& readings, motion::msg::Message* error);

} // namespace dev::files::accuracy
