#pragma once
// Mechanical and control parameters of the simulated instruments. Units: the
// axis' own unit (mm, or µL for the pump) unless a name says otherwise.
#include "device/protocol/messages.h"

#include <string>
#include <vector>

namespace dev::sim {

enum class ProfileKind { SeedSCurve, JerkLimited };

struct AxisConfig {
    char letter = 'X';
    dev::proto::AxisUnit unit = dev::proto::AxisUnit::Millimetre;
    double travel = 100;            ///< soft limits default to [0, travel]
    double stepSize = 0.0025;       ///< one microstep of the motor, in axis units
    double resolution = 0.002;      ///< one count of encoder or grating
    double maxSpeed = 100;          ///< per second
    double defaultSpeed = 50;
    double accelTimeS = 0.1;        ///< seed 000 S-curve acceleration phase
    double maxAccel = 1000;         ///< jerk-limited planner, per s²; also the jog ramp
    double maxJerk = 20000;         ///< per s³
    /// Per s²: the motor's pull-out limit. Every ramp the firmware plans (the jog
    /// watchdog's steep stop included, see its test) stays below it; the plant
    /// models slip from overload (SimAxis::setLoadFactor), not from acceleration.
    double physicalMaxAccel = 4000;
    double homeFastSpeed = 20;
    double homeSlowSpeed = 2;
    double homeBackoff = 1.0;       ///< travel off the switch before the slow re-approach
    double homeSwitchAt = -0.5;     ///< machine coordinate where the home switch closes (active below)
    double limitSwitchMargin = 0.5; ///< limit switch closes this far past the travel
    double hardStopMargin = 3.0;    ///< carriage cannot pass this far beyond either switch
    double backlash = 0.0;          ///< lost motion on reversal
    double leadErrorPerUnit = 0.0;  ///< screw lead error, fraction of travel (open-loop axes see it)
    /// Periodic pitch error of the screw: the nut is ahead of its nominal place by
    /// amplitude · sin(2π · screw / period); one period per turn of the screw (its lead).
    /// The stage's grating loop hides it; the analyzer's carriage carries it.
    double pitchErrorAmplitude = 0.0;
    double pitchErrorPeriod = 0.0;  ///< screw travel per period (the lead); 0: no pitch error
    /// The encoder or grating reads carriage × (1 + this): a scale that is itself
    /// slightly long or short (a grating's accuracy class, ±µm per metre). A loop
    /// closed on that reading puts the carriage off by the same share.
    double scaleErrorPerUnit = 0.0;
    /// The work point against the carriage where the scale reads it, µm, a polynomial
    /// in the carriage position (mm), c0 first: the Abbe error of a work point that
    /// sits off the scale's line (seed 002: the grating runs along the stage's edge,
    /// the sample sits in the middle) times the guides' pitch and yaw along travel.
    std::vector<double> abbeErrorPolyUm;
    double switchRepeatability = 0.0; ///< ±, added to the latched home position
    double startPosition = 10;      ///< machine coordinate at power-up
};

struct PidGains { double kp = 0.25, ki = 0.5, kd = 0.03; };  ///< seed 002's tuned gains

/// What the stage's loop does around seed 002's PID.
struct ClosedLoopTuning {
    /// An error of at most this many grating counts counts as zero. Integral action
    /// on a quantized reading through screw backlash otherwise hunts forever (a
    /// limit cycle of ±1 count every ~45 ms on the stage).
    double deadbandCounts = 1.0;
    /// The motor leads the reference by velocity × this, matching the lags of the
    /// rotor and the drive, so the integrator does not have to store the lag (and
    /// give it back as overshoot when the reference stops).
    double velocityFeedForwardS = 0.002;
    /// …and by the acceleration's change × this (τ_rotor·τ_drive), so the second
    /// lag does not leave a following error to clean up after every ramp.
    double accelFeedForwardS2 = 0.0;
};

struct MachineConfig {
    dev::proto::DeviceKind kind = dev::proto::DeviceKind::Analyzer;
    std::string model;
    std::vector<AxisConfig> axes;
    ProfileKind profile = ProfileKind::SeedSCurve;
    bool closedLoop = false;        ///< stage: grating feedback + incremental PID
    bool zAfterXy = false;          ///< analyzer: Z starts when the XY move has arrived
    double controlPeriodS = 0.001;  ///< PID period
    double driveLagS = 0.002;       ///< carriage follows the screw with this first-order lag (closed loop)
    /// Closed loop: the motor's rotor (torque build-up, coupling) follows its
    /// steps with this first-order lag before the screw turns. 0: at once.
    double rotorLagS = 0.0;
    double inPositionWindow = 0.002;///< closed loop: |error| below this for settleTimeS means arrived
    double settleTimeS = 0.01;
    /// Open loop: |encoder − command| above this at rest raises LostSteps. It must
    /// clear healthy lead error plus backlash (50 µm on the analyzer's X at 199 mm
    /// after a reversal); 0.1 mm is 2.5 full steps of an 8 mm lead.
    double lostStepTolerance = 0.1;
    PidGains gains;
    ClosedLoopTuning loop;
    std::uint64_t seed = 12345;     ///< noise is deterministic for a given seed
};

MachineConfig analyzerConfig();
MachineConfig stageConfig();

} // namespace dev::sim
