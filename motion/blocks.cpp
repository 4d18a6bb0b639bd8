#include "motion/blocks.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace motion {

namespace {

constexpr double kReachToleranceSteps = 0.5;  // integer S against real-valued speeds × ms

struct RawBlock {  // a block before its shape is chosen; speeds signed
    int sourceIndex;
    double steps;
    double v1, v2;
    double durationS;
};

motion::msg::Arg jointArg(int joint) { return motion::msg::integer("joint", joint, motion::msg::Unit::None); }
motion::msg::Arg blockArg(int index) { return motion::msg::integer("block", index, motion::msg::Unit::None); }

/// Chooses the shape of a block that does not change direction.
bool shapeBlock(const RawBlock& raw, BlockPlan& plan, motion::msg::Message& error, int joint)
{
    const double w1 = std::fabs(raw.v1), w2 = std::fabs(raw.v2), t0 = raw.durationS;
    const double D = std::fabs(raw.steps);
    // Direction: of the speeds if any is non-zero, else of S.
    const double dirSource = raw.v1 != 0.0 ? raw.v1 : (raw.v2 != 0.0 ? raw.v2 : raw.steps);
    plan.direction = dirSource < 0.0 ? -1 : 1;
    plan.sourceIndex = raw.sourceIndex;
    plan.steps = std::llround(D);
    plan.startSpeedStepsS = w1;
    plan.endSpeedStepsS = w2;
    plan.durationS = t0;
    const double lo = std::min(w1, w2) * t0, hi = std::max(w1, w2) * t0;
    const bool wrongWay = raw.steps != 0.0 && (raw.steps < 0.0) != (plan.direction < 0);
    if (wrongWay || D < lo - kReachToleranceSteps || D > hi + kReachToleranceSteps) {
        error = motion::msg::make("profile.block_unreachable",
                          {jointArg(joint), blockArg(raw.sourceIndex), motion::msg::real("steps", raw.steps), motion::msg::real("v1", raw.v1),
                           motion::msg::real("v2", raw.v2), motion::msg::real("t0", t0 * 1000.0, motion::msg::Unit::Ms), motion::msg::real("from", plan.direction < 0 ? -hi : lo),
                           motion::msg::real("to", plan.direction < 0 ? -lo : hi)});
        return false;
    }
    const double Dc = std::clamp(D, lo, hi);
    const double s0 = 0.5 * (w1 + w2) * t0;
    double t1 = 0.0;
    if (w1 == w2) {
        plan.shape = BlockShape::Cruise;
    } else if (w1 < w2) {
        plan.rampFirst = Dc >= s0;
        plan.shape = plan.rampFirst ? BlockShape::AccelThenCruise : BlockShape::CruiseThenAccel;
        t1 = plan.rampFirst ? 2.0 * (w2 * t0 - Dc) / (w2 - w1) : 2.0 * (Dc - w1 * t0) / (w2 - w1);
    } else {
        plan.rampFirst = Dc <= s0;
        plan.shape = plan.rampFirst ? BlockShape::DecelThenCruise : BlockShape::CruiseThenDecel;
        t1 = plan.rampFirst ? 2.0 * (Dc - w2 * t0) / (w1 - w2) : 2.0 * (w1 * t0 - Dc) / (w1 - w2);
    }
    t1 = std::clamp(t1, 0.0, t0);
    plan.rampTimeS = t1;
    plan.cruiseTimeS = t0 - t1;
    plan.accelStepsS2 = t1 > 0.0 ? (w2 - w1) / t1 : 0.0;
    plan.rampSteps = std::min<std::int64_t>(plan.steps, std::llround(0.5 * (w1 + w2) * t1));
    if (plan.shape == BlockShape::Cruise)
        plan.rampSteps = 0;
    return true;
}

}  // namespace

const char* blockShapeName(BlockShape shape)
{
    switch (shape) {
    case BlockShape::Cruise: return "cruise";
    case BlockShape::AccelThenCruise: return "accelerate-then-cruise";
    case BlockShape::CruiseThenAccel: return "cruise-then-accelerate";
    case BlockShape::DecelThenCruise: return "decelerate-then-cruise";
    case BlockShape::CruiseThenDecel: return "cruise-then-decelerate";
    }
    return "?";
}

