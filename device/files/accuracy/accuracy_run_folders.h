#pragma once
// A test's runs side by side. The first run of a test goes into its folder
// ("<out>/<test name>"); a run of the same test after it has finished (after
// compensation, after a repair) goes into "<folder>-2", then "<folder>-3", … Each is a
// whole run folder of its own (run log, readings, result, report), so a new run never
// overwrites or mixes with the one before, and the two can be compared.
#include <QString>
#include <QStringList>

namespace dev::files::accuracy {

/// The run folders of `base` that exist, in order: `base`, "<base>-2", "<base>-3", … up to
/// the first number missing.
QStringList runFolders(const QString& base);
/// The newest run: the last of runFolders(), or `base` when there is none yet.
QString latestRunFolder(const QString& base);
/// Where a new run beside the others goes: the first of `base`, "<base>-2", … not there yet.
QString nextRunFolder(const QString& base);

} // namespace dev::files::accuracy
