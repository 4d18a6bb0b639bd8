// Fuzz target "accuracy-readings": the readings CSV reader and the evaluation
// behind `accuracy analyze`. Invariants: no crash; every problem names the file;
// accepted readings write out and read back to the same numbers; an evaluation
// without errors has A ≥ R↑/… as ISO 230-2's definitions imply.
#include "fuzz_files.h"

#include "device/files/accuracy/readings_csv.h"

namespace {

std::vector<std::string> seeds()
{
    return fuzzfiles::exampleFiles(".readings.csv");
}

void check(std::string_view input)
{
    using namespace dev::files::accuracy;
    const AnalyzedReadings a = analyzeReadingsCsv(input, "fuzz.csv");
    for (const motion::msg::Problem& p : a.problems)
        if (p.file != "fuzz.csv" || p.message.id.empty())
            fuzzfiles::fail("a problem that does not say where or what: " + debugFormat(a.problems));
    if (!a.read.ok())
        return;
    if (a.read.lines.size() != a.read.readings.size())
        fuzzfiles::fail("a reading without its line");
    const ReadingsRead again = readingsFromCsv(readingsToCsv(a.read.readings), "again.csv");
    if (!again.ok() || again.readings.size() != a.read.readings.size())
        fuzzfiles::fail("written readings do not read back: " + debugFormat(again.problems));
    for (std::size_t i = 0; i < again.readings.size(); ++i) {
        const auto &x = a.read.readings[i], &y = again.readings[i];
        if (x.targetMm != y.targetMm || x.measuredMm != y.measuredMm || x.cycle != y.cycle || x.direction != y.direction)
            fuzzfiles::fail("write → read changed reading " + std::to_string(i));
    }
    if (a.ok()) {
        const auto& f = a.evaluation.figures;
        if (f.aUpMm < f.rUpMm * (1 - 1e-12) - 1e-15 || (f.aMm && *f.aMm < *f.rDownMm * (1 - 1e-12) - 1e-15))
            fuzzfiles::fail("accuracy below repeatability");
    }
}

} // namespace

BP_FUZZ_FILE_TARGET({"accuracy-readings", seeds, check});
