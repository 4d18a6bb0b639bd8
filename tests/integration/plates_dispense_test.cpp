// The dispensing side of a run on the simulated analyzer, with the shipped
// reagent-transfer example: dispenses into many wells from a source in syringe
// rounds, a touch-off after each well, mixing, washing, an air gap, a wait and
// a touch-off step. Run to the end; aborted part-way through a multi-well
// dispense and resumed from the log; killed, or its cable pulled, while a
// dispense's plunger moves and resumed: no target well is ever dispensed into
// twice, and the plunger ends where the volumes say.
#include "device/english_words.h"
#include "device/files/recipes/recipe_loader.h"
#include "plates_run_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <memory>
#include <set>

using namespace itest;
using namespace platestest;
using dev::jobs::InterruptedChoice;
using dev::jobs::InterruptedOp;
using dev::jobs::RecipeRunner;
using dev::jobs::RunState;

namespace {

QString examplePath() { return QStringLiteral(BP_SOURCE_DIR "/resources/examples/reagent-transfer.recipe.json"); }

/// One MOVE request as the host sent it, in axis units.
struct SentMove {
    quint8 mask = 0;
    bool relative = false;
    std::vector<double> targets;
};

constexpr quint8 kXy = 0b11, kZ = 0b100, kP = 0b1000;

class PlateDispense : public ::testing::Test {
protected:
    void SetUp() override
    {
        loaded = dev::files::plates::loadRecipe(examplePath(), dev::files::plates::builtinDeck(), {});
        ASSERT_TRUE(loaded.ok()) << i18ntest::englishFormat(loaded.problems);
        ASSERT_TRUE(s.connect()) << s.linkErrors.join(QLatin1Char(' ')).toStdString();
        ASSERT_TRUE(s.homeAll());
        s.link.host().setTimeScale(kRunTimeScale);
        logPath = dir.filePath(QStringLiteral("transfer.run.jsonl"));
        s.tap.beforeWrite = [this](const QByteArray& bytes) {
            for (const auto& f : framesIn(bytes))
                if (f.type == static_cast<std::uint8_t>(dev::proto::MsgType::Move))
                    if (const auto m = dev::proto::decodeMoveRequest(f.payload)) {
                        SentMove x{m->axisMask, m->relative, {}};
                        // Each axis in its own unit (mm, µL) from the wire's.
                        std::size_t k = 0;
                        for (int a = 0; a < 8 && k < m->targets.size(); ++a)
                            if (m->axisMask & (1u << a))
                                x.targets.push_back(m->targets[k++] / s.client.identity().axes[a].wireScale());
                        sent.push_back(x);
                        if (onMove)
                            onMove(sent.back());
                    }
        };
    }
    void TearDown() override { s.tap.beforeWrite = nullptr; }

    motion::plates::RecipePlan plan() const
    {
        const auto& a = s.client.status().axes;
        motion::plates::StartState st;
        if (a.size() >= 4)
            st = {a[0].commanded, a[1].commanded, a[2].commanded, a[3].commanded};
        return motion::plates::planRecipe(loaded.recipe, loaded.context, st);
    }
    motion::plates::RecipePlan resumePlan() const
    {
        return motion::plates::planRecipe(loaded.recipe, loaded.context, RecipeRunner::resumeStart(logPath, s.client));
    }
    /// A generous wall-clock bound for `p` at the sped-up clock.
    static int timeoutMs(const motion::plates::RecipePlan& p) { return static_cast<int>(p.totalTimeS / kRunTimeScale * 4000) + 30000; }
    double p() const { return s.readout('P').commanded; }

    /// Every dispense op of the plan sent its plunger move once and was closed
    /// once; it was begun once, or twice when in `restarted` (begun again after
    /// an abort that came before any liquid moved).
    void expectEachDispenseOnce(const motion::plates::RecipePlan& pl, const std::set<int>& restarted = {}) const
    {
        const LogCounts c = countLog(logPath);
        int dispenses = 0;
        for (const auto& op : pl.ops) {
            if (op.type != motion::plates::StepType::Dispense)
                continue;
            ++dispenses;
            SCOPED_TRACE(op.label());
            EXPECT_EQ(c.pumps.count(op.index) ? c.pumps.at(op.index) : 0, 1) << "one plunger move into the well: never twice";
            EXPECT_EQ(c.dones.count(op.index) + c.skips.count(op.index), 1u) << "closed exactly once";
            EXPECT_EQ(c.starts.count(op.index) ? c.starts.at(op.index) : 0, restarted.count(op.index) ? 2 : 1);
        }
        EXPECT_EQ(dispenses, 28) << "row A (12), A1:H1 and B2:H2 (15), B5";
    }

