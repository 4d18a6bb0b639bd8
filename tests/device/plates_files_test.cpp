// The plate and recipe files: every problem with its line, column and field;
// the examples load; what is written reads back the same.
#include "device/english_words.h"
#include "device/files/plates/calibration_file.h"
#include "device/files/plates/labware_file.h"
#include "device/files/recipes/recipe_file.h"
#include "device/files/recipes/recipe_loader.h"
#include "plates_support.h"

#include <QTemporaryDir>

#include <gtest/gtest.h>

using namespace dev::files::plates;
using platestest::examplePath;
using platestest::readExample;
using platestest::text;

namespace {

motion::plates::PlanContext builtinContext()
{
    motion::plates::PlanContext c;
    c.deck = builtinDeck();
    for (auto& lw : motion::plates::builtinLabware())
        c.labware[lw.id] = lw;
    return c;
}

/// Reads a recipe text and plans it on the built-in deck: the lines `recipe validate` prints.
std::string validate(const std::string& recipe)
{
    RecipeRead r = parseRecipe(recipe);
    if (r.recipe)
        placeProblems(r, motion::plates::planRecipe(*r.recipe, builtinContext()).problems);
    return i18ntest::englishFormat(r.problems, "plate.recipe.json");
}

const char* kHead = "{\n  \"schema\": \"benchpilot.recipe\",\n  \"version\": 1,\n  \"name\": \"t\",\n"
                    "  \"plates\": [{\"name\": \"samples\", \"slot\": \"1\", \"labware\": \"sbs-96\", \"safe_z_mm\": 55, \"depth_z_mm\": 70}],\n";

} // namespace

TEST(PlateFiles, TheBuiltInDeckReadsAndMatchesTheSimulatedAnalyzer)
{
    const DeckRead r = parseDeck(builtinDeckText());
    ASSERT_TRUE(r.deck) << text(r.problems);
    const motion::plates::Deck& d = *r.deck;
    EXPECT_EQ(d.plateSlots.size(), 2u);
    ASSERT_TRUE(d.station("wash"));
    EXPECT_DOUBLE_EQ(d.syringeUl, 1000);
    // Written back and read again: the same deck.
    EXPECT_EQ(writeDeck(*parseDeck(writeDeck(d)).deck), writeDeck(d));
}

TEST(PlateFiles, UnknownWellVolumeOverCapacityUnknownTypeAndMissingPlateAllAtOnce)
{
    const std::string recipe = std::string(kHead) +
        "  \"steps\": [\n"
        "    {\"type\": \"aspirate\", \"wells\": \"A1\", \"volume_ul\": 1200},\n"
        "    {\"type\": \"pipette\", \"wells\": \"A1\"},\n"
        "    {\"type\": \"aspirate\", \"plate\": \"reagents\", \"wells\": \"A1\", \"volume_ul\": 5},\n"
        "    {\"type\": \"aspirate\", \"wells\": \"B1\", \"volume_ul\": -5},\n"
        "    {\"type\": \"aspirate\", \"wells\": \"I13\", \"volume_ul\": 5}\n"
        "  ]\n}\n";
    const std::string out = validate(recipe);
    EXPECT_NE(out.find("plate.recipe.json:7:54: steps[0].volume_ul: volume over capacity: 1200.0 µL is more than the syringe holds (1000.0 µL)\n"),
              std::string::npos)
        << out;
    EXPECT_NE(out.find("plate.recipe.json:8:14: steps[1].type: unknown step type \"pipette\"; the types are aspirate, dispense, mix, "
                       "wash, air_gap, wait, touch_off\n"),
              std::string::npos)
        << out;
    EXPECT_NE(out.find("steps[2].plate: unknown plate \"reagents\""), std::string::npos) << out;
    EXPECT_NE(out.find("steps[3].volume_ul: must be more than 0 (got -5.0 µL)"), std::string::npos) << out;
    EXPECT_NE(out.find("steps[4].wells: unknown well \"I13\" on a 96-well plate"), std::string::npos) << out;
    EXPECT_EQ(std::count(out.begin(), out.end(), '\n'), 5) << out;
}

