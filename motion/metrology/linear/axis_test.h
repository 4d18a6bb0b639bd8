#pragma once
// An axis accuracy test as a person defines it (ISO 230-2's standard test):
// the targets, how many cycles, from which sides, how the axis moves and when a
// reading is taken. Plain data with a validator that reports every problem at
// once; runSequence() (run_sequence.h) turns it into the stops a runner visits.
#include "motion/metrology/problem.h"
#include "motion/metrology/linear/tolerances.h"

#include <optional>
#include <string>
#include <vector>

namespace motion::metrology {

/// Targets from start to end. ISO 230-2 asks that target positions not all sit at
/// the same phase of a periodic error (a screw's pitch, a scale's period): with
/// `irregular`, each inner target is moved off the even grid by a different
/// amount within ±p/4 of the spacing p (gridTargets() documents the rule).
struct TargetGrid {
    double startMm = 0;
    double endMm = 0;
    int count = 0;
    bool irregular = false;
};

/// When a reading is taken: after `dwellS`, once the axis's readback has stayed
/// within `toleranceUm` of its final value for `windowS`; after `timeoutS` the
/// reading is taken anyway and marked unsettled (the runner's business).
struct SettleRule {
    double toleranceUm = 1.0;
    double windowS = 0.2;
    double timeoutS = 10.0;
};

struct AxisTest {
    std::string name;
    std::string axis = "X";            ///< one capital letter
    std::vector<double> targetsMm;     ///< explicit targets, increasing; or empty and `grid`
    std::optional<TargetGrid> grid;
    int cycles = 5;                    ///< ISO 230-2 asks for 5; 2 is the least that gives a spread
    bool bidirectional = true;         ///< false: approached from below only (↑)
    double overrunMm = 1.0;            ///< past the end targets, so every approach comes from its side
    double feedMmS = 5.0;
    double dwellS = 0.5;               ///< wait after arriving, before the settle rule starts
    SettleRule settle;
    AxisTolerances tolerances;         ///< pass/fail limits; empty: not judged
};

/// What the instrument allows; empty members are not checked.
struct AxisLimits {
    std::optional<double> minMm;       ///< soft limits
    std::optional<double> maxMm;
    std::optional<double> maxFeedMmS;
};

/// Hard bounds that catch typos (a feed of 5000 mm/s, 100 000 targets).
constexpr double kMaxFeedMmS = 1000;
constexpr int kMaxTargets = 1000;
constexpr int kMaxCycles = 100;
/// ISO 230-2's recommendations: below these a test is allowed with a warning.
constexpr int kIsoCycles = 5;
constexpr int kIsoTargets = 5;

/// The regular grid start + i·p, p = (end − start)/(count − 1), rounded to the
/// nanometre. With `irregular`, inner target i (the first and last stay on start and
/// end, so the travel measured is the travel asked for) becomes
///   P_i = start + i·p + r_i,  r_i = (frac(i·φ) − ½)·p/2,  φ = (√5 − 1)/2,
/// rounded to the micrometre. frac(i·φ) is the golden-ratio sequence: it never
/// repeats and spreads evenly over [0, 1), so no two targets share the offset and any
/// period is sampled at scattered phases; |r_i| < p/4 keeps targets in order and at
/// least p/2 apart. It is deterministic, so a test file always gives the same targets.
std::vector<double> gridTargets(const TargetGrid& g);

/// The explicit list, or the grid's targets.
std::vector<double> targetsOf(const AxisTest& t);

/// Every problem: fewer than 2 targets or cycles (errors), fewer than ISO's 5
/// (warnings), targets not increasing or not finite, targets or overrun points
/// outside the soft limits, a feed that is not above 0 or above the instrument's
/// (or 1000 mm/s), settle times that contradict each other.
motion::msg::Problems validate(const AxisTest& t, const AxisLimits& limits = {});

/// The settle rule's checks alone (paths "settle.tolerance_um", …), shared by the
/// XY and circular tests.
void validateSettle(const SettleRule& s, motion::msg::Problems& out);

} // namespace motion::metrology
