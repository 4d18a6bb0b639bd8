#pragma once
// The accuracy examples under resources/examples/ and the ones derived from them.
// The derived examples (result, compensation table, exports) are what BenchPilot's
// writers make of the interferometer readings example; a test compares them, and
// BP_REGENERATE_EXAMPLES=1 writes them again after a deliberate format change.
#include "device/files/accuracy/accuracy_result_file.h"
#include "device/files/accuracy/compensation/compensation_exports.h"
#include "device/files/accuracy/compensation/compensation_file.h"
#include "device/files/accuracy/error_curve_csv.h"
#include "device/files/accuracy/readings_csv.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

namespace accuracyexamples {

inline std::string path(const std::string& name)
{
    return std::string(BP_SOURCE_DIR) + "/resources/examples/" + name;
}

inline std::string read(const std::string& name)
{
    std::ifstream f(path(name), std::ios::binary);
    std::stringstream s;
    s << f.rdbuf();
    return s.str();
}

inline const char* kReadings = "stage-x-interferometer.readings.csv";

inline dev::files::accuracy::AnalyzedReadings interferometerRun()
{
    return dev::files::accuracy::analyzeReadingsCsv(read(kReadings), kReadings);
}

/// File name → the text BenchPilot's writers make of the readings example.
inline std::map<std::string, std::string> derivedExamples()
{
    using namespace dev::files::accuracy;
    using namespace motion::metrology;
    const AnalyzedReadings a = interferometerRun();
    std::map<std::string, std::string> out;
    AccuracyResult result;
    result.axis = "X";
    result.evaluation = a.evaluation;
    result.tolerances.rMm = 0.01;
    result.reference = "interferometer";
    result.readingsFile = kReadings;
    out["stage-x-interferometer.accuracy-result.json"] = accuracyResultToJson(result);
    out["stage-x-interferometer.error-curve.csv"] = errorCurveCsv(a.evaluation);

    const CompensationModel table = tableModel("X", a.evaluation, true);
    out["stage-x-table.compensation.json"] = compensationToJson({table, std::nullopt, "stage-x-interferometer.accuracy-result.json, per direction"});
    out["stage-x-table.compensation.csv"] = compensationCsv(table);
    out["stage-x-table.linuxcnc-type0.comp"] = linuxcncCompensation(table, LinuxcncCompType::ActualPositions);
    out["stage-x-table.linuxcnc-type1.comp"] = linuxcncCompensation(table, LinuxcncCompType::Corrections);

    const FitTable fit = fitPolynomials(fitPointsOf(a.evaluation));
    const PolynomialFit& f = *fit.chosen();
    CompensationFile poly{polynomialModel("X", f.polynomial, 0, 100, backlashUmFrom(a.evaluation)),
                          FitRecord{f.order, f.sseUm2, f.r2, f.adjustedR2, static_cast<int>(f.points), false},
                          "stage-x-interferometer.accuracy-result.json, x̄i fitted"};
    out["stage-x-fit.compensation.json"] = compensationToJson(poly);
    return out;
}

/// Compares (or, with BP_REGENERATE_EXAMPLES=1, writes) every derived example.
inline void checkDerivedExamples()
{
    const bool regenerate = std::getenv("BP_REGENERATE_EXAMPLES") != nullptr;
    for (const auto& [name, text] : derivedExamples()) {
        if (regenerate) {
            std::ofstream(path(name), std::ios::binary) << text;
            continue;
        }
        EXPECT_EQ(read(name), text) << name << " is not what the writers make of " << kReadings;
    }
}

} // namespace accuracyexamples
