#pragma once
// Running the built programs (benchpilot-cli, benchpilot-sim) from tests.
#include <QCoreApplication>
#include <QDir>
#include <QProcess>
#include <QProcessEnvironment>
#include <QString>
#include <QStringList>

#include <string>

namespace itest {

inline QString binDir()
{
    const QString fromEnv = qEnvironmentVariable("BP_BIN_DIR");
    if (!fromEnv.isEmpty())
        return fromEnv;
    // Run by hand from the build tree: <build>/tests/test_integration next to <build>/app.
    return QDir(QCoreApplication::applicationDirPath() + QStringLiteral("/../app")).absolutePath();
}

inline QString binary(const char* name) { return binDir() + QLatin1Char('/') + QLatin1String(name); }

struct ProgramRun {
    bool finished = false;
    int exitCode = -1;
    QString out, err;
    std::string describe() const
    {
        return QStringLiteral("exit %1, stdout: %2, stderr: %3").arg(exitCode).arg(out.trimmed(), err.trimmed()).toStdString();
    }
};

/// What a started program left: its exit code and output. One that has not `finished`
/// is killed first (and its exit code is then -1).
inline ProgramRun collectRun(QProcess& p, bool finished)
{
    ProgramRun r;
    r.finished = finished;
    if (!finished) {
        p.kill();
        p.waitForFinished(5000);
    }
    r.exitCode = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1;
    r.out = QString::fromUtf8(p.readAllStandardOutput());
    r.err = QString::fromUtf8(p.readAllStandardError());
    return r;
}

/// Runs a program to completion (killed after `timeoutMs`); `env` replaces the environment when not empty.
inline ProgramRun runProgram(const QString& program, const QStringList& args, int timeoutMs = 60000,
                             const QProcessEnvironment& env = {})
{
    QProcess p;
    if (!env.isEmpty())
        p.setProcessEnvironment(env);
    p.start(program, args);
    ProgramRun r;
    if (!p.waitForStarted(10000)) {
        r.err = QStringLiteral("could not start %1: %2").arg(program, p.errorString());
        return r;
    }
    return collectRun(p, p.waitForFinished(timeoutMs));
}

} // namespace itest