    dev::files::plates::LoadedRecipe loaded;
    SimSession s{dev::proto::DeviceKind::Analyzer, kUnpaced};
    QTemporaryDir dir;
    QString logPath;
    std::vector<SentMove> sent;
    std::function<void(const SentMove&)> onMove;
};

/// The first dispense of the 150 µL transfer's second round: part-way through the step.
int secondRoundOp(const motion::plates::RecipePlan& pl, int nth)
{
    int seen = 0;
    for (const auto& op : pl.ops)
        if (op.step == 2 && op.type == motion::plates::StepType::Dispense && op.round == 2 && seen++ == nth)
            return op.index;
    return -1;
}

/// An operator who reads the evidence (and `asked` records what was asked):
/// the liquid went in, so the well counts as done; anything else, no decision.
dev::jobs::InterruptedDecider skipWhenMovedInFull(std::vector<InterruptedOp>* asked)
{
    return [asked](const InterruptedOp& q) {
        asked->push_back(q);
        return q.evidence.id == "recipe.evidence.moved_in_full" ? InterruptedChoice::Skip : InterruptedChoice::Cancel;
    };
}

} // namespace

TEST_F(PlateDispense, TheReagentTransferExampleRunsToTheEndWithTheTipUpWheneverItTravels)
{
    const motion::plates::RecipePlan pl = plan();
    ASSERT_TRUE(pl.ok());
    // What the example promises: 150 µL into 15 wells from a 1000 µL syringe
    // is three rounds (6, 6 and 3 wells), each drawn from reagents A2 first.
    std::vector<int> rounds;
    for (const auto& op : pl.ops)
        if (op.step == 2 && op.type == motion::plates::StepType::Aspirate) {
            EXPECT_EQ(op.well, "A2");
            rounds.push_back(op.round);
        }
    EXPECT_EQ(rounds, (std::vector<int>{1, 2, 3}));

    RecipeRunner runner(&s.client);
    std::string problems;
    QObject::connect(&runner, &RecipeRunner::message, &runner, [&](const motion::msg::Message& m, bool bad) {
        if (bad)
            problems += motion::msg::debugString(m) + "\n";
    });
    motion::msg::Message error;
    ASSERT_TRUE(runner.setPlan(pl, QStringLiteral("transfer"), &error)) << error;
    const double p0 = p();
    const auto& axes = s.client.status().axes;
    double x = axes[0].commanded, y = axes[1].commanded, z = axes[2].commanded;
    sent.clear();
    ASSERT_TRUE(runner.start(logPath, &error)) << error;
    ASSERT_TRUE(waitFor([&] { return runner.state() == RunState::Finished || runner.state() == RunState::Stopped; }, timeoutMs(pl)));
    ASSERT_EQ(runner.state(), RunState::Finished) << problems;
    ASSERT_TRUE(s.waitStill());

    // The log: every op once, every dispense well exactly once, in the wells the recipe names.
    const LogCounts c = countLog(logPath);
    for (const auto& op : pl.ops) {
        EXPECT_EQ(c.starts.count(op.index) ? c.starts.at(op.index) : 0, 1) << op.label();
        EXPECT_EQ(c.dones.count(op.index) ? c.dones.at(op.index) : 0, 1) << op.label();
    }
    expectEachDispenseOnce(pl);
    const auto st = readLog(logPath);
    EXPECT_TRUE(st.finished);
    EXPECT_TRUE(st.problems.empty()) << i18ntest::englishFormat(st.problems, "log");
    std::multiset<std::string> dispensed;
    for (std::size_t i = 0; i < st.ops.size(); ++i)
        if (pl.ops[i].type == motion::plates::StepType::Dispense)
            dispensed.insert(st.ops[i].plate + " " + st.ops[i].well);
    for (const char* w : {"A1", "B1", "C1", "D1", "E1", "F1", "G1", "H1", "B2", "C2", "D2", "E2", "F2", "G2", "H2", "B5"})
        EXPECT_EQ(dispensed.count(std::string("assay ") + w), std::string(w) == "A1" ? 2u : 1u) << w << " (A1 is in row A and A1:H1)";
    for (int col = 2; col <= 12; ++col)
        EXPECT_EQ(dispensed.count("assay A" + std::to_string(col)), 1u) << "A" << col;

    // The plunger, followed through the moves sent: every µL drawn is pushed
    // out again (600 µL for row A in one round; 2250 µL in rounds of 900, 900
    // and 450; 20 µL with its 5 µL air gap into B5; mixing and washing net
    // nothing), so it ends where it began, and a round never held more than 900.
    double pump = p0, peak = p0;
    // Where each place is, and the heights that clear it and reach into it.
    struct Heights {
        double safe, depth;
    };
    std::map<std::pair<long, long>, Heights> places;
    const auto key = [](double a, double b) { return std::make_pair(std::lround(a * 1000), std::lround(b * 1000)); };
    for (const auto& op : pl.ops)
        if (!op.where().empty())
            places[key(op.at.x, op.at.y)] = {op.safeZMm, op.depthZMm};
    const Heights* over = nullptr;  // the place the tip is over, if any
    std::pair<double, double> loweredAt{x, y};
    int downs = 0, travels = 0;
    for (const SentMove& m : sent) {
        if (m.mask == kP) {
            ASSERT_TRUE(m.relative);
            pump += m.targets[0];
            peak = std::max(peak, pump);
        } else if (m.mask == kZ) {
            // Z grows downward: the tip goes down only over a well or station, and no deeper than its depth.
            if (m.targets[0] > z + 1e-6) {
                ++downs;
                EXPECT_NE(over, nullptr) << "Z sent down to " << m.targets[0] << " at (" << x << ", " << y << "), over no well";
                if (over) {
                    EXPECT_LE(m.targets[0], over->depth + 1e-6);
                }
                loweredAt = {x, y};
            }
            z = m.targets[0];
        } else if (m.mask == kXy) {
            const auto to = places.find(key(m.targets[0], m.targets[1]));
            const bool inWell = over && z > over->safe + 1e-6;
            if (inWell) {
                // A touch-off: sideways inside the well the tip went down into, and back.
                EXPECT_LE(std::hypot(m.targets[0] - loweredAt.first, m.targets[1] - loweredAt.second), 2.5 + 1e-6)
                    << "moved sideways out of the well with the tip down in it";
            } else {
                ++travels;
                ASSERT_NE(to, places.end()) << "travel to (" << m.targets[0] << ", " << m.targets[1] << "): no place of the recipe";
                EXPECT_LE(z, to->second.safe + 1e-6) << "travelled at Z " << z << " into a place that needs " << to->second.safe;
                if (over) {
                    EXPECT_LE(z, over->safe + 1e-6) << "left a place at Z " << z << " below its safe height " << over->safe;
                }
                over = &to->second;
            }
            x = m.targets[0];
            y = m.targets[1];
        } else {
            ADD_FAILURE() << "a move of axes " << int(m.mask) << " together";
        }
    }
    EXPECT_GT(downs, 40);
    EXPECT_GT(travels, 40);
    EXPECT_NEAR(pump, p0, 1e-6);
    EXPECT_NEAR(peak - p0, 900, 1e-6) << "six 150 µL wells a round";
    EXPECT_NEAR(p(), p0, 1e-6);
    EXPECT_NEAR(s.readout('P').measured, p0, 0.05);
    EXPECT_LE(s.readout('Z').commanded, 55 + 1e-6) << "the tip ends up";
    std::printf("reagent-transfer run: %zu ops, planned %.1f s\n", pl.ops.size(), pl.totalTimeS);
}

