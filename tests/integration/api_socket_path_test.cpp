// Where the GUI's API socket is when nobody says (docs/api.md): one rule,
// app::cli::defaultApiSocketPath(), for the GUI and benchpilot-cli --attach, and the Python
// client's default_socket_path() spelling the same rule. The programs are run as a user
// runs them, with XDG_RUNTIME_DIR set and without it (under sudo, cron or ssh it is
// often missing): all three must name the same place.
#include "api_support.h"
#include "programs.h"

#include "app/cli/command.h"

#include <QProcessEnvironment>
#include <QRegularExpression>
#include <QStandardPaths>

#include <unistd.h>

namespace {

QProcessEnvironment environment(const QString& runtimeDir)
{
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.remove(QStringLiteral("XDG_RUNTIME_DIR"));
    if (!runtimeDir.isNull())
        env.insert(QStringLiteral("XDG_RUNTIME_DIR"), runtimeDir);
    env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
    env.insert(QStringLiteral("PYTHONPATH"), QStringLiteral(BP_SOURCE_DIR "/clients/python"));
    return env;
}

/// benchpilot.default_socket_path() in `env`; "" without Python.
QString pythonsPath(const QProcessEnvironment& env)
{
    const QString python = QStandardPaths::findExecutable(QStringLiteral("python3"));
    if (python.isEmpty())
        return {};
    const itest::ProgramRun r = itest::runProgram(
        python, {QStringLiteral("-c"), QStringLiteral("import benchpilot; print(benchpilot.default_socket_path())")}, 30000, env);
    EXPECT_EQ(r.exitCode, 0) << r.describe();
    return r.out.trimmed();
}

/// The default benchpilot-cli's --help gives for --api-socket in `env`.
QString clisPath(const QProcessEnvironment& env)
{
    const itest::ProgramRun r = itest::runProgram(itest::binary("benchpilot-cli"), {QStringLiteral("--help")}, 30000, env);
    EXPECT_EQ(r.exitCode, 0) << r.describe();
    const QRegularExpressionMatch m = QRegularExpression(QStringLiteral("--api-socket PATH[^\\n]*\\(default: ([^;]+);")).match(r.out);
    EXPECT_TRUE(m.hasMatch()) << r.out.toStdString();
    return m.captured(1);
}

TEST(ApiSocketPath, ThePythonClientTheCliAndTheGuiAgreeWithAndWithoutXdgRuntimeDir)
{
    if (QStandardPaths::findExecutable(QStringLiteral("python3")).isEmpty())
        GTEST_SKIP() << "no python3 to run the Python client's rule";
    QTemporaryDir runtime;
    const QString unset;  // null: XDG_RUNTIME_DIR removed
    for (const QString& dir : {unset, runtime.path(), runtime.path() + QLatin1Char('/')}) {
        const QProcessEnvironment env = environment(dir);
        const QString python = pythonsPath(env);
        const QString gui = app::cli::apiSocketPathFor(dir, ::getuid());  // what the GUI's own process computes there
        SCOPED_TRACE(dir.isNull() ? std::string("XDG_RUNTIME_DIR unset") : dir.toStdString());
        EXPECT_EQ(clisPath(env).toStdString(), python.toStdString());
        EXPECT_EQ(gui.toStdString(), python.toStdString());
    }
    EXPECT_EQ(pythonsPath(environment(unset)).toStdString(), QStringLiteral("/tmp/benchpilot-%1/api.sock").arg(::getuid()).toStdString());
    EXPECT_EQ(pythonsPath(environment(runtime.path())).toStdString(), (runtime.path() + QStringLiteral("/benchpilot/api.sock")).toStdString());
}

TEST(ApiSocketPath, AttachFindsTheGuiAtThePythonClientsDefault)
{
    // A GUI (the server in this process) at the default path of an XDG_RUNTIME_DIR, and
    // benchpilot-cli --attach with no --api-socket in that environment.
    QTemporaryDir runtime;
    const QString path = app::cli::apiSocketPathFor(runtime.path(), ::getuid());
    itest::ServedSim stage(dev::proto::DeviceKind::Stage);
    app::api::ApiServer server({{QStringLiteral("stage"), &stage.proxy, -1, {}}}, nullptr);
    QString error;
    ASSERT_TRUE(server.listen(path, &error)) << error.toStdString();
    ASSERT_TRUE(itest::waitFor([&] { return stage.proxy.isReady(); }, 10000));
    QProcess p;
    p.setProcessEnvironment(environment(runtime.path()));
    p.start(itest::binary("benchpilot-cli"), {QStringLiteral("--attach"), QStringLiteral("status")});
    ASSERT_TRUE(p.waitForStarted(10000));
    const itest::ProgramRun r = itest::collectRun(p, itest::waitFor([&] { return p.state() == QProcess::NotRunning; }, 60000));
    EXPECT_EQ(r.exitCode, 0) << r.describe();
    EXPECT_TRUE(r.out.startsWith(QStringLiteral("stage"))) << r.describe();

    // Without XDG_RUNTIME_DIR: where it looks, said when nobody is there, is the same place.
    const QProcessEnvironment bare = environment(QString());
    const itest::ProgramRun none = itest::runProgram(itest::binary("benchpilot-cli"), {QStringLiteral("--attach"), QStringLiteral("status")}, 30000, bare);
    const QString expected = QStringLiteral("/tmp/benchpilot-%1/api.sock").arg(::getuid());
    if (none.exitCode != 0) {  // (0: a GUI of this user's really is running there)
        EXPECT_TRUE(none.err.contains(expected + QLatin1Char('.'))) << none.describe();
    }
}

} // namespace
