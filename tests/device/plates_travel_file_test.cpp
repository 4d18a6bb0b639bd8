// The travel rules and well orders in recipe files: version 2 travels in arches
// unless it says otherwise, version 1 as it always did; every problem with its
// line, column and field; what is written reads back the same.
#include "device/english_words.h"
#include "device/files/recipes/recipe_file.h"
#include "device/files/recipes/recipe_loader.h"
#include "plates_support.h"

#include <gtest/gtest.h>

using namespace dev::files::plates;
using platestest::examplePath;
using platestest::text;

namespace {

motion::plates::PlanContext travelContext()
{
    motion::plates::PlanContext c;
    c.deck = builtinDeck();
    for (auto& lw : motion::plates::builtinLabware())
        c.labware[lw.id] = lw;
    return c;
}

std::string checkTravel(const std::string& recipe)
{
    RecipeRead r = parseRecipe(recipe);
    if (r.recipe)
        placeProblems(r, motion::plates::planRecipe(*r.recipe, travelContext()).problems);
    return i18ntest::englishFormat(r.problems, "t.recipe.json");
}

std::string recipeText(int version, const std::string& extra, const std::string& step)
{
    return "{\n  \"schema\": \"benchpilot.recipe\",\n  \"version\": " + std::to_string(version) + ",\n  \"name\": \"t\",\n" + extra
        + "  \"plates\": [{\"name\": \"samples\", \"slot\": \"1\", \"labware\": \"sbs-96\", \"safe_z_mm\": 55, \"depth_z_mm\": 70}],\n"
          "  \"steps\": [\n    "
        + step + "\n  ]\n}\n";
}

const std::string kStep = R"({"type": "aspirate", "wells": "A1:B3", "volume_ul": 5})";

} // namespace

TEST(PlateTravelFile, VersionTwoArchesVersionOneGoesStraight)
{
    const RecipeRead v1 = parseRecipe(recipeText(1, "", kStep));
    ASSERT_TRUE(v1.recipe) << text(v1.problems);
    EXPECT_EQ(v1.recipe->travel.mode, motion::plates::TravelMode::StraightUpDown);
    const RecipeRead v2 = parseRecipe(recipeText(2, "", kStep));
    ASSERT_TRUE(v2.recipe) << text(v2.problems);
    EXPECT_EQ(v2.recipe->travel.mode, motion::plates::TravelMode::Arched);
    const RecipeRead asked = parseRecipe(recipeText(2, "  \"travel\": {\"mode\": \"straight-up-down\", \"clearance_in_plate_mm\": 3},\n", kStep));
    ASSERT_TRUE(asked.recipe) << text(asked.problems);
    EXPECT_EQ(asked.recipe->travel.mode, motion::plates::TravelMode::StraightUpDown);
    EXPECT_DOUBLE_EQ(asked.recipe->travel.clearanceInPlateMm, 3);
    EXPECT_DOUBLE_EQ(asked.recipe->travel.clearanceBetweenMm, 10);
    // Straight up and down plans exactly as version 1 does.
    EXPECT_DOUBLE_EQ(motion::plates::planRecipe(*asked.recipe, travelContext()).totalTimeS, motion::plates::planRecipe(*v1.recipe, travelContext()).totalTimeS);
    EXPECT_LT(motion::plates::planRecipe(*v2.recipe, travelContext()).totalTimeS, motion::plates::planRecipe(*v1.recipe, travelContext()).totalTimeS);
}

