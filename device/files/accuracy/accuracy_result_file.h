#pragma once
// The result of an axis accuracy test as JSON: schema "benchpilot.accuracy-result",
// version 1 (docs/accuracy.md, "Result file"). The overall figures in mm under
// "figures" with the keys A, A_up, A_down, E, E_up, E_down, M, R, R_up, R_down, B,
// B_mean (null where a unidirectional test has none), the per-target table beside
// them under "targets", the tolerances and verdicts. `benchpilot-cli accuracy
// analyze --json` prints exactly this document.
//
// A reader trusts only the table's primary columns (target, counts, means and
// standard deviations): it recomputes everything else and refuses a file whose
// figures disagree with its own table by more than a nanometre.
#include "device/files/accuracy/file_problem.h"
#include "motion/metrology/linear/iso230_2.h"
#include "motion/metrology/linear/tolerances.h"

#include <QString>

#include <optional>
#include <string>
#include <string_view>

namespace dev::files::accuracy {

constexpr const char* kAccuracyResultSchema = "benchpilot.accuracy-result";
constexpr int kAccuracyResultVersion = 1;
/// How far a figure written in a file may be from the one its table gives.
constexpr double kFigureAgreementMm = 1e-6;

struct AccuracyResult {
    std::string axis = "X";
    motion::metrology::Evaluation evaluation;     ///< must be ok() to be written
    motion::metrology::AxisTolerances tolerances;
    std::string reference;     ///< where the readings came from: "readback", "gauge", "interferometer", "manual", "camera"; "" unknown
    std::string readingsFile;  ///< the readings CSV it was evaluated from, if any
    std::string createdUtc;    ///< ISO 8601, if known
};

/// The JSON keys of the overall figures, in the order they are written.
const std::vector<std::string>& figureKeys();
/// A figure by its key ("A_up"), empty where it does not apply.
std::optional<double> figureByKey(const motion::metrology::Figures& f, const std::string& key);

std::string accuracyResultToJson(const AccuracyResult& result);

struct AccuracyResultRead {
    std::optional<AccuracyResult> result;
    motion::msg::Problems problems;
};
/// Plain C++: what the fuzzer drives.
AccuracyResultRead accuracyResultFromJson(std::string_view text, std::string_view fileName);

AccuracyResultRead loadAccuracyResultFile(const QString& path);
bool saveAccuracyResultFile(const QString& path, const AccuracyResult& result, motion::msg::Message* error);

} // namespace dev::files::accuracy
