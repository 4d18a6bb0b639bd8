// Velocity jog on both simulated instruments: it runs while refreshed, the
// device watchdog brings it to rest within 250 ms of the last refresh when the
// host goes quiet, it stops at soft limits once homed and at switches before.
#include "sim_test_support.h"

#include "device/link/simulated_link.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>

namespace {

using simtest::anyMoving;
using simtest::bit;

using dev::proto::ErrorCode;
using dev::proto::EventKind;

long ticksFor(double s) { return static_cast<long>(std::lround(s / dev::sim::SimMachine::kTickS)); }

dev::proto::JogVelocityRequest jog(int axis, double velocityPerS, double wireScale = 1e6)
{
    dev::proto::JogVelocityRequest r;
    r.axisMask = bit(axis);
    r.velocities = {static_cast<std::int32_t>(std::lround(velocityPerS * wireScale))};
    return r;
}


std::vector<dev::proto::EventMsg> runCollect(dev::sim::SimMachine& m, double seconds)
{
    std::vector<dev::proto::EventMsg> out;
    for (long k = 0; k < ticksFor(seconds); ++k) {
        m.tick();
        auto e = m.takeEvents();
        out.insert(out.end(), e.begin(), e.end());
    }
    return out;
}

bool runUntilIdle(dev::sim::SimMachine& m, double timeoutS)
{
    for (long k = 0; k < ticksFor(timeoutS); ++k) {
        m.tick();
        m.takeEvents();
        if (k % 10 == 0 && !anyMoving(m))
            return true;
    }
    return false;
}

struct StopMeasurement {
    /// From here on the carriage stays within one count of where it ends (the
    /// stage: within its in-position window, as its servo settles by a count or two).
    double atRestAfterS = -1;
    double referenceStopS = -1;   ///< the controller's reference reached zero speed
    double statusIdleS = -1;      ///< the device stopped reporting the axis as moving
    bool expiredEvent = false;
    double cruiseSpeed = 0;       ///< measured just before the refreshes stopped
};

/// Jogs `axis` at `velocity` (axis units/s) refreshed every `refreshS` for `holdS`,
/// then stops refreshing, as a frozen GUI or a pulled cable would.
StopMeasurement jogThenGoQuiet(dev::sim::SimMachine& m, int axis, double velocity, double holdS, double refreshS = 0.05)
{
    StopMeasurement out;
    const double wire = m.config().axes[static_cast<std::size_t>(axis)].unit == dev::proto::AxisUnit::Microlitre ? 1e3 : 1e6;
    double lastRefreshS = 0;
    for (double t = 0; t < holdS; t += refreshS) {
        EXPECT_FALSE(m.jogVelocity(jog(axis, velocity, wire)));
        lastRefreshS = m.timeS();
        runCollect(m, refreshS);
    }
    // The refresh at lastRefreshS was the last one.
    out.cruiseSpeed = m.axis(axis).measuredVelocity();
    const double resolution = m.config().axes[static_cast<std::size_t>(axis)].resolution;
    const double restBand = m.config().closedLoop ? std::max(resolution, m.config().inPositionWindow) : resolution;
    std::vector<std::pair<double, double>> trace;  // time since last refresh, carriage
    for (long k = 0; k < ticksFor(1.0); ++k) {
        m.tick();
        for (const auto& e : m.takeEvents())
            if (e.kind == EventKind::JogExpired && e.axis == axis)
                out.expiredEvent = true;
        const double since = m.timeS() - lastRefreshS;
        trace.emplace_back(since, m.axis(axis).carriage());
        if (out.referenceStopS < 0 && m.axis(axis).referenceVelocity() == 0 && since > 0.01)
            out.referenceStopS = since;
        if (out.statusIdleS < 0 && !(m.status().axes[static_cast<std::size_t>(axis)].flags & dev::proto::AxisMoving))
            out.statusIdleS = since;
    }
    const double finalPos = trace.back().second;
    out.atRestAfterS = trace.front().first;
    for (const auto& [since, pos] : trace)
        if (std::abs(pos - finalPos) > restBand)
            out.atRestAfterS = since;
    return out;
}

struct JogCase {
    const char* name;
    bool stage;
    int axis;
};

void PrintTo(const JogCase& c, std::ostream* os) { *os << c.name; }

class SimJogWatchdog : public ::testing::TestWithParam<JogCase> {};

} // namespace

