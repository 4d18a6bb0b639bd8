#pragma once
// The time-optimal bound of a plan: the least time any controller could take
// for the same ops in the same order under the axes' limits and the travel
// rules, against which a run's measured time is judged (its figure of merit).
//
// Per visit the tip rises from where it is to the clearance height over what it
// crosses (PlanOp::clearZMm), crosses in XY, and goes down again. XY may not
// cross a rim below the clearance, so the rise to it, the crossing and the
// descent from it happen one after another; taking the wells as points, that is
//     τ_reach(Z, Δz_up) + τ(XY, d) + τ_reach(Z, Δz_down)
// where τ(XY, d) is the time-optimal jerk-limited rest-to-rest move along the
// line (7 segments, each axis under its own speed, acceleration and jerk) and
// τ_reach(Z, Δ) the least time to cover Δ starting (or ending) at rest with the
// other end free: Z may carry its speed through the clearance height while XY
// starts or ends there. Moves that do not cross (a touch-off, a raise and lower
// at one place) are rest-to-rest; the plunger's moves run at the recipe's speed
// (chemistry, not motion) and waits last what they say.
//
// Jerk: a seed S-curve axis never exceeds 6·v/t² (seed_scurve.h), at most
// 6·min(vmax, amax·t2/1.5)/t2²; an axis without an acceleration time is
// acceleration-limited (jerk unbounded).
#include "motion/plans/recipes/recipe_plan.h"

namespace motion::plates {

/// The bound of `plan` in seconds (no per-move link overhead: it is a property of the motion).
double planBoundS(const RecipePlan& plan, const Deck& deck, const StartState& start = {});

/// The jerk an axis' planner never exceeds (per s³), per the rule above.
double axisJerkLimit(const AxisMotion& axis);

/// Least seconds for `distance` (≥ 0) from rest to rest on one axis.
double restToRestS(const AxisMotion& axis, double distance);
/// Least seconds for a straight XY move of (dx, dy) from rest to rest.
double xyRestToRestS(const AxisMotion& x, const AxisMotion& y, double dx, double dy);
/// Least seconds to cover `distance` (≥ 0) from rest with the end speed free.
double reachS(const AxisMotion& axis, double distance);

} // namespace motion::plates

namespace motion::plates {

/// One well order applied to every step of a recipe: its planned time and bound.
struct OrderComparison {
    WellOrder order = WellOrder::AsWritten;
    double totalTimeS = 0, boundS = 0;
    bool ok = false;  ///< the recipe plans with this order (a station step refuses any but as-written)
};
/// Every order, each given to every step that has wells (steps' own orders set aside).
std::vector<OrderComparison> compareOrders(const Recipe& recipe, const PlanContext& context, const StartState& start = {});

} // namespace motion::plates
