// Fuzz target "accuracy-result": the reader of ISO 230-2 result files. Invariants:
// no crash; a refusal says where; an accepted result writes out, reads back and
// writes out to the same text (its figures recomputed from its own table).
#include "fuzz_files.h"

#include "device/files/accuracy/accuracy_result_file.h"
#include "device/files/accuracy/readings_csv.h"

namespace {

std::vector<std::string> seeds()
{
    std::vector<std::string> s = fuzzfiles::exampleFiles(".accuracy-result.json");
    // A unidirectional one too: its nulls are a case of their own.
    for (const std::string& csv : fuzzfiles::exampleFiles(".readings.csv")) {
        const auto a = dev::files::accuracy::analyzeReadingsCsv(csv, "seed.csv");
        if (!a.ok())
            continue;
        dev::files::accuracy::AccuracyResult r;
        r.evaluation = a.evaluation;
        r.tolerances = motion::metrology::analyzerTolerances('X');
        s.push_back(dev::files::accuracy::accuracyResultToJson(r));
    }
    return s;
}

void check(std::string_view input)
{
    using namespace dev::files::accuracy;
    const AccuracyResultRead r = accuracyResultFromJson(input, "fuzz.json");
    for (const motion::msg::Problem& p : r.problems)
        if (p.file != "fuzz.json" || p.line < 1 || p.message.id.empty())
            fuzzfiles::fail("a problem that does not say where or what: " + debugFormat(r.problems));
    if (!r.result) {
        if (r.problems.empty())
            fuzzfiles::fail("refused without a problem");
        return;
    }
    const std::string once = accuracyResultToJson(*r.result);
    const AccuracyResultRead again = accuracyResultFromJson(once, "again.json");
    if (!again.result)
        fuzzfiles::fail("a written result does not read back: " + debugFormat(again.problems));
    if (accuracyResultToJson(*again.result) != once)
        fuzzfiles::fail("write → read → write changed the result");
}

} // namespace

BP_FUZZ_FILE_TARGET({"accuracy-result", seeds, check});
