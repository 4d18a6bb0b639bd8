// benchpilot-cli --attach: the same commands, the same output and the same exit codes
// through the running GUI's API socket; without a GUI it says so.
#include "api_support.h"
#include "cli_in_process.h"
#include "programs.h"

#include <QProcess>

using itest::ApiFixture;

namespace {

/// Runs benchpilot-cli while this process's event loop serves the API.
itest::ProgramRun runCli(const QStringList& args)
{
    QProcess p;
    p.start(itest::binary("benchpilot-cli"), args);
    itest::ProgramRun r;
    if (!p.waitForStarted(10000))
        return r;
    return itest::collectRun(p, itest::waitFor([&] { return p.state() == QProcess::NotRunning; }, 60000));
}

TEST(ApiAttach, TheSameCommandGivesTheSameOutputAndExitCodeThroughTheGui)
{
    ApiFixture f(false);
    const QStringList attach{QStringLiteral("--attach"), QStringLiteral("--api-socket"), f.path};
    const struct {
        const char* words;  ///< after --sim stage (local) or --attach (through the GUI)
        int code;
    } cases[] = {
        {"--json status", 0},
        {"status", 0},
        {"move", 1},         // usage: no target
        {"move X=5", 2},     // refused by the device: X is not homed
        {"jog X 1", 1},      // the CLI's jog needs SECONDS, attached or not
        {"profile --kind trapezoid --distance 2 --vmax 10 --amax 100 --dt 0.1", 0},
    };
    for (const auto& c : cases) {
        const itest::ProgramRun through = runCli(attach + itest::splitWords(c.words));
        const itest::CliResult local = itest::runCliInProcess(QStringList{QStringLiteral("--sim"), QStringLiteral("stage")} + itest::splitWords(c.words));
        ASSERT_TRUE(through.finished) << c.words;
        EXPECT_EQ(through.exitCode, c.code) << c.words << ": " << through.describe();
        EXPECT_EQ(through.exitCode, local.code) << c.words;
        EXPECT_EQ(through.out, local.out) << c.words;
        EXPECT_EQ(through.err, local.err) << c.words;
    }
}

TEST(ApiAttach, WithoutAGuiItSaysSoClearly)
{
    QTemporaryDir dir;
    const itest::ProgramRun r = runCli({QStringLiteral("--attach"), QStringLiteral("--api-socket"), dir.filePath(QStringLiteral("none.sock")),
                                        QStringLiteral("status")});
    ASSERT_TRUE(r.finished);
    EXPECT_EQ(r.exitCode, 3) << r.describe();
    EXPECT_TRUE(r.err.contains(QStringLiteral("no BenchPilot GUI is running"))) << r.describe();
    EXPECT_TRUE(r.err.contains(QStringLiteral("--attach"))) << "and what to do instead";
}

TEST(ApiAttach, ApiSocketWithoutAttachIsAUsageError)
{
    const itest::CliResult r = itest::runCliInProcess(itest::splitWords("--api-socket /tmp/x.sock status"));
    EXPECT_EQ(r.code, 1);
    EXPECT_TRUE(r.err.contains(QStringLiteral("--attach")));
}

} // namespace
