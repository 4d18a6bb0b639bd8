#pragma once
// Seed 003 (automatic tissue microtome): exponential acceleration f(t) = fm·(1 - e^(-t/τ)),
// which uses the stepper's falling torque–speed curve better than a linear ramp, approximated by
// a staircase of timer reloads. The motor jumps to a start rate below its maximum pull-in rate,
// runs a number of steps at each stair, and the top stair carries "0 steps" as the end-of-table
// marker. Deceleration walks the same table backwards. The reload values are shortened by the
// interrupt latency (response time + the instructions before the reload), because the timer only
// restarts once the ISR has reloaded it.
//
// ExponentialProfile is the ideal curve as a rest-to-rest Profile (mm, s); ExponentialStair is the
// seed's table with its error against that curve.

#include "motion/profile.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace motion {

/// Ideal exponential rest-to-rest move: v = vm(1 - e^(-t/τ)) for accelTimeS, cruise at the speed
/// reached, deceleration the time-mirror of acceleration. Short moves shorten the acceleration
/// time (solved by Newton: the distance of an exponential ramp is transcendental in its duration).
class ExponentialProfile final : public Profile {
public:
    static std::optional<ExponentialProfile> plan(double distanceMm, double vMaxMmS, double timeConstantS,
                                                  double accelTimeS);

    double duration() const override { return 2.0 * m_accelTimeS + m_cruiseTimeS; }
    double distance() const override { return m_direction * m_lengthMm; }
    ProfileSample at(double tS) const override;

    double accelTimeS() const { return m_accelTimeS; }
    double cruiseTimeS() const { return m_cruiseTimeS; }
    double cruiseSpeedMmS() const;  ///< vm(1 - e^(-Ta/τ))

private:
    ExponentialProfile() = default;
    double m_lengthMm = 0, m_direction = 1, m_vMaxMmS = 0, m_tauS = 1, m_accelTimeS = 0, m_cruiseTimeS = 0;
};

struct ExponentialStairConfig {
    double maxRateHz = 4000;           ///< fm, steps/s
    double timeConstantS = 0.05;       ///< τ
    double accelTimeS = 0.15;          ///< the stair covers [0, accelTimeS]; 3τ reaches 95 % of fm
    double startRateHz = 200;          ///< jump rate: the first stair never runs slower than this
    int stages = 10;                   ///< N, including the top stair (the 0-step end marker)
    double timerClockHz = 1e6;         ///< e.g. an 8051 at 12 MHz counts at 1 MHz
    double interruptLatencyS = 12e-6;  ///< ISR response + instructions before the reload
    std::uint32_t timerModulus = 65536;  ///< up-counter overflows here (16-bit timer)
};

struct StairStage {
    double rateHz = 0;               ///< step rate of this stair
    std::uint32_t periodTicks = 0;   ///< timer ticks between steps at this rate
    std::uint32_t reloadTicks = 0;   ///< periodTicks minus the latency: what the timer must count
    std::uint32_t reloadValue = 0;   ///< value loaded into an up-counter: modulus - reloadTicks
    std::uint32_t steps = 0;         ///< steps run on this stair; 0 on the top stair
    bool last = false;               ///< the top stair (end-of-acceleration marker)
};

struct ExponentialStair {
    std::vector<StairStage> stages;
    double accelSteps = 0;           ///< steps of all stairs below the top
    double idealAccelSteps = 0;      ///< ∫ f dt over [0, accelTimeS]
    double stairAccelTimeS = 0;      ///< time the stairs take to reach the top stair
    double timeErrorS = 0;           ///< stairAccelTimeS - accelTimeS
    double maxRateErrorHz = 0;       ///< max |stair(t) - f(t)| over the acceleration
    double rmsRateErrorHz = 0;
};

/// nullopt when a parameter is out of range (non-positive rates/times, < 2 stages, a reload that
/// would not fit the timer or would be ≤ 0 after the latency correction).
std::optional<ExponentialStair> buildExponentialStair(const ExponentialStairConfig& config);

/// Periods (s) of every step of a move of totalSteps: up the stairs, cruise on the top stair,
/// down the stairs in reverse. A move shorter than both staircases climbs only halfway and comes
/// back down. Period = (reloadTicks + latency) / clock: what the corrected firmware produces.
std::vector<double> stairStepPeriodsS(const ExponentialStair& stair, const ExponentialStairConfig& config,
                                      std::int64_t totalSteps);

}  // namespace motion
