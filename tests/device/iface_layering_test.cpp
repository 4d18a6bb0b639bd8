// The instrument interface's layering, checked on the sources: runners, the telemetry
// hub, the interface itself and the screens never name a backend ("the runners do not
// know which backend they drive"), and the simulator's room holds only the
// protocol and the machine model. CMake enforces the link direction; this catches an
// include of a backend header, which would compile either way.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

/// Files under `dir` (relative to the source tree) whose code (comments left out: they
/// may point at a backend as an example) contains any of `needles`, once every text in
/// `allowed` is taken out.
std::vector<std::string> filesMentioning(const std::string& dir, const std::vector<std::string>& needles,
                                         const std::vector<std::string>& allowed = {})
{
    std::vector<std::string> hits;
    const fs::path root = fs::path(BP_SOURCE_DIR) / dir;
    EXPECT_TRUE(fs::is_directory(root)) << root;
    for (const auto& entry : fs::recursive_directory_iterator(root)) {
        const auto ext = entry.path().extension();
        if (!entry.is_regular_file() || (ext != ".h" && ext != ".cpp"))
            continue;
        std::ifstream in(entry.path());
        std::string line, code;
        while (std::getline(in, line))
            code += line.substr(0, line.find("//")) + "\n";
        for (const auto& a : allowed)
            for (std::size_t at = code.find(a); at != std::string::npos; at = code.find(a, at))
                code.erase(at, a.size());
        for (const auto& n : needles)
            if (code.find(n) != std::string::npos) {
                hits.push_back(entry.path().string() + " (" + n + ")");
                break;
            }
    }
    return hits;
}

std::string list(const std::vector<std::string>& v)
{
    std::string s;
    for (const auto& x : v)
        s += "\n  " + x;
    return s;
}

} // namespace

TEST(IfaceLayering, NothingAboveTheBackendsNamesOne)
{
    const std::vector<std::string> backend = {"\"device/backends/", "BenchPilotClient", "ProtocolPathClient", "ProtocolTuningClient",
                                              "GrblClient", "GrblPathClient", "ProtocolProbe"};
    // The wording layer words each backend's vocabulary: GRBL's error and alarm meanings are a
    // plain data table it may read (the words, not the backend).
    const std::vector<std::string> vocabulary = {"\"device/backends/grbl/grbl_codes.h\""};
    for (const char* dir : {"device/client", "device/jobs", "device/telemetry", "widgets"}) {
        const auto hits = filesMentioning(dir, backend, vocabulary);
        EXPECT_TRUE(hits.empty()) << dir << " names a backend:" << list(hits);
    }
}

TEST(IfaceLayering, TheSimulatorsRoomHoldsTheProtocolAndTheMachineModelOnly)
{
    const std::vector<std::string> outside = {"\"device/client/", "\"device/backends/", "\"device/link/", "\"device/jobs/",
                                              "\"device/telemetry/", "\"device/files/", "#include <Q"};
    // GRBL's protocol constants: header only and dependency free (its own comment says
    // so), the GRBL counterpart of device/protocol/ that the simulator's GRBL personality
    // speaks. It would sit better in device/protocol/; until it moves it is the one exception.
    const auto hits = filesMentioning("device/sim", outside, {"\"device/backends/grbl/grbl_protocol.h\""});
    EXPECT_TRUE(hits.empty()) << "device/sim reaches outside protocol/ and motion/:" << list(hits);
    const auto protocolHits = filesMentioning("device/protocol", {"\"device/sim/", "\"device/client/", "#include <Q", "\"motion/"});
    EXPECT_TRUE(protocolHits.empty()) << "device/protocol is not plain:" << list(protocolHits);
}
