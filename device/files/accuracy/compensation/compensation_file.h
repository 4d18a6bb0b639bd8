#pragma once
// An axis's compensation as a file the host keeps: schema "benchpilot.compensation",
// version 1 (docs/accuracy.md, "Compensation file"). Either the error polynomial
// (coefficients in µm, c0 first, position in mm, with the range it was fitted
// on) or a table of corrections per nominal position (one column, or one per
// direction), plus the backlash. How a fit was chosen travels beside it for the
// record; the reader validates the model as a device would.
#include "device/files/accuracy/file_problem.h"
#include "motion/metrology/compensation/compensation_model.h"
#include "motion/metrology/compensation/polynomial_fit.h"

#include <QString>

#include <optional>
#include <string>
#include <string_view>

namespace dev::files::accuracy {

constexpr const char* kCompensationSchema = "benchpilot.compensation";
constexpr int kCompensationVersion = 1;

/// How the polynomial was fitted (seed 002's table row of the order used).
struct FitRecord {
    int order = 0;
    double sseUm2 = 0;
    double r2 = 0;
    double adjustedR2 = 0;
    int points = 0;
    bool chosenByOperator = false;
};

struct CompensationFile {
    motion::metrology::CompensationModel model;
    std::optional<FitRecord> fit;
    std::string source;   ///< free text: the result file or test it came from
};

std::string compensationToJson(const CompensationFile& c);

struct CompensationRead {
    std::optional<CompensationFile> compensation;
    motion::msg::Problems problems;
};
/// Plain C++: what the fuzzer drives.
CompensationRead compensationFromJson(std::string_view text, std::string_view fileName);

CompensationRead loadCompensationFile(const QString& path);
bool saveCompensationFile(const QString& path, const CompensationFile& c, motion::msg::Message* error);

} // namespace dev::files::accuracy
