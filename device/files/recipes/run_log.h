#pragma once
// The run log of a recipe run (benchpilot.run-log, docs/recipes.md): JSON
// lines, appended and synced to disk before the machine is told to do what a
// line announces, so after a crash, a pulled cable or SIGKILL the log says
// exactly how far the run got:
//   run     header: recipe, plan fingerprint, number of ops, plunger at the start
//   start   an op (a well visit) begins: the tip is about to move there
//   pump    its first plunger move is about to be sent (liquid may move from here on)
//   done    the op finished; the tip is back up
//   skip    the operator decided an interrupted op counts as done
//   redo    the operator decided an interrupted op is done again
//   stop    the run stopped (abort, link lost, refusal), with the reason
//   resume  a later run continues this log
//   finished
// An op with "start" but no "pump" moved no liquid and is simply done again on
// resume; one with "pump" but no "done" was interrupted mid-dispense and the
// operator decides. The reader is plain C++ (fuzzed); the writer syncs with fsync.
#include "device/files/json_fields.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace dev::files::plates {

constexpr const char* kRunLogSchema = "benchpilot.run-log";
constexpr int kRunLogVersion = 1;

enum class OpState { NotStarted, Started, Interrupted, Done, Skipped };
/// Done or skipped: nothing more is owed to this op.
inline bool isClosed(OpState s) { return s == OpState::Done || s == OpState::Skipped; }

struct OpRecord {
    OpState state = OpState::NotStarted;
    std::string kind, plate, well, station;  ///< as the last "start" line said
    double volumeUl = 0;
    std::optional<double> pumpStartUl;       ///< plunger when the "pump" line was written
    std::optional<double> pumpEndUl;         ///< plunger at "done"
    int starts = 0;                          ///< how often the op was begun
    int line = 0;                            ///< its last line in the log
};

struct RunLogState {
    std::string recipe, fingerprint;
    int opCount = 0;
    /// The plunger when the run began: a resumed run is planned from it, so its
    /// plan (and the syringe's accounting) is the original run's.
    std::optional<double> startPumpUl;
    std::vector<OpRecord> ops;
    bool finished = false;
    int runs = 0;                  ///< the header and each resume
    std::string lastStop;          ///< reason of the last "stop" line
    std::optional<double> lastPumpUl;  ///< plunger after the last op that completed
    bool tornTail = false;         ///< the last line was cut short (crash mid-write): ignored
    dev::files::json::Problems problems;     ///< a log with problems is not resumed
    int doneCount() const;         ///< Done or Skipped
    int firstOpenOp() const;       ///< first op not Done/Skipped; opCount when none
};

RunLogState readRunLog(std::string_view text);

} // namespace dev::files::plates
