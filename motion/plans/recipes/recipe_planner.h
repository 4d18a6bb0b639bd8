#pragma once
// The planner behind planRecipe() (recipe_plan.h): one pass over a recipe that
// checks it and turns it into ops and moves, following the tip, the plunger
// and the syringe's content. Internal to motion/plans/recipes: the recipe-level
// checks, places and moves are in recipe_plan.cpp, the steps in
// recipe_plan_steps.cpp.
#include "motion/plans/recipes/move_time.h"
#include "motion/plans/recipes/recipe_plan.h"

#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace motion::plates::planning {

constexpr double kEps = 1e-9;
/// Slowest speed a recipe may ask for (mm/s or µL/s): slower is a typo, and the
/// wire's whole nanometres per second cannot carry much less.
constexpr double kMinSpeed = 0.1;

/// A place the tip visits, resolved to machine coordinates.
struct Place {
    std::string plate, well, station;
    PointMm at;
    double safeZMm = 0, depthZMm = 0;
    double topZMm = 0;         ///< machine Z of the labware's top (a station: its safe height)
    const Well* w = nullptr;
    PlateTransform transform;  ///< plate → machine, for touch-off directions
};

class Planner {
public:
    Planner(const Recipe& r, const PlanContext& c, const StartState& s);

    RecipePlan run();

private:
    void error(const std::string& path, motion::msg::Message message) { m_plan.problems.push_back(motion::msg::error(path, std::move(message))); }
    void warning(const std::string& path, motion::msg::Message message) { m_plan.problems.push_back(motion::msg::warning(path, std::move(message))); }

    static motion::msg::Arg volume(std::string name, double v) { return ulArg(std::move(name), std::round(v * 1000) / 1000); }

    // ---- recipe-level checks ---------------------------------------------------

    void checkRecipe();

    /// The tip must clear the plate's top at its safe height and stay above the
    /// wells' bottoms at its depth (Z grows downward from home).
    void checkHeights(const RecipePlate& p, const Labware& lw, const std::string& at);

    // ---- resolving places ------------------------------------------------------

    const RecipePlate* resolvePlate(const std::string& name, const std::string& path);

    const RecipePlate* findPlate(const std::string& name, const std::string& path);

    Place wellPlace(const RecipePlate& p, const Well& w);

    bool reachable(const PointMm& at) const;

    /// The wells a step names, as places; problems at `path` ("steps[2].wells").
    std::vector<Place> wellPlaces(const Step& s, const std::string& stepPath);

    bool stationPlace(const std::string& id, const std::string& path, Place* pl);

    /// Puts `places` in the step's well order (the recipe's default when it names none).
    void orderPlaces(int step, const Step& s, std::vector<Place>& places);

    /// The lowest the tip may cross going from the place it is over to `to`.
    double clearanceTo(const Place& to) const;

    // ---- moves -----------------------------------------------------------------

    double overheadFor(double t) const { return t > 0 ? t + m_c.deck.moveOverheadS : 0.0; }

    void raiseTo(PlanOp& op, double z);

    void travelTo(PlanOp& op, const PointMm& at, MoveKind kind = MoveKind::Travel);

    void lowerTo(PlanOp& op, double z);

    void pump(PlanOp& op, double delta, double speed);

    /// Up to a height that clears both where the tip is and where it goes, across, down.
    void goInto(PlanOp& op, const Place& pl);

    /// Arched travel (TravelMode::Arched): the op before, when it ended straight up out of
    /// a well, leaves it toward `pl` while rising; across at the clearance; into `pl`'s
    /// well while going down.
    void goIntoArched(PlanOp& op, const Place& pl);

    /// Arched travel on a device that blends it (Deck::archedMoves): one move from the well
    /// the op before ended in (its raise deferred to this move) to `pl`'s depth.
    void goIntoBlended(PlanOp& op, const Place& pl);

    /// A dispense on a device that runs the plunger inside an arched move (Deck::archPump):
    /// the op's arch into `pl`'s well also pushes `delta` out while the tip is below the
    /// well's top and rises to the travel height after it (`stayDown`: the tip stays at the
    /// depth, for what follows there). False (nothing changed) where it cannot: not
    /// arched, a station, no way down.
    bool pumpInsideArch(PlanOp& op, const Place& pl, double delta, double speed, bool stayDown = false);

    /// The end of a visit: the tip up to the travel height; remembers the op for a depart.
    void leave(PlanOp& op);

    /// How far the tip's centre may go from the centre of `pl`'s well while below the
    /// clearance (0 at a station: its opening is not known).
    static double openingMm(const Place& pl);

    /// A Travel that moves Z to `z` at the same time.
    MachineMove travelWithZ(const PointMm& at, double z);

    PlanOp& newOp(int step, StepType type, const Place* pl, double volume);

    WellTotal& totalOf(const Place& pl);

    // ---- steps -----------------------------------------------------------------

    bool checkVolume(const Step& s, const std::string& path, bool capacityBound);

    double pumpSpeed(const Step& s, const std::string& path);

    /// False (once per step) when `delta` would take the plunger past its ends.
    bool roomFor(double delta, const std::string& path, bool* reported);

    void aspirateAt(int step, const Place& pl, double vol, double speed, const std::string& volPath, bool* reported);

    /// `mayFold` false: the tip stays down for what follows here (a disposal volume returned
    /// to the source the next round draws from): the plunger rides the arch's way down only.
    void dispenseAt(int step, const Place& pl, double vol, double speed, double touchMm, bool mayFold = true);

    void planStep(int i);

    void checkCycles(const Step& s, const std::string& path);

    /// A dispense that refills from a source: as many wells per round as the
    /// syringe has room for, one aspirate from the source before each round.
    void planTransfer(int i, const Step& s, const std::string& path, const std::vector<Place>& targets, double speed);

    /// A transfer with `distribute`: each round draws its wells plus the disposal
    /// volume (and an air gap), doses the wells, and returns the disposal volume.
    void planDistribute(int i, const Step& s, const std::string& path, const std::vector<Place>& targets, double speed, const Place& src,
                        double room);

    void finish();

    const Recipe& m_r;
    const PlanContext& m_c;
    const double m_cap;
    RecipePlan m_plan;
    double m_x = 0, m_y = 0, m_z = 0, m_p = 0;
    double m_safeZ = std::numeric_limits<double>::infinity();  ///< the place the tip is over; none yet
    std::string m_overPlate;   ///< the plate the tip is over ("" at a station or nowhere yet)
    double m_inWellMm = 0;     ///< the opening (openingMm) of the well the tip is in; 0 elsewhere
    int m_departOp = -1;       ///< the op that ended straight up out of a well, its last move a Raise
    double m_departFromZ = 0;  ///< where that Raise began
    double m_allClearZ = 0;    ///< the height that clears every labware and station of the deck
    double m_tallestTopZMm = std::numeric_limits<double>::infinity();  ///< the deck's tallest labware in this recipe
    double m_liquid = 0, m_air = 0;
    bool m_tooMany = false;
    /// The last blended arch's parts, as goIntoBlended timed them (pumpInsideArch adds to them).
    struct ArchParts {
        std::optional<motion::SeedSCurve> rise, xy, down;
        double departMm = 0, approachMm = 0, topZ = 0;
    } m_lastArch;
};

} // namespace motion::plates::planning
