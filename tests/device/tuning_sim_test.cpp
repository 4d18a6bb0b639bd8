// The simulated stage's tuning side (sim_tuning.cpp) driven directly: gains
// per axis, step and relay tests with the abort envelope on the device, and
// what ends a test — always with the axis stopped under the operator's gains.
#include "sim_test_support.h"

#include "device/sim/sim_tuning.h"
#include "motion/control/experiment.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>

namespace {

using namespace simtest;
using motion::control::EndReason;

constexpr int kX = 0;

struct TuningStage : HomedMachine<dev::sim::stageConfig> {
    void SetUp() override
    {
        HomedMachine::SetUp();
        ASSERT_FALSE(m.move(absMove(bit(kX), {50})));
        ASSERT_TRUE(r.runUntilIdle(20));
        r.events.clear();
    }
    dev::sim::SimTuning& t() { return m.tuning(); }
    /// Runs with a host that keeps talking (the client's 50 ms polls).
    void run(double s, const std::function<void()>& each = {})
    {
        r.run(s, [&] {
            t().hostHeard();
            if (each)
                each();
        });
    }
    dev::proto::GainsReply gains()
    {
        dev::proto::GainsReply g;
        EXPECT_FALSE(t().getGains(kX, g));
        return g;
    }
    dev::proto::CaptureReply capture(std::uint32_t first = 0)
    {
        dev::proto::CaptureReply c;
        const auto e = t().capture({kX, first, dev::proto::kMaxCaptureSamplesPerReply}, c);
        EXPECT_FALSE(e) << (e ? e->message : "");
        return c;
    }
    static dev::proto::StepTestRequest step(double mm, std::optional<dev::proto::WireGains> trial = {})
    {
        dev::proto::StepTestRequest s;
        s.axis = kX;
        s.step = nm(mm);
        s.settleBand = nm(0.001);  // two grating counts: the loop's deadband is one
        s.settleHoldMs = 20;
        s.envelope = {static_cast<std::uint32_t>(nm(3 * std::abs(mm))), static_cast<std::uint32_t>(nm(2 * std::abs(mm))), 2000};
        s.trialGains = trial;
        return s;
    }
    static dev::proto::RelayTestRequest relay(double dMm, int cycles)
    {
        dev::proto::RelayTestRequest q;
        q.axis = kX;
        q.amplitude = static_cast<std::uint32_t>(nm(dMm));
        q.hysteresis = static_cast<std::uint32_t>(nm(0.001));
        q.cycles = static_cast<std::uint16_t>(cycles);
        q.envelope = {static_cast<std::uint32_t>(nm(0.1)), static_cast<std::uint32_t>(nm(0.1)), 5000};
        return q;
    }
};

} // namespace

TEST_F(TuningStage, GainsAreTheSeedsAndTheControlPeriodIsReported)
{
    const auto g = gains();
    EXPECT_EQ(g.controlPeriodUs, 1000u);
    EXPECT_FLOAT_EQ(g.gains.kp, 0.25f);
    EXPECT_FLOAT_EQ(g.gains.ki, 0.5f);
    EXPECT_FLOAT_EQ(g.gains.kd, 0.03f);
    EXPECT_EQ(g.saved, g.gains);
    EXPECT_EQ(g.flags, 0);
    EXPECT_GT(g.limits.kp, 1.0f);
}

