#include "motion/plans/recipes/recipe.h"

namespace motion::plates {
namespace {
const char* const kNames[kStepTypeCount] = {"aspirate", "dispense", "mix", "wash", "air_gap", "wait", "touch_off"};
}

const char* stepTypeName(StepType t) { return kNames[static_cast<int>(t)]; }

std::optional<StepType> stepTypeFromName(const std::string& name)
{
    for (int i = 0; i < kStepTypeCount; ++i)
        if (name == kNames[i])
            return static_cast<StepType>(i);
    return std::nullopt;
}

std::string stepTypeList()
{
    std::string s;
    for (int i = 0; i < kStepTypeCount; ++i)
        s += (i ? ", " : "") + std::string(kNames[i]);
    return s;
}

namespace {
const char* const kOrderNames[kWellOrderCount] = {"as-written", "column-major", "snake-rows", "snake-columns", "shortest"};
}

const char* wellOrderName(WellOrder o) { return kOrderNames[static_cast<int>(o)]; }

std::optional<WellOrder> wellOrderFromName(const std::string& name)
{
    for (int i = 0; i < kWellOrderCount; ++i)
        if (name == kOrderNames[i])
            return static_cast<WellOrder>(i);
    return std::nullopt;
}

std::string wellOrderList()
{
    std::string s;
    for (int i = 0; i < kWellOrderCount; ++i)
        s += (i ? ", " : "") + std::string(kOrderNames[i]);
    return s;
}

const char* travelModeName(TravelMode m) { return m == TravelMode::Arched ? "arched" : "straight-up-down"; }

std::optional<TravelMode> travelModeFromName(const std::string& name)
{
    if (name == "arched")
        return TravelMode::Arched;
    if (name == "straight-up-down")
        return TravelMode::StraightUpDown;
    return std::nullopt;
}

const RecipePlate* Recipe::plate(const std::string& plateName) const
{
    for (const RecipePlate& p : plates)
        if (p.name == plateName)
            return &p;
    return nullptr;
}

} // namespace motion::plates
