// benchpilot-cli recipe validate | plan | run, as a script uses them; and the
// run killed with SIGKILL part-way on a pty simulator (whose machine outlives
// the CLI), resumed from its log: the remaining wells are done, none twice.
#include "device/english_words.h"
#include "plates_run_support.h"
#include "programs.h"
#include "pty_simulator.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <QRegularExpression>

#include <gtest/gtest.h>

using namespace itest;
using namespace platestest;

namespace {

QString example(const char* name) { return QStringLiteral(BP_SOURCE_DIR "/resources/examples/") + QLatin1String(name); }

/// Writes `text` to `name` in `dir`; its path, or "" when it could not be written.
QString writeFile(const QTemporaryDir& dir, const char* name, const char* text)
{
    const QString path = dir.filePath(QString::fromUtf8(name));
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly) || f.write(text) < 0)
        return {};
    return path;
}

ProgramRun cli(const QStringList& args, int timeoutMs = 60000) { return runProgram(binary("benchpilot-cli"), args, timeoutMs); }

} // namespace

TEST(PlateCli, ValidateListsEveryErrorAndExitsOne)
{
    QTemporaryDir dir;
    const QString path = writeFile(dir, "bad.recipe.json", R"({
  "schema": "benchpilot.recipe",
  "version": 1,
  "name": "bad",
  "plates": [{"name": "samples", "slot": "1", "labware": "sbs-96", "safe_z_mm": 55, "depth_z_mm": 70}],
  "steps": [
    {"type": "aspirate", "wells": "A1", "volume_ul": 1200},
    {"type": "pipette", "wells": "A1"},
    {"type": "aspirate", "plate": "reagents", "wells": "A1", "volume_ul": 5},
    {"type": "dispense", "wells": "I13", "volume_ul": 5}
  ]
}
)");
    ASSERT_FALSE(path.isEmpty());
    const ProgramRun r = cli({QStringLiteral("recipe"), QStringLiteral("validate"), path, QStringLiteral("--calibration"), QStringLiteral("none")});
    ASSERT_TRUE(r.finished);
    EXPECT_EQ(r.exitCode, 1) << r.describe();
    const QStringList expected = {
        QStringLiteral("bad.recipe.json:7:54: steps[0].volume_ul: volume over capacity: "),
        QStringLiteral("bad.recipe.json:8:14: steps[1].type: unknown step type \"pipette\""),
        QStringLiteral("bad.recipe.json:9:35: steps[2].plate: unknown plate \"reagents\"; the recipe's plates are \"samples\""),
        QStringLiteral("bad.recipe.json:10:35: steps[3].wells: unknown well \"I13\" on a 96-well plate"),
    };
    for (const QString& e : expected)
        EXPECT_TRUE(r.err.contains(e)) << e.toStdString() << "\n" << r.describe();
    // The numbers as the locale writes them ("1,200.0" or "1200.0"), with the unit's precision.
    EXPECT_TRUE(r.err.contains(QRegularExpression(QStringLiteral("1,?200\\.0 µL is more than the syringe holds \\(1,?000\\.0 µL\\)"))))
        << r.describe();
    const ProgramRun ok = cli({QStringLiteral("recipe"), QStringLiteral("validate"), example("reagent-transfer.recipe.json"),
                               QStringLiteral("--calibration=none")});
    EXPECT_EQ(ok.exitCode, 0) << ok.describe();
}

TEST(PlateCli, PlanGivesEachMoveAndTheTotalTimeWithoutMoving)
{
    const ProgramRun r = cli({QStringLiteral("recipe"), QStringLiteral("plan"), example("sampling-96.recipe.json"), QStringLiteral("--json"),
                              QStringLiteral("--calibration"), QStringLiteral("none")});
    ASSERT_EQ(r.exitCode, 0) << r.describe();
    const QJsonObject plan = lastJson(r.out);
    const QJsonArray ops = plan.value(QStringLiteral("ops")).toArray();
    ASSERT_EQ(ops.size(), 96);
    const QJsonObject b1 = ops.at(12).toObject();
    EXPECT_EQ(b1.value(QStringLiteral("well")).toString(), QStringLiteral("B1"));
    EXPECT_DOUBLE_EQ(b1.value(QStringLiteral("x_mm")).toDouble(), 22.38);
    EXPECT_DOUBLE_EQ(b1.value(QStringLiteral("y_mm")).toDouble(), 28.24);
    EXPECT_DOUBLE_EQ(b1.value(QStringLiteral("z_mm")).toDouble(), 70);
    EXPECT_DOUBLE_EQ(b1.value(QStringLiteral("volume_ul")).toDouble(), 10);
    QStringList kinds;
    for (const auto& m : b1.value(QStringLiteral("moves")).toArray())
        kinds << m.toObject().value(QStringLiteral("move")).toString();
    EXPECT_EQ(kinds, (QStringList{QStringLiteral("raise"), QStringLiteral("travel"), QStringLiteral("lower"), QStringLiteral("pump"),
                                  QStringLiteral("raise")}));
    double sum = 0;
    for (const auto& o : ops)
        sum += o.toObject().value(QStringLiteral("duration_s")).toDouble();
    EXPECT_NEAR(plan.value(QStringLiteral("total_time_s")).toDouble(), sum, 1e-3);
    EXPECT_DOUBLE_EQ(plan.value(QStringLiteral("pump_end_ul")).toDouble(), 960);
    EXPECT_EQ(plan.value(QStringLiteral("wells")).toArray().size(), 96);
}