TEST_F(TuningStage, BadGainsAreRefusedWithAReasonAndThePreviousOnesStay)
{
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    const dev::proto::WireGains before = gains().gains;
    for (const dev::proto::WireGains& bad : {dev::proto::WireGains{nan, 0.5f, 0.03f}, dev::proto::WireGains{0.25f, -1.0f, 0.03f},
                                        dev::proto::WireGains{0.25f, 0.5f, inf}, dev::proto::WireGains{1e9f, 0.5f, 0.03f}}) {
        const auto e = t().setGains({kX, 0, bad});
        ASSERT_TRUE(e);
        EXPECT_EQ(e->code, dev::proto::kErrBadGains);
        EXPECT_NE(e->message.find("the previous ones stay"), std::string::npos) << e->message;
        EXPECT_EQ(gains().gains, before);
    }
    EXPECT_EQ(r.count(dev::proto::kEvGainsChanged), 0);
    // A good set takes effect, is announced, and is kept for power-up only when asked.
    ASSERT_FALSE(t().setGains({kX, 0, {0.3f, 0.4f, 0.02f}}));
    r.take();
    EXPECT_EQ(r.count(dev::proto::kEvGainsChanged, kX), 1);
    EXPECT_EQ(gains().gains, (dev::proto::WireGains{0.3f, 0.4f, 0.02f}));
    EXPECT_EQ(gains().saved, before);
    ASSERT_FALSE(t().setGains({kX, dev::proto::kSetGainsSave, {0.3f, 0.4f, 0.02f}}));
    EXPECT_EQ(gains().saved, (dev::proto::WireGains{0.3f, 0.4f, 0.02f}));
}

TEST_F(TuningStage, StepTestSettlesUnderTheOperatorsGainsAndIsCaptured)
{
    ASSERT_FALSE(t().stepTest(step(0.02)));
    EXPECT_TRUE(moving(m, kX));
    EXPECT_TRUE(t().setGains({kX, 0, {1, 1, 1}}));  // refused while it runs
    run(1.0);
    EXPECT_FALSE(moving(m, kX));
    const auto* ended = r.find(dev::proto::kEvTestEnded, kX);
    ASSERT_NE(ended, nullptr);
    EXPECT_NE(ended->text.find("settled"), std::string::npos) << ended->text;
    ASSERT_TRUE(ended->reason);
    EXPECT_EQ(ended->reason->code, dev::proto::reason::kSettled);
    ASSERT_EQ(ended->reason->values.size(), 2u);
    EXPECT_EQ(ended->reason->values[0], dev::proto::reason::kStepTest);
    EXPECT_GT(ended->reason->values[1], 0.0) << "how long it ran";
    EXPECT_NEAR(measuredMm(m, kX), 50.02, 0.001);
    EXPECT_NEAR(commandedMm(m, kX), 50.02, 1e-9);  // it stays on the step it settled on
    const auto c = capture();
    EXPECT_EQ(c.kind, 1);
    EXPECT_EQ(c.reason, static_cast<std::uint8_t>(EndReason::Settled));
    EXPECT_EQ(c.periodUs, 1000u);
    EXPECT_EQ(c.startPosition, nm(50));
    EXPECT_EQ(c.gains, (dev::proto::WireGains{0.25f, 0.5f, 0.03f}));
    ASSERT_GT(c.total, 20u);
    EXPECT_EQ(c.samples.front().setpoint, nm(50.02));
    EXPECT_NEAR(c.samples.back().measured, nm(50.02), 1000);
}

