// Fuzz target "machine_profile": the machine profile reader. Invariants: never crashes; an
// accepted text passes validate() and writes out to a text that reads back to the same text;
// a refusal names a place inside the text.
#include "fuzz_files.h"

#include "device/files/machine_profile_file.h"

#include <algorithm>

namespace {

std::vector<std::string> seeds()
{
    std::vector<std::string> s = fuzzfiles::exampleFiles(".machine.json");
    s.push_back(dev::files::writeMachineProfile(dev::files::defaultProfile(dev::proto::DeviceKind::Analyzer)));
    s.push_back(dev::files::writeMachineProfile(dev::files::defaultProfile(dev::proto::DeviceKind::Stage)));
    return s;
}

void check(std::string_view input)
{
    const auto r = dev::files::parseMachineProfile(input);
    if (!r.profile) {
        if (r.problems.empty())
            fuzzfiles::fail("a refusal without a problem");
        const long lines = 1 + std::count(input.begin(), input.end(), '\n');
        for (const auto& p : r.problems.list())
            if (p.line < 1 || p.line > lines || p.message.empty())
                fuzzfiles::fail("a problem outside the text or without a message: " + motion::msg::debugString(p.message));
        return;
    }
    if (!dev::files::validate(*r.profile).empty())
        fuzzfiles::fail("an accepted profile breaks its own rules");
    const std::string once = dev::files::writeMachineProfile(*r.profile);
    const auto again = dev::files::parseMachineProfile(once);
    if (!again.profile)
        fuzzfiles::fail("a written profile does not read back: " + again.problems.format("w"));
    if (dev::files::writeMachineProfile(*again.profile) != once)
        fuzzfiles::fail("write → read → write changed the profile");
}

} // namespace

BP_FUZZ_FILE_TARGET({"machine_profile", seeds, check});
