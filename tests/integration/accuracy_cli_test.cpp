// benchpilot-cli accuracy and compensation, as scripts use them: the JSON shapes of
// docs/accuracy.md (figures under "figures" with A … B_mean, the fit's order, coefficients_um,
// sse, r2, adj_r2 and its table of orders), bad input named by file, line and column,
// a run on the simulated stage measured by its gauge, and the device keeping an
// uploaded compensation across separate programs.
#include "cli_in_process.h"
#include "pty_simulator.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QTemporaryDir>

#include <gtest/gtest.h>

using namespace itest;

namespace {

QString example(const char* name) { return QStringLiteral(BP_SOURCE_DIR "/resources/examples/") + QLatin1String(name); }

bool writeFile(const QString& path, const QByteArray& text)
{
    QFile f(path);
    return f.open(QIODevice::WriteOnly) && f.write(text) == text.size();
}

TEST(AccuracyCli, AnalyzePrintsTheFiguresAndTheTableUnderTheirKeys)
{
    const auto r = runCliInProcess({QStringLiteral("accuracy"), QStringLiteral("analyze"), example("stage-x-interferometer.readings.csv"),
                                    QStringLiteral("--json")});
    ASSERT_EQ(r.code, 0) << r.err.toStdString();
    const QJsonObject o = r.json();
    const QJsonObject f = o.value(QStringLiteral("figures")).toObject();
    for (const char* key : {"A", "A_up", "A_down", "E", "E_up", "E_down", "M", "R", "R_up", "R_down", "B", "B_mean"})
        EXPECT_TRUE(f.value(QLatin1String(key)).isDouble()) << key;
    EXPECT_GT(o.value(QStringLiteral("targets")).toArray().size(), 5);
    EXPECT_EQ(o.value(QStringLiteral("schema")).toString(), QStringLiteral("benchpilot.accuracy-result"));
}

TEST(AccuracyCli, BadReadingsAreNamedByFileLineAndColumn)
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("bad.readings.csv"));
    ASSERT_TRUE(writeFile(path, "target_mm,direction,cycle,measured_mm\n10,up,1,10.001\n10,up,2,NaN\n20,up,1,20\n20,up,2,20.002\n"));
    auto r = runCliInProcess({QStringLiteral("accuracy"), QStringLiteral("analyze"), path, QStringLiteral("--json")});
    EXPECT_EQ(r.code, 1);
    QJsonObject p = r.json().value(QStringLiteral("problems")).toArray().first().toObject();
    EXPECT_EQ(p.value(QStringLiteral("id")).toString(), QStringLiteral("accuracy.value_not_finite"));
    EXPECT_EQ(p.value(QStringLiteral("file")).toString(), QStringLiteral("bad.readings.csv"));
    EXPECT_EQ(p.value(QStringLiteral("line")).toInt(), 3);
    EXPECT_EQ(p.value(QStringLiteral("column")).toInt(), 9);
    // A unit it cannot read, in text: file, line, column and the sentence.
    ASSERT_TRUE(writeFile(path, "target_mm,direction,cycle,measured_furlong\n10,up,1,10\n"));
    r = runCliInProcess({QStringLiteral("accuracy"), QStringLiteral("analyze"), path});
    EXPECT_EQ(r.code, 1);
    EXPECT_TRUE(r.err.contains(QStringLiteral("bad.readings.csv:1:27"))) << r.err.toStdString();
    EXPECT_TRUE(r.err.contains(QStringLiteral("cannot read the unit of column measured_furlong"))) << r.err.toStdString();
}

TEST(AccuracyCli, ATestOutsideTheSoftLimitsOrNotIncreasingIsRefusedNamingTheOption)
{
    auto r = runCliInProcess(splitWords("--sim stage --json accuracy run --axis X --targets 10,50,30 --cycles 2"));
    EXPECT_EQ(r.code, 1);
    const QJsonArray problems = r.json().value(QStringLiteral("problems")).toArray();
    bool found = false;
    for (const auto& p : problems)
        if (p.toObject().value(QStringLiteral("id")).toString() == QStringLiteral("accuracy.targets_not_increasing")) {
            found = true;
            EXPECT_EQ(p.toObject().value(QStringLiteral("option")).toString(), QStringLiteral("--targets"));
        }
    EXPECT_TRUE(found) << r.out.toStdString();
    QTemporaryDir dir;
    r = runCliInProcess({QStringLiteral("--sim"), QStringLiteral("stage"), QStringLiteral("accuracy"), QStringLiteral("run"),
                         QStringLiteral("--home"), QStringLiteral("--time-scale"), QStringLiteral("20"), QStringLiteral("--targets"),
                         QStringLiteral("10:120:3"), QStringLiteral("--cycles"), QStringLiteral("2"), QStringLiteral("--out"), dir.path()});
    EXPECT_EQ(r.code, 1);
    EXPECT_TRUE(r.err.contains(QStringLiteral("above the soft limit"))) << r.err.toStdString();
    EXPECT_TRUE(QDir(dir.path()).entryList(QDir::Files).isEmpty()) << "nothing written";
}