TEST(PlateFiles, MeaningProblemsCarryTheirPositions)
{
    const std::string recipe = std::string(kHead) +
        "  \"steps\": [\n"
        "    {\"type\": \"aspirate\", \"wells\": \"A1\", \"volume_ul\": 1200},\n"
        "    {\"type\": \"aspirate\", \"plate\": \"reagents\", \"wells\": \"A1\", \"volume_ul\": 5},\n"
        "    {\"type\": \"aspirate\", \"wells\": \"B1\", \"volume_ul\": -5},\n"
        "    {\"type\": \"aspirate\", \"wells\": [\"C1\", \"I13\"], \"volume_ul\": 5}\n"
        "  ]\n}\n";
    const std::string out = validate(recipe);
    EXPECT_NE(out.find("plate.recipe.json:7:54: steps[0].volume_ul: volume over capacity"), std::string::npos) << out;
    EXPECT_NE(out.find("plate.recipe.json:8:35: steps[1].plate: unknown plate \"reagents\"; the recipe's plates are \"samples\"\n"),
              std::string::npos)
        << out;
    EXPECT_NE(out.find("plate.recipe.json:9:54: steps[2].volume_ul: must be more than 0 (got -5.0 µL)\n"), std::string::npos) << out;
    EXPECT_NE(out.find("plate.recipe.json:10:42: steps[3].wells[1]: unknown well \"I13\" on a 96-well plate\n"), std::string::npos) << out;
    EXPECT_EQ(std::count(out.begin(), out.end(), '\n'), 4) << out;
}

TEST(PlateFiles, FormProblemsOfStepsAreNamed)
{
    const std::string recipe = std::string(kHead) +
        "  \"steps\": [\n"
        "    {\"type\": \"wait\", \"seconds\": 1, \"cycles\": 2},\n"
        "    {\"type\": \"mix\", \"wells\": \"A1\", \"volume\": 5},\n"
        "    {\"type\": \"dispense\", \"wells\": 7, \"volume_ul\": \"5\"}\n"
        "  ]\n}\n";
    const std::string out = validate(recipe);
    EXPECT_NE(out.find("steps[0].cycles: a wait step has no \"cycles\""), std::string::npos) << out;
    EXPECT_NE(out.find("steps[1].volume: unknown field; did you mean \"volume_ul\"?"), std::string::npos) << out;
    EXPECT_NE(out.find("steps[1].volume_ul: is missing"), std::string::npos) << out;
    EXPECT_NE(out.find("steps[2].wells: must be a well set"), std::string::npos) << out;
    EXPECT_NE(out.find("steps[2].volume_ul: must be a number, not a string"), std::string::npos) << out;
}

TEST(PlateFiles, TheExamplesLoadAndValidate)
{
    const motion::plates::Deck deck = builtinDeck();
    for (const char* name : {"sampling-96.recipe.json", "reagent-transfer.recipe.json"}) {
        const LoadedRecipe l = loadRecipe(examplePath(name), deck, {});
        EXPECT_TRUE(l.ok()) << name << ": " << i18ntest::englishFormat(l.problems);
        EXPECT_FALSE(l.plan.ops.empty());
    }
    const LoadedRecipe s = loadRecipe(examplePath("sampling-96.recipe.json"), deck, {});
    EXPECT_EQ(s.plan.ops.size(), 96u);
    EXPECT_DOUBLE_EQ(s.plan.pumpEndUl, 960);
    const LoadedRecipe t = loadRecipe(examplePath("reagent-transfer.recipe.json"), deck, {});
    // The labware file beside the recipe was read.
    ASSERT_TRUE(t.context.labware.count("reservoir-12.labware.json"));
    EXPECT_EQ(t.context.labware.at("reservoir-12.labware.json").wells.size(), 12u);
    int rounds150 = 0;
    for (const auto& op : t.plan.ops)
        rounds150 += op.type == motion::plates::StepType::Aspirate && op.step == 2;
    EXPECT_EQ(rounds150, 3) << "16 wells × 150 µL through a 1000 µL syringe";
    // Written back: the same recipe.
    const std::string once = writeRecipe(t.recipe);
    const RecipeRead again = parseRecipe(once);
    ASSERT_TRUE(again.recipe) << text(again.problems);
    EXPECT_EQ(writeRecipe(*again.recipe), once);
}