TEST_F(TuningStage, TrialGainsAreUsedForTheTestOnlyAndTheEnvelopeStopsTheAxis)
{
    // P-only far above the loop's ultimate gain: it grows until the envelope trips.
    auto s = step(0.01, dev::proto::WireGains{12, 0, 0});
    s.envelope.maxFollowingError = static_cast<std::uint32_t>(nm(0.05));  // the excursion limit is the one to trip
    ASSERT_FALSE(t().stepTest(s));
    EXPECT_EQ(gains().gains, (dev::proto::WireGains{0.25f, 0.5f, 0.03f}));  // the operator's set, untouched
    EXPECT_EQ(gains().flags, dev::proto::kGainsTestRunning);
    double worst = 0;
    run(1.0, [&] { worst = std::max(worst, std::abs(m.measuredLogical(kX) - 50)); });
    const auto* tripped = r.find(dev::proto::kEvTestTripped, kX);
    ASSERT_NE(tripped, nullptr);
    EXPECT_NE(tripped->text.find("max excursion 0.0300 mm crossed"), std::string::npos) << tripped->text;
    ASSERT_TRUE(tripped->reason);
    EXPECT_EQ(tripped->reason->code, dev::proto::reason::kExcursion);
    ASSERT_EQ(tripped->reason->values.size(), 5u) << "test, limit, value, seconds, where it stopped";
    EXPECT_EQ(tripped->reason->values[0], dev::proto::reason::kStepTest);
    EXPECT_DOUBLE_EQ(tripped->reason->values[1], 0.03);
    EXPECT_GT(tripped->reason->values[2], 0.03);
    EXPECT_FALSE(moving(m, kX));
    const auto c = capture();
    EXPECT_EQ(c.reason, static_cast<std::uint8_t>(EndReason::Excursion));
    EXPECT_EQ(c.tripLimit, 30000u);
    EXPECT_GT(c.tripValue, 30000u);
    // The limit is checked once a control period, and this loop (P at ~2.4 Ku)
    // moves the table up to ~20 µm in one: that overrun, and no more, is what
    // trial envelopes (60 % of the operator's) leave room for.
    EXPECT_LT(worst, 0.03 + 0.02) << "the grating ran on after the trip";
    // Stopped, and holding under the operator's gains: it stays put.
    const double here = measuredMm(m, kX);
    run(0.5);
    EXPECT_NEAR(measuredMm(m, kX), here, 0.002);
    EXPECT_EQ(gains().flags, 0);
}

TEST_F(TuningStage, RelayOscillatesAroundWhereItStarted)
{
    ASSERT_FALSE(t().relayTest(relay(0.01, 20)));
    run(1.0);
    const auto* ended = r.find(dev::proto::kEvTestEnded, kX);
    ASSERT_NE(ended, nullptr);
    const auto c = capture();
    EXPECT_EQ(c.kind, 2);
    EXPECT_EQ(c.reason, static_cast<std::uint8_t>(EndReason::Completed));
    int highs = 0, lows = 0;
    for (const auto& s : c.samples) {
        EXPECT_TRUE(s.output == nm(0.01) || s.output == nm(-0.01)) << s.output;
        highs += s.output > 0;
        lows += s.output < 0;
        EXPECT_EQ(s.setpoint, nm(50));
    }
    EXPECT_NEAR(highs, lows, 0.2 * (highs + lows));
}

TEST_F(TuningStage, EStopMidOscillationEndsTheTestAndKeepsTheGains)
{
    ASSERT_FALSE(t().relayTest(relay(0.01, 1000)));
    run(0.2);
    ASSERT_TRUE(t().testRunning(kX));
    ASSERT_FALSE(m.estop());
    r.take();
    const auto* aborted = r.find(dev::proto::kEvTestAborted, kX);
    ASSERT_NE(aborted, nullptr);
    EXPECT_NE(aborted->text.find("E-stop"), std::string::npos);
    ASSERT_TRUE(aborted->reason);
    EXPECT_EQ(*aborted->reason, (dev::proto::EventReason{dev::proto::reason::kByEStop, {dev::proto::reason::kRelayTest}}));
    EXPECT_FALSE(t().testRunning(kX));
    EXPECT_EQ(capture().reason, static_cast<std::uint8_t>(EndReason::EStop));
    const double here = m.measuredLogical(kX);
    run(0.3);
    // Frozen: no more steps. The table only settles onto the motor, which the
    // relay (d = 10 µm) had set at most d away from it.
    EXPECT_NEAR(m.measuredLogical(kX), here, 0.011);
    ASSERT_FALSE(m.reset());
    run(0.3);
    EXPECT_FALSE(moving(m, kX));
    EXPECT_EQ(gains().gains, (dev::proto::WireGains{0.25f, 0.5f, 0.03f}));
}

