#pragma once
// Recipes on disk (benchpilot.recipe, docs/recipes.md). The reader checks the
// form (types, fields each step type takes, unknown fields); the plan
// (motion/plans/recipes/recipe_plan.h) checks the meaning (wells, volumes,
// capacity, plates). placeProblems() puts the plan's problems at their line and
// column, so `recipe validate` lists every error of both kinds at once.
#include "device/files/json_fields.h"
#include "motion/plans/recipes/recipe.h"
#include "motion/plans/recipes/recipe_plan.h"

#include <optional>
#include <string>
#include <string_view>

namespace dev::files::plates {

constexpr const char* kRecipeSchema = "benchpilot.recipe";
constexpr int kRecipeVersion = 1;

struct RecipeRead {
    /// As much of the recipe as could be read, whenever the document is a
    /// recipe: planning it finds the meaning's problems beside the form's. An
    /// unreadable step stands in as a zero-second wait, so indices stay right.
    std::optional<motion::plates::Recipe> recipe;
    bool wellFormed = false;               ///< the form had no problem: `recipe` is exactly the file
    dev::files::json::Problems problems;             ///< the form's problems (and, after placeProblems, the plan's)
    std::optional<dev::files::json::Value> root;     ///< the parsed document, for placing later problems
};

RecipeRead parseRecipe(std::string_view text);
std::string writeRecipe(const motion::plates::Recipe& recipe);

/// The plan's problems added to `read.problems` at their positions, except
/// where the reader already reported that field. Warnings say "warning: ".
void placeProblems(RecipeRead& read, const motion::msg::Problems& problems);

/// A labware reference that names a file (ends in ".json") rather than a built-in id.
bool isLabwareFile(const std::string& reference);

} // namespace dev::files::plates
