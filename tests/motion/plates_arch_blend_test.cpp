// Arched travel on a device that blends it (Deck::archedMoves, the analyzer's
// ARCH_MOVE): each visit is one move from the well before — whose raise it takes over —
// up to the clearance, across, and down, timed by motion::archTiming as the firmware
// runs it. The tip's true path against the rims is checked on the simulator
// (tests/integration/plates_arched_run_test.cpp, tests/device/sim_arch_move_test.cpp).
#include "motion/arch_timing.h"
#include "motion/message_print.h"
#include "motion/plans/recipes/move_time.h"
#include "plates_support.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace motion::plates;
using platestest::context;
using platestest::oneStep;

namespace {

Recipe archedSampling(std::vector<std::string> wells)
{
    Recipe r = oneStep(StepType::Aspirate, std::move(wells), 10);
    r.travel.mode = TravelMode::Arched;
    return r;
}

} // namespace

TEST(PlateArchBlend, AHopIsOneArchedMoveThatTakesOverTheRaiseBeforeIt)
{
    const PlanContext c = context();
    ASSERT_TRUE(c.deck.archedMoves) << "the analyzer's reference firmware blends arches";
    const RecipePlan plan = planRecipe(archedSampling({"A1:A3"}), c);
    ASSERT_TRUE(plan.ok());
    ASSERT_EQ(plan.ops.size(), 3u);
    const double clear = 75 - 14.22 - 5;
    const double opening = 6.86 / 2 - kTipWallMarginMm;
    // A1's raise is left to A2's move: no time of its own.
    const MachineMove& up = plan.ops[0].moves.back();
    EXPECT_EQ(up.kind, MoveKind::Raise);
    EXPECT_TRUE(up.deferred);
    EXPECT_DOUBLE_EQ(up.durationS, 0);
    const PlanOp& a2 = plan.ops[1];
    ASSERT_EQ(a2.visitMoves, 1);
    const MachineMove& m = a2.moves[0];
    EXPECT_TRUE(m.arch);
    EXPECT_NEAR(m.clearZMm, clear, 1e-9);
    EXPECT_NEAR(m.departMm, opening, 1e-9) << "it leaves A1 sideways within A1's opening";
    EXPECT_NEAR(m.approachMm, opening, 1e-9);
    EXPECT_NEAR(m.zMm, 70, 1e-9);
    EXPECT_NEAR(m.xMm, a2.at.x, 1e-9);
    // Its time is the blend's: less than up, across and down one after another.
    const Deck& d = c.deck;
    const auto rise = moveProfile({{&d.z, clear - 70}}, 0), xy = moveProfile({{&d.x, 9}}, 0), down = moveProfile({{&d.z, 70 - clear}}, 0);
    ASSERT_TRUE(rise && xy && down);
    const double blended = motion::archTiming(&*rise, &*xy, &*down, opening, opening).durationS;
    EXPECT_NEAR(m.durationS, blended + d.moveOverheadS, 1e-9);
    EXPECT_LT(blended, rise->duration() + xy->duration() + down->duration() - 0.2);
    // The last well ends straight up, with its own time: nothing takes it over.
    EXPECT_FALSE(plan.ops[2].moves.back().deferred);
    EXPECT_GT(plan.ops[2].moves.back().durationS, 0);
    // The first visit comes from nowhere known: it does not leave sideways.
    EXPECT_DOUBLE_EQ(plan.ops[0].moves[0].departMm, 0);
}

TEST(PlateArchBlend, SamplingNinetySixIsAtLeastATenthFasterThanStraightAndTheSameOps)
{
    const RecipePlan s = planRecipe(oneStep(StepType::Aspirate, {"A1:H12"}, 10), context());
    const RecipePlan a = planRecipe(archedSampling({"A1:H12"}), context());
    PlanContext legs = context();
    legs.deck.archedMoves = false;
    const RecipePlan l = planRecipe(archedSampling({"A1:H12"}), legs);
    ASSERT_TRUE(a.ok());
    EXPECT_EQ(a.fingerprint, s.fingerprint) << "the same ops: a log resumes in either mode";
    EXPECT_DOUBLE_EQ(a.pumpEndUl, s.pumpEndUl);
    EXPECT_LT(a.totalTimeS, l.totalTimeS);
    EXPECT_GE(1 - a.totalTimeS / s.totalTimeS, 0.10);
    EXPECT_GT(a.totalTimeS, a.boundS) << "the bound stays a bound";
    std::printf("sampling-96 planned: straight %.1f s, arched in legs %.1f s, blended arches %.1f s (%.1f %% less than straight), "
                "bound %.1f s\n",
                s.totalTimeS, l.totalTimeS, a.totalTimeS, 100 * (1 - a.totalTimeS / s.totalTimeS), a.boundS);
}

