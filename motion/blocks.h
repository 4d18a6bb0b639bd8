#pragma once
// Seed 004 (micro-step path planning for an arm's joints): the host sends each joint a stream of
// blocks (microsteps S, end speed V2, duration t0). The start speed V1 of a block is the previous
// block's V2 (0 for the first). Within t0 the joint must cover S and end at V2, which the seed
// does with one constant-acceleration segment (t1) and one constant-speed segment (t2), t1+t2 = t0.
//
// With w1 = |V1|, w2 = |V2|, D = |S| and s0 = (w1 + w2)/2·t0 (the steps of a ramp lasting all of
// t0), the four shapes (the seed's Fig. 2–4 and the case it leaves out) are:
//   w1 < w2, D ≥ s0: accelerate then cruise at w2,   t1 = 2(w2·t0 - D)/(w2 - w1)
//   w1 < w2, D < s0: cruise at w1 then accelerate,   t1 = 2(D - w1·t0)/(w2 - w1)
//   w1 > w2, D ≤ s0: decelerate then cruise at w2,   t1 = 2(D - w2·t0)/(w1 - w2)
//   w1 > w2, D > s0: cruise at w1 then decelerate,   t1 = 2(w1·t0 - D)/(w1 - w2)
//   w1 = w2:         cruise,                          D = w1·t0
// and a = (w2 - w1)/t1. D is reachable only inside [min(w1,w2)·t0, max(w1,w2)·t0].
// A block whose speed changes sign is split at zero speed into two blocks (seed step S3); the
// split point assumes one constant deceleration through zero, i.e. t_a = t0·w1/(w1 + w2).
//
// Per-microstep delays: speed after microstep i is v_i = √(v_{i-1}² + 2a) (one microstep of
// constant acceleration) and the timer delay is p_i = F/v_i. The seed avoids the square root with
// a first-order Taylor step, valid for |n| ≤ 1 where n = 2a·p²/F²:
//     p_i = p_{i-1}·(1 + m·p_{i-1}²),  m = -a/F²  (m < 0 accelerating, 0 cruising, > 0 braking)
// Its error per step (given an exact p_{i-1}) is (1+n)^(-1/2) - (1 - n/2) ∈ [0, 3n²/8·(1+n)^(-5/2)]:
// the recurrence always gives a slightly SHORTER delay. See taylorStepErrorBound().

#include "motion/checked.h"

#include <cstdint>
#include <vector>

namespace motion {

/// A block as it travels on the wire (seed claim 7: int32 S, int16 V2, uint16 t0).
struct Block {
    std::int32_t steps = 0;        ///< S, microsteps, signed
    std::int16_t endSpeed = 0;     ///< V2, microsteps/s, signed
    std::uint16_t durationMs = 0;  ///< t0, ms (the seed gives no unit; ms makes 16 bits span 65 s)
};

enum class BlockShape { Cruise, AccelThenCruise, CruiseThenAccel, DecelThenCruise, CruiseThenDecel };
const char* blockShapeName(BlockShape shape);

/// One block as the planner executes it (after splitting): all speeds in microsteps/s.
struct BlockPlan {
    int sourceIndex = 0;           ///< index of the wire block it came from
    std::int64_t steps = 0;        ///< |S| of this (possibly split) block
    int direction = 1;             ///< +1 or -1
    double startSpeedStepsS = 0;   ///< w1 ≥ 0
    double endSpeedStepsS = 0;     ///< w2 ≥ 0
    double durationS = 0;          ///< t0
    BlockShape shape = BlockShape::Cruise;
    double rampTimeS = 0;          ///< t1
    double cruiseTimeS = 0;        ///< t2
    double accelStepsS2 = 0;       ///< a, signed: > 0 speeds up
    std::int64_t rampSteps = 0;    ///< microsteps of the ramp (rounded); the rest cruise
    bool rampFirst = true;
};

struct JointPlan {
    std::vector<BlockPlan> blocks;  ///< in execution order, split blocks included
    int splitCount = 0;             ///< wire blocks that were split at a direction change
};

/// Validates and plans one joint's block stream. Fails with "joint J block K: …" naming the field
/// and value (t0 > 0, |V2| ≤ vMax, S reachable; 0.5-microstep tolerance on reachability).
motion::msg::Checked<JointPlan> planJointBlocks(const std::vector<Block>& blocks, double maxSpeedStepsS, int joint = 0);

/// Exact delays (timer ticks at timerHz) of every microstep of the block: F / √(v² + 2a).
std::vector<double> exactDelaysTicks(const BlockPlan& plan, double timerHz);

/// The seed's Taylor-recurrence delays. Steps where |n| > maxN (near zero speed) fall back to the
/// exact form, because the series does not converge there.
/// While braking, the recurrence amplifies its own error (each step multiplies a relative error
/// by g = (1 + 3mp²)/(1 + mp²) > 1): 1000 → 5000 → 1000 microsteps/s at 20 000 microsteps/s² ends
/// 4.4 % off. anchorEverySteps > 0 restarts the recurrence from the closed form
/// v_k² = w1² + 2a·k every that many microsteps (one square root per anchor), which keeps the
/// error at the level of one stretch (< 1 % in that example); 0 is the seed's unanchored recurrence.
std::vector<double> taylorDelaysTicks(const BlockPlan& plan, double timerHz, double maxN = 0.25,
                                      int anchorEverySteps = 0);

/// Inner loop of the recurrence: writes count delays starting from p0 (the delay before the first
/// one). Returns the last delay. m = -a/F² (see above). Hot path: no checks, no allocation.
double taylorRecurrence(double p0, double m, std::int64_t count, double* out);

/// Upper bound of one recurrence step's relative error for a given n = 2a·p²/F² (|n| < 1).
double taylorStepErrorBound(double n);

}  // namespace motion
