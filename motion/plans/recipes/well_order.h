#pragma once
// The order a step visits its wells in (recipe.h, WellOrder). The orders by
// rows and columns need only the wells' grid positions; "shortest" walks from
// the well written first to the nearest well left by the planned time of the
// move, then improves that walk by 2-opt (reversing a stretch while that
// shortens it; steps of more than 1024 wells keep the nearest-neighbour walk).
// Everything is deterministic: ties go to the well written first, so the same
// recipe always plans the same path and a resumed run matches its log.
#include "motion/plans/plates/transform.h"
#include "motion/plans/plates/wells.h"
#include "motion/plans/recipes/recipe.h"

#include <functional>
#include <vector>

namespace motion::plates {

/// Seconds to move the tip between two machine points; it must depend only on
/// |Δx| and |Δy| (a straight move's time does), which lets it be remembered.
using MoveCost = std::function<double(const PointMm& a, const PointMm& b)>;

/// The visiting order: indices into `ids`/`at` (same length); only "shortest" uses `cost`.
/// It never depends on where the tip stands, so a resumed run plans the sequence it logged.
std::vector<std::size_t> wellOrderIndices(WellOrder order, const std::vector<WellId>& ids, const std::vector<PointMm>& at, const MoveCost& cost);

/// The cost of visiting `at` in `sequence` starting from `from`.
double pathCost(const std::vector<std::size_t>& sequence, const std::vector<PointMm>& at, const PointMm& from, const MoveCost& cost);

} // namespace motion::plates
