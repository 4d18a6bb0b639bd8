#pragma once
// benchpilot-cli's motion-library commands (issue 3): `profile`, `interpolate`, `steptable`,
// `blocks`. They need no instrument; they print JSON on stdout, and errors that name the bad
// option and its value on stderr. Exit codes follow the CLI's: 0 ok, 1 usage (a bad or missing
// option), 2 the motion library refused the request (e.g. an unreachable block).
#include <QString>
#include <QStringList>
#include <QTextStream>

#include <optional>

namespace cli {
/// Runs `profile`, `interpolate`, `steptable` or `blocks` (issue 3's CLI). nullopt when `command` is none of them, else the process exit code.
/// `args` are the words after the command. JSON to `out`, errors (naming the bad option and value) to `err` with a non-zero code.
std::optional<int> runMotionCommand(const QString& command, const QStringList& args, QTextStream& out, QTextStream& err);
}  // namespace cli
