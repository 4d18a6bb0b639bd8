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

const RecipePlate* Recipe::plate(const std::string& plateName) const
{
    for (const RecipePlate& p : plates)
        if (p.name == plateName)
            return &p;
    return nullptr;
}

} // namespace motion::plates
