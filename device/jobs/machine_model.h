#pragma once
// What plans and estimates assume about the machine, taken from what the connected
// device reported (HELLO's motion limits on the BenchPilot protocol, $$ on GRBL)
// rather than from the simulator's constants. A device that reported no planner
// limits (a protocol 1.0 device) is assumed to plan like the reference firmware
// (device/sim/machine_config.cpp): the stage model's defaults, the deck file's axes.
#include "device/client/instrument_types.h"
#include "motion/plans/plates/deck.h"
#include "motion/plans/scan/scan_plan.h"

namespace dev::jobs {

/// No jerk limit (a trapezoid planner, GRBL): a jerk so high that every ramp is within a
/// microsecond of a trapezoid's, so the jerk-limited estimate times it as one.
constexpr double kUnlimitedJerkMmS3 = 1e9;

/// The stage as a scan must fit it: travel within the device's soft limits, top speed,
/// acceleration and jerk as the device reported them.
motion::scan::StageModel stageModelOf(const dev::DeviceIdentity& identity, const QVector<dev::SoftLimits>& limits);

/// The deck with each axis' motion (X, Y, Z, P by letter) as the analyzer reported it: its
/// top speed always, and its acceleration, default speed and S-curve phase when it reported
/// its planner's limits. Recipe plans and their ETAs follow. An identity without axes (not
/// connected) leaves the deck as the file has it.
motion::plates::Deck deckWithDeviceMotion(motion::plates::Deck deck, const dev::DeviceIdentity& identity);

} // namespace dev::jobs
