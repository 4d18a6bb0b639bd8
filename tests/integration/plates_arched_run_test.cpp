// Arched travel on the simulated analyzer, its clock stepped by hand so the
// times are the machine's own and every 2 ms of the tip's true path is seen:
// over a rim (the plate's material, outside every well's opening) the tip is
// never lower than the clearance, and the run takes less time than straight up
// and down.
#include "plates_run_support.h"

#include <QCoreApplication>

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>

using namespace itest;
using namespace platestest;
using dev::jobs::RecipeRunner;
using dev::jobs::RunState;

namespace {

struct TipRun {
    double deviceS = 0;
    double plannedS = 0, boundS = 0;
    double lowestOverRimMm = -1e300;  ///< the largest Z (lowest tip) seen over material
    int samplesOverRim = 0;
    int samples = 0;
    bool finished = false;
    double plungerEndUl = 0;
    int wellsDone = 0;  ///< "done" lines of the run log for plate wells
    /// The plunger's travel out (µL) while the tip's true point was down inside each well of
    /// the plate (its opening, below its top): what each well received, from the machine.
    std::map<std::string, double> pushedIntoUl;
};

/// Runs `recipe` with the simulator's clock stepped 2 ms at a time, sampling the tip's
/// true position after each step against the sbs-96 plate in slot 1. `legs`: planned for
/// a device that does not blend arches (each arch as separate moves).
TipRun runStepped(const motion::plates::Recipe& recipe, bool legs = false)
{
    TipRun out;
    SimSession s{dev::proto::DeviceKind::Analyzer, kUnpaced};
    if (!s.connect() || !s.homeAll()) {
        ADD_FAILURE() << "no simulated analyzer";
        return out;
    }
    motion::plates::PlanContext context = builtinContext();
    context.deck.archedMoves = !legs;
    const auto& axesNow = s.client.status().axes;
    const motion::plates::RecipePlan plan = motion::plates::planRecipe(
        recipe, context, {axesNow[0].commanded, axesNow[1].commanded, axesNow[2].commanded, axesNow[3].commanded});
    out.plannedS = plan.totalTimeS;
    out.boundS = plan.boundS;
    RecipeRunner runner(&s.client);
    motion::msg::Message error;
    QTemporaryDir dir;
    if (!runner.setPlan(plan, QStringLiteral("arched"), &error)) {
        ADD_FAILURE() << error;
        return out;
    }
    const motion::plates::Labware lw = *motion::plates::findBuiltinLabware("sbs-96");
    const double ox = 8, oy = 8;  // slot 1, nominal
    auto& host = s.link.host();
    const dev::sim::SimMachine& m = s.link.machine();
    host.setManualClock(true);
    if (!runner.start(dir.filePath(QStringLiteral("run.jsonl")), &error)) {
        ADD_FAILURE() << error;
        return out;
    }
    const double topZ = 75 - lw.heightMm;
    double plungerBefore = m.workPointLogical(3);
    for (int step = 0; step < 200000; ++step) {
        host.advance(0.002);
        for (int k = 0; k < 3; ++k)
            QCoreApplication::processEvents();
        const double x = m.workPointLogical(0), y = m.workPointLogical(1), z = m.workPointLogical(2);
        const double plunger = m.workPointLogical(3);
        if (plunger < plungerBefore && z > topZ)
            for (const motion::plates::Well& w : lw.wells)
                if (std::hypot(x - ox - w.xMm, y - oy - w.yMm) < w.diameterMm / 2)
                    out.pushedIntoUl[motion::plates::wellName(w.id)] += plungerBefore - plunger;
        plungerBefore = plunger;
        ++out.samples;
        const double px = x - ox, py = y - oy;
        if (px >= 0 && py >= 0 && px <= lw.lengthMm && py <= lw.widthMm) {
            bool inOpening = false;
            for (const motion::plates::Well& w : lw.wells)
                inOpening = inOpening || std::hypot(px - w.xMm, py - w.yMm) < w.diameterMm / 2;
            if (!inOpening) {
                ++out.samplesOverRim;
                out.lowestOverRimMm = std::max(out.lowestOverRimMm, z);
            }
        }
        if (runner.state() == RunState::Finished || runner.state() == RunState::Stopped)
            break;
    }
    host.setManualClock(false);
    out.plungerEndUl = m.commandedLogical(3);
    const auto logged = readLog(dir.filePath(QStringLiteral("run.jsonl")));
    for (const auto& op : logged.ops)
        out.wellsDone += op.state == dev::files::plates::OpState::Done && op.plate == "samples";
    out.finished = runner.state() == RunState::Finished;
    out.deviceS = runner.progress().deviceS;
    return out;
}

} // namespace

