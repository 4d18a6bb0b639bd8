#pragma once
// The $$ settings and the machine limits read from them.
//
// GRBL stores every length setting in millimetres whatever $13 says: $13=1 only changes the
// units of status reports, WCO, $# and the reported feed. So limits are always read as mm
// here, and MachineLimits::reportInches tells the status side (StatusTracker) to convert —
// reports are never taken as mm while $13=1.
//
//   $110–$112 max rate, mm/min → maxRateMmS (÷ 60)
//   $120–$122 acceleration, mm/s²
//   $130–$132 max travel, mm (machine space is [−travel, 0] unless homing forces the origin)
//   $20 soft limits, $21 hard limits, $22 homing (grblHAL: bit 0 of a flag mask)
//   $23 homing direction invert mask, $3 direction invert mask, $27 pull-off
//   $10 status mask (bit 0 MPos), $11 junction deviation, $12 arc tolerance, $13 inches
// Axes past Z (A, B, C: $113, $123, $133…) are read when the firmware has them.
#include "device/backends/grbl/grbl_lines.h"
#include "motion/message.h"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace dev::grbl {

/// Every $N=V line of a $$ answer, by number.
class Settings {
public:
    void add(const SettingLine& s);
    void set(int id, double value) { m_values[id] = value; }
    std::optional<double> value(int id) const;
    bool has(int id) const { return m_values.count(id) != 0; }
    std::size_t size() const { return m_values.size(); }
    void clear() { m_values.clear(); }
    const std::map<int, double>& values() const { return m_values; }

private:
    std::map<int, double> m_values;
};

struct AxisLimits {
    char letter = 'X';
    double maxRateMmS = 0;       ///< $11x ÷ 60
    double accelMmS2 = 0;        ///< $12x
    double maxTravelMm = 0;      ///< $13x
    double stepsPerMm = 0;       ///< $10x (0 when absent)
    bool directionInverted = false;  ///< bit of $3
    bool homesNegative = false;      ///< bit of $23: homing seeks towards −
};

struct MachineLimits {
    std::vector<AxisLimits> axes;
    bool softLimits = false;     ///< $20
    bool hardLimits = false;     ///< $21
    bool homingEnabled = false;  ///< $22 (bit 0)
    bool reportInches = false;   ///< $13: reports (not settings) are in inches
    bool reportsMachinePosition = true;  ///< $10 bit 0
    double junctionDeviationMm = 0.01;   ///< $11
    double arcToleranceMm = 0.002;       ///< $12
    double homingPulloffMm = 1.0;        ///< $27
};

struct LimitsRead {
    std::optional<MachineLimits> limits;  ///< absent when a required setting is missing or invalid
    /// Refusals (grbl.settings.missing{setting}, grbl.settings.invalid{setting, value}) and
    /// warnings (grbl.settings.report_inches, grbl.settings.soft_limits_without_homing).
    std::vector<motion::msg::Message> problems;
    std::vector<motion::msg::Message> warnings;
};

/// Limits of the axes named by `axisLetters` ("XYZ", or grblHAL's [AXS:] letters), in the
/// firmware's order. Rate, acceleration and travel of each are required and must be > 0.
LimitsRead machineLimits(const Settings& s, std::string_view axisLetters = "XYZ");

} // namespace dev::grbl
