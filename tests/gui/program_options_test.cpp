// benchpilot --help and --version answer without a display (on a server or over ssh).
#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QProcess>

#include <gtest/gtest.h>

namespace {
QString benchpilot()
{
    const QString dir = qEnvironmentVariable("BP_BIN_DIR");
    return (dir.isEmpty() ? QCoreApplication::applicationDirPath() + QStringLiteral("/../app") : dir) + QStringLiteral("/benchpilot");
}

/// Runs benchpilot where no display can be opened: a QApplication would abort.
int runHeadless(const QStringList& args, QString* out)
{
    QProcess p;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.remove(QStringLiteral("DISPLAY"));
    env.remove(QStringLiteral("WAYLAND_DISPLAY"));
    env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("xcb"));
    p.setProcessEnvironment(env);
    p.start(benchpilot(), args);
    EXPECT_TRUE(p.waitForFinished(20000));
    *out = QString::fromUtf8(p.readAllStandardOutput());
    return p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1;
}
} // namespace

TEST(ProgramOptions, HelpAndVersionNeedNoDisplay)
{
    QString out;
    EXPECT_EQ(runHeadless({QStringLiteral("--help")}, &out), 0);
    EXPECT_TRUE(out.startsWith(QStringLiteral("Usage: benchpilot [options]"))) << out.toStdString();
    for (const char* o : {"--screenshot", "--screen", "--sim", "--specimen", "--port", "--instrument", "--profile", "--baud", "--version"})
        EXPECT_TRUE(out.contains(QLatin1String(o))) << o;
    EXPECT_EQ(runHeadless({QStringLiteral("-h")}, &out), 0);
    EXPECT_EQ(runHeadless({QStringLiteral("--version")}, &out), 0);
    EXPECT_EQ(out.section(QLatin1Char('\n'), 0, 0), QStringLiteral("benchpilot " BP_VERSION));
    EXPECT_TRUE(out.contains(QStringLiteral("License GPL-3.0-or-later"))) << out.toStdString();
}

TEST(ProgramOptions, JoinedValuesReachTheScreenshotOptions)
{
    QProcess p;
    const QString file = QDir::temp().filePath(QStringLiteral("bp-options-test.png"));
    QFile::remove(file);
    p.start(benchpilot(), {QStringLiteral("--screenshot=") + file, QStringLiteral("--screen=profiles"), QStringLiteral("--settle-ms=50")});
    ASSERT_TRUE(p.waitForFinished(60000));
    EXPECT_EQ(p.exitCode(), 0) << p.readAllStandardError().toStdString();
    EXPECT_TRUE(QFile::exists(file));
    QFile::remove(file);
}
