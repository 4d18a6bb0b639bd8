#pragma once
// The order in which a runner visits an axis test's targets: ISO 230-2's
// standard linear cycle. In every cycle the axis goes below the first target by
// the overrun, approaches P1, P2, … Pm from below (↑), goes past Pm by the overrun,
// and approaches Pm … P1 from above (↓). A unidirectional test returns below P1
// before each cycle and reads ↑ only. The overrun makes the final move to every
// target come from the side the reading is filed under, so the reversal of the
// drive (backlash) happens outside the measured targets.
#include "motion/metrology/linear/axis_test.h"
#include "motion/metrology/readings.h"

#include <cstddef>
#include <optional>
#include <vector>

namespace motion::metrology {

struct Stop {
    int cycle = 1;                     ///< 1-based
    Direction direction = Direction::Up;
    std::size_t targetIndex = 0;       ///< into targetsOf(test), ascending
    double targetMm = 0;
    /// Go here first (below P1 or above Pm) before moving to the target.
    std::optional<double> overrunMm;
    /// Where the final move to the target starts: the overrun point or the previous
    /// target. Below the target for ↑, above it for ↓.
    double approachFromMm = 0;
};

/// Every stop in order; empty when the test has errors (validate()).
std::vector<Stop> runSequence(const AxisTest& t);

/// targets × cycles × directions: the number of readings a complete run gives.
std::size_t readingCount(const AxisTest& t);

} // namespace motion::metrology

namespace motion::metrology {

/// Readings against the plan: the count a complete run gives (else
/// accuracy.reading_count_wrong at "readings"), each reading a stop of the plan
/// (else accuracy.reading_not_in_plan at "readings[k]": a target, direction or cycle
/// the test does not have) and every stop read (else accuracy.reading_missing for
/// the first missing one).
motion::msg::Problems checkAgainstPlan(const AxisTest& t, const std::vector<Reading>& readings);

} // namespace motion::metrology
