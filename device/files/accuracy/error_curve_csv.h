#pragma once
// An error curve as CSV, the input of `compensation fit` when it is not a result
// file: position_mm,error_um (docs/accuracy.md, "Error curve CSV"). Other columns
// are allowed and ignored; other length units by the column name's suffix as in
// the readings CSV. The writer gives the mean deviations x̄i of an evaluation, with
// the per-direction means beside them.
#include "device/files/accuracy/file_problem.h"
#include "motion/metrology/linear/iso230_2.h"
#include "motion/metrology/compensation/polynomial_fit.h"

#include <string>
#include <string_view>
#include <vector>

namespace dev::files::accuracy {

struct ErrorCurveRead {
    std::vector<motion::metrology::FitPoint> points;
    motion::msg::Problems problems;
    bool ok() const { return !hasErrors(problems); }
};
/// Plain C++: what the fuzzer drives.
ErrorCurveRead errorCurveFromCsv(std::string_view text, std::string_view fileName);

/// position_mm,error_um,error_up_um,error_down_um (the last empty when unidirectional).
std::string errorCurveCsv(const motion::metrology::Evaluation& e);

/// The points a fit uses from an evaluation: each target's x̄i in µm.
std::vector<motion::metrology::FitPoint> fitPointsOf(const motion::metrology::Evaluation& e);

} // namespace dev::files::accuracy
