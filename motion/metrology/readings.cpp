#include "motion/metrology/readings.h"

namespace motion::metrology {

const char* directionName(Direction d)
{
    return d == Direction::Up ? "up" : "down";
}

const char* directionTermId(Direction d)
{
    return d == Direction::Up ? "direction.up" : "direction.down";
}

std::optional<Direction> directionFromName(std::string_view name)
{
    if (name == "up")
        return Direction::Up;
    if (name == "down")
        return Direction::Down;
    return std::nullopt;
}

} // namespace motion::metrology