TEST(PlateCli, RunRefusesAnInvalidRecipeBeforeConnecting)
{
    QTemporaryDir dir;
    const QString path = writeFile(dir, "bad.recipe.json", R"({"schema": "benchpilot.recipe", "version": 1, "name": "b",
  "plates": [{"name": "p", "slot": "1", "labware": "sbs-96", "safe_z_mm": 55, "depth_z_mm": 70}],
  "steps": [{"type": "aspirate", "wells": "A1", "volume_ul": -1}]})");
    ASSERT_FALSE(path.isEmpty());
    // A port that does not exist: the refusal comes before any attempt to open it.
    const ProgramRun r = cli({QStringLiteral("--port"), dir.filePath(QStringLiteral("nowhere")), QStringLiteral("recipe"), QStringLiteral("run"), path,
                              QStringLiteral("--calibration=none")});
    EXPECT_EQ(r.exitCode, 1) << r.describe();
    EXPECT_TRUE(r.err.contains(QStringLiteral("must be more than 0 (got -1.0 µL)"))) << r.describe();
    EXPECT_TRUE(r.err.contains(QStringLiteral("nothing moved"))) << r.describe();
    EXPECT_FALSE(r.err.contains(QStringLiteral("cannot connect"))) << r.describe();
}

TEST(PlateCli, KilledPartWayAndResumedFromItsLogEveryWellIsDoneOnce)
{
    PtySimulator sim;
    ASSERT_TRUE(sim.start(QStringLiteral("analyzer"), kRunTimeScale)) << sim.error().toStdString();
    const QStringList port{QStringLiteral("--port"), sim.link()};
    ProgramRun r = cli(port + QStringList{QStringLiteral("home")});
    ASSERT_EQ(r.exitCode, 0) << r.describe();
    QTemporaryDir dir;
    const QString log = dir.filePath(QStringLiteral("sampling.run.jsonl"));
    const QString recipe = example("sampling-96.recipe.json");

    QProcess first;
    first.start(binary("benchpilot-cli"), port + QStringList{QStringLiteral("recipe"), QStringLiteral("run"), recipe, QStringLiteral("--log"), log,
                                                             QStringLiteral("--json"), QStringLiteral("--calibration"), QStringLiteral("none")});
    ASSERT_TRUE(first.waitForStarted(10000));
    // Part-way: some 30 wells done.
    ASSERT_TRUE(waitFor([&] { return countLog(log).dones.size() >= 30 || first.state() == QProcess::NotRunning; }, 60000));
    ASSERT_EQ(first.state(), QProcess::Running) << QString::fromUtf8(first.readAllStandardError()).toStdString();
    first.kill();  // SIGKILL: no chance to write anything more
    ASSERT_TRUE(first.waitForFinished(5000));
    EXPECT_EQ(first.exitStatus(), QProcess::CrashExit);
    const LogCounts before = countLog(log);
    const int doneBefore = static_cast<int>(before.dones.size());
    ASSERT_GE(doneBefore, 30);
    ASSERT_LT(doneBefore, 96);
    EXPECT_EQ(before.finished, 0);
    EXPECT_EQ(before.stops, 0) << "killed, not stopped";

    // Resumed from the log. A well interrupted mid-aspirate is put to the
    // operator, who answers by flag after reading the evidence: the log's "pump"
    // line goes out before the plunger move, so the kill may have come before
    // the move left ("no liquid moved": do it again) or after (the analyzer
    // finished it: count it done).
    const QStringList resume = port + QStringList{QStringLiteral("recipe"), QStringLiteral("run"), recipe, QStringLiteral("--resume"), log,
                                                  QStringLiteral("--json"), QStringLiteral("--calibration"), QStringLiteral("none")};
    int interruptedOp = -1;
    r = cli(resume, 120000);
    if (r.exitCode == 1) {
        ASSERT_TRUE(r.err.contains(QStringLiteral("was interrupted after its plunger move was sent"))) << r.describe();
        for (const auto& [op, n] : before.pumps)
            if (!before.dones.count(op))
                interruptedOp = op;
        const bool moved = r.err.contains(QStringLiteral("moved in full"));
        ASSERT_TRUE(moved || r.err.contains(QStringLiteral("no liquid moved"))) << r.describe();
        r = cli(resume + QStringList{moved ? QStringLiteral("--interrupted=skip") : QStringLiteral("--interrupted=redo")}, 120000);
    }
    ASSERT_EQ(r.exitCode, 0) << r.describe();
    EXPECT_EQ(lastJson(r.out).value(QStringLiteral("event")).toString(), QStringLiteral("finished")) << r.describe();

    const LogCounts after = countLog(log);
    EXPECT_EQ(after.resumes, 1);
    EXPECT_EQ(after.finished, 1);
    for (int i = 0; i < 96; ++i) {
        SCOPED_TRACE("op " + std::to_string(i));
        EXPECT_EQ(after.dones.count(i) + after.skips.count(i), 1u) << "closed exactly once";
        if (i != interruptedOp) {
            EXPECT_EQ(after.pumps.count(i) ? after.pumps.at(i) : 0, 1) << "one plunger move: never twice";
        }
        if (i < doneBefore) {
            EXPECT_EQ(after.starts.at(i), 1) << "done before the kill: not begun again";
        }
    }
    const auto st = readLog(log);
    EXPECT_TRUE(st.problems.empty()) << i18ntest::englishFormat(st.problems, "log");
    EXPECT_EQ(st.doneCount(), 96);

    // The plunger holds every well's 10 µL, once.
    r = cli(port + QStringList{QStringLiteral("--json"), QStringLiteral("status")});
    ASSERT_EQ(r.exitCode, 0) << r.describe();
    const QJsonObject p = lastJson(r.out).value(QStringLiteral("axes")).toObject().value(QStringLiteral("P")).toObject();
    EXPECT_NEAR(p.value(QStringLiteral("position")).toDouble(), 960.0, 1e-6) << r.describe();

    // The same log again: nothing left.
    r = cli(port + QStringList{QStringLiteral("recipe"), QStringLiteral("run"), recipe, QStringLiteral("--resume"), log, QStringLiteral("--calibration"),
                               QStringLiteral("none")});
    EXPECT_EQ(r.exitCode, 2) << r.describe();
    EXPECT_TRUE(r.err.contains(QStringLiteral("finished: nothing to resume"))) << r.describe();
}

