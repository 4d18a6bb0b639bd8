// Fuzz target "error-curve": the position_mm,error_um reader and the fits made from
// what it accepts. Invariants: no crash; problems name the file; a fit's chosen
// order is one of the table's, and available.
#include "fuzz_files.h"

#include "device/files/accuracy/error_curve_csv.h"

namespace {

std::vector<std::string> seeds()
{
    return fuzzfiles::exampleFiles(".error-curve.csv");
}

void check(std::string_view input)
{
    using namespace dev::files::accuracy;
    const ErrorCurveRead r = errorCurveFromCsv(input, "fuzz.csv");
    for (const motion::msg::Problem& p : r.problems)
        if (p.file != "fuzz.csv" || p.message.id.empty())
            fuzzfiles::fail("a problem that does not say where or what: " + debugFormat(r.problems));
    if (!r.ok())
        return;
    const auto fit = motion::metrology::fitPolynomials(r.points);
    if (fit.chosenOrder != 0 && (!fit.chosen() || !fit.chosen()->available))
        fuzzfiles::fail("a chosen order that is not available");
}

} // namespace

BP_FUZZ_FILE_TARGET({"error-curve", seeds, check});