TEST(PlateArchedRun, TheTipNeverCrossesARimBelowTheClearanceAndArchesAreFaster)
{
    motion::plates::Recipe straight = samplingRecipe("A1:H12", 10);
    motion::plates::Recipe arched = straight;
    arched.travel.mode = motion::plates::TravelMode::Arched;
    const TipRun a = runStepped(arched);
    ASSERT_TRUE(a.finished);
    const double clear = 75 - 14.22 - 5;
    ASSERT_GT(a.samplesOverRim, 1000) << "the path crosses rims all the time";
    EXPECT_LE(a.lowestOverRimMm, clear + 0.02) << "over a rim the tip was at Z " << a.lowestOverRimMm;
    const TipRun s = runStepped(straight);
    ASSERT_TRUE(s.finished);
    EXPECT_LE(s.lowestOverRimMm, 55 + 0.02);
    const TipRun l = runStepped(arched, true);
    ASSERT_TRUE(l.finished);
    EXPECT_LE(l.lowestOverRimMm, clear + 0.02);
    const double saved = 1 - a.deviceS / s.deviceS;
    std::printf("sampling-96 on the machine's clock: straight up-down %.1f s (planned %.1f, bound %.1f), arched in legs %.1f s, "
                "blended arches %.1f s (planned %.1f; %.1f %% less than straight; run/bound %.2f); lowest over a rim: %.3f mm "
                "(clearance %.2f)\n",
                s.deviceS, s.plannedS, s.boundS, l.deviceS, a.deviceS, a.plannedS, 100 * saved, a.deviceS / a.boundS,
                a.lowestOverRimMm, clear);
    RecordProperty("straight_s", std::to_string(s.deviceS));
    RecordProperty("arched_s", std::to_string(a.deviceS));
    EXPECT_GE(saved, 0.10) << "arched travel alone saves at least a tenth";
    EXPECT_NEAR(a.deviceS, a.plannedS, 0.02 * a.plannedS) << "the plan times the blended arches as the machine runs them";
}

// 96 wells × 50 µL from a trough: today one aspiration per round, the wells as written,
// straight up and down; against distributing (one aspiration per round with a disposal
// volume, returned), snake rows and arches, each dispense inside its arch. Every well gets
// its 50 µL either way, pushed out while the tip was below that well's rim inside its
// opening (the syringe ends where it began and each well's op is done once).
TEST(PlateArchedRun, DistributingInSnakeRowsWithArchesAgainstTodaysRounds)
{
    motion::plates::Recipe today = samplingRecipe("all", 50);
    today.plates.push_back({"reagents", "2", "sbs-12", 50, 70});
    today.steps[0].type = motion::plates::StepType::Dispense;
    today.steps[0].plate = "samples";
    today.steps[0].source = {"reagents", "A1", ""};
    motion::plates::Recipe quick = today;
    quick.steps[0].distribute = true;
    quick.steps[0].disposalUl = 10;
    quick.order = motion::plates::WellOrder::SnakeRows;
    quick.travel.mode = motion::plates::TravelMode::Arched;
    const TipRun t = runStepped(today);
    const TipRun q = runStepped(quick);
    ASSERT_TRUE(t.finished);
    ASSERT_TRUE(q.finished);
    EXPECT_EQ(t.wellsDone, 96);
    EXPECT_EQ(q.wellsDone, 96);
    EXPECT_NEAR(t.plungerEndUl, 0, 1e-6);
    EXPECT_NEAR(q.plungerEndUl, 0, 1e-6) << "each round's disposal volume went back: nothing left in the syringe";
    // What the plunger pushed out while the tip was in each well: 50 µL, either way.
    for (const TipRun* run : {&t, &q}) {
        EXPECT_EQ(run->pushedIntoUl.size(), 96u);
        for (const auto& [well, ul] : run->pushedIntoUl)
            EXPECT_NEAR(ul, 50, 0.01) << well;
    }
    const TipRun l = runStepped(quick, true);
    std::printf("the same distributed in arched legs: %.1f s (planned %.1f)\n", l.deviceS, l.plannedS);
    const double saved = 1 - q.deviceS / t.deviceS;
    std::printf("96 x 50 uL from a trough on the machine's clock: rounds as written straight %.1f s (planned %.1f, bound %.1f); "
                "distribute, snake rows, arched %.1f s (planned %.1f, bound %.1f; %.1f %% less; run/bound %.2f)\n",
                t.deviceS, t.plannedS, t.boundS, q.deviceS, q.plannedS, q.boundS, 100 * saved, q.deviceS / q.boundS);
    RecordProperty("today_s", std::to_string(t.deviceS));
    RecordProperty("distribute_s", std::to_string(q.deviceS));
    // Today's transfer already draws once per round: distributing adds the disposal volume's
    // round and returns, so what is saved comes from the order, the blended arches and the
    // plunger running inside each arch while the tip is below the well's rim (the per-well
    // volumes above, from the tip's true path, show that nothing left the tip elsewhere).
    EXPECT_GE(saved, 0.25) << "distributing, snake rows and arches save at least a quarter";
    EXPECT_NEAR(q.deviceS, q.plannedS, 0.02 * q.plannedS) << "the plan times the blended arches as the machine runs them";
}
