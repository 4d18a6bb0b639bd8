#pragma once
// What the recipe commands share: the options naming the deck and the
// calibration, and loading a recipe with them.
#include "command.h"

#include "device/files/recipes/recipe_loader.h"

namespace app::cli {

struct RecipeSetup {
    dev::files::plates::LoadedRecipe loaded;
    motion::plates::Deck deck;
    std::vector<motion::plates::SlotCalibration> calibration;
    QString calibrationPath;  ///< "" when none is used
};

/// --deck FILE, --calibration FILE|none.
QList<QCommandLineOption> recipeSetupOptions();
/// Reads the deck, the calibration and the recipe named by the one argument.
/// Returns 0, or the exit code after reporting why not (a recipe with errors is
/// loaded: the caller decides).
int loadSetup(Invocation& inv, RecipeSetup* setup);

/// Prints every problem of a recipe that does not validate on stderr; returns Usage.
int reportInvalid(Invocation& inv, const dev::files::plates::LoadedRecipe& loaded);

/// recipe run (recipe_run.cpp).
int runRecipe(Invocation& inv);

} // namespace app::cli