TEST(PlateFiles, AMissingLabwareFileIsReported)
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("r.recipe.json"));
    QFile f(path);
    ASSERT_TRUE(f.open(QIODevice::WriteOnly));
    std::string recipe = std::string(kHead) + "  \"steps\": [{\"type\": \"aspirate\", \"wells\": \"A1\", \"volume_ul\": 5}]\n}\n";
    recipe.replace(recipe.find("sbs-96"), 6, "nowhere.labware.json");
    f.write(recipe.c_str());
    f.close();
    const LoadedRecipe l = loadRecipe(path, builtinDeck(), {});
    EXPECT_FALSE(l.ok());
    EXPECT_NE(i18ntest::englishFormat(l.problems).find("nowhere.labware.json"), std::string::npos) << i18ntest::englishFormat(l.problems);
}

TEST(PlateFiles, AnOpentronsDefinitionTurnsIntoOurFrame)
{
    const LabwareRead r = parseLabware(readExample("deep-well-24.opentrons-labware.json"));
    ASSERT_TRUE(r.labware) << text(r.problems);
    EXPECT_TRUE(r.opentrons);
    const motion::plates::Labware& lw = *r.labware;
    EXPECT_EQ(lw.id, "benchpilot_24_deepwell_10ml");
    EXPECT_EQ(lw.rows, 4);
    EXPECT_EQ(lw.columns, 6);
    ASSERT_EQ(lw.wells.size(), 24u);
    // Opentrons: origin front-left, y to the back (A1 at y 72.24 of 85.48).
    // Ours: origin back-left, y to the front: A1 is 13.24 mm from the back edge.
    const motion::plates::Well* a1 = lw.wellNamed("A1");
    EXPECT_DOUBLE_EQ(a1->xMm, 13.88);
    EXPECT_NEAR(a1->yMm, 85.48 - 72.24, 1e-12);
    EXPECT_NEAR(lw.wellNamed("D1")->yMm, 85.48 - 12.24, 1e-12);
    EXPECT_GT(lw.wellNamed("D1")->yMm, a1->yMm) << "row D is in front of row A";
    EXPECT_EQ(a1->shape, motion::plates::WellShape::Rectangular);
    EXPECT_DOUBLE_EQ(a1->sizeXMm, 17);
    EXPECT_DOUBLE_EQ(a1->bottomZMm, 4);
    EXPECT_DOUBLE_EQ(a1->volumeUl, 10000);
    // Exported as our own format, and read back: the same plate.
    const std::string ours = writeLabware(lw);
    EXPECT_NE(ours.find("\"schema\": \"benchpilot.labware\""), std::string::npos);
    EXPECT_NE(ours.find("\"grid\""), std::string::npos) << "a regular plate is written as its grid";
    const LabwareRead back = parseLabware(ours);
    ASSERT_TRUE(back.labware) << text(back.problems);
    ASSERT_EQ(back.labware->wells.size(), 24u);
    for (std::size_t i = 0; i < 24; ++i) {
        EXPECT_NEAR(back.labware->wells[i].xMm, lw.wells[i].xMm, 1e-9);
        EXPECT_NEAR(back.labware->wells[i].yMm, lw.wells[i].yMm, 1e-9);
    }
}

TEST(PlateFiles, OpentronsProblemsAreNamed)
{
    std::string def = readExample("deep-well-24.opentrons-labware.json");
    auto swap = [](std::string& t, const std::string& from, const std::string& to) { t.replace(t.find(from), from.size(), to); };
    swap(def, "\"isTiprack\": false", "\"isTiprack\": true");
    const LabwareRead r = parseLabware(def);
    EXPECT_FALSE(r.labware);
    const std::string out = text(r.problems);
    EXPECT_NE(out.find("parameters.isTiprack: this is a tip rack, not a plate"), std::string::npos) << out;
    std::string shifted = readExample("deep-well-24.opentrons-labware.json");
    swap(shifted, "\"x\": 113.88, \"y\": 12.24", "\"x\": 125.88, \"y\": 12.24");
    const std::string out2 = text(parseLabware(shifted).problems);
    EXPECT_NE(out2.find("well D6 at (125.880 mm, 73.240 mm) does not fit on the 127.760 mm × 85.480 mm footprint"), std::string::npos) << out2;
    std::string v1 = readExample("deep-well-24.opentrons-labware.json");
    swap(v1, "\"schemaVersion\": 2", "\"schemaVersion\": 1");
    EXPECT_NE(text(parseLabware(v1).problems).find("only Opentrons labware schema 2 is read"), std::string::npos);
}