TEST(PlateArchBlend, ArchTimingWaitsForTheClearanceAndTheApproach)
{
    const auto z = motion::SeedSCurve::plan(14, 30, 0.2), xy = motion::SeedSCurve::plan(9, 60, 0.2);
    ASSERT_TRUE(z && xy);
    // No radii: one after another.
    const motion::ArchTiming none = motion::archTiming(&*z, &*xy, &*z, 0, 0);
    EXPECT_NEAR(none.xyStartS, z->duration(), 1e-12);
    EXPECT_NEAR(none.downStartS, z->duration() + xy->duration(), 1e-12);
    EXPECT_NEAR(none.durationS, 2 * z->duration() + xy->duration(), 1e-12);
    // With radii: XY is at the depart radius exactly when Z reaches the clearance, and Z
    // leaves the clearance exactly when XY is at the approach radius.
    const motion::ArchTiming t = motion::archTiming(&*z, &*xy, &*z, 3, 3);
    EXPECT_NEAR(std::abs(xy->at(z->duration() - t.xyStartS).s), 3, 1e-6);
    EXPECT_NEAR(std::abs(xy->at(t.downStartS - t.xyStartS).s), 6, 1e-6);
    EXPECT_LT(t.durationS, none.durationS);
    // A target inside the depart circle: XY may run while Z rises, ending with it at the latest.
    const motion::ArchTiming near = motion::archTiming(&*z, &*xy, nullptr, 20, 0);
    EXPECT_DOUBLE_EQ(near.xyStartS, std::max(0.0, z->duration() - xy->duration()));
}

TEST(PlateArchBlend, BetweenPlatesTheArchRisesToClearTheTallest)
{
    Recipe r = archedSampling({"A1"});
    r.plates.push_back({"tall", "2", "sbs-384", 50, 70});
    Step s = r.steps[0];
    s.plate = "tall";
    r.steps[0].plate = "samples";
    r.steps.push_back(s);
    const RecipePlan p = planRecipe(r, context());
    ASSERT_TRUE(p.ok()) << p.problems.front().message;
    ASSERT_TRUE(p.ops[1].moves[0].arch);
    EXPECT_NEAR(p.ops[1].moves[0].clearZMm, 75 - 14.22 - 10, 1e-9) << "between labware: 10 mm over the tallest";
    EXPECT_TRUE(p.ops[0].moves.back().deferred);
}

TEST(PlateArchBlend, FillingNinetySixWellsFromATroughPlannedBothWays)
{
    // Today's behaviour: a transfer in rounds (one aspiration per syringe-full), the
    // wells as written, straight up and down.
    Recipe today = oneStep(StepType::Dispense, {"all"}, 50);
    today.plates.push_back({"reagents", "2", "sbs-12", 50, 70});
    today.steps[0].plate = "samples";
    today.steps[0].source = {"reagents", "A1", ""};
    Recipe quick = today;
    quick.steps[0].distribute = true;
    quick.steps[0].disposalUl = 10;
    quick.order = WellOrder::SnakeRows;
    quick.travel.mode = TravelMode::Arched;
    const RecipePlan t = planRecipe(today, context());
    const RecipePlan q = planRecipe(quick, context());
    ASSERT_TRUE(t.ok()) << t.problems.front().path << ": " << t.problems.front().message;
    ASSERT_TRUE(q.ok()) << q.problems.front().path << ": " << q.problems.front().message;
    EXPECT_LT(q.totalTimeS, t.totalTimeS);
    // A round's disposal volume goes back into the trough's well and the next round draws
    // from it without the tip leaving it: no time planned for a move the run does not make.
    for (std::size_t i = 1; i < q.ops.size(); ++i)
        if (q.ops[i].plate == "reagents" && q.ops[i - 1].plate == "reagents" && q.ops[i - 1].well == q.ops[i].well) {
            EXPECT_TRUE(q.ops[i - 1].moves.back().deferred);
            EXPECT_DOUBLE_EQ(q.ops[i].moves[0].durationS, 0) << "op " << i;
        }
    std::printf("96 x 50 uL from a trough planned: rounds as written straight %.1f s (bound %.1f); distribute, snake rows, "
                "blended arches %.1f s (bound %.1f; %.1f %% less)\n",
                t.totalTimeS, t.boundS, q.totalTimeS, q.boundS, 100 * (1 - q.totalTimeS / t.totalTimeS));
}