TEST(PlateCli, AnInterruptedWellNeedsTheOperatorsWord)
{
    PtySimulator sim;
    ASSERT_TRUE(sim.start(QStringLiteral("analyzer"), 4)) << sim.error().toStdString();
    const QStringList port{QStringLiteral("--port"), sim.link()};
    ASSERT_EQ(cli(port + QStringList{QStringLiteral("home")}).exitCode, 0);
    QTemporaryDir dir;
    // A slow aspirate (5 µL/s) so the kill lands while the plunger moves.
    const QString recipe = writeFile(dir, "slow.recipe.json", R"({"schema": "benchpilot.recipe", "version": 1, "name": "slow",
  "plates": [{"name": "samples", "slot": "1", "labware": "sbs-96", "safe_z_mm": 55, "depth_z_mm": 70}],
  "steps": [{"type": "aspirate", "wells": "A1:A4", "volume_ul": 20, "speed_ul_s": 5}]})");
    ASSERT_FALSE(recipe.isEmpty());
    const QString log = dir.filePath(QStringLiteral("slow.run.jsonl"));
    QProcess first;
    first.start(binary("benchpilot-cli"), port + QStringList{QStringLiteral("recipe"), QStringLiteral("run"), recipe, QStringLiteral("--log"), log,
                                                             QStringLiteral("--calibration=none")});
    ASSERT_TRUE(first.waitForStarted(10000));
    ASSERT_TRUE(waitFor(
        [&] {
            const LogCounts c = countLog(log);
            return c.pumps.count(1) && !c.dones.count(1);
        },
        60000));
    first.kill();
    ASSERT_TRUE(first.waitForFinished(5000));
    // The log's "pump" line is written before the plunger move is sent, so the
    // kill came either before the move left (the plunger at 20 µL) or after
    // (the analyzer finished it: 40 µL). The evidence says which.
    ASSERT_TRUE(waitFor([&] { return lastJson(cli(port + QStringList{QStringLiteral("--json"), QStringLiteral("status")}).out)
                                         .value(QStringLiteral("axes")).toObject().value(QStringLiteral("P")).toObject()
                                         .value(QStringLiteral("moving")) == false; },
                        10000));
    ProgramRun st = cli(port + QStringList{QStringLiteral("--json"), QStringLiteral("status")});
    const double p0 = lastJson(st.out).value(QStringLiteral("axes")).toObject().value(QStringLiteral("P")).toObject().value(QStringLiteral("position")).toDouble();
    ASSERT_TRUE(std::abs(p0 - 20) < 1e-6 || std::abs(p0 - 40) < 1e-6) << st.describe();
    // Without a decision: refused, and the log untouched.
    ProgramRun r = cli(port + QStringList{QStringLiteral("recipe"), QStringLiteral("run"), recipe, QStringLiteral("--resume"), log,
                                          QStringLiteral("--calibration=none")});
    EXPECT_EQ(r.exitCode, 1) << r.describe();
    EXPECT_TRUE(r.err.contains(QStringLiteral("aspirate 20.0 µL from samples A2 was interrupted after its plunger move was sent"))) << r.describe();
    EXPECT_TRUE(r.err.contains(QStringLiteral("--interrupted=skip"))) << r.describe();
    EXPECT_TRUE(r.err.contains(std::abs(p0 - 40) < 1e-6 ? QStringLiteral("its liquid most likely moved in full") : QStringLiteral("no liquid moved")))
        << r.describe();
    EXPECT_EQ(countLog(log).resumes, 0);
    // Redo: A2 is drawn from again, in full.
    r = cli(port + QStringList{QStringLiteral("recipe"), QStringLiteral("run"), recipe, QStringLiteral("--resume"), log, QStringLiteral("--interrupted"),
                               QStringLiteral("redo"), QStringLiteral("--calibration=none")},
            60000);
    ASSERT_EQ(r.exitCode, 0) << r.describe();
    r = cli(port + QStringList{QStringLiteral("--json"), QStringLiteral("status")});
    const QJsonObject p = lastJson(r.out).value(QStringLiteral("axes")).toObject().value(QStringLiteral("P")).toObject();
    EXPECT_NEAR(p.value(QStringLiteral("position")).toDouble(), p0 + 60.0, 1e-6) << "A2 once more in full, then A3 and A4";
}