TEST_F(TuningStage, ATestEndsByItselfWhenTheHostGoesSilent)
{
    ASSERT_FALSE(t().relayTest(relay(0.01, 1000)));
    r.run(0.49);  // nobody calls hostHeard(): the host is gone
    EXPECT_TRUE(t().testRunning(kX));
    r.run(0.05);
    EXPECT_FALSE(t().testRunning(kX));
    const auto* aborted = r.find(dev::proto::kEvTestAborted, kX);
    ASSERT_NE(aborted, nullptr);
    EXPECT_NE(aborted->text.find("no frame from the host"), std::string::npos) << aborted->text;
    EXPECT_EQ(capture().reason, static_cast<std::uint8_t>(EndReason::HostSilent));
    r.run(0.3);
    EXPECT_FALSE(moving(m, kX));
}

TEST_F(TuningStage, StopAndTestAbortEndATestAndTheAxisHolds)
{
    ASSERT_FALSE(t().relayTest(relay(0.01, 1000)));
    run(0.1);
    ASSERT_FALSE(m.stop(0));
    r.take();
    ASSERT_NE(r.find(dev::proto::kEvTestAborted, kX), nullptr);
    EXPECT_EQ(capture().reason, static_cast<std::uint8_t>(EndReason::Stopped));
    ASSERT_FALSE(t().relayTest(relay(0.01, 1000)));
    run(0.1);
    ASSERT_FALSE(t().abort(bit(kX), EndReason::Stopped));
    EXPECT_FALSE(t().testRunning(kX));
    EXPECT_FALSE(t().abort(0, EndReason::Stopped));  // nothing running: still fine
}

TEST_F(TuningStage, TestsAreRefusedWhereTheyCannotRunSafely)
{
    auto code = [](const dev::sim::SimTuning::Result& e) { return e ? e->code : dev::proto::ErrorCode{}; };
    auto far = step(0.01);
    far.envelope.maxExcursion = static_cast<std::uint32_t>(nm(60));  // 50 ± 60 mm crosses both soft limits
    EXPECT_EQ(code(t().stepTest(far)), dev::proto::ErrorCode::SoftLimit);
    auto tight = step(0.01);
    tight.envelope.maxFollowingError = static_cast<std::uint32_t>(nm(0.005));  // below the step itself
    const auto e = t().stepTest(tight);
    EXPECT_EQ(code(e), dev::proto::ErrorCode::OutOfRange);
    EXPECT_NE(e->message.find("max following error must be above the step size"), std::string::npos) << e->message;
    EXPECT_EQ(code(t().stepTest(step(0.01, dev::proto::WireGains{-1, 0, 0}))), dev::proto::kErrBadGains);
    ASSERT_FALSE(t().stepTest(step(0.01)));
    EXPECT_EQ(code(t().relayTest(relay(0.01, 10))), dev::proto::kErrTestActive);
    EXPECT_EQ(code(m.move(relMove(bit(kX), {1}))), dev::proto::ErrorCode::Busy);
    run(1.0);
    ASSERT_FALSE(m.estop());
    EXPECT_EQ(code(t().stepTest(step(0.01))), dev::proto::ErrorCode::EStopActive);

    dev::sim::SimMachine analyzer(dev::sim::analyzerConfig());
    dev::proto::GainsReply g;
    EXPECT_EQ(code(analyzer.tuning().getGains(0, g)), dev::proto::kErrNotClosedLoop);
    dev::sim::SimMachine unhomed(dev::sim::stageConfig());
    EXPECT_EQ(code(unhomed.tuning().stepTest(step(0.01))), dev::proto::ErrorCode::NotHomed);
    dev::proto::CaptureReply c;
    EXPECT_EQ(code(unhomed.tuning().capture({0, 0, 10}, c)), dev::proto::kErrNoCapture);
}

