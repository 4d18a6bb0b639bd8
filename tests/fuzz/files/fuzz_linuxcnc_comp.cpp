// Fuzz target "linuxcnc-comp": the reader of LinuxCNC compensation files (both
// types). Invariants: no crash; every problem names the file; an accepted file
// writes out in the same type and reads back to the same corrections, to the
// nanometre the format keeps.
#include "fuzz_files.h"

#include "device/files/accuracy/compensation/compensation_exports.h"

#include <cmath>

namespace {

std::vector<std::string> seeds()
{
    return fuzzfiles::exampleFiles(".comp");
}

void check(std::string_view input)
{
    using namespace dev::files::accuracy;
    for (auto type : {LinuxcncCompType::ActualPositions, LinuxcncCompType::Corrections}) {
        const LinuxcncRead r = linuxcncFromText(input, "fuzz.comp", type);
        for (const motion::msg::Problem& p : r.problems)
            if (p.file != "fuzz.comp" || p.message.id.empty())
                fuzzfiles::fail("a problem that does not say where or what: " + debugFormat(r.problems));
        if (!r.model)
            continue;
        const LinuxcncRead again = linuxcncFromText(linuxcncCompensation(*r.model, type), "again.comp", type);
        if (!again.model || again.model->table.size() != r.model->table.size())
            fuzzfiles::fail("a written table does not read back: " + debugFormat(again.problems));
        for (std::size_t i = 0; i < r.model->table.size(); ++i) {
            const auto &a = r.model->table[i], &b = again.model->table[i];
            const double tolUm = 1.1e-3 + 1e-9 * std::fabs(a.nominalMm) * 1e3;
            if (std::fabs(a.nominalMm - b.nominalMm) > 0.6e-6 || std::fabs(a.correctionUpUm - b.correctionUpUm) > tolUm
                || std::fabs(a.correctionDownUm - b.correctionDownUm) > tolUm)
                fuzzfiles::fail("write → read changed point " + std::to_string(i));
        }
    }
}

} // namespace

BP_FUZZ_FILE_TARGET({"linuxcnc-comp", seeds, check});
