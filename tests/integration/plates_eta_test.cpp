// The plan's own time is the run's time: the ETA shown before Run is the plan,
// and a finished run's time on the instrument's clock is within 2 % of it. The
// simulated analyzer's clock is stepped by hand (2 ms at a time, the runner
// answering between steps), so what is measured is the machine's motion, not
// how busy the computer running the test is: the plan's per-move allowance for
// the link (4 ms) is all that separates the two.
#include "device/files/recipes/recipe_loader.h"
#include "device/jobs/machine_model.h"
#include "plates_run_support.h"

#include <QCoreApplication>

#include <gtest/gtest.h>

using namespace itest;
using namespace platestest;
using dev::jobs::RecipeRunner;
using dev::jobs::RunState;

namespace {

struct Measured {
    double plannedS = 0, boundS = 0, deviceS = 0, statusS = 0;
    double etaBeforeS = 0;
};

Measured runExample(const char* name)
{
    Measured out;
    SimSession s{dev::proto::DeviceKind::Analyzer, kUnpaced};
    if (!s.connect() || !s.homeAll()) {
        ADD_FAILURE() << "no simulated analyzer";
        return out;
    }
    const dev::files::plates::LoadedRecipe l = dev::files::plates::loadRecipe(QStringLiteral(BP_SOURCE_DIR "/resources/examples/") + QLatin1String(name),
                                                              dev::files::plates::builtinDeck(), {});
    if (!l.ok()) {
        ADD_FAILURE() << name << " does not load";
        return out;
    }
    motion::plates::PlanContext c = l.context;
    c.deck = dev::jobs::deckWithDeviceMotion(c.deck, s.client.identity());
    motion::plates::StartState start;
    const auto& a = s.client.status().axes;
    start = {a[0].commanded, a[1].commanded, a[2].commanded, a[3].commanded};
    const motion::plates::RecipePlan plan = motion::plates::planRecipe(l.recipe, c, start);
    RecipeRunner runner(&s.client);
    motion::msg::Message error;
    QTemporaryDir dir;
    if (!runner.setPlan(plan, QString::fromLatin1(name), &error)) {
        ADD_FAILURE() << error;
        return out;
    }
    out.plannedS = plan.totalTimeS;
    out.boundS = plan.boundS;
    out.etaBeforeS = runner.progress().etaS;
    auto& host = s.link.host();
    host.setManualClock(true);
    const quint64 t0 = s.link.machine().timeUs();
    if (!runner.start(dir.filePath(QStringLiteral("run.jsonl")), &error)) {
        ADD_FAILURE() << error;
        return out;
    }
    for (int step = 0; step < 400000 && runner.state() != RunState::Finished && runner.state() != RunState::Stopped; ++step) {
        host.advance(0.002);
        for (int k = 0; k < 3; ++k)
            QCoreApplication::processEvents();
    }
    out.statusS = (s.link.machine().timeUs() - t0) / 1e6;
    host.setManualClock(false);
    EXPECT_EQ(runner.state(), RunState::Finished);
    out.deviceS = runner.progress().deviceS;
    return out;
}

} // namespace

TEST(PlateEta, BeforeRunTheEtaIsThePlanAndTheRunTakesItWithinTwoPercent)
{
    // fill-96-arched: the blended arches (ARCH_MOVE) with their deferred raises.
    for (const char* name : {"sampling-96.recipe.json", "reagent-transfer.recipe.json", "fill-96-arched.recipe.json"}) {
        SCOPED_TRACE(name);
        const Measured m = runExample(name);
        EXPECT_DOUBLE_EQ(m.etaBeforeS, m.plannedS) << "before Run the ETA is the plan's own time";
        ASSERT_GT(m.deviceS, 0);
        // The run's clock is the device's, read from its events: the machine's own clock agrees.
        EXPECT_NEAR(m.deviceS, m.statusS, 0.05);
        EXPECT_NEAR(m.deviceS, m.plannedS, 0.02 * m.plannedS) << "planned " << m.plannedS << " s, took " << m.deviceS << " s";
        EXPECT_LT(m.boundS, m.deviceS);
        RecordProperty(std::string(name) + ".planned_s", std::to_string(m.plannedS));
        RecordProperty(std::string(name) + ".device_s", std::to_string(m.deviceS));
        RecordProperty(std::string(name) + ".bound_s", std::to_string(m.boundS));
        std::printf("%s: planned %.1f s, took %.1f s on the device's clock (%.2f %%), bound %.1f s, run/bound %.2f\n", name, m.plannedS, m.deviceS,
                    100 * (m.deviceS / m.plannedS - 1), m.boundS, m.deviceS / m.boundS);
    }
}
