#pragma once
// The analyzer's table: where plates sit (slots), where the tip is washed
// (stations), how far each axis travels and how it moves (for time estimates).
// Read from resources/machines/analyzer.deck.json (docs/plates.md).
//
// Machine frame: X to the right, Y toward the front (the operator), Z down from
// its home at the top (Z = 0 is the tip fully raised, larger Z is lower). A slot
// holds a plate landscape with A1 at the back-left, so plate y and machine Y
// point the same way and a slot's nominal transform is a translation (plus a
// rotation when a slot is built turned).
#include "motion/plans/plates/problem.h"
#include "motion/plans/plates/transform.h"

#include <string>
#include <vector>

namespace motion::plates {

/// How one axis moves, as the firmware plans it: seed 000's S-curve with the
/// acceleration phase stretched until every axis stays under its maxAccel.
struct AxisMotion {
    double maxSpeed = 0;      ///< axis units per second (mm/s, µL/s)
    double defaultSpeed = 0;  ///< a MOVE with speed 0 runs at this
    double accelTimeS = 0;    ///< seed 000's t2
    double maxAccel = 0;      ///< per s²
};

struct Slot {
    std::string id;           ///< "1", "2": what recipes name
    std::string name;         ///< "front left"
    double originXMm = 0, originYMm = 0;  ///< machine XY of a seated plate's back-left corner
    double rotationDeg = 0;
    PlateTransform nominal() const { return PlateTransform::make(originXMm, originYMm, rotationDeg); }
};

/// A fixed place the tip visits: a wash trough, a waste, a reagent trough.
struct Station {
    std::string id;           ///< "wash", "waste"
    std::string name;
    double xMm = 0, yMm = 0;  ///< machine XY of its centre
    double depthZMm = 0;      ///< Z the tip goes down to there
    double safeZMm = 0;       ///< Z to travel at when arriving or leaving
};

struct Deck {
    std::string id = "analyzer";
    std::string name;
    double travelXMm = 200, travelYMm = 200, travelZMm = 100;
    /// Z at which the tip touches the deck surface a plate stands on: a well's
    /// bottom is at tableZMm − its bottomZMm, a plate's top at tableZMm − its height.
    double tableZMm = 75;
    double syringeUl = 1000;  ///< plunger pump capacity
    AxisMotion x, y, z, p;
    /// Host ↔ device time per MOVE that the profiles do not show: the request's
    /// trip, the device's tick, the MotionDone event's trip (measured on the link).
    double moveOverheadS = 0.004;
    /// The firmware blends arched travel into one move (ARCH_MOVE, docs/protocol.md): the
    /// analyzer's reference firmware does; a device that does not say so in its HELLO
    /// travels in legs (dev::jobs::deckWithDeviceMotion).
    bool archedMoves = true;
    /// With archedMoves: a dispense's plunger runs inside its arched move, while the tip is
    /// below the well's rim on its way down and back up (ARCH_MOVE's pump block, HELLO bit 17).
    bool archPump = true;
    std::vector<Slot> plateSlots;  ///< not "slots": that is a Qt keyword
    std::vector<Station> stations;

    const Slot* slot(const std::string& slotId) const;
    const Station* station(const std::string& stationId) const;
};

/// Ids unique and present, speeds and accelerations positive, slots and
/// stations inside the travel, a plate in one slot not overlapping another's.
motion::msg::Problems validateDeck(const Deck& deck);

} // namespace motion::plates
