#pragma once
// The planner behind planRecipe() (recipe_plan.h): one pass over a recipe that
// checks it and turns it into ops and moves, following the tip, the plunger
// and the syringe's content. Internal to motion/plans/recipes: the recipe-level
// checks, places and moves are in recipe_plan.cpp, the steps in
// recipe_plan_steps.cpp.
#include "motion/plans/recipes/recipe_plan.h"

#include <cmath>
#include <limits>
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

    // ---- moves -----------------------------------------------------------------

    double overheadFor(double t) const { return t > 0 ? t + m_c.deck.moveOverheadS : 0.0; }

    void raiseTo(PlanOp& op, double z);

    void travelTo(PlanOp& op, const PointMm& at, MoveKind kind = MoveKind::Travel);

    void lowerTo(PlanOp& op, double z);

    void pump(PlanOp& op, double delta, double speed);

    /// Up to a height that clears both where the tip is and where it goes, across, down.
    void goInto(PlanOp& op, const Place& pl);

    PlanOp& newOp(int step, StepType type, const Place* pl, double volume);

    WellTotal& totalOf(const Place& pl);

    // ---- steps -----------------------------------------------------------------

    bool checkVolume(const Step& s, const std::string& path, bool capacityBound);

    double pumpSpeed(const Step& s, const std::string& path);

    /// False (once per step) when `delta` would take the plunger past its ends.
    bool roomFor(double delta, const std::string& path, bool* reported);

    void aspirateAt(int step, const Place& pl, double vol, double speed, const std::string& volPath, bool* reported);

    void dispenseAt(int step, const Place& pl, double vol, double speed, double touchMm);

    void planStep(int i);

    void checkCycles(const Step& s, const std::string& path);

    /// A dispense that refills from a source: as many wells per round as the
    /// syringe has room for, one aspirate from the source before each round.
    void planTransfer(int i, const Step& s, const std::string& path, const std::vector<Place>& targets, double speed);

    void finish();

    const Recipe& m_r;
    const PlanContext& m_c;
    const double m_cap;
    RecipePlan m_plan;
    double m_x = 0, m_y = 0, m_z = 0, m_p = 0;
    double m_safeZ = std::numeric_limits<double>::infinity();  ///< the place the tip is over; none yet
    double m_liquid = 0, m_air = 0;
    bool m_tooMany = false;
};

} // namespace motion::plates::planning
