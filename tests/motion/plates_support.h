#pragma once
// A deck like resources/machines/analyzer.deck.json, built in code (test_motion
// links the motion library alone), and a one-plate recipe to vary.
#include "motion/plans/recipes/recipe_plan.h"

namespace platestest {

inline motion::plates::Deck analyzerDeck()
{
    motion::plates::Deck d;
    d.travelXMm = d.travelYMm = 200;
    d.travelZMm = 100;
    d.tableZMm = 75;
    d.syringeUl = 1000;
    d.moveOverheadS = 0.004;
    d.x = {100, 50, 0.1, 1500};
    d.y = {100, 50, 0.1, 2000};
    d.z = {50, 30, 0.1, 800};
    d.p = {500, 100, 0.05, 5000};
    d.plateSlots = {{"1", "back", 8, 8, 0}, {"2", "front", 8, 106, 0}};
    d.stations = {{"wash", "wash trough", 170, 50, 65, 40}, {"waste", "waste trough", 170, 150, 55, 40}};
    return d;
}

inline motion::plates::PlanContext context()
{
    motion::plates::PlanContext c;
    c.deck = analyzerDeck();
    for (auto& lw : motion::plates::builtinLabware())
        c.labware[lw.id] = lw;
    return c;
}

inline motion::plates::Recipe oneStep(motion::plates::StepType type, std::vector<std::string> wells, double volumeUl)
{
    motion::plates::Recipe r;
    r.name = "test";
    r.plates = {{"samples", "1", "sbs-96", 55, 70}};
    motion::plates::Step s;
    s.type = type;
    s.wells = std::move(wells);
    s.volumeUl = volumeUl;
    r.steps = {s};
    return r;
}

/// The problem at `path`, or an empty one.
inline motion::msg::Problem problemAt(const motion::plates::RecipePlan& plan, const std::string& path)
{
    for (const auto& p : plan.problems)
        if (p.path == path)
            return p;
    return {};
}

} // namespace platestest