motion::msg::Checked<JointPlan> planJointBlocks(const std::vector<Block>& blocks, double maxSpeedStepsS, int joint)
{
    using Result = motion::msg::Checked<JointPlan>;
    JointPlan out;
    out.blocks.reserve(blocks.size() + 4);
    double v1 = 0.0;
    for (std::size_t i = 0; i < blocks.size(); ++i) {
        const Block& b = blocks[i];
        const int index = static_cast<int>(i);
        if (b.durationMs == 0) {
            return Result::fail(motion::msg::make("profile.block_zero_duration", {jointArg(joint), blockArg(index)}));
        }
        if (std::fabs(static_cast<double>(b.endSpeed)) > maxSpeedStepsS) {
            return Result::fail(motion::msg::make("profile.block_too_fast", {jointArg(joint), blockArg(index),
                                                                     motion::msg::real("v2", std::abs(static_cast<double>(b.endSpeed))),
                                                                     motion::msg::real("max", maxSpeedStepsS)}));
        }
        const double v2 = b.endSpeed, t0 = b.durationMs / 1000.0;
        std::vector<RawBlock> parts;
        if (v1 * v2 < 0.0) {
            // Direction change: split at zero speed, assuming one constant deceleration through 0.
            const double ta = t0 * std::fabs(v1) / (std::fabs(v1) + std::fabs(v2));
            const double sa = std::round(0.5 * v1 * ta);  // whole microsteps on each side
            parts.push_back({index, sa, v1, 0.0, ta});
            parts.push_back({index, b.steps - sa, 0.0, v2, t0 - ta});
            ++out.splitCount;
        } else {
            parts.push_back({index, static_cast<double>(b.steps), v1, v2, t0});
        }
        for (const RawBlock& raw : parts) {
            BlockPlan plan;
            motion::msg::Message error;
            if (!shapeBlock(raw, plan, error, joint))
                return Result::fail(error);
            out.blocks.push_back(plan);
        }
        v1 = v2;
    }
    return Result::ok(std::move(out));
}

namespace {

/// Shared walk over a block's microsteps; `ramp` produces the next delay during the ramp.
template <class RampStep>
std::vector<double> walkDelays(const BlockPlan& plan, double timerHz, RampStep ramp)
{
    std::vector<double> out;
    out.reserve(static_cast<std::size_t>(plan.steps));
    const std::int64_t cruiseSteps = plan.steps - plan.rampSteps;
    const double cruiseSpeed = plan.rampFirst ? plan.endSpeedStepsS : plan.startSpeedStepsS;
    const auto cruise = [&] {
        for (std::int64_t k = 0; k < cruiseSteps; ++k)
            out.push_back(cruiseSpeed > 0.0 ? timerHz / cruiseSpeed : 0.0);
    };
    if (!plan.rampFirst)
        cruise();
    ramp(out);
    if (plan.rampFirst)
        cruise();
    return out;
}

}  // namespace

std::vector<double> exactDelaysTicks(const BlockPlan& plan, double timerHz)
{
    return walkDelays(plan, timerHz, [&](std::vector<double>& out) {
        const double a = plan.accelStepsS2;
        // Speed never drops below one microstep's worth from rest (√(2|a|)): a ramp that brakes to
        // zero still has to take its last microstep, mirroring the first one out of rest.
        const double floorSq = 2.0 * std::fabs(a);
        double vSq = plan.startSpeedStepsS * plan.startSpeedStepsS;
        for (std::int64_t k = 0; k < plan.rampSteps; ++k) {
            vSq = std::max(vSq + 2.0 * a, floorSq);
            out.push_back(timerHz / std::sqrt(vSq));
        }
    });
}

std::vector<double> taylorDelaysTicks(const BlockPlan& plan, double timerHz, double maxN, int anchorEverySteps)
{
    return walkDelays(plan, timerHz, [&](std::vector<double>& out) {
        const double a = plan.accelStepsS2;
        const double F2 = timerHz * timerHz;
        const double m = -a / F2;
        const double floorSq = 2.0 * std::fabs(a);
        double p = plan.startSpeedStepsS > 0.0 ? timerHz / plan.startSpeedStepsS : std::numeric_limits<double>::infinity();
        const double w1Sq = plan.startSpeedStepsS * plan.startSpeedStepsS;
        for (std::int64_t k = 0; k < plan.rampSteps; ++k) {
            const double n = 2.0 * a * p * p / F2;
            if (anchorEverySteps > 0 && k > 0 && k % anchorEverySteps == 0) {
                p = timerHz / std::sqrt(std::max(w1Sq + 2.0 * a * static_cast<double>(k + 1), floorSq));
            } else if (std::fabs(n) <= maxN) {
                p = p * (1.0 + m * p * p);  // the seed's recurrence
            } else {
                // Near zero speed the series diverges: take the square root for this microstep.
                const double vSq = std::max(F2 / (p * p) + 2.0 * a, floorSq);
                p = timerHz / std::sqrt(vSq);
            }
            out.push_back(p);
        }
    });
}

double taylorRecurrence(double p0, double m, std::int64_t count, double* out)
{
    double p = p0;
    for (std::int64_t i = 0; i < count; ++i) {
        p = p * (1.0 + m * p * p);
        out[i] = p;
    }
    return p;
}

double taylorStepErrorBound(double n)
{
    // Lagrange remainder of (1+n)^(-1/2) after the linear term: 3/8·(1+ξ)^(-5/2)·n², ξ between 0 and n.
    const double xi = std::min(n, 0.0);
    return 0.375 * n * n * std::pow(1.0 + xi, -2.5);
}

}  // namespace motion
