// benchpilot-cli scan plan / scan run: the plan printed in each format and read
// back by the tools' rules, bad input named by its option, and a run on the
// simulated stage (benchpilot-sim on a pty) that writes the exports with measured
// positions and continues after a crash.
#include "device/english_words.h"
#include "app/cli/command.h"
#include "device/files/scan_plan_file.h"
#include "device/files/scan_run_log.h"
#include "device/files/text_file.h"
#include "programs.h"
#include "pty_simulator.h"

#include "../device/scan_format_readers.h"
#include "../device/pseudo_translation.h"

#include <QDir>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>

#include <gtest/gtest.h>

using namespace itest;

namespace {

struct CliOutput {
    int code = -1;
    QString out, err;
};

CliOutput scanCli(const QString& line)
{
    CliOutput r;
    QTextStream out(&r.out), err(&r.err);
    r.code = app::cli::runCli(line.split(QLatin1Char(' '), Qt::SkipEmptyParts), out, err);
    out.flush();
    err.flush();
    return r;
}

std::string readFile(const QString& path)
{
    std::string text;
    QString error;
    dev::files::readText(path, &text, &error);
    return text;
}

} // namespace

TEST(ScanCli, PlanPrintsAPlanFileThatRunsAsIs)
{
    const CliOutput r = scanCli(QStringLiteral("scan plan --roi 10,10,20,15 --fov 1.2,1 --overlap 0.2,0.1 --order snake-cols --start bottom-right"));
    ASSERT_EQ(r.code, 0) << r.err.toStdString();
    const auto plan = dev::files::scan::parsePlan(r.out.toStdString());
    ASSERT_TRUE(plan.plan) << i18ntest::englishFormat(plan.problems, "stdout");
    EXPECT_EQ(plan.plan->order, motion::scan::ScanOrder::SnakeColumns);
    EXPECT_EQ(plan.plan->start, motion::scan::StartCorner::BottomRight);
    EXPECT_EQ(plan.plan->overlapX, 0.2);
    EXPECT_EQ(plan.plan->overlapY, 0.1);
    // The printed plan is a plan file: it prints again from the file, in any format.
    QTemporaryDir dir;
    const QString file = dir.filePath(QStringLiteral("p.scan.json"));
    QString error;
    ASSERT_TRUE(dev::files::writeAtomically(file, r.out.toStdString(), &error));
    const CliOutput again = scanCli(QStringLiteral("scan plan %1 --format tileconfig --pixel-um 0.5").arg(file));
    ASSERT_EQ(again.code, 0) << again.err.toStdString();
    const auto fiji = scanread::readTileConfiguration(again.out.toStdString());
    ASSERT_TRUE(fiji.error.empty()) << fiji.error;
    EXPECT_TRUE(again.out.contains(QStringLiteral("0.5 µm each")));
    const CliOutput both = scanCli(QStringLiteral("scan plan %1 --roi 1,1,2,2").arg(file));
    EXPECT_EQ(both.code, 1);
    EXPECT_TRUE(both.err.contains(QStringLiteral("not both (--roi)"))) << both.err.toStdString();
    const CliOutput s = scanCli(QStringLiteral("scan plan --roi 10,10,20,15 --fov 1.2,1 --overlap 0.2 --format summary"));
    ASSERT_EQ(s.code, 0) << s.err.toStdString();
    const QJsonObject j = QJsonDocument::fromJson(s.out.toUtf8()).object();
    EXPECT_EQ(j[QStringLiteral("columns")].toInt(), 11);  // (10 − 1.2)/0.96 = 9.2 → 10 steps
    EXPECT_EQ(j[QStringLiteral("rows")].toInt(), 6);      // (5 − 1)/0.8 = 5 steps
    EXPECT_EQ(j[QStringLiteral("tiles")].toInt(), 66);
    EXPECT_GT(j[QStringLiteral("estimate_s")].toDouble(), 66 * (0.02 + 0.05));
}

