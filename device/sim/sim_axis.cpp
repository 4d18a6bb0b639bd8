#include "device/sim/sim_axis.h"

#include <algorithm>
#include <cmath>

namespace dev::sim {

SimAxis::SimAxis(const AxisConfig& config, bool closedLoop, std::uint64_t seed, double driveLagS, double rotorLagS)
    : m_cfg(config), m_closedLoop(closedLoop), m_lagS(driveLagS), m_rotorLagS(rotorLagS), m_rng(seed)
{
    m_motorSteps = std::llround(config.startPosition / config.stepSize);
    m_screw = static_cast<double>(m_motorSteps) * config.stepSize;
    m_rotor = m_screw;
    m_driven = nutPosition(m_screw);  // power-up: the play sits centred
    m_carriage = m_driven;
    m_ref = measured();
    m_drive = m_ref;
    m_prevRefForLoop = m_drive;
    m_prevMeasured = measured();
}

double SimAxis::correctionAt(double nominal) const
{
    if (!m_comp)
        return 0;
    const double home = nominal - m_compHome;
    return m_comp->commandMm(home, m_approach) - home;
}

void SimAxis::updateDrive() { m_drive = m_ref + correctionAt(m_ref); }

double SimAxis::nominalForDrive(double drive) const
{
    // n + k(n) = drive; k changes by far less than n (its slope is below 0.1), so the
    // fixed-point iteration converges by an order of magnitude a step.
    double n = drive - (m_drive - m_ref);
    for (int i = 0; i < 8; ++i)
        n = drive - correctionAt(n);
    return n;
}

void SimAxis::setCompensation(const motion::metrology::CompensationModel* model, double homeMachine)
{
    const double drive = m_drive;
    if (model)
        m_comp = *model;
    else
        m_comp.reset();
    m_compHome = homeMachine;
    m_ref = nominalForDrive(drive);
    updateDrive();
    m_drive = drive;  // exactly: the axis does not move
}

void SimAxis::setReference(double position, double velocity)
{
    if (m_frozen)
        return;
    // The approach side follows the reference's motion: its velocity, or for a
    // setpoint that jumps (a tuning step) the jump.
    if (velocity > 1e-12 || (velocity == 0 && position > m_ref + 1e-9))
        m_approach = motion::metrology::Direction::Up;
    else if (velocity < -1e-12 || (velocity == 0 && position < m_ref - 1e-9))
        m_approach = motion::metrology::Direction::Down;
    m_ref = position;
    m_refVel = velocity;
    updateDrive();
}

void SimAxis::freeze()
{
    m_frozen = true;
    m_refVel = 0;
    m_stepAccumulator = 0;
}

void SimAxis::holdHere()
{
    m_frozen = false;
    m_ref = nominalForDrive(m_closedLoop ? measured() : static_cast<double>(m_motorSteps) * m_cfg.stepSize);
    updateDrive();
    m_refVel = 0;
    m_prevRefForLoop = m_drive;
    m_prevRefVelForLoop = 0;
    m_prevDvForLoop = 0;
    m_e1 = m_e2 = 0;
    m_stepAccumulator = 0;
}

void SimAxis::stopAtMeasured()
{
    holdHere();
    if (!m_closedLoop)
        return;
    // The screw position that puts the carriage at the grating's reading (the pitch
    // error's ripple is left to the loop: it is a few µm).
    const double screwTarget = measured() / (1.0 + m_cfg.scaleErrorPerUnit) / (1.0 + m_cfg.leadErrorPerUnit);
    m_stepAccumulator = std::round((screwTarget - static_cast<double>(m_motorSteps) * m_cfg.stepSize) / m_cfg.stepSize);
    m_ticksLeft = 1;
}

void SimAxis::takeUpPlay()
{
    // Lead error grows along the screw. The nut sits in a gap of `backlash` in the
    // carriage: the carriage only moves once the nut presses one side of the gap,
    // so on reversal the screw first turns through the play with the carriage
    // standing still (a play operator, never a jump against the motion).
    const double nominal = nutPosition(m_rotor);
    const double half = 0.5 * m_cfg.backlash;
    m_driven = std::clamp(m_driven, nominal - half, nominal + half);
}

double SimAxis::nutPosition(double screw) const
{
    double nut = screw * (1.0 + m_cfg.leadErrorPerUnit);
    if (m_cfg.pitchErrorPeriod > 0)
        nut += m_cfg.pitchErrorAmplitude * std::sin(6.283185307179586 * screw / m_cfg.pitchErrorPeriod);
    return nut;
}

double SimAxis::measured() const
{
    return std::floor(m_carriage * (1.0 + m_cfg.scaleErrorPerUnit) / m_cfg.resolution + 0.5) * m_cfg.resolution;
}

double SimAxis::workPoint() const
{
    double errUm = 0, p = 1;
    for (double c : m_cfg.abbeErrorPolyUm) {
        errUm += c * p;
        p *= m_carriage;
    }
    return m_carriage + errUm * 1e-3;
}

void SimAxis::issueSteps(std::int64_t steps, double dtS)
{
    if (steps == 0)
        return;
    (void)dtS;
    m_motorSteps += steps;
    // Slip: under overload a share of the steps never reaches the nut, and steps
    // that would push the carriage into a hard stop are lost too.
    const double load = m_load;
    const std::int64_t dir = steps > 0 ? 1 : -1;
    for (std::int64_t i = 0; i < std::abs(steps); ++i) {
        const double next = m_screw + static_cast<double>(dir) * m_cfg.stepSize;
        const bool hardStop = next < m_cfg.homeSwitchAt - m_cfg.hardStopMargin
            || next > m_cfg.travel + m_cfg.limitSwitchMargin + m_cfg.hardStopMargin;
        const bool slip = load > 1.0 && uniform(0, 1) < 1.0 - 1.0 / load;
        if (hardStop || slip) {
            ++m_lostSteps;
            continue;
        }
        m_screw = next;
    }
}

void SimAxis::controlStep(const PidGains& g, int ticksPerPeriod, const ClosedLoopTuning& tuning)
{
    if (!m_closedLoop || m_frozen)
        return;
    // Seed 002 eq. 2: Δu = Kp(e_k − e_{k−1}) + Ki·e_k + Kd(e_k − 2e_{k−1} + e_{k−2}),
    // with Δu the motor travel sent this period on top of the reference's own
    // advance (feed-forward), so the loop only corrects what the screw got wrong.
    const double raw = m_drive - measured();
    const double e = std::abs(raw) <= tuning.deadbandCounts * m_cfg.resolution + 1e-12 ? 0.0 : raw;
    const double du = g.kp * (e - m_e1) + g.ki * e + g.kd * (e - 2 * m_e1 + m_e2);
    m_e2 = m_e1;
    m_e1 = e;
    m_u += du;
    // Two lags in series (rotor, table) are undone by τ1+τ2 on the velocity's
    // change and τ1·τ2 on the acceleration's change.
    const double dv = m_refVel - m_prevRefVelForLoop;
    const double periodS = std::max(1, ticksPerPeriod) * m_tickS;
    const double feedForward = (m_drive - m_prevRefForLoop) + tuning.velocityFeedForwardS * dv
        + tuning.accelFeedForwardS2 * (dv - m_prevDvForLoop) / periodS;
    m_prevDvForLoop = dv;
    m_prevRefForLoop = m_drive;
    m_prevRefVelForLoop = m_refVel;
    m_stepAccumulator += (feedForward + du) / m_cfg.stepSize;
    m_ticksLeft = ticksPerPeriod < 1 ? 1 : ticksPerPeriod;
}

void SimAxis::applyCorrection(double du, int ticksPerPeriod)
{
    if (!m_closedLoop || m_frozen)
        return;
    m_prevRefForLoop = m_drive;
    m_prevRefVelForLoop = m_refVel;
    m_prevDvForLoop = 0;
    m_u += du;
    m_stepAccumulator += du / m_cfg.stepSize;
    m_ticksLeft = ticksPerPeriod < 1 ? 1 : ticksPerPeriod;
}

void SimAxis::resumeLoop(const ClosedLoopTuning& tuning)
{
    // Eq. 2 differences errors: an error history from before the test would
    // look like a jump and kick the derivative term.
    const double raw = m_drive - measured();
    m_e1 = m_e2 = std::abs(raw) <= tuning.deadbandCounts * m_cfg.resolution + 1e-12 ? 0.0 : raw;
    m_prevRefForLoop = m_drive;
    m_prevRefVelForLoop = m_refVel;
    m_prevDvForLoop = 0;
}

void SimAxis::tick(double dtS)
{
    m_tickS = dtS;
    std::int64_t steps = 0;
    if (m_closedLoop) {
        // Spread the period's steps evenly over its ticks, as a step generator
        // would; the fraction of a step left at the end carries to the next period.
        const double want = m_stepAccumulator / (m_ticksLeft > 1 ? m_ticksLeft : 1);
        if (m_ticksLeft > 1)
            --m_ticksLeft;
        steps = static_cast<std::int64_t>(std::trunc(want));
        m_stepAccumulator -= static_cast<double>(steps);
        m_outputStepsS = static_cast<double>(steps) / dtS;
    } else if (!m_frozen) {
        steps = std::llround(m_drive / m_cfg.stepSize) - m_motorSteps;
        m_outputStepsS = static_cast<double>(steps) / dtS;
    }
    issueSteps(steps, dtS);
    if (m_closedLoop && m_rotorLagS > 0)
        m_rotor += (m_screw - m_rotor) * std::min(1.0, dtS / m_rotorLagS);
    else
        m_rotor = m_screw;
    takeUpPlay();
    if (m_closedLoop && m_lagS > 0) {
        // The table follows the nut through the coupling and its own compliance.
        m_carriage += (m_driven - m_carriage) * std::min(1.0, dtS / m_lagS);
    } else {
        m_carriage = m_driven;
    }
    const double meas = measured();
    // A light low-pass so the velocity channel is not pure quantization noise.
    const double rawVel = (meas - m_prevMeasured) / dtS;
    m_measuredVel += (rawVel - m_measuredVel) * std::min(1.0, dtS / 0.005);
    m_prevMeasured = meas;
}

} // namespace dev::sim
