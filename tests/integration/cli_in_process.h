#pragma once
// benchpilot-cli run in-process with string buffers, for tests of its commands.
#include "app/cli/command.h"

#include <QJsonDocument>
#include <QJsonObject>
#include <QStringList>
#include <QTextStream>

namespace itest {

struct CliResult {
    int code = -1;
    QString out, err;
    QJsonObject json() const { return QJsonDocument::fromJson(out.toUtf8()).object(); }
};

inline CliResult runCliInProcess(const QStringList& args)
{
    CliResult r;
    QTextStream out(&r.out), err(&r.err);
    r.code = app::cli::runCli(args, out, err);
    out.flush();
    err.flush();
    return r;
}

/// "a b  c" → {"a", "b", "c"}.
inline QStringList splitWords(const char* text) { return QString::fromUtf8(text).split(QLatin1Char(' '), Qt::SkipEmptyParts); }

} // namespace itest