TEST(ScanCli, PlanPrintsWhatFijiAndMicroManagerRead)
{
    const CliOutput t = scanCli(QStringLiteral("scan plan --roi 10,10,14,12 --fov 1,1 --overlap 0.2 --format tileconfig --pixel-um 0.5"));
    ASSERT_EQ(t.code, 0) << t.err.toStdString();
    const auto fiji = scanread::readTileConfiguration(t.out.toStdString());
    ASSERT_TRUE(fiji.error.empty()) << fiji.error;
    EXPECT_EQ(fiji.tiles.size(), 5u * 3u);  // 3/0.8 → 4 steps, 1/0.8 → 2
    EXPECT_NEAR(fiji.tiles[1].coords[0] - fiji.tiles[0].coords[0], 1600, 1e-3);  // 0.8 mm / 0.5 µm
    const CliOutput m = scanCli(QStringLiteral("scan plan --roi 10,10,14,12 --fov 1,1 --overlap 0.2 --format mmpos --mm-stage XY"));
    ASSERT_EQ(m.code, 0) << m.err.toStdString();
    const auto mm = scanread::readMicroManagerPositions(m.out.toStdString());
    ASSERT_TRUE(mm.error.empty()) << mm.error;
    ASSERT_EQ(mm.positions.size(), 15u);
    EXPECT_EQ(mm.positions[0].devices[0].name, "XY");
    const CliOutput c = scanCli(QStringLiteral("scan plan --roi 10,10,14,12 --fov 1,1 --format csv"));
    ASSERT_EQ(c.code, 0) << c.err.toStdString();
    EXPECT_EQ(scanread::readCsv(c.out.toStdString()).size(), 1u + 5u * 3u);
    const CliOutput noPixel = scanCli(QStringLiteral("scan plan --roi 10,10,14,12 --fov 1,1 --format tileconfig"));
    EXPECT_EQ(noPixel.code, 1);
    EXPECT_TRUE(noPixel.err.contains(QStringLiteral("--pixel-um"))) << noPixel.err.toStdString();
}

TEST(ScanCli, BadInputIsNamedByItsOption)
{
    struct Case {
        const char* line;
        const char* expect;
    };
    const Case cases[] = {
        {"scan plan --roi 10,10,20,15 --fov 1,1 --overlap 1.0", "--overlap: must be from 0 to 0.9, a share of the field (got 1)"},
        {"scan plan --roi 10,10,20,15 --fov 1,1 --overlap 1.5,0.1", "--overlap: must be from 0 to 0.9"},
        {"scan plan --roi 10,10,20,15 --fov 120,1", "--fov: the field 120.000 mm × 1.000 mm is larger than the stage's travel 100.000 mm × 100.000 mm"},
        {"scan plan --roi 10,10,20,15 --sensor 20000,2000 --sensor-um 6.5 --mag 1", "--sensor: the field 130.000 mm × 13.000 mm is larger"},
        {"scan plan --roi 10,10,10,15 --fov 1,1", "--roi: the region has zero size (0.000 mm × 5.000 mm)"},
        {"scan plan --centre 50,50 --size 0,4 --fov 1,1", "--size: the region has zero size"},
        {"scan plan --roi 10,10,20,15 --fov 1,1 --order zigzag", "--order 'zigzag' is not one of snake-rows, rows, snake-cols, cols"},
        {"scan plan --roi 10,10,20,15 --fov 1,1 --start middle", "--start 'middle' is not one of top-left"},
        {"scan plan --roi 10,10,20 --fov 1,1", "--roi '10,10,20' needs 4 comma-separated numbers"},
        {"scan plan --roi 10,10,20,15 --fov 1,x", "--fov '1,x': 'x' is not a number"},
        {"scan plan --roi 90,10,120,15 --fov 1,1", "--roi: the region X 90.000 mm … 120.000 mm, Y 10.000 mm … 15.000 mm reaches beyond the stage's travel"},
        {"scan plan --roi 10,10,20,15 --fov 1,1 --format png", "--format 'png' is not one of"},
        {"scan plan --fov 1,1", "give the region"},
        {"scan plan --roi 10,10,20,15", "give the camera field"},
    };
    for (const Case& c : cases) {
        const CliOutput r = scanCli(QString::fromUtf8(c.line));
        EXPECT_EQ(r.code, 1) << c.line;
        EXPECT_TRUE(r.err.contains(QString::fromUtf8(c.expect))) << c.line << "\n  said: " << r.err.toStdString();
        EXPECT_TRUE(r.out.isEmpty()) << c.line;
    }
    const CliOutput twice = scanCli(QStringLiteral("scan plan --roi 10,10,20,15 --fov 1,1 --overlap 1.0"));
    EXPECT_EQ(twice.err.count(QStringLiteral("--overlap")), 1) << "X and Y saying the same is said once";
}

