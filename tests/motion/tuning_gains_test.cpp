// Seed 002's gains: eq. 2 (incremental PID), Table 1 (Ziegler–Nichols) and the
// two forms of the gains, discrete per period and continuous.
#include "motion/control/gains.h"
#include "motion/control/loop_sim.h"
#include "motion/control/pid.h"
#include "motion/control/tuning/tuning_rules.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace motion::control;

TEST(TuningGains, SeedTable1ReproducesTheSeedsGainsFromKuAndTu)
{
    // Seed 002 §2.2 reports Kp = 0.25, Ki = 0.5, Kd = 0.03 from Table 1's PID row.
    // Table 1 (Kp = 0.6·Ku, Ki = 2·Kp/Tu, Kd = Kp·Tu/8) gives exactly those for
    // Ku = 0.25/0.6 ≈ 0.417 and Tu = 1 (the seed does not give its time unit);
    // Kd = 0.25/8 = 0.03125, which the seed prints rounded to 0.03.
    const TuningRule* pid = findRule("zn-pid");
    ASSERT_NE(pid, nullptr);
    const ContinuousGains g = applyRule(*pid, 0.25 / 0.6, 1.0);
    EXPECT_NEAR(g.kp, 0.25, 1e-12);
    EXPECT_NEAR(g.kiPerS, 0.5, 1e-12);
    EXPECT_NEAR(g.kdS, 0.03125, 1e-12);
    EXPECT_NEAR(g.kdS, 0.03, 0.0015);
    // The other two rows of Table 1, as printed.
    const ContinuousGains p = applyRule(*findRule("zn-p"), 2.2, 0.5);
    EXPECT_NEAR(p.kp, 1.1, 1e-12);
    EXPECT_EQ(p.kiPerS, 0);
    EXPECT_EQ(p.kdS, 0);
    const ContinuousGains pi = applyRule(*findRule("zn-pi"), 2.2, 0.5);
    EXPECT_NEAR(pi.kp, 1.0, 1e-12);              // Ku/2.2
    EXPECT_NEAR(pi.kiPerS, 1.2 * 1.0 / 0.5, 1e-12);  // 1.2·Kp/Tu
    EXPECT_EQ(pi.kdS, 0);
}

TEST(TuningGains, SeedPlugsTable1StraightIntoEq2OnlyRightWhenTIsTheTimeUnit)
{
    // Table 1 gives continuous gains; eq. 2 needs them per period: ki = Ki·T,
    // kd = Kd/T. The seed uses 0.25/0.5/0.03 in eq. 2 unchanged, which is the
    // same thing only if its control period is its unit of time (T = 1). The
    // simulated stage runs the seed's numbers as per-period gains at T = 1 ms,
    // i.e. Ki = 500 /s and Kd = 30 µs in continuous form.
    const ContinuousGains seed{0.25, 0.5, 0.03};
    EXPECT_TRUE(toDiscrete(seed, 1.0) == (DiscreteGains{0.25, 0.5, 0.03}));
    const DiscreteGains at1ms = toDiscrete(seed, 1e-3);
    EXPECT_NEAR(at1ms.ki, 0.0005, 1e-15);
    EXPECT_NEAR(at1ms.kd, 30, 1e-12);
    const ContinuousGains stage = toContinuous({0.25, 0.5, 0.03}, 1e-3);
    EXPECT_NEAR(stage.kiPerS, 500, 1e-9);
    EXPECT_NEAR(stage.kdS, 3e-5, 1e-15);
    EXPECT_NEAR(stage.tiS(), 0.25 / 500, 1e-15);
    EXPECT_NEAR(stage.tdS(), 3e-5 / 0.25, 1e-15);
}

TEST(TuningGains, ConversionsRoundTrip)
{
    const ContinuousGains c{1.7, 42.0, 0.0035};
    const ContinuousGains back = toContinuous(toDiscrete(c, 2.5e-4), 2.5e-4);
    EXPECT_NEAR(back.kp, c.kp, 1e-12);
    EXPECT_NEAR(back.kiPerS, c.kiPerS, 1e-9);
    EXPECT_NEAR(back.kdS, c.kdS, 1e-15);
    EXPECT_TRUE(std::isinf(ContinuousGains{1, 0, 0}.tiS()));
    EXPECT_EQ((ContinuousGains{0, 1, 1}.tdS()), 0);
}

TEST(TuningGains, BadGainsAreRefusedEachWithItsReason)
{
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    EXPECT_TRUE(checkGains({0.25, 0.5, 0.03}).empty());
    const auto p = checkGains({nan, -0.1, inf});
    ASSERT_EQ(p.size(), 3u);
    EXPECT_EQ(p[0].field, "kp");
    EXPECT_EQ(p[0].message.id, "tuning.gain_not_finite");
    EXPECT_NE(motion::control::wireText(p[0]).find("NaN"), std::string::npos);
    EXPECT_EQ(p[1].field, "ki");
    EXPECT_EQ(p[1].message.id, "tuning.gain_negative");
    EXPECT_EQ(p[2].message.id, "tuning.gain_not_finite");
    EXPECT_NE(motion::control::wireText(p[2]).find("infinite"), std::string::npos);
    const auto big = checkGains({1e6, 0, 0});
    ASSERT_EQ(big.size(), 1u);
    EXPECT_EQ(big[0].message.id, "tuning.gain_above_limit");
}

TEST(TuningGains, IncrementalPidSwitchesGainsWithoutABump)
{
    // A PI loop on a plant with an offset to hold (K = 2, setpoint 1: u = 0.5 at
    // rest, all of it in the integral). Switching to very different gains at rest
    // must leave u where it is: eq. 2 only changes the size of later increments.
    const PlantSpec plant{PlantSpec::Kind::Fopdt, 2, 0.05, 0.01, 1, 1e-3};
    PlantSim sim(plant);
    IncrementalPid pid({0.1, 0.02, 0});
    for (int k = 0; k < 20000; ++k) {
        pid.step(1 - sim.output());
        sim.step(pid.output());
    }
    ASSERT_NEAR(sim.output(), 1, 1e-6);
    const double before = pid.output();
    ASSERT_NEAR(before, 0.5, 1e-5);
    pid.setGains({0.4, 0.2, 0.05});
    pid.step(1 - sim.output());
    const double jump = pid.output() - before;
    EXPECT_LT(std::abs(jump), 1e-5) << "the output jumped at the gain switch";
    // What a positional PID would have done: u = Kp·e + Ki·Σe, with Σe = u/Ki before.
    const double positionalJump = (0.2 / 0.02 - 1) * before;
    EXPECT_GT(positionalJump, 1e5 * std::abs(jump));
}