TEST(PlateCli, OnTheInProcessSimulatorHomeThenRunDispensesEndToEnd)
{
    // Every --sim command starts a fresh simulator at real time, so the recipe
    // is short: draw 30 µL, dispense 10 into three wells with a touch-off,
    // wash. --home makes the fresh machine runnable.
    QTemporaryDir dir;
    const QString recipe = writeFile(dir, "short.recipe.json", R"({"schema": "benchpilot.recipe", "version": 1, "name": "short",
  "plates": [{"name": "samples", "slot": "1", "labware": "sbs-96", "safe_z_mm": 55, "depth_z_mm": 70}],
  "steps": [{"type": "aspirate", "wells": "A1", "volume_ul": 30},
            {"type": "dispense", "wells": "B1:B3", "volume_ul": 10, "touch_off_mm": 1},
            {"type": "wash", "station": "wash", "volume_ul": 20}]})");
    ASSERT_FALSE(recipe.isEmpty());
    const QString log = dir.filePath(QStringLiteral("short.run.jsonl"));
    const QStringList run{QStringLiteral("--sim"), QStringLiteral("analyzer"), QStringLiteral("--json"), QStringLiteral("recipe"), QStringLiteral("run"),
                          recipe, QStringLiteral("--log"), log, QStringLiteral("--calibration=none")};

    // Without --home a fresh simulator is refused before anything moves.
    ProgramRun r = cli(run);
    EXPECT_NE(r.exitCode, 0) << r.describe();
    EXPECT_TRUE(r.err.contains(QStringLiteral("home the analyzer first"))) << r.describe();
    EXPECT_FALSE(QFileInfo::exists(log)) << "no log for a run that never began";

    r = cli(run + QStringList{QStringLiteral("--home")}, 120000);
    ASSERT_EQ(r.exitCode, 0) << r.describe();
    const QJsonObject last = lastJson(r.out);
    EXPECT_EQ(last.value(QStringLiteral("event")).toString(), QStringLiteral("finished")) << r.describe();
    EXPECT_EQ(last.value(QStringLiteral("ops_done")).toInt(), 5);
    QStringList dispensed;
    for (const QString& line : r.out.split(QLatin1Char('\n'), Qt::SkipEmptyParts)) {
        const QJsonObject o = QJsonDocument::fromJson(line.toUtf8()).object();
        if (o.value(QStringLiteral("event")) == QStringLiteral("done") && o.value(QStringLiteral("kind")) == QStringLiteral("dispense"))
            dispensed << o.value(QStringLiteral("well")).toString();
    }
    EXPECT_EQ(dispensed, (QStringList{QStringLiteral("B1"), QStringLiteral("B2"), QStringLiteral("B3")})) << r.describe();
    const LogCounts c = countLog(log);
    for (int i = 0; i < 5; ++i) {
        EXPECT_EQ(c.dones.count(i) ? c.dones.at(i) : 0, 1) << "op " << i;
        EXPECT_EQ(c.pumps.count(i) ? c.pumps.at(i) : 0, 1) << "op " << i;
    }
    EXPECT_EQ(c.finished, 1);
    // The log's plunger: 30 µL drawn, 10 out per well, the wash nets nothing.
    const auto st = readLog(log);
    ASSERT_EQ(st.ops.size(), 5u);
    ASSERT_TRUE(st.ops[3].pumpEndUl);
    EXPECT_NEAR(*st.ops[3].pumpEndUl, 0, 1e-6);
    ASSERT_TRUE(st.lastPumpUl);
    EXPECT_NEAR(*st.lastPumpUl, 0, 1e-6);
}