TEST(ScanCli, RunRefusesTheAnalyzerAndAnUnhomedStage)
{
    QTemporaryDir dir;
    const QString plan = dir.filePath(QStringLiteral("p.scan.json"));
    const CliOutput p = scanCli(QStringLiteral("scan plan --roi 40,60,42,62 --fov 1,1"));
    ASSERT_EQ(p.code, 0);
    QString error;
    ASSERT_TRUE(dev::files::writeAtomically(plan, p.out.toStdString(), &error));
    const CliOutput analyzer = scanCli(QStringLiteral("--sim analyzer scan run %1 --out %2").arg(plan, dir.filePath(QStringLiteral("a"))));
    EXPECT_EQ(analyzer.code, 2);
    EXPECT_TRUE(analyzer.err.contains(QStringLiteral("scans run on the microscope stage"))) << analyzer.err.toStdString();
    const CliOutput unhomed = scanCli(QStringLiteral("--sim stage scan run %1 --out %2").arg(plan, dir.filePath(QStringLiteral("b"))));
    EXPECT_EQ(unhomed.code, 2);
    EXPECT_TRUE(unhomed.err.contains(QStringLiteral("Home the stage first"))) << unhomed.err.toStdString();
    const CliOutput missing = scanCli(QStringLiteral("--sim stage scan run %1").arg(dir.filePath(QStringLiteral("none.scan.json"))));
    EXPECT_EQ(missing.code, 1);
}

TEST(ScanCli, AnotherPlansRunLogAsksForRestartInAnyLanguage)
{
    QTemporaryDir dir;
    const QString planA = dir.filePath(QStringLiteral("a.scan.json")), planB = dir.filePath(QStringLiteral("b.scan.json"));
    const QString out = dir.filePath(QStringLiteral("out"));
    QString error;
    const CliOutput a = scanCli(QStringLiteral("scan plan --roi 40,60,42,62 --fov 1,1"));
    const CliOutput b = scanCli(QStringLiteral("scan plan --roi 40,60,42,62 --fov 1,1 --overlap 0.3"));
    ASSERT_EQ(a.code, 0);
    ASSERT_EQ(b.code, 0);
    ASSERT_TRUE(dev::files::writeAtomically(planA, a.out.toStdString(), &error));
    ASSERT_TRUE(dev::files::writeAtomically(planB, b.out.toStdString(), &error));
    // Plan A's run log goes into the folder (the unhomed stage then refuses to move).
    EXPECT_EQ(scanCli(QStringLiteral("--sim stage scan run %1 --out %2").arg(planA, out)).code, 2);
    ASSERT_TRUE(QFile::exists(QDir(out).filePath(QLatin1String(dev::files::scan::kRunLogFile))));

    // The runner's messages translated: the hint must not depend on their English words.
    const i18ntest::PseudoTranslation translated({QStringLiteral("ui::words::ScanWords")});
    const CliOutput other = scanCli(QStringLiteral("--sim stage scan run %1 --out %2").arg(planB, out));
    EXPECT_EQ(other.code, 1) << "a usage problem: the command line decides";
    EXPECT_TRUE(other.err.contains(QStringLiteral("--restart starts over"))) << other.err.toStdString();
    EXPECT_TRUE(other.err.contains(QStringLiteral("dífférént scán"))) << "the translated reason is shown: " << other.err.toStdString();
    const CliOutput restart = scanCli(QStringLiteral("--sim stage scan run %1 --out %2 --restart").arg(planB, out));
    EXPECT_EQ(restart.code, 2) << "past the run log, stopped by the unhomed stage: " << restart.err.toStdString();
    EXPECT_FALSE(restart.err.contains(QStringLiteral("--restart"))) << restart.err.toStdString();
    EXPECT_EQ(QDir(out).entryList({QStringLiteral("scan-run*.jsonl")}).size(), 2) << "plan A's log is kept aside";
}

