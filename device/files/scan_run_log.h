#pragma once
// The run log of a stitching scan: a JSON Lines journal that survives a crash,
// a pulled cable or a closed window, so a run resumes at its next tile.
//   line 1:  {"schema": "benchpilot.scan-run", "version": 1, "plan": NAME,
//             "fingerprint": HEX, "tiles": N}
//   then one line per tile taken, in the order taken:
//            {"tile": K, "label": …, "planned_mm": [x, y], "commanded_mm": […],
//             "measured_mm": […], "device_time_us": T, "settle_s": S
//             [, "image": FILE, "sha256": HEX]}   (with a camera: the tile's image)
// A line is appended (and flushed) once the tile's exposure has ended. A whole
// file is never rewritten, so a crash can only tear the last line: a last line
// without its newline that does not parse is dropped, anything else wrong is an
// error with its line and column. Plain C++ (fuzzed); docs/scan.md.
#include "device/files/json_fields.h"
#include "motion/records/position_record.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace dev::files::scan {

constexpr const char* kRunLogSchema = "benchpilot.scan-run";
constexpr int kRunLogVersion = 1;
constexpr const char* kRunLogFile = "scan-run.jsonl";

/// A tile's image as the run log names it: the file in the output folder and its SHA-256.
struct TileImageRef {
    std::string file;    ///< empty: the tile was taken without a camera
    std::string sha256;  ///< 64 lower-case hex digits
};

struct RunLog {
    std::string planName;
    std::uint64_t fingerprint = 0;
    int tiles = 0;
    std::vector<motion::PositionRecord> records;  ///< in the order taken
    std::vector<TileImageRef> images;             ///< beside records, one each
    bool tornTail = false;                        ///< a last line cut short by a crash was dropped
};

struct RunLogReadResult {
    std::optional<RunLog> log;
    dev::files::json::Problems problems;
};

std::string runLogHeader(const std::string& planName, std::uint64_t fingerprint, int tiles);
std::string runLogLine(const motion::PositionRecord& record, const TileImageRef& image = {});
RunLogReadResult parseRunLog(std::string_view text);

std::string fingerprintText(std::uint64_t fingerprint);  ///< 16 hex digits

} // namespace dev::files::scan
