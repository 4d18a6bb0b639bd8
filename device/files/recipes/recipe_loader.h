#pragma once
// A recipe file and everything it needs to run: the labware it names (built in
// or files beside it), the deck, the slots' calibration. What `recipe validate`,
// `recipe plan`, `recipe run` and the Plates screen all open a recipe with.
#include "device/files/recipes/recipe_file.h"
#include "motion/plans/plates/calibration.h"

#include <QString>
#include <QStringList>

#include <vector>

namespace dev::files::plates {

struct LoadedRecipe {
    QString path;
    motion::plates::Recipe recipe;
    motion::plates::PlanContext context;
    motion::plates::RecipePlan plan;      ///< from the machine's start (0, 0, 0, 0) unless re-planned
    motion::msg::Problems problems; ///< errors and warnings, files in order (ui::words::fileProblems words them)
    bool readable = false;        ///< the recipe's form was right: `recipe` is the file
    int errorCount = 0;
    bool ok() const { return readable && errorCount == 0; }
};

/// Reads `path`, the labware files it names, and plans it on `deck` with the
/// `calibration` it finds for its slots. Never throws; everything wrong is in
/// `problems` (a file that cannot be read included).
LoadedRecipe loadRecipe(const QString& path, const motion::plates::Deck& deck, const std::vector<motion::plates::SlotCalibration>& calibration);

/// Fills `context.labware` for the plates of `recipe`: built-in ids, and labware
/// files (ours or Opentrons) relative to `baseDir`. Problems go to `problems`;
/// returns how many errors.
int resolveLabware(const motion::plates::Recipe& recipe, const QString& baseDir, motion::plates::PlanContext& context, motion::msg::Problems* problems);

} // namespace dev::files::plates