TEST(AccuracyCli, ARunOnTheSimulatedStageByItsGaugeThenItsFit)
{
    QTemporaryDir dir;
    const auto r = runCliInProcess({QStringLiteral("--sim"), QStringLiteral("stage"), QStringLiteral("--json"), QStringLiteral("accuracy"),
                                    QStringLiteral("run"), QStringLiteral("--home"), QStringLiteral("--time-scale"), QStringLiteral("25"),
                                    QStringLiteral("--axis"), QStringLiteral("X"), QStringLiteral("--targets"), QStringLiteral("10:90:4"),
                                    QStringLiteral("--cycles"), QStringLiteral("2"), QStringLiteral("--feed"), QStringLiteral("15"),
                                    QStringLiteral("--dwell"), QStringLiteral("0.05"), QStringLiteral("--source"), QStringLiteral("gauge:sim"),
                                    QStringLiteral("--out"), dir.path()});
    ASSERT_EQ(r.code, 0) << r.err.toStdString() << r.out.toStdString();
    const QJsonObject o = r.json();
    EXPECT_EQ(o.value(QStringLiteral("source")).toString(), QStringLiteral("gauge"));
    EXPECT_GT(o.value(QStringLiteral("figures")).toObject().value(QStringLiteral("A")).toDouble(), 0.05) << "the Abbe error the grating hides";
    QString result;
    for (const auto& f : o.value(QStringLiteral("files")).toArray())
        if (f.toString().endsWith(QStringLiteral(".accuracy-result.json")))
            result = f.toString();
    ASSERT_FALSE(result.isEmpty()) << r.out.toStdString();
    const QString comp = dir.filePath(QStringLiteral("x.compensation.json"));
    const auto fit = runCliInProcess({QStringLiteral("compensation"), QStringLiteral("fit"), result, QStringLiteral("--order"),
                                      QStringLiteral("auto"), QStringLiteral("--out"), comp, QStringLiteral("--json")});
    ASSERT_EQ(fit.code, 0) << fit.err.toStdString();
    const QJsonObject j = fit.json();
    for (const char* key : {"order", "coefficients_um", "sse", "r2", "adj_r2", "orders"})
        EXPECT_TRUE(j.contains(QLatin1String(key))) << key;
    EXPECT_EQ(j.value(QStringLiteral("orders")).toArray().size(), 5);
    EXPECT_NEAR(j.value(QStringLiteral("coefficients_um")).toArray().at(1).toDouble(), 0.95, 0.1) << "seed 002's X slope";
    EXPECT_TRUE(QFile::exists(comp));
    const auto csv = runCliInProcess({QStringLiteral("compensation"), QStringLiteral("export"), QStringLiteral("--format"),
                                      QStringLiteral("linuxcnc"), comp});
    ASSERT_EQ(csv.code, 0) << csv.err.toStdString();
    EXPECT_EQ(csv.out.count(QLatin1Char('\n')), 41) << "41 triplets over the fitted range";
}

// The reading sources' refusals are worded in the language asked for: their strings
// were once filed by lupdate under another context than the one they are looked up in.
TEST(AccuracyCli, AReadingSourcesRefusalIsInTheChosenLanguage)
{
    QTemporaryDir dir;
    const QStringList args = {QStringLiteral("--sim"), QStringLiteral("stage"), QStringLiteral("accuracy"), QStringLiteral("run"),
                              QStringLiteral("--axis"), QStringLiteral("X"), QStringLiteral("--targets"), QStringLiteral("10:90:4"),
                              QStringLiteral("--source"), QStringLiteral("gauge:sim"), QStringLiteral("--gauge-timeout"), QStringLiteral("99"),
                              QStringLiteral("--out"), dir.path()};
    const auto en = runCliInProcess(args);
    EXPECT_NE(en.code, 0);
    EXPECT_TRUE(en.err.contains(QStringLiteral("--gauge-timeout must be from 0 to 60 s"))) << en.err.toStdString();
    const auto zh = runCliInProcess(QStringList{QStringLiteral("--lang"), QStringLiteral("zh_CN")} + args);
    EXPECT_NE(zh.code, 0);
    EXPECT_TRUE(zh.err.contains(QStringLiteral("--gauge-timeout 必须在 0 到 60 s 之间"))) << zh.err.toStdString();
}

