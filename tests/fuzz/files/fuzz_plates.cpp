// Fuzz targets for the plate and recipe files: "recipe", "labware" (ours and
// Opentrons), "deck", "calibration" and "run-log". Invariants: no input
// crashes or hangs a reader; what a reader accepts writes out and reads back
// the same; a recipe that validates never asks for a move outside the machine
// or a plunger past its ends.
#include "fuzz_files.h"

#include "device/files/plates/calibration_file.h"
#include "device/files/plates/deck_file.h"
#include "device/files/plates/labware_file.h"
#include "device/files/recipes/recipe_file.h"
#include "device/files/recipes/run_log.h"

#include <cmath>

namespace {

using fuzzfiles::fail;

motion::plates::PlanContext context()
{
    static const motion::plates::PlanContext c = [] {
        motion::plates::PlanContext x;
        x.deck = dev::files::plates::builtinDeck();
        for (auto& lw : motion::plates::builtinLabware())
            x.labware[lw.id] = lw;
        return x;
    }();
    return c;
}

std::vector<std::string> recipeSeeds()
{
    std::vector<std::string> s = fuzzfiles::exampleFiles(".recipe.json");
    s.push_back(R"({"schema":"benchpilot.recipe","version":1,"name":"all",
"plates":[{"name":"a","slot":"1","labware":"sbs-384","safe_z_mm":55,"depth_z_mm":70},{"name":"b","slot":"2","labware":"sbs-6","safe_z_mm":50,"depth_z_mm":70}],
"steps":[{"type":"dispense","plate":"a","wells":["A1:C4","P24"],"volume_ul":100,"source":{"plate":"b","well":"A1"},"touch_off_mm":1},
{"type":"mix","plate":"b","wells":"row A","volume_ul":300,"cycles":2},{"type":"air_gap","volume_ul":5},
{"type":"aspirate","station":"wash","volume_ul":50},{"type":"dispense","station":"waste","volume_ul":40},
{"type":"touch_off","plate":"a","wells":"column 3","offset_mm":1.5},{"type":"wait","seconds":0.5},
{"type":"wash","station":"wash","volume_ul":200,"cycles":3}]})");
    // Version 2: the travel rules and well orders, per recipe and per step.
    s.push_back(R"({"schema":"benchpilot.recipe","version":2,"name":"arched","order":"snake-columns",
"travel":{"mode":"arched","clearance_in_plate_mm":4,"clearance_between_mm":12},
"plates":[{"name":"a","slot":"1","labware":"sbs-96","safe_z_mm":55,"depth_z_mm":70},{"name":"b","slot":"2","labware":"sbs-24","safe_z_mm":50,"depth_z_mm":70}],
"steps":[{"type":"dispense","plate":"a","wells":"all","volume_ul":40,"source":{"plate":"b","well":"A1"},"order":"shortest"},
{"type":"mix","plate":"a","wells":"A1:H3","volume_ul":20,"order":"column-major"},{"type":"aspirate","plate":"b","wells":"row B","volume_ul":5,"order":"snake-rows"},
{"type":"touch_off","plate":"a","wells":"column 3","offset_mm":1.5,"order":"as-written"},{"type":"wash","station":"wash","volume_ul":200}]})");
    return s;
}

void checkRecipe(std::string_view input)
{
    dev::files::plates::RecipeRead r = dev::files::plates::parseRecipe(input);
    if (!r.recipe)
        return;
    const motion::plates::PlanContext c = context();
    const motion::plates::RecipePlan plan = motion::plates::planRecipe(*r.recipe, c);
    dev::files::plates::placeProblems(r, plan.problems);
    (void)r.problems.format("fuzz.recipe.json");
    if (plan.ok() && r.wellFormed) {
        double p = plan.pumpStartUl;
        for (const auto& op : plan.ops)
            for (const auto& m : op.moves) {
                if ((m.kind == motion::plates::MoveKind::Travel || m.kind == motion::plates::MoveKind::Touch)
                    && (!(m.xMm >= -1e-6) || !(m.yMm >= -1e-6) || m.xMm > c.deck.travelXMm + 1e-6 || m.yMm > c.deck.travelYMm + 1e-6)) {
                    // A touch-off may reach past a well at the edge only within the well: still inside the travel.
                    fail("an accepted recipe moves to (" + std::to_string(m.xMm) + ", " + std::to_string(m.yMm) + ")");
                }
                if ((m.kind == motion::plates::MoveKind::Raise || m.kind == motion::plates::MoveKind::Lower || m.withZ) && (m.zMm < 0 || m.zMm > c.deck.travelZMm))
                    fail("an accepted recipe moves Z to " + std::to_string(m.zMm));
                if (m.kind == motion::plates::MoveKind::Pump || m.archPump) {  // an arch may carry the plunger
                    p += m.pumpDeltaUl;
                    if (p < -1e-6 || p > c.deck.syringeUl + 1e-6)
                        fail("an accepted recipe takes the plunger to " + std::to_string(p) + " µL");
                }
                if (!std::isfinite(m.durationS) || m.durationS < 0)
                    fail("a move with a duration of " + std::to_string(m.durationS) + " s");
            }
        if (!std::isfinite(plan.boundS) || plan.boundS < 0)
            fail("a bound of " + std::to_string(plan.boundS) + " s");
    }
    if (r.wellFormed) {
        const std::string once = dev::files::plates::writeRecipe(*r.recipe);
        const dev::files::plates::RecipeRead again = dev::files::plates::parseRecipe(once);
        if (!again.wellFormed)
            fail("a written recipe does not read back: " + again.problems.format("written"));
        if (dev::files::plates::writeRecipe(*again.recipe) != once)
            fail("recipe write → read → write changed the text");
    }
}

