#pragma once
// From a recipe to the moves a run makes, with the same pass finding every
// problem (validation is planning that collects problems: the checks and the
// moves can never disagree). Each planned op is one visit — one well, one
// station, one air gap or one wait — and is the unit the run log records.
//
// Per well the tip goes: up to the travel height (Raise), across (Travel, X and
// Y together), down (Lower), the plunger (Pump, relative), up (Raise). Times
// come from move_time.h, the firmware's own profile planning.
#include "motion/plans/plates/deck.h"
#include "motion/plans/plates/labware.h"
#include "motion/plans/plates/problem.h"
#include "motion/plans/recipes/recipe.h"

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace motion::plates {

struct PlanContext {
    Deck deck;
    /// Labware by the reference recipe plates use: built-in ids and files.
    std::map<std::string, Labware> labware;
    /// Fitted transforms by slot id; a slot without one uses its nominal place.
    std::map<std::string, PlateTransform> calibration;
    double syringeUl = 0;  ///< 0 = the deck's
    PlateTransform transform(const std::string& slotId) const;
    double capacityUl() const { return syringeUl > 0 ? syringeUl : deck.syringeUl; }
};

/// Where the machine is when the run starts (or resumes).
struct StartState {
    double xMm = 0, yMm = 0, zMm = 0, pumpUl = 0;
};

enum class MoveKind { Raise, Travel, Lower, Pump, Touch, Dwell };
const char* moveKindName(MoveKind k);  ///< "raise", "travel", "lower", "pump", "touch", "dwell"

struct MachineMove {
    MoveKind kind = MoveKind::Dwell;
    double xMm = 0, yMm = 0;   ///< Travel, Touch: XY target
    double zMm = 0;            ///< Raise, Lower: Z target; Travel with `withZ`: Z's target
    /// Travel (arched): Z runs to zMm at the same time as XY — leaving a well while it rises,
    /// or entering one while it goes down; the XY part stays within the well's opening.
    bool withZ = false;
    double zSpeed = 0;         ///< with `withZ`: Z's speed (mm/s); 0 = the device's default
    /// Travel with `withZ` on a device that blends (Deck::archedMoves): one arched move — Z
    /// up to `clearZMm` (from wherever it is), XY across, Z down to `zMm`; XY starts while Z
    /// still rises as long as it is within `departMm` of its start when Z reaches the
    /// clearance, and Z goes down once XY is within `approachMm` of its target
    /// (motion/arch_timing.h).
    bool arch = false;
    double clearZMm = 0, departMm = 0, approachMm = 0;
    /// Raise: the next op's arched move takes the tip up out of this well instead, and its
    /// time is counted there (0 here); the runner makes this raise only when the run
    /// pauses, stops or ends after this op.
    bool deferred = false;
    /// An arched move that also runs the plunger (Deck::archPump): `pumpDeltaUl` at
    /// `pumpSpeed` once the way down has passed `liquidZMm` (the well's rim), then Z back
    /// up to `leaveZMm`, above `liquidZMm` only once the plunger has stopped.
    bool archPump = false;
    double pumpSpeed = 0;      ///< with `archPump`: µL/s; 0 = the plunger's default
    double liquidZMm = 0, leaveZMm = 0;
    double pumpDeltaUl = 0;    ///< Pump (and an arch with `archPump`): + draws in, − pushes out
    double speed = 0;          ///< axis units per second; 0 = the device's default
    double seconds = 0;        ///< Dwell
    double durationS = 0;      ///< planned, with the link's per-move overhead
};

struct PlanOp {
    int index = 0;
    int step = 0;              ///< the recipe step it comes from
    StepType type = StepType::Dispense;
    std::string plate, well;   ///< a well on a plate …
    std::string station;       ///< … or a deck station
    int round = 0;             ///< transfer round (1, 2, …) of a dispense with a source; 0 otherwise
    double volumeUl = 0;       ///< the step's volume here (per well, per stroke, air gap)
    double pumpNetUl = 0;      ///< net plunger change: + aspirate / air gap, − dispense, 0 mix / wash
    PointMm at;                ///< machine XY
    double safeZMm = 0, depthZMm = 0;
    /// The lowest the tip may cross on its way here (machine Z, down from home): the
    /// clearance above the plate's top within one plate, above the deck's tallest
    /// labware between two (TravelRules), a station's safe height at a station.
    double clearZMm = 0;
    std::vector<MachineMove> moves;
    int visitMoves = 0;        ///< the leading moves that bring the tip into its place (raise, travel, lower)
    double durationS = 0;
    double startS = 0;         ///< planned start, from the run's start
    bool pumps() const;        ///< has a plunger move (liquid may have moved once it started)
    motion::msg::Message where() const; ///< recipe.where.well {plate, well} "samples B3", recipe.where.station; empty (air gap, wait)
    motion::msg::Message label() const; ///< recipe.op.dispense {volume, where}: "dispense 10 µL into samples B3"
};

struct WellTotal {
    std::string plate, well;
    double dispensedUl = 0, aspiratedUl = 0;
    int visits = 0;
};

struct RecipePlan {
    std::vector<PlanOp> ops;
    motion::msg::Problems problems;
    double totalTimeS = 0;
    /// The time-optimal bound of these ops in this order (plan_bound.h): no run can be faster.
    double boundS = 0;
    /// The well order each step was planned with (by step index; AsWritten for steps without wells).
    std::vector<WellOrder> orders;
    double pumpStartUl = 0, pumpEndUl = 0;
    double totalDispensedUl = 0, totalAspiratedUl = 0;
    std::vector<WellTotal> wells;   ///< in order of first visit
    /// The ops' identity (type, place, volumes) — not their coordinates, so a run
    /// may resume after the plate was re-taught — for matching a run log to its recipe.
    std::uint64_t fingerprint = 0;
    bool ok() const { return !hasErrors(problems); }
    const WellTotal* total(const std::string& plate, const std::string& well) const;
    /// Wells the run goes into (a wash station is not one); fewer than ops.size() when a
    /// recipe also washes, mixes or aspirates.
    int wellsVisited() const
    {
        int n = 0;
        for (const auto& w : wells)
            n += w.visits > 0;
        return n;
    }
};

RecipePlan planRecipe(const Recipe& recipe, const PlanContext& context, const StartState& start = {});

/// 16 hex digits.
std::string fingerprintHex(std::uint64_t fingerprint);

/// Seconds of the ops from `fromOp` on (for an ETA).
double remainingTimeS(const RecipePlan& plan, int fromOp);

} // namespace motion::plates
