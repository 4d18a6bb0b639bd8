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

/// The order a step visits its wells in. Only within one step, and never changing
/// which well gets what: the same wells, the same volumes, another sequence.
enum class WellOrder { AsWritten, ColumnMajor, SnakeRows, SnakeColumns, Shortest };
constexpr int kWellOrderCount = 5;
/// "as-written", "column-major", "snake-rows", "snake-columns", "shortest".
const char* wellOrderName(WellOrder o);
std::optional<WellOrder> wellOrderFromName(const std::string& name);
/// "as-written, column-major, snake-rows, snake-columns, shortest", for messages.
std::string wellOrderList();

/// How the tip goes from one place to the next.
///  * StraightUpDown: up to the travel height (the plates' safe_z_mm), across, down — one
///    axis group at a time, as recipes of version 1 always ran.
///  * Arched: up to the clearance over what it crosses; within the well it leaves, XY
///    already starts toward the next while Z rises, and within the well it enters Z
///    already goes down while XY ends (the tip stays inside the well's opening while it
///    is below the clearance, so it never crosses a rim lower than the clearance).
enum class TravelMode { StraightUpDown, Arched };
const char* travelModeName(TravelMode m);  ///< "straight-up-down", "arched"
std::optional<TravelMode> travelModeFromName(const std::string& name);

/// Clearances above labware while the tip travels (mm above the item's top).
struct TravelRules {
    TravelMode mode = TravelMode::StraightUpDown;
    double clearanceInPlateMm = 5;   ///< between two wells of one plate
    double clearanceBetweenMm = 10;  ///< between labware: above the tallest item on the deck
    bool isDefault() const { return mode == TravelMode::StraightUpDown && clearanceInPlateMm == 5 && clearanceBetweenMm == 10; }
};
/// How far inside a well's wall the tip's centre keeps while it is below the clearance (mm):
/// the tip's own half-width and what a calibration may be off by.
constexpr double kTipWallMarginMm = 0.5;

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
    /// Dispense with a source: one aspiration for as many wells as the syringe holds
    /// with `disposalUl` more (and `airGapUl` of air drawn after it), the wells in
    /// order, then the disposal volume back to the source (or to the station `restTo`).
    bool distribute = false;
    double disposalUl = 0;           ///< extra drawn each round and returned: the last well gets as much as the first
    double airGapUl = 0;             ///< air drawn after each round's aspiration; it leaves with the first well's dispense
    std::string restTo;              ///< "" = back to the source; or a deck station ("waste")
    std::optional<WellOrder> order;  ///< the wells' order; none = the recipe's default
    std::string note;                ///< free text for the person reading the recipe
};

struct Recipe {
    std::string name;
    std::string description;
    std::vector<RecipePlate> plates;
    std::vector<Step> steps;
    std::optional<double> travelSpeedMmS;  ///< XY; default the deck's
    std::optional<double> zSpeedMmS;       ///< Z; default the deck's
    std::optional<WellOrder> order;        ///< default well order of the steps; none = as written
    TravelRules travel;

    /// The order step `s` visits its wells in.
    WellOrder orderOf(const Step& s) const { return s.order ? *s.order : order.value_or(WellOrder::AsWritten); }

    const RecipePlate* plate(const std::string& name) const;
};

/// Limits the validator enforces, so a typo cannot ask for a day of mixing.
constexpr int kMaxCycles = 100;
constexpr double kMaxWaitS = 24 * 3600.0;
constexpr std::size_t kMaxSteps = 10000;
/// Wells a recipe may visit in all (a 1536-well plate dosed a few times over).
constexpr std::size_t kMaxPlannedOps = 20000;

} // namespace motion::plates
