#pragma once
// One simulated axis: the plant (stepper, screw, carriage, switches, encoder or
// grating) and, for the stage, its incremental PID loop. Positions here are
// machine coordinates in axis units; the machine maps them to what the host sees.
#include "device/sim/machine_config.h"
#include "motion/metrology/compensation/compensation_model.h"

#include <cstdint>
#include <optional>
#include <random>

namespace dev::sim {

class SimAxis {
public:
    /// `driveLagS`: closed loop only, the table follows the nut with this first-order lag;
    /// `rotorLagS`: closed loop only, the screw follows the motor's steps with this one.
    SimAxis(const AxisConfig& config, bool closedLoop, std::uint64_t seed, double driveLagS = 0.002, double rotorLagS = 0);

    const AxisConfig& config() const { return m_cfg; }

    /// The reference the trajectory generator wants now, and its velocity. With a
    /// compensation attached this is the nominal position; the drive follows it plus
    /// the correction (driveReference()).
    void setReference(double position, double velocity);
    double reference() const { return m_ref; }
    /// Where the motor (open loop) or the position loop (closed loop) is sent: the
    /// reference plus the compensation's correction at it, for the side it is
    /// approached from (seed 002: every position command has the error at that
    /// position taken off; here on every tick, so paths and jogs are compensated too).
    double driveReference() const { return m_drive; }

    /// Attaches an error compensation (positions in home coordinates: machine
    /// position − `homeMachine`), or detaches it (nullptr). The drive does not move:
    /// the nominal reference is shifted instead, so enabling or disabling never
    /// jerks the axis; the next move goes to the compensated place.
    void setCompensation(const motion::metrology::CompensationModel* model, double homeMachine);
    bool compensated() const { return m_comp.has_value(); }
    double referenceVelocity() const { return m_refVel; }

    /// Advances the plant by one simulation tick.
    void tick(double dtS);
    /// Closed loop only: one PID period (seed 002 eq. 2, incremental form) on top of
    /// the reference's feed-forward.
    void controlStep(const PidGains& gains, int ticksPerPeriod, const ClosedLoopTuning& tuning = {});
    /// Closed loop, a tuning test in force: this period's correction Δu comes from
    /// the test instead of the PID, and the reference (the test's setpoint) is not fed forward.
    void applyCorrection(double du, int ticksPerPeriod);
    /// Closed loop: the PID takes over again from the present error, without a kick.
    void resumeLoop(const ClosedLoopTuning& tuning = {});
    /// The controller output u: the running sum of every period's Δu since power-up.
    double controllerU() const { return m_u; }
    /// Makes the reference equal to where the carriage is, e.g. after a latched stop.
    void holdHere();
    /// Closed loop: holdHere, and the motor is sent back at once to where the
    /// grating reads, instead of letting the table follow a motor that a wild
    /// test drove far ahead of it: the safe stop after a trip.
    void stopAtMeasured();
    /// E-stop: the reference freezes; the motor gets no more steps.
    void freeze();

    // Three positions, as on a real machine: where the carriage truly is (at the
    // scale's line), what the encoder or grating reads of it (quantized, with the
    // scale's own error), and where the work point is (the carriage plus the Abbe
    // error): what a gauge or an interferometer at the work point measures.
    double carriage() const { return m_carriage; }                 ///< true position of the carriage
    double measured() const;                                       ///< encoder or grating reading
    double workPoint() const;                                      ///< what a gauge or interferometer at the work point reads
    /// The reading reported to the host, in the nominal frame the reference is in: on a
    /// closed loop the grating less the correction in force (the device's best idea of
    /// the work point; a compensated stage at rest reads its nominal target). An open
    /// loop's encoder on the carriage already reads where the carriage is: as it is.
    double reportedMeasured() const { return m_closedLoop ? measured() - (m_drive - m_ref) : measured(); }
    double followingError() const { return reportedMeasured() - m_ref; }
    double measuredVelocity() const { return m_measuredVel; }
    double controllerOutputStepsS() const { return m_outputStepsS; }
    bool homeSwitch() const { return m_carriage <= m_cfg.homeSwitchAt; }
    bool limitSwitch() const { return m_carriage >= m_cfg.travel + m_cfg.limitSwitchMargin; }
    std::int64_t lostSteps() const { return m_lostSteps; }

    /// Overload factor ≥ 1: above 1 the motor slips and a share 1 − 1/load of steps is lost.
    void setLoadFactor(double load) { m_load = load < 1 ? 1 : load; }
    double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(m_rng); }

private:
    /// Where the nut pushes for a screw position: lead error and the pitch error's ripple.
    double nutPosition(double screw) const;
    void issueSteps(std::int64_t steps, double dtS);
    void takeUpPlay();
    /// m_drive from m_ref and the approach direction.
    void updateDrive();
    /// The nominal reference whose drive reference is `drive` (the correction inverted).
    double nominalForDrive(double drive) const;
    double correctionAt(double nominal) const;

    AxisConfig m_cfg;
    bool m_closedLoop;
    double m_lagS;
    double m_rotorLagS;
    std::mt19937_64 m_rng;

    double m_ref = 0, m_refVel = 0, m_prevRefForLoop = 0, m_prevRefVelForLoop = 0;
    double m_drive = 0;             ///< m_ref plus the compensation's correction (m_prevRefForLoop tracks this)
    std::optional<motion::metrology::CompensationModel> m_comp;
    double m_compHome = 0;          ///< machine position of home coordinate 0
    motion::metrology::Direction m_approach = motion::metrology::Direction::Up;  ///< the side the reference last moved towards
    double m_prevDvForLoop = 0;     ///< last period's change of the reference velocity (acceleration feed-forward)
    double m_tickS = 1e-4;          ///< the simulation tick, as tick() was last given it
    std::int64_t m_motorSteps = 0;  ///< steps the driver has received, from machine zero
    double m_screw = 0;             ///< nut position: motor position less slipped steps
    double m_rotor = 0;             ///< closed loop: where the rotor has turned the screw to (lags m_screw)
    std::int64_t m_lostSteps = 0;
    double m_driven = 0;            ///< where the nut has pushed the carriage to, through the play
    double m_carriage = 0;
    double m_prevMeasured = 0, m_measuredVel = 0;
    double m_outputStepsS = 0;
    double m_stepAccumulator = 0;   ///< closed loop: fractional steps carried between periods
    double m_e1 = 0, m_e2 = 0;      ///< PID: error at k−1, k−2 (axis units)
    double m_u = 0;                 ///< controller output, running sum of Δu (axis units)
    double m_load = 1;
    int m_ticksLeft = 1;            ///< ticks left in the current PID period
    bool m_frozen = false;
};

} // namespace dev::sim
