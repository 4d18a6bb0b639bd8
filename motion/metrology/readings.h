#pragma once
// One reading of an accuracy test: where the axis was sent, from which side it
// came, in which cycle, and where the reference (the instrument's readback, a
// gauge, an interferometer, a person with a dial indicator) saw it stop.
#include <optional>
#include <string_view>

namespace motion::metrology {

/// The approach direction of ISO 230-2: Up (↑) arrives from below (increasing
/// position), Down (↓) from above.
enum class Direction { Up, Down };

/// "up" / "down": the word the readings CSV uses and, prefixed with
/// "direction.", the term id the wording layer translates.
const char* directionName(Direction d);
const char* directionTermId(Direction d);
std::optional<Direction> directionFromName(std::string_view name);

struct Reading {
    double targetMm = 0;
    Direction direction = Direction::Up;
    int cycle = 1;          ///< 1-based, as people count them
    double measuredMm = 0;

    /// x_ij of ISO 230-2: measured − target.
    double deviationMm() const { return measuredMm - targetMm; }
};

} // namespace motion::metrology
