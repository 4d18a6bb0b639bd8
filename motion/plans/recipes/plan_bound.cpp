#include "motion/plans/recipes/plan_bound.h"

#include "motion/jerk_limited.h"
#include "motion/plans/recipes/move_time.h"

#include <algorithm>
#include <cmath>

namespace motion::plates {

namespace {
constexpr double kBoundEps = 1e-9;
constexpr double kNoJerkLimit = 1e12;

double jerkTimeLimitedS(double distance, double v, double a, double j)
{
    if (distance < kBoundEps)
        return 0;
    const auto p = motion::JerkLimitedProfile::plan(distance, motion::JerkLimits{v, a, j});
    return p ? p->duration() : 0;
}
} // namespace

double axisJerkLimit(const AxisMotion& axis)
{
    if (axis.accelTimeS <= 0)
        return kNoJerkLimit;
    const double v = std::min(axis.maxSpeed, axis.maxAccel * axis.accelTimeS / 1.5);
    return 6 * v / (axis.accelTimeS * axis.accelTimeS);
}

double restToRestS(const AxisMotion& axis, double distance)
{
    return jerkTimeLimitedS(std::abs(distance), axis.maxSpeed, axis.maxAccel, axisJerkLimit(axis));
}

double xyRestToRestS(const AxisMotion& x, const AxisMotion& y, double dx, double dy)
{
    const double len = std::hypot(dx, dy);
    if (len < kBoundEps)
        return 0;
    double v = 1e300, a = 1e300, j = 1e300;
    for (const auto& [axis, d] : {std::pair<const AxisMotion*, double>{&x, dx}, {&y, dy}}) {
        const double u = std::abs(d) / len;
        if (u < 1e-12)
            continue;
        v = std::min(v, axis->maxSpeed / u);
        a = std::min(a, axis->maxAccel / u);
        j = std::min(j, axisJerkLimit(*axis) / u);
    }
    return jerkTimeLimitedS(len, v, a, j);
}

double reachS(const AxisMotion& axis, double distance)
{
    if (distance < kBoundEps)
        return 0;
    // The hardest push from rest: jerk up to the acceleration limit, hold it,
    // jerk down to reach the top speed, cruise. Covering a distance soonest
    // with a free end speed means following that push until the distance is covered.
    const double v = axis.maxSpeed, a = axis.maxAccel, j = axisJerkLimit(axis);
    double tj = a / j, ta = 0;
    if (v < a * tj)  // the top speed comes before the full acceleration
        tj = std::sqrt(v / j);
    else
        ta = (v - a * tj) / a;
    struct Phase {
        double jerk, seconds;
    };
    const Phase phases[] = {{j, tj}, {0, ta}, {-j, tj}, {0, 1e300}};
    double s = 0, vel = 0, acc = 0, t = 0;
    for (const Phase& ph : phases) {
        auto at = [&](double dt) { return s + vel * dt + acc * dt * dt / 2 + ph.jerk * dt * dt * dt / 6; };
        if (at(ph.seconds) < distance) {
            const double dt = ph.seconds;
            s = at(dt);
            vel += acc * dt + ph.jerk * dt * dt / 2;
            acc += ph.jerk * dt;
            t += dt;
            continue;
        }
        double lo = 0, hi = std::min(ph.seconds, 1e6);
        for (int k = 0; k < 100 && hi - lo > 1e-12; ++k) {
            const double mid = (lo + hi) / 2;
            (at(mid) < distance ? lo : hi) = mid;
        }
        return t + hi;
    }
    return t;
}

double planBoundS(const RecipePlan& plan, const Deck& deck, const StartState& start)
{
    // Each visit is timed from the op's place alone (the wells as points), whichever way
    // the plan travels there. A raise that ends an op is the next visit's rise: it is
    // counted there, or on its own when something else comes first (a pump, a wait).
    double t = 0;
    double x = start.xMm, y = start.yMm, z = start.zMm;
    bool pending = false;
    double pendingZ = 0;
    auto realize = [&] {
        if (!pending)
            return;
        t += restToRestS(deck.z, z - pendingZ);
        z = pendingZ;
        pending = false;
    };
    for (std::size_t i = 0; i < plan.ops.size(); ++i) {
        const PlanOp& op = plan.ops[i];
        if (op.visitMoves > 0) {
            const double dx = op.at.x - x, dy = op.at.y - y;
            if (std::hypot(dx, dy) < kBoundEps) {
                t += restToRestS(deck.z, op.depthZMm - z);
            } else {
                t += reachS(deck.z, std::max(0.0, z - op.clearZMm));
                t += xyRestToRestS(deck.x, deck.y, dx, dy);
                t += reachS(deck.z, std::max(0.0, op.depthZMm - op.clearZMm));
            }
            x = op.at.x;
            y = op.at.y;
            z = op.depthZMm;
            pending = false;
            const MachineMove& visit = op.moves[static_cast<std::size_t>(op.visitMoves - 1)];
            if (visit.archPump) {
                // The plunger runs only while the tip is below the rim: from the clearance
                // down past it and, after the plunger, back up past it to the next visit's
                // clearance, each stretch at no more than Z's top speed. Z's way down and
                // back up is counted already (here and as the next visit's rise); the
                // plunger adds what they cannot hide.
                // A tip that stays down (for what follows in the same well) hides it behind
                // the way down alone.
                const bool staysDown = visit.leaveZMm >= op.depthZMm - kBoundEps;
                const PlanOp* next = i + 1 < plan.ops.size() && plan.ops[i + 1].visitMoves > 0 ? &plan.ops[i + 1] : nullptr;
                const double upTo = next ? std::min(visit.leaveZMm, next->clearZMm) : visit.leaveZMm;
                double below = moveTimeS({{&deck.p, visit.pumpDeltaUl}}, visit.pumpSpeed) + std::max(0.0, visit.liquidZMm - op.clearZMm) / deck.z.maxSpeed;
                double hidden = reachS(deck.z, std::max(0.0, op.depthZMm - op.clearZMm));
                if (!staysDown) {
                    below += std::max(0.0, visit.liquidZMm - upTo) / deck.z.maxSpeed;
                    hidden += reachS(deck.z, std::max(0.0, op.depthZMm - upTo));
                    pendingZ = visit.leaveZMm;
                    pending = true;
                }
                t += std::max(0.0, below - hidden);
            }
        }
        for (std::size_t k = static_cast<std::size_t>(std::max(0, op.visitMoves)); k < op.moves.size(); ++k) {
            const MachineMove& m = op.moves[k];
            switch (m.kind) {
            case MoveKind::Raise:
                pendingZ = pending ? std::min(pendingZ, m.zMm) : std::min(z, m.zMm);
                pending = true;
                break;
            case MoveKind::Travel:
                if (m.withZ) {  // an arched depart: the next visit's rise
                    pendingZ = pending ? std::min(pendingZ, m.zMm) : std::min(z, m.zMm);
                    pending = true;
                    break;
                }
                realize();
                t += xyRestToRestS(deck.x, deck.y, m.xMm - x, m.yMm - y);
                x = m.xMm;
                y = m.yMm;
                break;
            case MoveKind::Lower:
                pending = false;
                t += restToRestS(deck.z, m.zMm - z);
                z = m.zMm;
                break;
            case MoveKind::Touch:
                realize();
                t += xyRestToRestS(deck.x, deck.y, m.xMm - x, m.yMm - y);
                x = m.xMm;
                y = m.yMm;
                break;
            case MoveKind::Pump:
                realize();
                t += moveTimeS({{&deck.p, m.pumpDeltaUl}}, m.speed);
                break;
            case MoveKind::Dwell:
                realize();
                t += m.seconds;
                break;
            }
        }
    }
    realize();
    return t;
}

} // namespace motion::plates

namespace motion::plates {

std::vector<OrderComparison> compareOrders(const Recipe& recipe, const PlanContext& context, const StartState& start)
{
    std::vector<OrderComparison> out;
    for (int k = 0; k < kWellOrderCount; ++k) {
        Recipe r = recipe;
        const auto order = static_cast<WellOrder>(k);
        r.order = order;
        for (Step& s : r.steps)
            s.order = s.wells.empty() ? std::nullopt : std::optional<WellOrder>(order);
        const RecipePlan p = planRecipe(r, context, start);
        out.push_back({order, p.totalTimeS, p.boundS, p.ok()});
    }
    return out;
}

} // namespace motion::plates
