#pragma once
// A dispensing recipe as a plain data model: the plates it uses (which labware
// in which deck slot, at what heights) and its steps. The JSON form is in
// docs/recipes.md; device/files/recipes/recipe_file.h reads and writes it.
// planRecipe() (recipe_plan.h) finds every problem and, in the same pass,
// turns the recipe into the moves a run makes.
#include <optional>
#include <string>
#include <vector>

namespace motion::plates {

enum class StepType { Aspirate, Dispense, Mix, Wash, AirGap, Wait, TouchOff };
constexpr int kStepTypeCount = 7;
/// "aspirate", "dispense", "mix", "wash", "air_gap", "wait", "touch_off".
const char* stepTypeName(StepType t);
std::optional<StepType> stepTypeFromName(const std::string& name);
/// "aspirate, dispense, mix, wash, air_gap, wait, touch_off", for messages.
std::string stepTypeList();

/// One plate on the deck for this recipe.
struct RecipePlate {
    std::string name;          ///< what steps call it: "samples"
    std::string slot;          ///< deck slot id: "1"
    std::string labware;       ///< built-in id ("sbs-96") or a labware file beside the recipe
    double safeZMm = 5;        ///< Z at which the tip clears this plate (machine Z, down from home)
    double depthZMm = 40;      ///< Z the tip goes down to in a well
};

/// Where a dispense step refills the syringe from, round by round.
struct SourceRef {
    std::string plate;         ///< with `well`
    std::string well;
    std::string station;       ///< or a deck station (a reagent trough)
    bool empty() const { return well.empty() && station.empty(); }
};

struct Step {
    StepType type = StepType::Dispense;
    std::string plate;               ///< plate name; "" = the recipe's only plate
    std::vector<std::string> wells;  ///< well specs as written ("A1:H1", "row B", …)
    std::string station;             ///< a deck station instead of wells (aspirate, dispense, wash)
    double volumeUl = 0;             ///< per well (aspirate, dispense), per stroke (mix, wash), air gap
    std::optional<double> speedUlS;  ///< pump speed; default the deck's
    int cycles = 1;                  ///< mix, wash strokes
    double seconds = 0;              ///< wait
    double offsetMm = 0;             ///< touch_off: from the centre toward the well's +x wall; dispense: touch off after each well when > 0
    SourceRef source;                ///< dispense: refill from here (transfer in rounds)
    std::string note;                ///< free text for the person reading the recipe
};

struct Recipe {
    std::string name;
    std::string description;
    std::vector<RecipePlate> plates;
    std::vector<Step> steps;
    std::optional<double> travelSpeedMmS;  ///< XY; default the deck's
    std::optional<double> zSpeedMmS;       ///< Z; default the deck's

    const RecipePlate* plate(const std::string& name) const;
};

/// Limits the validator enforces, so a typo cannot ask for a day of mixing.
constexpr int kMaxCycles = 100;
constexpr double kMaxWaitS = 24 * 3600.0;
constexpr std::size_t kMaxSteps = 10000;
/// Wells a recipe may visit in all (a 1536-well plate dosed a few times over).
constexpr std::size_t kMaxPlannedOps = 20000;

} // namespace motion::plates
