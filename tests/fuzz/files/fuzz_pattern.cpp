// Fuzz target "pattern": the pattern file reader. Invariants: never crashes; an accepted text
// plans into segments and writes out to a text that reads back to the same pattern (and the
// same text); a refusal names a place inside the text.
#include "fuzz_files.h"

#include "device/files/pattern_file.h"

#include <algorithm>

namespace {

std::vector<std::string> seeds()
{
    std::vector<std::string> s = fuzzfiles::exampleFiles(".pattern.json");
    for (motion::plans::PatternShape shape : motion::plans::kAllShapes) {
        motion::plans::Pattern p;
        p.shape = shape;
        p.zMm = 3;
        s.push_back(dev::files::writePattern(p));
    }
    return s;
}

void check(std::string_view input)
{
    const auto r = dev::files::parsePattern(input);
    if (!r.pattern) {
        if (r.problems.empty())
            fuzzfiles::fail("a refusal without a problem");
        const long lines = 1 + std::count(input.begin(), input.end(), '\n');
        for (const auto& p : r.problems.list())
            if (p.line < 1 || p.line > lines || p.message.empty())
                fuzzfiles::fail("a problem outside the text or without a message: " + motion::msg::debugString(p.message));
        return;
    }
    if (motion::plans::plan(*r.pattern).empty())
        fuzzfiles::fail("an accepted pattern plans no segments");
    const std::string once = dev::files::writePattern(*r.pattern);
    const auto again = dev::files::parsePattern(once);
    if (!again.pattern)
        fuzzfiles::fail("a written pattern does not read back: " + again.problems.format("w"));
    if (dev::files::writePattern(*again.pattern) != once)
        fuzzfiles::fail("write → read → write changed the pattern");
}

} // namespace

BP_FUZZ_FILE_TARGET({"pattern", seeds, check});