std::vector<std::string> labwareSeeds()
{
    std::vector<std::string> s = fuzzfiles::exampleFiles(".labware.json");
    for (auto& t : fuzzfiles::exampleFiles(".opentrons-labware.json"))
        s.push_back(std::move(t));
    for (const auto& lw : motion::plates::builtinLabware())
        s.push_back(dev::files::plates::writeLabware(lw));
    return s;
}

void checkLabware(std::string_view input)
{
    const dev::files::plates::LabwareRead r = dev::files::plates::parseLabware(input);
    (void)r.problems.format("fuzz.labware.json");
    if (!r.labware)
        return;
    if (!motion::plates::validateLabware(*r.labware).empty())
        fail("accepted labware does not validate");
    const std::string once = dev::files::plates::writeLabware(*r.labware);
    const dev::files::plates::LabwareRead again = dev::files::plates::parseLabware(once);
    if (!again.labware)
        fail("written labware does not read back: " + again.problems.format("written"));
    if (again.labware->wells.size() != r.labware->wells.size())
        fail("written labware has another number of wells");
    for (std::size_t i = 0; i < r.labware->wells.size(); ++i)
        if (std::abs(again.labware->wells[i].xMm - r.labware->wells[i].xMm) > 1e-6
            || std::abs(again.labware->wells[i].yMm - r.labware->wells[i].yMm) > 1e-6 || !(again.labware->wells[i].id == r.labware->wells[i].id))
            fail("written labware moved well " + motion::plates::wellName(r.labware->wells[i].id));
}

std::vector<std::string> deckSeeds() { return {dev::files::plates::builtinDeckText()}; }

void checkDeck(std::string_view input)
{
    const dev::files::plates::DeckRead r = dev::files::plates::parseDeck(input);
    (void)r.problems.format("fuzz.deck.json");
    if (!r.deck)
        return;
    if (!motion::plates::validateDeck(*r.deck).empty())
        fail("an accepted deck does not validate");
    const std::string once = dev::files::plates::writeDeck(*r.deck);
    const dev::files::plates::DeckRead again = dev::files::plates::parseDeck(once);
    if (!again.deck || dev::files::plates::writeDeck(*again.deck) != once)
        fail("deck write → read → write changed it");
}

std::vector<std::string> calibrationSeeds() { return fuzzfiles::exampleFiles(".calibration.json"); }

void checkCalibration(std::string_view input)
{
    const dev::files::plates::CalibrationRead r = dev::files::plates::parseCalibration(input);
    (void)r.problems.format("fuzz.calibration.json");
    if (!r.ok())
        return;
    for (const auto& c : r.calibrations)
        if (!std::isfinite(c.fit.maxResidualMm) || !std::isfinite(c.fit.transform.txMm))
            fail("an accepted calibration has a non-finite fit");
    const std::string once = dev::files::plates::writeCalibration(r.deck, r.calibrations);
    const dev::files::plates::CalibrationRead again = dev::files::plates::parseCalibration(once);
    if (!again.ok() || again.calibrations.size() != r.calibrations.size())
        fail("calibration write → read lost slots: " + again.problems.format("written"));
}

std::vector<std::string> runLogSeeds()
{
    std::vector<std::string> s = fuzzfiles::exampleFiles(".run.jsonl");
    s.push_back(
        "{\"schema\":\"benchpilot.run-log\",\"version\":1,\"event\":\"run\",\"recipe\":\"r\",\"fingerprint\":\"0a\",\"ops\":3,\"time\":\"t\"}\n"
        "{\"event\":\"start\",\"op\":0,\"kind\":\"aspirate\",\"plate\":\"p\",\"well\":\"A1\",\"volume_ul\":10}\n"
        "{\"event\":\"pump\",\"op\":0,\"p_ul\":0}\n{\"event\":\"done\",\"op\":0,\"p_ul\":10}\n"
        "{\"event\":\"start\",\"op\":1,\"kind\":\"aspirate\",\"well\":\"A2\"}\n{\"event\":\"pump\",\"op\":1,\"p_ul\":10}\n"
        "{\"event\":\"stop\",\"reason\":\"link lost\"}\n{\"event\":\"resume\"}\n{\"event\":\"skip\",\"op\":1,\"p_ul\":20}\n"
        "{\"event\":\"redo\",\"op\":2}\n{\"event\":\"finished\"}\n");
    return s;
}

void checkRunLog(std::string_view input)
{
    const dev::files::plates::RunLogState st = dev::files::plates::readRunLog(input);
    (void)st.problems.format("fuzz.run.jsonl");
    if (static_cast<int>(st.ops.size()) != st.opCount)
        fail("the op table does not match the header's count");
    if (st.doneCount() > st.opCount || st.firstOpenOp() < 0 || st.firstOpenOp() > st.opCount)
        fail("op counts out of range");
}

} // namespace

BP_FUZZ_FILE_TARGET({"recipe", recipeSeeds, checkRecipe});
BP_FUZZ_FILE_TARGET({"labware", labwareSeeds, checkLabware});
BP_FUZZ_FILE_TARGET({"deck", deckSeeds, checkDeck});
BP_FUZZ_FILE_TARGET({"calibration", calibrationSeeds, checkCalibration});
BP_FUZZ_FILE_TARGET({"run-log", runLogSeeds, checkRunLog});
