#pragma once
// What the Plates screen shows for step types and planned ops: translated
// names ("Air gap", "Dispense 10 µL into assay B3"). The recipe file's ids
// ("air_gap") and motion/'s English labels (the run log, the CLI) stay as they
// are; widgets keep the ids as item data.
#include "motion/plans/recipes/recipe_plan.h"

#include <QString>

namespace ui {

/// "Aspirate", "Dispense", "Mix", "Wash", "Air gap", "Wait", "Touch off".
QString stepTypeTitle(motion::plates::StepType type);

/// One op for the plan table: "Dispense 10 µL into assay B3", "Wash 200 µL at station wash".
QString opTitle(const motion::plates::PlanOp& op);

} // namespace ui
