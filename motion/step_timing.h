#pragma once
// Seed 001: a move turned into step periods for a timer-driven pulse output.
//
// The seed's firmware runs a 50 µs PWM interrupt off a 72 MHz clock (3600 ticks a period). Each
// step is stored as (PWMTimers, PWMMatch): how many whole interrupt periods to wait, and the match
// value (tick) inside the period where the pulse edge goes out. Periods are measured from the
// previous pulse's edge, so an entry is  pulse = period + previous match + compensation:
//   wholePeriods = pulse / 3600,  match = pulse % 3600.
// A match of 0 cannot produce a pulse (the PWM resets there), so the seed moves the edge one tick
// later (match = 1) and takes that tick back from the next step (compensation -1): the absolute
// pulse times stay exact. The first reference edge is at match 1800 (mid-period).
// Rates are clamped to 80 Hz … 20 kHz: 20 kHz is one step per interrupt period (3600 ticks), and
// 80 Hz is 250 whole periods, the most that fits the seed's INT8U PWMTimers (78.1 Hz would not).

#include "motion/profile.h"
#include "motion/trapezoid.h"

#include <cstdint>
#include <vector>

namespace motion {

struct StepTimerConfig {
    double clockHz = 72e6;             ///< timer clock
    double interruptPeriodS = 50e-6;   ///< PWM period-match interrupt
    double minRateHz = 80.0;           ///< slower steps are sped up to this
    double maxRateHz = 20000.0;        ///< faster steps are slowed to this
    std::uint32_t firstMatchTicks = 1800;  ///< seed: PWMMatch[0] = 1800, the time origin
};

struct StepTableEntry {
    double idealPeriodS = 0;          ///< from the profile, before quantisation and clamping
    std::uint32_t periodTicks = 0;    ///< after clamping; what the table actually produces
    std::uint32_t wholePeriods = 0;   ///< seed's PWMTimers
    std::int32_t matchTicks = 0;      ///< seed's PWMMatch (1 … interruptTicks-1)
    bool zeroCorrected = false;       ///< this edge was moved one tick late (the next comes one early)
    bool clamped = false;             ///< rate was outside [minRateHz, maxRateHz]
};

struct StepTable {
    std::vector<StepTableEntry> entries;
    std::uint32_t interruptTicks = 0;  ///< ticks per interrupt period (3600 by default)
    double idealDurationS = 0;         ///< time of the last step on the ideal profile
    double tableDurationS = 0;         ///< sum of the table's periods
    double timeErrorS = 0;             ///< tableDurationS - idealDurationS
    int clampedCount = 0;
    int zeroCorrections = 0;
    std::uint32_t maxWholePeriods = 0;  ///< must fit the firmware's counter (INT8U in the seed)
};

/// Instants (s) at which the profile crosses each multiple of stepMm (|distance| / stepMm steps,
/// rounded down). Monotonic profiles only; uses Newton steps bracketed by bisection.
std::vector<double> stepInstantsS(const Profile& profile, double stepMm);

/// The seed-001 table of a step sequence given its ideal instants (s, increasing, first > 0).
/// Ticks are rounded from absolute times, so rounding never accumulates over a long move.
StepTable buildStepTable(const std::vector<double>& instantsS, const StepTimerConfig& config = {});

/// Convenience: stepInstantsS + buildStepTable. Empty table for stepMm ≤ 0.
StepTable stepTableForProfile(const Profile& profile, double stepMm, const StepTimerConfig& config = {});

/// Seed 001's own step-rate iteration for the plateau trapezoid, in steps: each new speed is the
/// previous speed plus a·t0, t0 being the previous step's period (the seed uses the old period
/// "to simplify", knowing it makes the speed reach vH slightly early in acceleration and v0
/// slightly late in deceleration, and clamps at both). Returns the instant of every step.
struct Seed001Move {
    double startRateHz = 0;    ///< v0 in steps/s (> 0)
    double topRateHz = 0;      ///< vH in steps/s
    double accelHzS = 0;       ///< a in steps/s²
    double decelHzS = 0;       ///< d in steps/s² (magnitude)
    std::int64_t plateauSteps = 0;
    std::int64_t totalSteps = 0;
};
std::vector<double> seed001StepInstantsS(const Seed001Move& move);

/// The same move as a continuous profile with 1 mm = 1 step (so the exact instants can be compared).
std::optional<TrapezoidProfile> seed001Profile(const Seed001Move& move);

}  // namespace motion