TEST(AccuracyCli, TheDeviceKeepsAnUploadedCompensationAcrossPrograms)
{
    PtySimulator sim;
    ASSERT_TRUE(sim.start(QStringLiteral("stage"), 4)) << qPrintable(sim.error());
    const QString cli = binary("benchpilot-cli");
    const QString port = sim.link();
    auto run = [&](const QStringList& args) { return runProgram(cli, QStringList{QStringLiteral("--port"), port} + args, 60000); };
    auto up = run({QStringLiteral("compensation"), QStringLiteral("upload"), QStringLiteral("--axis"), QStringLiteral("Y"),
                   example("stage-y-seed002.compensation.json"), QStringLiteral("--json")});
    ASSERT_EQ(up.exitCode, 0) << up.describe();
    auto shown = lastJson(up.out);
    EXPECT_TRUE(shown.value(QStringLiteral("present")).toBool());
    EXPECT_FALSE(shown.value(QStringLiteral("enabled")).toBool()) << "installed disabled";
    auto on = run({QStringLiteral("compensation"), QStringLiteral("enable"), QStringLiteral("--axis"), QStringLiteral("Y"), QStringLiteral("--json")});
    ASSERT_EQ(on.exitCode, 0) << on.describe();
    // A third program, a new session: the device still has it, enabled.
    auto show = run({QStringLiteral("compensation"), QStringLiteral("show"), QStringLiteral("--axis"), QStringLiteral("Y"), QStringLiteral("--json")});
    ASSERT_EQ(show.exitCode, 0) << show.describe();
    shown = lastJson(show.out);
    EXPECT_TRUE(shown.value(QStringLiteral("enabled")).toBool());
    EXPECT_FALSE(shown.value(QStringLiteral("saved")).toBool());
    EXPECT_EQ(shown.value(QStringLiteral("kind")).toString(), QStringLiteral("polynomial"));
    EXPECT_NEAR(shown.value(QStringLiteral("polynomial")).toObject().value(QStringLiteral("coefficients_um")).toArray().at(2).toDouble(), 0.0168, 1e-12);
    // A file a device could not apply is refused naming it, and the device keeps what it had.
    QTemporaryDir dir;
    const QString bad = dir.filePath(QStringLiteral("steep.compensation.json"));
    ASSERT_TRUE(writeFile(bad, R"({"schema": "benchpilot.compensation", "version": 1, "axis": "Y", "kind": "polynomial",
"polynomial": {"coefficients_um": [0, 500], "valid_from_mm": 0, "valid_to_mm": 100}, "backlash_um": 0})"));
    auto refused = run({QStringLiteral("compensation"), QStringLiteral("upload"), QStringLiteral("--axis"), QStringLiteral("Y"), bad});
    EXPECT_EQ(refused.exitCode, 1) << refused.describe();
    EXPECT_TRUE(refused.err.contains(QStringLiteral("steep.compensation.json"))) << refused.describe();
}

} // namespace

// `accuracy run` into a folder whose run has finished did nothing but print the old
// results. It still does (a script may read them), and says how to measure again; with
// --new-run the test runs again beside the finished one, and both runs are kept.
TEST(AccuracyCli, ARunIntoAFinishedFolderSaysSoAndNewRunRunsBesideIt)
{
    QTemporaryDir dir;
    const QString out = dir.filePath(QStringLiteral("x"));
    auto run = [&](const QStringList& extra) {
        QStringList args{QStringLiteral("--sim"), QStringLiteral("stage"), QStringLiteral("--json"), QStringLiteral("accuracy"),
                         QStringLiteral("run"), QStringLiteral("--home"), QStringLiteral("--time-scale"), QStringLiteral("25"),
                         QStringLiteral("--axis"), QStringLiteral("X"), QStringLiteral("--targets"), QStringLiteral("20,50"),
                         QStringLiteral("--cycles"), QStringLiteral("2"), QStringLiteral("--feed"), QStringLiteral("15"),
                         QStringLiteral("--dwell"), QStringLiteral("0.05"), QStringLiteral("--out"), out};
        return runCliInProcess(args + extra);
    };
    auto readings = [](const QString& folder) {
        const QStringList found = QDir(folder).entryList({QStringLiteral("*.readings.csv")}, QDir::Files);
        QFile f(found.isEmpty() ? QString() : QDir(folder).filePath(found.front()));
        return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
    };
    const auto first = run({});
    ASSERT_EQ(first.code, 0) << first.err.toStdString() << first.out.toStdString();
    const QByteArray firstReadings = readings(out);
    ASSERT_FALSE(firstReadings.isEmpty()) << "files: " << QDir(out).entryList().join(QLatin1Char(' ')).toStdString();

    const auto again = run({});
    ASSERT_EQ(again.code, 0) << again.err.toStdString();
    EXPECT_TRUE(again.err.contains(QStringLiteral("finished run"))) << again.err.toStdString();
    EXPECT_TRUE(again.err.contains(QStringLiteral("--new-run"))) << again.err.toStdString();
    EXPECT_FALSE(QFileInfo::exists(out + QStringLiteral("-2")));

    const auto after = run({QStringLiteral("--new-run")});
    ASSERT_EQ(after.code, 0) << after.err.toStdString() << after.out.toStdString();
    EXPECT_EQ(QDir(after.json().value(QStringLiteral("folder")).toString()), QDir(out + QStringLiteral("-2")));
    EXPECT_FALSE(readings(out + QStringLiteral("-2")).isEmpty());
    EXPECT_EQ(readings(out), firstReadings) << "the first run's readings changed";

    const auto refused = run({QStringLiteral("--new-run"), QStringLiteral("--restart")});
    EXPECT_NE(refused.code, 0);
}