TEST(PlateTravelFile, BadTravelAndOrdersAreNamedWithTheirPlace)
{
    std::string out = checkTravel(recipeText(1, "  \"travel\": {\"mode\": \"arched\"},\n", kStep));
    EXPECT_NE(out.find("t.recipe.json:5:13: travel: \"travel\" needs a recipe of version 2 (this one is version 1)"), std::string::npos) << out;
    out = checkTravel(recipeText(2, "  \"travel\": {\"mode\": \"jump\", \"clearance_in_plate_mm\": -2},\n", kStep));
    EXPECT_NE(out.find("t.recipe.json:5:22: travel.mode: unknown travel mode \"jump\"; the modes are arched, straight-up-down"), std::string::npos) << out;
    EXPECT_NE(out.find("t.recipe.json:5:55: travel.clearance_in_plate_mm: a clearance counts up from the labware's top: -2.0"), std::string::npos)
        << out;
    out = checkTravel(recipeText(2, "  \"order\": \"zigzag\",\n", R"({"type": "aspirate", "wells": "A1", "volume_ul": 5, "order": "rows"},
    {"type": "wash", "station": "wash", "volume_ul": 5, "order": "shortest"},
    {"type": "aspirate", "station": "wash", "volume_ul": 5, "order": "shortest"})"));
    EXPECT_NE(out.find("t.recipe.json:5:12: order: unknown well order \"zigzag\"; the orders are as-written, column-major, snake-rows, "
                       "snake-columns, shortest"),
              std::string::npos)
        << out;
    EXPECT_NE(out.find("t.recipe.json:8:66: steps[0].order: unknown well order \"rows\""), std::string::npos) << out;
    EXPECT_NE(out.find("t.recipe.json:9:57: steps[1].order: a wash step has no \"order\""), std::string::npos) << out;
    EXPECT_NE(out.find("t.recipe.json:10:70: steps[2].order: a step at a station has no wells to put in order \"shortest\""), std::string::npos)
        << out;
}

TEST(PlateTravelFile, WrittenBackTheSameAndVersionOneStaysVersionOne)
{
    const RecipeRead v1 = parseRecipe(recipeText(1, "", kStep));
    ASSERT_TRUE(v1.recipe);
    EXPECT_NE(writeRecipe(*v1.recipe).find("\"version\": 1"), std::string::npos) << writeRecipe(*v1.recipe);
    const RecipeRead v2 = parseRecipe(recipeText(2, "  \"order\": \"shortest\",\n", R"({"type": "mix", "wells": "all", "volume_ul": 5, "order": "snake-columns"})"));
    ASSERT_TRUE(v2.recipe) << text(v2.problems);
    const std::string once = writeRecipe(*v2.recipe);
    const RecipeRead again = parseRecipe(once);
    ASSERT_TRUE(again.recipe) << text(again.problems);
    EXPECT_EQ(writeRecipe(*again.recipe), once);
    EXPECT_EQ(again.recipe->travel.mode, motion::plates::TravelMode::Arched);
    EXPECT_EQ(again.recipe->order, motion::plates::WellOrder::Shortest);
    EXPECT_EQ(again.recipe->steps[0].order, motion::plates::WellOrder::SnakeColumns);
}

TEST(PlateTravelFile, TheArchedFillExampleLoadsAndIsQuickerThanStraight)
{
    const LoadedRecipe l = loadRecipe(examplePath("fill-96-arched.recipe.json"), builtinDeck(), {});
    ASSERT_TRUE(l.ok()) << i18ntest::englishFormat(l.problems);
    EXPECT_EQ(l.recipe.travel.mode, motion::plates::TravelMode::Arched);
    EXPECT_EQ(l.plan.orders, std::vector<motion::plates::WellOrder>{motion::plates::WellOrder::SnakeRows});
    int dispensed = 0;
    for (const auto& op : l.plan.ops)
        dispensed += op.type == motion::plates::StepType::Dispense;
    EXPECT_EQ(dispensed, 96);
    EXPECT_DOUBLE_EQ(l.plan.totalDispensedUl, 4800);
    motion::plates::Recipe today = l.recipe;
    today.travel.mode = motion::plates::TravelMode::StraightUpDown;
    today.order.reset();
    const motion::plates::RecipePlan slow = motion::plates::planRecipe(today, l.context);
    EXPECT_LT(l.plan.totalTimeS, slow.totalTimeS);
    std::printf("fill-96: as written, straight %.1f s; snake rows, arched %.1f s (%.1f %% less); bound %.1f s\n", slow.totalTimeS,
                l.plan.totalTimeS, 100 * (1 - l.plan.totalTimeS / slow.totalTimeS), l.plan.boundS);
}