TEST(PlateFiles, OurLabwareFormatReadsBothGridAndWellLists)
{
    const LabwareRead r = parseLabware(readExample("reservoir-12.labware.json"));
    ASSERT_TRUE(r.labware) << text(r.problems);
    EXPECT_EQ(r.labware->wells.size(), 12u);
    EXPECT_NEAR(r.labware->wellNamed("A12")->xMm, 13.94 + 99, 1e-9);
    // An irregular plate is written well by well.
    motion::plates::Labware odd = *r.labware;
    odd.wells.erase(odd.wells.begin() + 3);
    const std::string text2 = writeLabware(odd);
    EXPECT_NE(text2.find("\"wells\""), std::string::npos);
    const LabwareRead back = parseLabware(text2);
    ASSERT_TRUE(back.labware) << text(back.problems);
    EXPECT_EQ(back.labware->wells.size(), 11u);
    EXPECT_FALSE(back.labware->wellNamed("A4"));
    // Built-ins export and read back the same.
    for (const auto& lw : motion::plates::builtinLabware()) {
        const LabwareRead b = parseLabware(writeLabware(lw));
        ASSERT_TRUE(b.labware) << lw.id << text(b.problems);
        EXPECT_EQ(writeLabware(*b.labware), writeLabware(lw)) << lw.id;
    }
}

TEST(PlateFiles, EveryLabwareExampleLoadsAndTheFormatKeepsIt)
{
    const QStringList names = QDir(examplePath("")).entryList({QStringLiteral("*.labware.json")}, QDir::Files);
    ASSERT_GE(names.size(), 2) << "a plate and a reservoir";
    for (const QString& name : names) {
        const LabwareRead r = parseLabware(readExample(name.toUtf8().constData()));
        ASSERT_TRUE(r.labware) << name.toStdString() << ": " << text(r.problems);
        EXPECT_FALSE(r.opentrons);
        const LabwareRead back = parseLabware(writeLabware(*r.labware));
        ASSERT_TRUE(back.labware) << name.toStdString();
        EXPECT_EQ(writeLabware(*back.labware), writeLabware(*r.labware)) << name.toStdString();
    }
    // The PCR plate: the SBS 96 grid (A1 14.38 mm from the left, 11.24 mm from the top, 9 mm pitch).
    const LabwareRead pcr = parseLabware(readExample("pcr-plate-96.labware.json"));
    ASSERT_TRUE(pcr.labware) << text(pcr.problems);
    EXPECT_EQ(pcr.labware->wells.size(), 96u);
    const motion::plates::Well* h12 = pcr.labware->wellNamed("H12");
    ASSERT_TRUE(h12);
    EXPECT_NEAR(h12->xMm, 14.38 + 11 * 9, 1e-9);
    EXPECT_NEAR(h12->yMm, 11.24 + 7 * 9, 1e-9);
    EXPECT_DOUBLE_EQ(h12->volumeUl, 200);
}

TEST(PlateFiles, CalibrationIsKeptPerSlotAndRefittedOnReading)
{
    const CalibrationRead r = parseCalibration(readExample("analyzer.calibration.json"));
    ASSERT_TRUE(r.ok()) << text(r.problems);
    ASSERT_EQ(r.calibrations.size(), 1u);
    const auto& c = r.calibrations[0];
    EXPECT_EQ(c.slot, "1");
    EXPECT_LT(c.fit.maxResidualMm, motion::plates::kResidualWarnMm);
    EXPECT_NEAR(c.fit.rotationDeg, 0.27, 0.02);
    const std::string written = writeCalibration(r.deck, r.calibrations);
    const CalibrationRead again = parseCalibration(written);
    ASSERT_TRUE(again.ok()) << text(again.problems);
    EXPECT_EQ(writeCalibration(again.deck, again.calibrations), written);
    EXPECT_NEAR(calibrationTransforms(again.calibrations).at("1").txMm, c.fit.transform.txMm, 1e-12);
}