TEST_P(SimJogWatchdog, AtRestWithin250msOfTheLastRefresh)
{
    const JogCase c = GetParam();
    dev::sim::SimMachine m(c.stage ? dev::sim::stageConfig() : dev::sim::analyzerConfig());
    const auto& ac = m.config().axes[static_cast<std::size_t>(c.axis)];
    // Worst case: full speed, toward the middle of the travel so no switch interferes.
    const double direction = ac.startPosition < ac.travel / 2 ? 1.0 : -1.0;
    const double holdS = std::min(1.0, 0.4 * ac.travel / ac.maxSpeed);
    const auto r = jogThenGoQuiet(m, c.axis, direction * ac.maxSpeed, holdS);
    EXPECT_NEAR(std::abs(r.cruiseSpeed), ac.maxSpeed, 0.05 * ac.maxSpeed) << "the jog ran at the requested speed";
    EXPECT_TRUE(r.expiredEvent);
    EXPECT_GT(r.atRestAfterS, 0.2) << "the watchdog must not trip while the refresh is still fresh";
    EXPECT_LE(r.atRestAfterS, 0.250);
    EXPECT_LE(r.referenceStopS, 0.250);
    EXPECT_GT(r.statusIdleS, 0);
    EXPECT_FALSE(anyMoving(m));
    const std::string key = std::string(c.name) + "_jog_stop_latency_ms";
    RecordProperty(key, std::to_string(r.atRestAfterS * 1e3));
    std::cout << "[ latency  ] " << c.name << ": at rest " << r.atRestAfterS * 1e3 << " ms after the last refresh"
              << " (reference stopped at " << r.referenceStopS * 1e3 << " ms, status idle at " << r.statusIdleS * 1e3
              << " ms, from " << std::abs(r.cruiseSpeed) << " units/s)\n";
}

INSTANTIATE_TEST_SUITE_P(BothInstruments, SimJogWatchdog,
                         ::testing::Values(JogCase{"analyzer_X", false, 0}, JogCase{"analyzer_Y", false, 1},
                                           JogCase{"analyzer_Z", false, 2}, JogCase{"analyzer_P", false, 3},
                                           JogCase{"stage_X", true, 0}, JogCase{"stage_Y", true, 1}),
                         [](const ::testing::TestParamInfo<JogCase>& i) { return std::string(i.param.name); });

TEST(SimJog, WatchdogStopStaysWithinWhatTheMotorsCanDo)
{
    // The watchdog's ramp is steeper than a normal stop; it must still be one the
    // motor can follow without losing steps, from every axis' top speed.
    for (const auto& cfg : {dev::sim::analyzerConfig(), dev::sim::stageConfig()})
        for (const auto& a : cfg.axes)
            EXPECT_LE(a.maxSpeed / dev::sim::SimMachine::kJogStopBudgetS, a.physicalMaxAccel) << cfg.model << " " << a.letter;
}

TEST(SimJog, KeepsRunningWhileRefreshed)
{
    dev::sim::SimMachine m(dev::sim::analyzerConfig());
    const double x0 = m.axis(0).carriage();
    for (int n = 0; n < 20; ++n) {  // 2 s of refreshes every 100 ms
        ASSERT_FALSE(m.jogVelocity(jog(0, 20)));
        const auto ev = runCollect(m, 0.1);
        for (const auto& e : ev)
            EXPECT_NE(e.kind, EventKind::JogExpired);
    }
    EXPECT_NEAR(m.axis(0).carriage() - x0, 40, 0.5);
    EXPECT_TRUE(m.status().axes[0].flags & dev::proto::AxisJogging);
}

