#pragma once
// The run log of an accuracy run: a JSON Lines journal, appended and flushed after
// every reading, so a run that stopped for any reason (abort, E-stop, a lost link, a
// crash) continues at its next reading and never reads a stop twice
// (docs/accuracy.md, "Run log").
//   line 1:  {"schema": "benchpilot.accuracy-run", "version": 1, "test": NAME,
//             "kind": "axis"|"xy-line", "fingerprint": HEX, "stops": N, "source": "gauge"}
//   then one line per stop read, in the order of the run:
//            {"stop": K, "cycle": C, "direction": "up"|"down", "target_mm": [..],
//             "measured_mm": [..] or null (an interferometer's: it comes with the import),
//             "settled": true, "device_time_us": T, "time_s": S}
// target_mm and measured_mm hold one position per axis read (X, or X and Y). A whole
// file is never rewritten, so a crash can only tear the last line: a last line
// without its newline that does not parse is dropped; anything else wrong is an error
// with its line and column. Plain C++ (fuzzed).
#include "device/files/json_fields.h"
#include "motion/metrology/readings.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace dev::files::accuracy {

constexpr const char* kRunLogSchema = "benchpilot.accuracy-run";
constexpr int kRunLogVersion = 1;
constexpr const char* kRunLogFile = "accuracy-run.jsonl";

struct RunLogEntry {
    int stop = 0;                           ///< 0-based index in the run's order
    int cycle = 1;
    motion::metrology::Direction direction = motion::metrology::Direction::Up;
    std::vector<double> targetMm;
    std::optional<std::vector<double>> measuredMm;  ///< empty: read later (an interferometer)
    bool settled = true;
    std::uint64_t deviceTimeUs = 0;
    double timeS = 0;                       ///< device seconds since the run began
};

struct RunLogHeader {
    std::string test;
    std::string kind = "axis";
    std::uint64_t fingerprint = 0;
    int stops = 0;
    std::string source;
};

struct RunLog {
    RunLogHeader header;
    std::vector<RunLogEntry> entries;
    bool tornTail = false;
};

struct RunLogRead {
    std::optional<RunLog> log;
    dev::files::json::Problems problems;
};

std::string runLogHeader(const RunLogHeader& h);
std::string runLogLine(const RunLogEntry& e);
/// Entries must come in stop order 0, 1, 2, …: a gap or a repeat is an error (the
/// runner never reads a stop twice).
RunLogRead parseRunLog(std::string_view text);

/// 64-bit FNV-1a of a text: what a header's fingerprint is made of.
std::uint64_t fingerprintOf(std::string_view text);
std::string fingerprintText(std::uint64_t fingerprint);  ///< 16 hex digits

} // namespace dev::files::accuracy