// Found by libFuzzer (tests/fuzz/corpus/codec/regress-test-duration-over-int32, replayed by
// fuzz_codec): a test asked to last 2.3e9 ms was refused with that value cast to the reply's
// int32 — undefined behaviour, and under UBSan a crash of the firmware.
TEST_F(TuningStage, ADurationBeyondTheWiresInt32IsRefusedNamingTheLargestValue)
{
    auto s = step(0.01);
    s.envelope.maxDurationMs = 3'000'000'000u;
    const auto e = t().stepTest(s);
    ASSERT_TRUE(e);
    EXPECT_EQ(e->code, dev::proto::ErrorCode::OutOfRange);
    EXPECT_EQ(e->value, std::numeric_limits<std::int32_t>::max());
    EXPECT_NE(e->message.find("at most"), std::string::npos) << e->message;
}

TEST_F(TuningStage, ALongTestKeepsAllOfItsCaptureAtAHalvedRate)
{
    auto s = step(0.01);
    s.settleBand = 0;
    s.runMs = 20000;  // 20 000 periods: more than the capture holds
    s.envelope.maxDurationMs = 21000;
    ASSERT_FALSE(t().stepTest(s));
    run(20.1);
    const auto c = capture();
    EXPECT_EQ(c.reason, static_cast<std::uint8_t>(EndReason::Completed));
    EXPECT_EQ(c.periodUs, 2000u);
    EXPECT_NEAR(c.total, 10000u, 2u);
}

TEST_F(TuningStage, NewGainsTakeOverBetweenTwoPeriodsWithoutABump)
{
    // At rest the PID's output u holds the screw's lead error (all of it in the
    // integral): a positional PID switched to twice the ki would jump by u.
    run(0.2);
    const double u0 = m.axis(kX).controllerU();
    ASSERT_GT(std::abs(u0), 0.005) << "the loop holds next to nothing: the test would show nothing";
    ASSERT_FALSE(t().setGains({kX, 0, {0.5f, 1.0f, 0.06f}}));
    double worst = 0;
    run(0.2, [&] { worst = std::max(worst, std::abs(m.axis(kX).controllerU() - u0)); });
    EXPECT_LT(worst, 0.001) << "the output moved at the switch";
    EXPECT_NEAR(measuredMm(m, kX), 50, 0.001);
}

// Kp 5 (a typed "-5" whose sign was dropped) applied as the
// operator's set, then a step test under it. It diverges and trips; after the
// trip the axis must be at rest under the gains it had before that set, not
// run on under the set that just diverged, and the trip says where it stopped.
TEST_F(TuningStage, AfterATripUnderTheOperatorsGainsTheAxisRestsUnderThePreviousSet)
{
    const dev::proto::WireGains before = gains().gains;
    ASSERT_FALSE(t().setGains({kX, 0, {5.0f, before.ki, before.kd}}));
    auto s = step(0.05);
    s.envelope.maxExcursion = static_cast<std::uint32_t>(nm(0.15));
    s.envelope.maxFollowingError = static_cast<std::uint32_t>(nm(0.1));
    ASSERT_FALSE(t().stepTest(s));
    run(2.0);
    const auto* tripped = r.find(dev::proto::kEvTestTripped, kX);
    ASSERT_NE(tripped, nullptr) << "Kp 5 should diverge";
    const double atTrip = measuredMm(m, kX);
    double worst = 0;
    run(1.0, [&] { worst = std::max(worst, std::abs(measuredMm(m, kX) - atTrip)); });
    EXPECT_LT(worst, 0.01) << "the axis ran on after the trip";
    EXPECT_FALSE(moving(m, kX));
    EXPECT_EQ(gains().gains, before) << "still under the gains that diverged";
    EXPECT_LT(std::abs(measuredMm(m, kX) - 50), 0.2);
    const auto at = tripped->text.find("stopped at ");
    ASSERT_NE(at, std::string::npos) << tripped->text;
    double said = 0;
    ASSERT_EQ(std::sscanf(tripped->text.c_str() + at, "stopped at %lf mm", &said), 1) << tripped->text;
    EXPECT_NEAR(said, measuredMm(m, kX), 0.005) << tripped->text;
}
