// Fuzz target "tuning": the reader of tuning results (docs/tuning_results.md).
// Invariants: it never crashes; a refusal says where; an accepted document
// writes out, reads back and writes out to the same text.
#include "fuzz_files.h"

#include "device/files/tuning_file.h"

#include <algorithm>

namespace {

std::vector<std::string> seeds()
{
    std::vector<std::string> s = fuzzfiles::exampleFiles(".tuning.json");
    motion::control::TuningResult r;
    r.target = "fopdt:K=1,tau=1,L=0.1";
    r.method = "ultimate-gain";
    r.controlPeriodS = 1e-4;
    r.ku = 16;
    r.tuS = 0.38;
    r.step = 1;
    r.envelope = {3, 3, 600};
    r.trials = {{0.1, 0, 0, "no oscillation"}, {16, 1.0, 0.38, "sustained"}};
    s.push_back(dev::files::tuningToJson(r));
    return s;
}

void check(std::string_view input)
{
    const dev::files::TuningRead r = dev::files::tuningFromJson(input);
    if (!r.result) {
        if (r.problems.empty())
            fuzzfiles::fail("a refusal without a problem");
        const long lines = 1 + std::count(input.begin(), input.end(), '\n');
        for (const auto& p : r.problems.list())
            if (p.line < 0 || p.line > lines || p.message.empty())
                fuzzfiles::fail("a problem outside the text or without a message: " + r.problems.format("fuzz.tuning.json"));
        return;
    }
    const std::string once = dev::files::tuningToJson(*r.result);
    const dev::files::TuningRead again = dev::files::tuningFromJson(once);
    if (!again.result)
        fuzzfiles::fail("a written document does not read back: " + again.problems.format("again.json"));
    if (dev::files::tuningToJson(*again.result) != once)
        fuzzfiles::fail("write → read → write changed the document");
}

} // namespace

BP_FUZZ_FILE_TARGET({"tuning", seeds, check});
