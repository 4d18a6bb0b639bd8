// Fuzz target "accuracy-test": the reader of accuracy test definitions
// (docs/accuracy.md). Invariants: it never crashes; a refusal says where (the
// file's name, a line); an accepted test writes out, reads back and writes out to
// the same text, and its stops can be planned.
#include "fuzz_files.h"

#include "device/files/accuracy/accuracy_test_file.h"
#include "motion/metrology/linear/run_sequence.h"

namespace {

std::vector<std::string> seeds()
{
    return fuzzfiles::exampleFiles(".accuracy-test.json");
}

void check(std::string_view input)
{
    using namespace dev::files::accuracy;
    const AccuracyTestRead r = accuracyTestFromJson(input, "fuzz.accuracy-test.json");
    for (const motion::msg::Problem& p : r.problems)
        if (p.file != "fuzz.accuracy-test.json" || p.line < 1 || p.message.id.empty())
            fuzzfiles::fail("a problem that does not say where or what: " + debugFormat(r.problems));
    if (!r.test) {
        if (!hasErrors(r.problems))
            fuzzfiles::fail("refused without an error");
        return;
    }
    const std::string once = accuracyTestToJson(*r.test);
    const AccuracyTestRead again = accuracyTestFromJson(once, "again.json");
    if (!again.test)
        fuzzfiles::fail("a written test does not read back: " + debugFormat(again.problems));
    if (accuracyTestToJson(*again.test) != once)
        fuzzfiles::fail("write → read → write changed the test");
    if (const auto* axis = std::get_if<motion::metrology::AxisTest>(&*r.test))
        if (motion::metrology::runSequence(*axis).size() != motion::metrology::readingCount(*axis))
            fuzzfiles::fail("an accepted axis test does not plan all its readings");
}

} // namespace

BP_FUZZ_FILE_TARGET({"accuracy-test", seeds, check});