TEST(SimJog, ALongerTripHoldsAJogRefreshedOnASlowerClock)
{
    // At time scale K a host refreshing every 50 ms of its own time refreshes every
    // K x 50 ms of the device's: with the trip scaled by K (SimulatorHost::setTimeScale)
    // the jog runs on; with the trip as built it expires between refreshes.
    for (const double tripS : {dev::sim::SimMachine::kJogWatchdogTripS, dev::sim::SimMachine::kJogWatchdogTripS * 10}) {
        dev::sim::SimMachine m(dev::sim::analyzerConfig());
        m.setJogWatchdogTripS(tripS);
        int expired = 0;
        for (int n = 0; n < 4; ++n) {  // refreshes every 0.5 s: a 50 ms host at 10x
            ASSERT_FALSE(m.jogVelocity(jog(0, 10)));
            for (const auto& e : runCollect(m, 0.5))
                expired += e.kind == EventKind::JogExpired;
        }
        EXPECT_EQ(expired > 0, tripS < 0.5) << "trip " << tripS << " s";
    }
}

TEST(SimJog, SimulatorHostScalesTheTripWithItsClock)
{
    dev::SimulatedLink link(dev::proto::DeviceKind::Stage, 0);
    EXPECT_DOUBLE_EQ(link.machine().jogWatchdogTripS(), dev::sim::SimMachine::kJogWatchdogTripS);
    link.host().setTimeScale(100);
    EXPECT_DOUBLE_EQ(link.machine().jogWatchdogTripS(), dev::sim::SimMachine::kJogWatchdogTripS * 100);
    link.host().setTimeScale(0.5);  // a slower clock never shortens the host's allowance
    EXPECT_DOUBLE_EQ(link.machine().jogWatchdogTripS(), dev::sim::SimMachine::kJogWatchdogTripS);
}

TEST(SimJog, ZeroVelocityStopsAndReportsDone)
{
    dev::sim::SimMachine m(dev::sim::analyzerConfig());
    ASSERT_FALSE(m.jogVelocity(jog(1, -30)));
    runCollect(m, 0.15);  // inside the watchdog's 200 ms
    ASSERT_FALSE(m.jogVelocity(jog(1, 0)));  // key released
    const auto ev = runCollect(m, 0.2);
    EXPECT_FALSE(anyMoving(m));
    bool done = false;
    for (const auto& e : ev) {
        done |= e.kind == EventKind::MotionDone && e.axis == 1;
        EXPECT_NE(e.kind, EventKind::JogExpired);
    }
    EXPECT_TRUE(done);
}

TEST(SimJog, StopsAtTheSoftLimitWhenHomed)
{
    for (bool stage : {false, true}) {
        dev::sim::SimMachine m(stage ? dev::sim::stageConfig() : dev::sim::analyzerConfig());
        ASSERT_FALSE(m.home(0));
        ASSERT_TRUE(runUntilIdle(m, 60));
        const double travel = m.config().axes[0].travel;
        double maxCommanded = -1e9;
        bool limitHit = false;
        for (int n = 0; n < 70; ++n) {  // long enough to reach the far end at full speed
            ASSERT_FALSE(m.jogVelocity(jog(0, m.config().axes[0].maxSpeed)));
            for (long k = 0; k < ticksFor(0.1); ++k) {
                m.tick();
                for (const auto& e : m.takeEvents())
                    limitHit |= e.kind == EventKind::LimitHit;
                maxCommanded = std::max(maxCommanded, m.status().axes[0].commanded / 1e6);
            }
        }
        EXPECT_LE(maxCommanded, travel + 1e-6) << (stage ? "stage" : "analyzer");
        EXPECT_NEAR(m.status().axes[0].measured / 1e6, travel, stage ? 0.001 : 0.05);
        EXPECT_FALSE(limitHit) << "the soft limit stops the jog before the switch";
        // …and the jog may leave the limit again.
        ASSERT_FALSE(m.jogVelocity(jog(0, -5)));
        runCollect(m, 0.3);
        EXPECT_LT(m.status().axes[0].commanded / 1e6, travel - 0.5);
    }
}