TEST(ScanCli, RunWritesTheExportsWithMeasuredPositionsAndContinuesAfterACrash)
{
    PtySimulator sim;
    ASSERT_TRUE(sim.start(QStringLiteral("stage"), 10)) << sim.error().toStdString();
    QTemporaryDir dir;
    const QString plan = dir.filePath(QStringLiteral("p.scan.json"));
    const QString out = dir.filePath(QStringLiteral("out"));
    const auto made = runProgram(binary("benchpilot-cli"), {QStringLiteral("scan"), QStringLiteral("plan"), QStringLiteral("--roi"),
                                                            QStringLiteral("40,60,42.8,62.8"), QStringLiteral("--fov"),
                                                            QStringLiteral("1,1"), QStringLiteral("--pixel-um"), QStringLiteral("0.5"),
                                                            QStringLiteral("--exposure"), QStringLiteral("0.01")});
    ASSERT_EQ(made.exitCode, 0) << made.describe();
    QString error;
    ASSERT_TRUE(dev::files::writeAtomically(plan, made.out.toStdString(), &error));
    const QStringList runArgs = {QStringLiteral("--port"), sim.link(), QStringLiteral("scan"), QStringLiteral("run"), plan,
                                 QStringLiteral("--out"), out, QStringLiteral("--home")};
    const auto first = runProgram(binary("benchpilot-cli"), runArgs, 90000);
    ASSERT_EQ(first.exitCode, 0) << first.describe();
    EXPECT_TRUE(first.out.contains(QStringLiteral("tile 9/9 tile_009.tif"))) << first.out.toStdString();
    const auto fiji = scanread::readTileConfiguration(readFile(QDir(out).filePath(QStringLiteral("TileConfiguration.txt"))));
    ASSERT_TRUE(fiji.error.empty()) << fiji.error;
    ASSERT_EQ(fiji.tiles.size(), 9u);
    EXPECT_NEAR(fiji.tiles[1].coords[0] - fiji.tiles[0].coords[0], 1800, 4);  // measured: within the tolerance of 0.9 mm
    const auto csv = scanread::readCsv(readFile(QDir(out).filePath(QStringLiteral("scan.csv"))));
    ASSERT_EQ(csv.size(), 10u);
    const auto col = std::find(csv[0].begin(), csv[0].end(), "measured_x_mm") - csv[0].begin();
    for (std::size_t i = 1; i < csv.size(); ++i)
        EXPECT_FALSE(csv[i][static_cast<std::size_t>(col)].empty()) << "tile " << i << " has no measured position";
    EXPECT_TRUE(scanread::readMicroManagerPositions(readFile(QDir(out).filePath(QStringLiteral("positions.pos")))).error.empty());

    // A crash after tile 4: the run log keeps four tiles (and half a line). Run again: it continues at tile 5.
    const QString logPath = QDir(out).filePath(QLatin1String(dev::files::scan::kRunLogFile));
    const std::string log = readFile(logPath);
    std::size_t cut = 0;
    for (int line = 0; line < 5; ++line)
        cut = log.find('\n', cut) + 1;
    ASSERT_TRUE(dev::files::writeAtomically(logPath, log.substr(0, cut) + log.substr(cut, 40), &error));
    const auto again = runProgram(binary("benchpilot-cli"), QStringList(runArgs.mid(0, 7)), 90000);
    ASSERT_EQ(again.exitCode, 0) << again.describe();
    EXPECT_TRUE(again.out.contains(QStringLiteral("Continuing at tile 5 of 9"))) << again.out.toStdString();
    EXPECT_FALSE(again.out.contains(QStringLiteral("tile 4/9"))) << "tiles already taken are not taken again";
    EXPECT_TRUE(again.out.contains(QStringLiteral("tile 9/9"))) << again.out.toStdString();
    const auto parsed = dev::files::scan::parseRunLog(readFile(logPath));
    ASSERT_TRUE(parsed.log) << i18ntest::englishFormat(parsed.problems, "log");
    EXPECT_EQ(parsed.log->records.size(), 9u);
}
