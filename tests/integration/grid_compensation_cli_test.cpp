// benchpilot-cli's 2D compensation, as scripts use it: a grid map's result file fitted
// into a table (the example's own table), the table uploaded to benchpilot-sim's stage
// (started with a stage-error file) and enabled, a later program finding it there
// still enabled; and a stage-error file with faults refused by file, line and column.
#include "cli_in_process.h"
#include "pty_simulator.h"

#include "device/files/accuracy/grid/compensation_2d_file.h"

#include <QFile>
#include <QTemporaryDir>

#include <gtest/gtest.h>

using namespace itest;

namespace {

QString gridExample(const char* name) { return QStringLiteral(BP_SOURCE_DIR "/resources/examples/") + QLatin1String(name); }

TEST(GridCompensationCli, FitTwoDMakesTheExampleTableFromTheExampleMap)
{
    QTemporaryDir dir;
    const QString out = dir.filePath(QStringLiteral("t.compensation-2d.json"));
    const auto r = runCliInProcess({QStringLiteral("--json"), QStringLiteral("compensation"), QStringLiteral("fit-2d"),
                                    gridExample("stage-example.grid-map-result.json"), QStringLiteral("--out"), out});
    ASSERT_EQ(r.code, 0) << qPrintable(r.err);
    EXPECT_EQ(r.json().value(QStringLiteral("columns")).toInt(), 7);
    const auto made = dev::files::accuracy::loadCompensation2DFile(out);
    const auto example = dev::files::accuracy::loadCompensation2DFile(gridExample("stage-example.compensation-2d.json"));
    ASSERT_TRUE(made.ok() && example.ok());
    EXPECT_EQ(made->table.correctionXUm, example->table.correctionXUm);
    EXPECT_EQ(made->table.correctionYUm, example->table.correctionYUm);
    // Without --out nothing is written and the command says what is missing.
    const auto noOut = runCliInProcess({QStringLiteral("compensation"), QStringLiteral("fit-2d"), gridExample("stage-example.grid-map-result.json")});
    EXPECT_EQ(noOut.code, 1);
}

TEST(GridCompensationCli, TheDeviceKeepsAnUploadedTableAcrossPrograms)
{
    PtySimulator sim;
    ASSERT_TRUE(sim.start(QStringLiteral("stage"), 4, {QStringLiteral("--stage-errors"), gridExample("stage-example.stage-errors.json")}))
        << qPrintable(sim.error());
    const QString cli = binary("benchpilot-cli");
    auto run = [&](const QStringList& args) { return runProgram(cli, QStringList{QStringLiteral("--port"), sim.link()} + args, 60000); };
    auto up = run({QStringLiteral("--json"), QStringLiteral("compensation"), QStringLiteral("upload-2d"),
                   gridExample("stage-example.compensation-2d.json"), QStringLiteral("--enable")});
    ASSERT_EQ(up.exitCode, 0) << up.describe();
    EXPECT_TRUE(lastJson(up.out).value(QStringLiteral("enabled")).toBool());
    auto show = run({QStringLiteral("--json"), QStringLiteral("compensation"), QStringLiteral("show-2d")});
    ASSERT_EQ(show.exitCode, 0) << show.describe();
    const QJsonObject s = lastJson(show.out);
    EXPECT_TRUE(s.value(QStringLiteral("installed")).toBool());
    EXPECT_TRUE(s.value(QStringLiteral("enabled")).toBool());
    EXPECT_FALSE(s.value(QStringLiteral("saved")).toBool());
    EXPECT_EQ(s.value(QStringLiteral("rows")).toInt(), 7);
    auto off = run({QStringLiteral("--json"), QStringLiteral("compensation"), QStringLiteral("disable-2d")});
    ASSERT_EQ(off.exitCode, 0) << off.describe();
    EXPECT_FALSE(lastJson(off.out).value(QStringLiteral("enabled")).toBool());
}

TEST(GridCompensationCli, AStageErrorFileWithFaultsIsRefusedByFileLineAndColumn)
{
    QTemporaryDir dir;
    const QString bad = dir.filePath(QStringLiteral("bad.stage-errors.json"));
    QFile f(bad);
    ASSERT_TRUE(f.open(QIODevice::WriteOnly));
    f.write("{\"schema\": \"benchpilot.stage-errors\", \"version\": 1,\n \"squareness_urad\": \"x\"}");
    f.close();
    const auto r = runCliInProcess({QStringLiteral("--sim"), QStringLiteral("stage"), QStringLiteral("--stage-errors"), bad,
                                    QStringLiteral("compensation"), QStringLiteral("show-2d")});
    EXPECT_EQ(r.code, 1);
    EXPECT_TRUE(r.err.contains(QStringLiteral("bad.stage-errors.json:2:21"))) << qPrintable(r.err);
    const auto analyzer = runCliInProcess({QStringLiteral("--sim"), QStringLiteral("analyzer"), QStringLiteral("--stage-errors"),
                                           gridExample("stage-example.stage-errors.json"), QStringLiteral("compensation"), QStringLiteral("show-2d")});
    EXPECT_EQ(analyzer.code, 1);
}

} // namespace
