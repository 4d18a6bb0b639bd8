#pragma once
// The simulated GRBL's $ settings: the documented GRBL 1.1 set, with defaults taken from the
// simulated machine (rates, accelerations and travel of its axes), written with $N=V and
// read back with $$. Values are what firmware stores: lengths in mm, rates in mm/min.
//
// Axis k of the GRBL personality is axis k of dev::sim::SimMachine; GRBL always has at least
// X, Y and Z, so the stage (XY) gets a Z without hardware (docs/grbl.md). The analyzer's
// pump P is GRBL's fourth axis, A, with 1 µL per "mm".
#include "device/sim/machine_config.h"

#include <map>
#include <string>

namespace dev::sim {

class GrblSimSettings {
public:
    explicit GrblSimSettings(const MachineConfig& machine, int grblAxes);

    /// error:N code of a write ($N=V), 0 when taken.
    int write(int id, double value);
    double get(int id) const;
    bool has(int id) const { return m_values.count(id) != 0; }
    /// The $$ printout, one "$N=V\r\n" per setting in number order.
    std::string printout() const;

    int axes() const { return m_axes; }
    double maxRateMmS(int axis) const { return get(110 + axis) / 60.0; }
    double accelMmS2(int axis) const { return get(120 + axis); }
    double maxTravelMm(int axis) const { return get(130 + axis); }
    bool softLimits() const { return flag(20); }
    bool hardLimits() const { return flag(21); }
    bool homingEnabled() const { return flag(22); }
    bool reportInches() const { return flag(13); }
    bool reportMachinePosition() const { return flag(10); }
    bool reportBuffers() const { return (static_cast<int>(get(10)) & 2) != 0; }
    double junctionDeviationMm() const { return get(11); }
    double arcToleranceMm() const { return get(12); }

private:
    bool flag(int id) const { return (static_cast<int>(get(id)) & 1) != 0; }
    std::map<int, double> m_values;
    int m_axes;
};

} // namespace dev::sim