TEST(SimJog, FromOutsideNarrowedLimitsDrivesBackInWithoutJumping)
{
    dev::sim::SimMachine m(dev::sim::analyzerConfig());
    ASSERT_FALSE(m.home(bit(0)));
    ASSERT_TRUE(runUntilIdle(m, 30));
    dev::proto::SetLimitsRequest q;
    q.axis = 0;
    q.limits = {10000000, 150000000};  // X stands at 0, below the new lower limit
    ASSERT_FALSE(m.setLimits(q));
    double maxStepMm = 0, prev = m.axis(0).reference();
    for (int n = 0; n < 5; ++n) {
        ASSERT_FALSE(m.jogVelocity(jog(0, 20)));
        for (long k = 0; k < ticksFor(0.1); ++k) {
            m.tick();
            m.takeEvents();
            maxStepMm = std::max(maxStepMm, std::abs(m.axis(0).reference() - prev));
            prev = m.axis(0).reference();
        }
    }
    EXPECT_LE(maxStepMm, 20 * dev::sim::SimMachine::kTickS + 1e-9) << "the reference jumped";
    EXPECT_NEAR(m.status().axes[0].commanded / 1e6, 10.0, 0.5);
    // Inside now, it cannot jog back out.
    ASSERT_FALSE(m.jogVelocity(jog(0, -5)));
    runCollect(m, 0.15);
    EXPECT_GE(m.status().axes[0].commanded / 1e6, 10.0 - 1e-6);
}

TEST(SimJog, RunsIntoTheSwitchWhenUnhomed)
{
    dev::sim::SimMachine m(dev::sim::analyzerConfig());
    bool limitHit = false;
    for (int n = 0; n < 30 && !limitHit; ++n) {
        ASSERT_FALSE(m.jogVelocity(jog(2, -40)));  // Z starts at 33 mm
        for (const auto& e : runCollect(m, 0.1))
            limitHit |= e.kind == EventKind::LimitHit && e.axis == 2;
    }
    EXPECT_TRUE(limitHit);
    EXPECT_TRUE(m.status().axes[2].flags & dev::proto::AxisHomeSwitch);
    EXPECT_FALSE(anyMoving(m));
}

TEST(SimJog, SpeedAboveMaximumIsRefused)
{
    dev::sim::SimMachine m(dev::sim::stageConfig());
    const auto e = m.jogVelocity(jog(1, 25));
    ASSERT_TRUE(e);
    EXPECT_EQ(e->code, ErrorCode::OutOfRange);
    EXPECT_EQ(e->axis, 1);
    EXPECT_NE(e->message.find("axis Y"), std::string::npos) << e->message;
    EXPECT_FALSE(anyMoving(m));
}

TEST(SimJog, StageAcceptsANewPressWhileSettling)
{
    // Hold-to-jog: press, release, press again at once. The stage is still
    // settling from the release; the second press must not be refused.
    dev::sim::SimMachine m(dev::sim::stageConfig());
    ASSERT_FALSE(m.jogVelocity(jog(0, 5)));
    runCollect(m, 0.2);
    ASSERT_FALSE(m.jogVelocity(jog(0, 0)));
    runCollect(m, 0.026);  // 5 mm/s at 200 mm/s² is at rest after 25 ms, then settles
    const auto e = m.jogVelocity(jog(0, 5));
    EXPECT_FALSE(e) << e->message;
}

TEST(SimJog, MovingAxisRefusesAJog)
{
    dev::sim::SimMachine m(dev::sim::analyzerConfig());
    dev::proto::MoveRequest mv;
    mv.relative = true;
    mv.axisMask = bit(0);
    mv.targets = {10000000};
    ASSERT_FALSE(m.move(mv));
    const auto e = m.jogVelocity(jog(0, 5));
    ASSERT_TRUE(e);
    EXPECT_EQ(e->code, ErrorCode::Busy);
}

TEST(SimJog, StopRampsAJogDown)
{
    dev::sim::SimMachine m(dev::sim::analyzerConfig());
    ASSERT_FALSE(m.jogVelocity(jog(0, 50)));
    runCollect(m, 0.15);
    ASSERT_FALSE(m.stop(bit(0)));
    const auto ev = runCollect(m, 0.2);
    EXPECT_FALSE(anyMoving(m));
    bool stopped = false;
    for (const auto& e : ev)
        stopped |= e.kind == EventKind::Stopped && e.axis == 0;
    EXPECT_TRUE(stopped);
}
