// Fuzz target "compensation": the reader of compensation files, and the exports
// made from what it accepts. Invariants: no crash; a refusal says where; an
// accepted file writes out, reads back and writes out the same; its LinuxCNC export
// reads back as a valid table.
#include "fuzz_files.h"

#include "device/files/accuracy/compensation/compensation_exports.h"
#include "device/files/accuracy/compensation/compensation_file.h"

namespace {

std::vector<std::string> seeds()
{
    return fuzzfiles::exampleFiles(".compensation.json");
}

void check(std::string_view input)
{
    using namespace dev::files::accuracy;
    const CompensationRead r = compensationFromJson(input, "fuzz.json");
    for (const motion::msg::Problem& p : r.problems)
        if (p.file != "fuzz.json" || p.line < 1 || p.message.id.empty())
            fuzzfiles::fail("a problem that does not say where or what: " + debugFormat(r.problems));
    if (!r.compensation) {
        if (r.problems.empty())
            fuzzfiles::fail("refused without a problem");
        return;
    }
    const std::string once = compensationToJson(*r.compensation);
    const CompensationRead again = compensationFromJson(once, "again.json");
    if (!again.compensation)
        fuzzfiles::fail("a written compensation does not read back: " + debugFormat(again.problems));
    if (compensationToJson(*again.compensation) != once)
        fuzzfiles::fail("write → read → write changed the compensation");
    const auto& m = r.compensation->model;
    const LinuxcncRead lc = linuxcncFromText(linuxcncCompensation(m, LinuxcncCompType::Corrections), "x.comp", LinuxcncCompType::Corrections, m.axis);
    // Corrections beyond ±10 mm are refused by the reader (a typo, not a compensation):
    // a polynomial far outside that is a valid file whose export a device would refuse too.
    for (const motion::msg::Problem& p : lc.problems)
        if (p.isError() && p.message.id != "accuracy.value_above" && p.message.id != "accuracy.value_below")
            fuzzfiles::fail("its LinuxCNC export does not read back: " + debugFormat(lc.problems));
}

} // namespace

BP_FUZZ_FILE_TARGET({"compensation", seeds, check});