TEST_F(PlateDispense, AbortedPartWayThroughAMultiWellDispenseTheResumedRunFillsTheRestAndNoWellTwice)
{
    const motion::plates::RecipePlan pl = plan();
    const int target = secondRoundOp(pl, 1);  // the second well of round two
    ASSERT_GT(target, 0);
    const motion::plates::PlanOp& op = pl.ops[static_cast<std::size_t>(target)];
    RecipeRunner runner(&s.client);
    int current = -1;
    QObject::connect(&runner, &RecipeRunner::opStarted, &runner, [&](int i) { current = i; });
    // Abort just after the tip is sent down into the target well: before its
    // plunger move, as an operator's click would land.
    bool aborted = false;
    onMove = [&](const SentMove& m) {
        if (!aborted && current == target && m.mask == kZ && std::abs(m.targets[0] - op.depthZMm) < 1e-6) {
            aborted = true;
            QTimer::singleShot(0, &runner, [&] { runner.abort(); });
        }
    };
    motion::msg::Message error;
    ASSERT_TRUE(runner.setPlan(pl, QStringLiteral("transfer"), &error));
    ASSERT_TRUE(runner.start(logPath, &error)) << error;
    ASSERT_TRUE(waitFor([&] { return runner.state() == RunState::Stopped || runner.state() == RunState::Finished; }, timeoutMs(pl)));
    ASSERT_EQ(runner.state(), RunState::Stopped);
    ASSERT_TRUE(aborted);
    ASSERT_TRUE(s.waitStill());
    EXPECT_LE(s.readout('Z').commanded, op.safeZMm + 1e-6) << "the tip rose out of the well";
    const auto st = readLog(logPath);
    EXPECT_EQ(st.lastStop, "recipe.run.aborted");
    EXPECT_EQ(st.doneCount(), target) << "every op before it, none after";
    ASSERT_EQ(st.ops[static_cast<std::size_t>(target)].state, dev::files::plates::OpState::Started) << "no liquid had moved into " << op.well;
    const double pAtStop = p();
    // Round two drew 900 µL, and the first of its six wells took 150.
    EXPECT_NEAR(pAtStop, 750, 1e-6);

    // A new runner (as after restarting the program) continues from the log.
    onMove = nullptr;
    RecipeRunner again(&s.client);
    ASSERT_TRUE(again.setPlan(resumePlan(), QStringLiteral("transfer"), &error)) << error;
    bool asked = false;
    ASSERT_TRUE(again.resumeFromLog(logPath, [&](const InterruptedOp&) { asked = true; return InterruptedChoice::Cancel; }, &error))
        << error;
    EXPECT_FALSE(asked) << "nothing to ask: no liquid had moved";
    ASSERT_TRUE(waitFor([&] { return again.state() == RunState::Finished || again.state() == RunState::Stopped; }, timeoutMs(pl)));
    ASSERT_EQ(again.state(), RunState::Finished);
    ASSERT_TRUE(s.waitStill());
    expectEachDispenseOnce(pl, {target});
    const LogCounts c = countLog(logPath);
    for (int i = 0; i < target; ++i)
        EXPECT_EQ(c.starts.at(i), 1) << "done before the abort: not begun again (op " << i << ")";
    EXPECT_EQ(c.stops, 1);
    EXPECT_EQ(c.resumes, 1);
    EXPECT_EQ(c.finished, 1);
    EXPECT_NEAR(p(), 0, 1e-6) << "the rest of round two, round three and the end of the recipe: every µL drawn pushed out";
}

