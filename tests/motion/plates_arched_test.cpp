// Arched travel in legs (a device that does not blend Z with XY): the tip leaves a well
// toward the next while it rises and enters the next while it goes down, staying inside
// the wells' openings while below the clearance; straight-up-down (and every recipe of
// version 1) plans as before. Blended arches: plates_arch_blend_test.cpp.
#include "motion/message_print.h"
#include "motion/plans/recipes/plan_bound.h"
#include "plates_support.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace motion::plates;
using platestest::context;
using platestest::oneStep;
using platestest::problemAt;

namespace {

Recipe arched(std::vector<std::string> wells)
{
    Recipe r = oneStep(StepType::Aspirate, std::move(wells), 10);
    r.travel.mode = TravelMode::Arched;
    return r;
}

/// A deck whose device travels arches in legs.
PlanContext legged()
{
    PlanContext c = context();
    c.deck.archedMoves = false;
    return c;
}

/// The tip's XY distance from the nearest well centre of the plan's ops.
double fromNearestWell(const RecipePlan& p, double x, double y)
{
    double best = 1e300;
    for (const PlanOp& op : p.ops)
        best = std::min(best, std::hypot(x - op.at.x, y - op.at.y));
    return best;
}

} // namespace

TEST(PlateArched, AHopLeavesRisingCrossesAtTheClearanceAndEntersGoingDown)
{
    const RecipePlan plan = planRecipe(arched({"A1:A3"}), legged());
    ASSERT_TRUE(plan.ok()) << plan.problems.front().message;
    ASSERT_EQ(plan.ops.size(), 3u);
    const double clear = 75 - 14.22 - 5;
    const double opening = 6.86 / 2 - kTipWallMarginMm;
    // A1 ends leaving toward A2: XY within A1's opening while Z rises to the clearance.
    const MachineMove& depart = plan.ops[0].moves.back();
    EXPECT_EQ(depart.kind, MoveKind::Travel);
    EXPECT_TRUE(depart.withZ);
    EXPECT_NEAR(depart.zMm, clear, 1e-9);
    EXPECT_NEAR(depart.xMm - plan.ops[0].at.x, opening, 1e-9);
    // A2: across to the edge of its opening at the clearance, then in while going down.
    const PlanOp& a2 = plan.ops[1];
    ASSERT_EQ(a2.visitMoves, 3);
    EXPECT_EQ(a2.moves[0].kind, MoveKind::Raise);
    EXPECT_DOUBLE_EQ(a2.moves[0].durationS, 0) << "already at the clearance";
    EXPECT_EQ(a2.moves[1].kind, MoveKind::Travel);
    EXPECT_FALSE(a2.moves[1].withZ);
    EXPECT_NEAR(a2.at.x - a2.moves[1].xMm, opening, 1e-9);
    EXPECT_TRUE(a2.moves[2].withZ);
    EXPECT_NEAR(a2.moves[2].zMm, 70, 1e-9);
    EXPECT_NEAR(a2.moves[2].xMm, a2.at.x, 1e-9);
    // The last well ends straight up: there is nowhere to go.
    EXPECT_EQ(plan.ops[2].moves.back().kind, MoveKind::Raise);
    EXPECT_NEAR(plan.ops[2].moves.back().zMm, clear, 1e-9);
    // Abort and a resumed run's first raise go above everything on the deck.
    EXPECT_LE(a2.safeZMm, 75 - 14.22 - 10 + 1e-9);
}

TEST(PlateArched, BelowTheClearanceTheTipIsAlwaysInsideAWellsOpening)
{
    const RecipePlan plan = planRecipe(arched({"A1:H12"}), legged());
    ASSERT_TRUE(plan.ok());
    const double clear = 75 - 14.22 - 5;
    const double opening = 6.86 / 2 - kTipWallMarginMm;
    double x = 0, y = 0, z = 0;
    for (const PlanOp& op : plan.ops)
        for (const MachineMove& m : op.moves) {
            if (m.kind == MoveKind::Travel) {
                // A move that starts or ends below the clearance stays within one opening:
                // its start and end are both within `opening` of the same well.
                const bool low = z > clear + 1e-9 || (m.withZ && m.zMm > clear + 1e-9);
                if (low) {
                    EXPECT_LE(fromNearestWell(plan, x, y), opening + 1e-9) << "op " << op.index;
                    EXPECT_LE(fromNearestWell(plan, m.xMm, m.yMm), opening + 1e-9) << "op " << op.index;
                    EXPECT_LE(std::hypot(m.xMm - x, m.yMm - y), opening + 1e-9) << "op " << op.index;
                }
                x = m.xMm;
                y = m.yMm;
                if (m.withZ)
                    z = m.zMm;
            } else if (m.kind == MoveKind::Raise) {
                z = std::min(z, m.zMm);
            } else if (m.kind == MoveKind::Lower) {
                z = m.zMm;
            }
        }
}

