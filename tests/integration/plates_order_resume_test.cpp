// A run in each well order, killed with SIGKILL part-way on a pty simulator and
// resumed from its log: every well is done exactly once and the plunger ends at
// the sum, in the order the run was planned with (its log names it).
#include "device/english_words.h"
#include "plates_run_support.h"
#include "programs.h"
#include "pty_simulator.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <gtest/gtest.h>

#include <set>

using namespace itest;
using namespace platestest;

namespace {

ProgramRun orderCli(const QStringList& args, int timeoutMs = 60000) { return runProgram(binary("benchpilot-cli"), args, timeoutMs); }

class PlateOrderResume : public ::testing::TestWithParam<const char*> {};

} // namespace

TEST_P(PlateOrderResume, KilledAtAWellAndResumedEveryWellIsDoneOnce)
{
    const QString order = QString::fromLatin1(GetParam());
    PtySimulator sim;
    ASSERT_TRUE(sim.start(QStringLiteral("analyzer"), kRunTimeScale)) << sim.error().toStdString();
    const QStringList port{QStringLiteral("--port"), sim.link()};
    ASSERT_EQ(orderCli(port + QStringList{QStringLiteral("home")}).exitCode, 0);
    QTemporaryDir dir;
    const QString recipe = dir.filePath(QStringLiteral("ordered.recipe.json"));
    {
        QFile f(recipe);
        ASSERT_TRUE(f.open(QIODevice::WriteOnly));
        f.write(QStringLiteral(R"({"schema": "benchpilot.recipe", "version": 1, "name": "ordered", "order": "%1",
  "plates": [{"name": "samples", "slot": "1", "labware": "sbs-96", "safe_z_mm": 55, "depth_z_mm": 70}],
  "steps": [{"type": "aspirate", "wells": ["D12:D1", "A1:C12"], "volume_ul": 10}]})")
                    .arg(order)
                    .toUtf8());
    }
    // The order the plan walks: what the log must follow.
    const ProgramRun planned = orderCli({QStringLiteral("recipe"), QStringLiteral("plan"), recipe, QStringLiteral("--json"), QStringLiteral("--calibration=none")});
    ASSERT_EQ(planned.exitCode, 0) << planned.describe();
    QStringList plannedWells;
    for (const auto& op : lastJson(planned.out).value(QStringLiteral("ops")).toArray())
        plannedWells << op.toObject().value(QStringLiteral("well")).toString();
    ASSERT_EQ(plannedWells.size(), 48);

    const QString log = dir.filePath(QStringLiteral("ordered.run.jsonl"));
    QProcess first;
    first.start(binary("benchpilot-cli"), port + QStringList{QStringLiteral("recipe"), QStringLiteral("run"), recipe, QStringLiteral("--log"), log,
                                                             QStringLiteral("--calibration=none")});
    ASSERT_TRUE(first.waitForStarted(10000));
    ASSERT_TRUE(waitFor([&] { return countLog(log).dones.size() >= 12 || first.state() == QProcess::NotRunning; }, 60000));
    ASSERT_EQ(first.state(), QProcess::Running);
    first.kill();
    ASSERT_TRUE(first.waitForFinished(5000));
    const LogCounts before = countLog(log);
    ASSERT_LT(before.dones.size(), 48u);

    const QStringList resume = port + QStringList{QStringLiteral("recipe"), QStringLiteral("run"), recipe, QStringLiteral("--resume"), log,
                                                  QStringLiteral("--json"), QStringLiteral("--calibration=none")};
    ProgramRun r = orderCli(resume, 120000);
    // A run that stops again (an interrupted operation to decide, or, on a loaded machine,
    // a link given up for lost) is taken up again as an operator would: every well must
    // still be closed exactly once however many times the run resumes.
    std::set<int> interruptedOps;
    for (int again = 0; again < 4 && r.exitCode != 0; ++again) {
        const LogCounts now = countLog(log);
        for (const auto& [op, n] : now.pumps)
            if (!now.dones.count(op) && !now.skips.count(op))
                interruptedOps.insert(op);
        QStringList args = resume;
        if (r.exitCode == 1) {
            const bool moved = r.err.contains(QStringLiteral("moved in full"));
            args << (moved ? QStringLiteral("--interrupted=skip") : QStringLiteral("--interrupted=redo"));
        }
        r = orderCli(args, 120000);
    }
    ASSERT_EQ(r.exitCode, 0) << r.describe();

    const LogCounts after = countLog(log);
    for (int i = 0; i < 48; ++i) {
        SCOPED_TRACE("op " + std::to_string(i));
        EXPECT_EQ(after.dones.count(i) + after.skips.count(i), 1u) << "closed exactly once";
        if (!interruptedOps.count(i)) {
            EXPECT_EQ(after.pumps.count(i) ? after.pumps.at(i) : 0, 1) << "one plunger move: never twice";
        }
    }
    const auto st = readLog(log);
    EXPECT_TRUE(st.problems.empty()) << i18ntest::englishFormat(st.problems, "log");
    ASSERT_EQ(st.orders.size(), 1u);
    EXPECT_EQ(st.orders[0], order.toStdString()) << "the log names the order it was planned with";
    ASSERT_EQ(st.ops.size(), 48u);
    for (int i = 0; i < 48; ++i)
        EXPECT_EQ(QString::fromStdString(st.ops[static_cast<std::size_t>(i)].well), plannedWells[i]) << "op " << i << " in the planned order";
    const ProgramRun status = orderCli(port + QStringList{QStringLiteral("--json"), QStringLiteral("status")});
    const QJsonObject p = lastJson(status.out).value(QStringLiteral("axes")).toObject().value(QStringLiteral("P")).toObject();
    EXPECT_NEAR(p.value(QStringLiteral("position")).toDouble(), 480.0, 1e-6) << "every well's 10 µL, once";
}

INSTANTIATE_TEST_SUITE_P(EveryOrder, PlateOrderResume, ::testing::Values("as-written", "column-major", "snake-rows", "snake-columns", "shortest"),
                         [](const ::testing::TestParamInfo<const char*>& p) {
                             std::string n = p.param;
                             n.erase(std::remove(n.begin(), n.end(), '-'), n.end());
                             return n;
                         });
