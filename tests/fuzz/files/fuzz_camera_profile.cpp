// Fuzz target "camera-profile": the camera profile file's reader. Invariants: no crash;
// a refusal says where and what; an accepted profile writes out, reads back and writes
// out the same.
#include "fuzz_files.h"

#include "device/files/camera/camera_profile_file.h"

namespace {

void checkCameraProfile(std::string_view input)
{
    using namespace dev::files::camera;
    const CameraProfileRead r = cameraProfileFromJson(input, "fuzz.json");
    for (const motion::msg::Problem& p : r.problems())
        if (p.file != "fuzz.json" || p.line < 1 || p.message.id.empty())
            fuzzfiles::fail("a problem that does not say where or what: " + motion::msg::debugFormat(r.problems()));
    if (!r.ok() && r.problems().empty())
        fuzzfiles::fail("refused without a problem");
    if (!r.ok())
        return;
    const std::string once = cameraProfileToJson(*r);
    const CameraProfileRead again = cameraProfileFromJson(once, "again.json");
    if (!again.ok())
        fuzzfiles::fail("a written profile does not read back: " + motion::msg::debugFormat(again.problems()));
    if (cameraProfileToJson(*again) != once)
        fuzzfiles::fail("write → read → write changed the profile");
}

} // namespace

BP_FUZZ_FILE_TARGET({"camera-profile", [] { return fuzzfiles::exampleFiles(".camera-profile.json"); }, checkCameraProfile});