TEST(PlateArched, FasterThanStraightUpDownAndEverythingElseTheSame)
{
    Recipe straight = oneStep(StepType::Aspirate, {"A1:H12"}, 10);
    const RecipePlan s = planRecipe(straight, legged());
    const RecipePlan a = planRecipe(arched({"A1:H12"}), legged());
    ASSERT_TRUE(a.ok());
    EXPECT_LT(a.totalTimeS, s.totalTimeS);
    EXPECT_EQ(a.fingerprint, s.fingerprint) << "the same ops: a log resumes in either mode";
    EXPECT_DOUBLE_EQ(a.pumpEndUl, s.pumpEndUl);
    // The bound is a property of the ops and the clearances, not of how the plan travels
    // (but for the last rise, to the plan's own height: 55 mm straight, the clearance arched).
    EXPECT_NEAR(a.boundS, s.boundS, 0.05);
    EXPECT_LT(a.boundS, a.totalTimeS);
    std::printf("sampling-96 planned: straight %.1f s, arched %.1f s (%.1f %% less), bound %.1f s\n", s.totalTimeS, a.totalTimeS,
                100 * (1 - a.totalTimeS / s.totalTimeS), a.boundS);
}

TEST(PlateArched, StraightUpDownIsTodaysPlanExactly)
{
    Recipe r = oneStep(StepType::Aspirate, {"A1:B12"}, 10);
    const RecipePlan before = planRecipe(r, context());
    r.travel.mode = TravelMode::StraightUpDown;
    r.travel.clearanceInPlateMm = 3;  // clearances only shape arches (and the bound)
    const RecipePlan after = planRecipe(r, context());
    ASSERT_EQ(after.ops.size(), before.ops.size());
    for (std::size_t i = 0; i < before.ops.size(); ++i) {
        ASSERT_EQ(after.ops[i].moves.size(), before.ops[i].moves.size());
        for (std::size_t k = 0; k < before.ops[i].moves.size(); ++k) {
            EXPECT_EQ(after.ops[i].moves[k].kind, before.ops[i].moves[k].kind);
            EXPECT_DOUBLE_EQ(after.ops[i].moves[k].zMm, before.ops[i].moves[k].zMm);
            EXPECT_FALSE(after.ops[i].moves[k].withZ);
        }
    }
    EXPECT_DOUBLE_EQ(after.totalTimeS, before.totalTimeS);
}

TEST(PlateArched, ANegativeClearanceIsRefused)
{
    Recipe r = arched({"A1:A2"});
    r.travel.clearanceInPlateMm = -1;
    const RecipePlan p = planRecipe(r, context());
    EXPECT_FALSE(p.ok());
    EXPECT_EQ(problemAt(p, "travel.clearance_in_plate_mm").message.id, "recipe.clearance_below_top");
}

TEST(PlateArched, BetweenPlatesTheTipClearsTheTallest)
{
    Recipe r = arched({"A1"});
    r.plates.push_back({"tall", "2", "sbs-384", 50, 70});
    Step s = r.steps[0];
    s.plate = "tall";
    r.steps[0].plate = "samples";
    r.steps.push_back(s);
    const RecipePlan p = planRecipe(r, legged());
    ASSERT_TRUE(p.ok()) << p.problems.front().message;
    EXPECT_NEAR(p.ops[1].clearZMm, 75 - 14.22 - 10, 1e-9);
    EXPECT_NEAR(p.ops[0].moves.back().zMm, 75 - 14.22 - 10, 1e-9) << "A1 departs straight for the other plate's clearance";
}