TEST_F(PlateDispense, KilledWhileThePlungerDispensesTheOperatorCountsTheWellAndItIsNotFilledAgain)
{
    const motion::plates::RecipePlan pl = plan();
    const int target = secondRoundOp(pl, 2);
    ASSERT_GT(target, 0);
    auto first = std::make_unique<RecipeRunner>(&s.client);
    int current = -1;
    QObject::connect(first.get(), &RecipeRunner::opStarted, first.get(), [&](int i) { current = i; });
    // The program dies the moment the target well's plunger move has gone out:
    // no stop line, and the analyzer finishes the move it has.
    bool killed = false;
    onMove = [&](const SentMove& m) {
        if (!killed && current == target && m.mask == kP && m.targets[0] < 0) {
            killed = true;
            QTimer::singleShot(0, [&] { first.reset(); });
        }
    };
    motion::msg::Message error;
    ASSERT_TRUE(first->setPlan(pl, QStringLiteral("transfer"), &error));
    ASSERT_TRUE(first->start(logPath, &error)) << error;
    ASSERT_TRUE(waitFor([&] { return !first; }, timeoutMs(pl)));
    onMove = nullptr;
    ASSERT_TRUE(s.waitStill());
    const auto st = readLog(logPath);
    ASSERT_EQ(st.ops[static_cast<std::size_t>(target)].state, dev::files::plates::OpState::Interrupted);
    ASSERT_EQ(st.doneCount(), target);

    RecipeRunner second(&s.client);
    ASSERT_TRUE(second.setPlan(resumePlan(), QStringLiteral("transfer"), &error)) << error;
    std::vector<InterruptedOp> asked;
    ASSERT_TRUE(second.resumeFromLog(logPath, skipWhenMovedInFull(&asked), &error)) << error;
    ASSERT_EQ(asked.size(), 1u);
    EXPECT_EQ(asked[0].op, target);
    EXPECT_EQ(asked[0].label, pl.ops[static_cast<std::size_t>(target)].label());
    EXPECT_DOUBLE_EQ(asked[0].plannedDeltaUl, -150);
    ASSERT_TRUE(waitFor([&] { return second.state() == RunState::Finished || second.state() == RunState::Stopped; }, timeoutMs(pl)));
    ASSERT_EQ(second.state(), RunState::Finished);
    ASSERT_TRUE(s.waitStill());
    expectEachDispenseOnce(pl);
    EXPECT_EQ(countLog(logPath).skips.count(target), 1u);
    EXPECT_NEAR(p(), 0, 1e-6) << "the skipped well's 150 µL went out once, by the first run";
}