TEST(PlateCli, ValidateJsonIsTheSameInEveryLanguageAndTheTextFollowsLang)
{
    QTemporaryDir dir;
    const QString path = writeFile(dir, "bad.recipe.json", R"({
  "schema": "benchpilot.recipe",
  "version": 1,
  "plates": [{"name": "samples", "slot": "1", "labware": "sbs-96", "safe_z_mm": 55, "depth_z_mm": 70}],
  "steps": [{"type": "dispense", "wells": "I13", "volume_ul": 5}]
}
)");
    ASSERT_FALSE(path.isEmpty());
    const QStringList args = {QStringLiteral("recipe"), QStringLiteral("validate"), path, QStringLiteral("--calibration=none"), QStringLiteral("--json")};
    const ProgramRun en = cli(args);
    const ProgramRun zh = cli(QStringList(args) << QStringLiteral("--lang") << QStringLiteral("zh_CN"));
    ASSERT_EQ(en.exitCode, 1) << en.describe();
    EXPECT_EQ(zh.out, en.out) << "--json must not change with the language";
    // A message in JSON: its id, typed arguments and the English sentence, with its place.
    const QJsonObject e = lastJson(en.out).value(QStringLiteral("errors")).toArray().at(0).toObject();
    EXPECT_EQ(e.value(QStringLiteral("id")).toString(), QStringLiteral("plate.unknown_well"));
    EXPECT_EQ(e.value(QStringLiteral("args")).toObject().value(QStringLiteral("wells")).toInt(), 96);
    EXPECT_EQ(e.value(QStringLiteral("message")).toString(), QStringLiteral("unknown well \"I13\" on a 96-well plate"));
    EXPECT_EQ(e.value(QStringLiteral("field")).toString(), QStringLiteral("steps[0].wells"));
    EXPECT_EQ(e.value(QStringLiteral("line")).toInt(), 5);
    // The text for people: English by default, Chinese when asked.
    const QStringList text = {QStringLiteral("recipe"), QStringLiteral("validate"), path, QStringLiteral("--calibration=none")};
    EXPECT_TRUE(cli(text).err.contains(QStringLiteral("unknown well \"I13\" on a 96-well plate")));
    const ProgramRun chinese = cli(QStringList(text) << QStringLiteral("--lang=zh_CN"));
    EXPECT_TRUE(chinese.err.contains(QStringLiteral("96 孔板上没有孔 \"I13\""))) << chinese.describe();
}
