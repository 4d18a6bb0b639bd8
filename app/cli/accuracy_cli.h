#pragma once
// What the accuracy and compensation commands share: problems printed as
// "FILE:LINE:COL: FIELD: message" or as JSON ({id, args, units, message} plus file,
// line, column, field), a result document as JSON, and one JSON line of output.
#include "command.h"
#include "device/files/accuracy/accuracy_result_file.h"
#include "device/files/accuracy/file_problem.h"
#include "motion/metrology/problem.h"

#include <QJsonArray>
#include <QJsonObject>

namespace app::cli {

QJsonObject problemJson(const motion::msg::Problem& p);
QJsonObject messageJson(const motion::msg::Message& m);

/// Prints every problem as ui::words::problem words it (text: errors on stderr, warnings on
/// stdout; JSON: one object {"ok": false, "problems": [...]} when any is an error). True
/// when any is an error. `optionNames` maps a field path's start to the command-line
/// option that set it ("cycles" → "--cycles"), for a data model's problems.
bool reportProblems(Invocation& inv, const motion::msg::Problems& problems,
                    const std::vector<std::pair<QString, QString>>& optionNames = {});
/// One message as the command's failure: text on stderr or {"ok": false, "error": {...}}.
int reportFailure(Invocation& inv, const motion::msg::Message& m, int exitCode);

/// A result file's document as JSON (figures, targets, tolerances, verdicts, pass).
QJsonObject resultJson(const dev::files::accuracy::AccuracyResult& r);
void printJson(Invocation& inv, const QJsonObject& o);
/// A number rounded to the nanometre (mm) for JSON.
double nm6(double v);

/// Why --time-scale is refused here: it speeds up benchpilot-cli's own simulator only
/// (the GUI's simulators keep the pace its screens and other clients rely on).
QString timeScaleRefusal(Invocation& inv);

/// The figures as a small text table for a person.
void printFiguresText(Invocation& inv, const dev::files::accuracy::AccuracyResult& r);

} // namespace app::cli