TEST_F(PlateDispense, ACablePulledMidDispenseResumesInTheSameRunWithoutFillingTheWellAgain)
{
    const motion::plates::RecipePlan pl = plan();
    const int target = secondRoundOp(pl, 3);
    ASSERT_GT(target, 0);
    RecipeRunner runner(&s.client);
    int current = -1;
    QObject::connect(&runner, &RecipeRunner::opStarted, &runner, [&](int i) { current = i; });
    // The cable goes while the target well's plunger moves (the device has the
    // move, and finishes it on its own). The clock runs at real time for that
    // well so the status sees the plunger moving.
    QObject::connect(&runner, &RecipeRunner::opStarted, &runner, [&](int i) {
        if (i == target)
            s.link.host().setTimeScale(1);
    });
    bool pumpSent = false;
    onMove = [&](const SentMove& m) { pumpSent = pumpSent || (current == target && m.mask == kP && m.targets[0] < 0); };
    motion::msg::Message error;
    ASSERT_TRUE(runner.setPlan(pl, QStringLiteral("transfer"), &error));
    ASSERT_TRUE(runner.start(logPath, &error)) << error;
    ASSERT_TRUE(waitFor([&] { return (pumpSent && s.readout('P').moving) || runner.state() != RunState::Running; }, timeoutMs(pl)));
    ASSERT_EQ(runner.state(), RunState::Running);
    s.link.pair().unplug();
    ASSERT_TRUE(waitFor([&] { return runner.state() == RunState::Stopped; }, 5000));
    onMove = nullptr;
    spin(1500);  // the analyzer finishes the move it had
    s.link.pair().replug();
    ASSERT_TRUE(s.connect());
    ASSERT_TRUE(s.waitStill());
    s.link.host().setTimeScale(kRunTimeScale);
    std::vector<InterruptedOp> asked;
    ASSERT_TRUE(runner.resume(skipWhenMovedInFull(&asked), &error)) << error;
    ASSERT_EQ(asked.size(), 1u);
    EXPECT_EQ(asked[0].op, target);
    EXPECT_EQ(asked[0].evidence.id, "recipe.evidence.moved_in_full") << asked[0].evidence;
    ASSERT_TRUE(waitFor([&] { return runner.state() == RunState::Finished || runner.state() == RunState::Stopped; }, timeoutMs(pl)));
    ASSERT_EQ(runner.state(), RunState::Finished);
    ASSERT_TRUE(s.waitStill());
    expectEachDispenseOnce(pl);
    EXPECT_NEAR(p(), 0, 1e-6);
}
