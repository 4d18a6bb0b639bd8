// The simulated analyzer (reference firmware, motion side) driven directly through
// dev::sim::SimMachine: power-up, homing order, accuracy, soft limits, the coupled XY
// line with Z following, set zero. Faults and stops: sim_analyzer_faults_test.cpp.
#include "sim_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>

namespace {

using namespace simtest;

using dev::proto::ErrorCode;
using dev::proto::EventKind;

constexpr int kX = 0, kY = 1, kZ = 2, kP = 3;

double measuredUl(const dev::sim::SimMachine& m) { return m.status().axes[kP].measured / 1e3; }



/// An analyzer that has been homed (all axes), with its events discarded.
struct SimAnalyzerHomed : HomedMachine<dev::sim::analyzerConfig> {};

} // namespace

TEST(SimAnalyzer, PowersUpUnhomedWithCountersAtZero)
{
    dev::sim::SimMachine m(dev::sim::analyzerConfig());
    const auto s = m.status();
    ASSERT_EQ(s.axes.size(), 4u);
    for (std::size_t i = 0; i < s.axes.size(); ++i) {
        EXPECT_FALSE(s.axes[i].flags & dev::proto::AxisHomed) << i;
        EXPECT_FALSE(s.axes[i].flags & dev::proto::AxisMoving) << i;
        // The step counter reads zero wherever the axis happens to be.
        EXPECT_EQ(s.axes[i].commanded, 0) << i;
        // The encoder differs from the step count only by screw lead error and a count.
        EXPECT_LE(std::abs(s.axes[i].measured), 20000) << i;
    }
    EXPECT_EQ(s.deviceFlags, 0);
}

TEST(SimAnalyzer, AbsoluteMoveUnhomedIsRefusedNamingTheAxis)
{
    dev::sim::SimMachine m(dev::sim::analyzerConfig());
    const auto e = m.move(absMove(bit(kY), {10}));
    ASSERT_TRUE(e);
    EXPECT_EQ(e->code, ErrorCode::NotHomed);
    EXPECT_EQ(e->axis, kY);
    EXPECT_NE(e->message.find("axis Y"), std::string::npos) << e->message;
    EXPECT_NE(e->message.find("not homed"), std::string::npos) << e->message;
    // Refused means nothing moves.
    Runner r{m, {}};
    r.run(0.2);
    EXPECT_EQ(commandedMm(m, kY), 0);
}

TEST(SimAnalyzer, RelativeMoveIsAllowedUnhomed)
{
    dev::sim::SimMachine m(dev::sim::analyzerConfig());
    Runner r{m, {}};
    ASSERT_FALSE(m.move(relMove(bit(kX), {5})));
    EXPECT_TRUE(moving(m, kX));
    ASSERT_TRUE(r.runUntilIdle(5));
    EXPECT_NEAR(commandedMm(m, kX), 5.0, 0.003);
    EXPECT_NEAR(measuredMm(m, kX), 5.0, 0.01);
    EXPECT_TRUE(r.find(EventKind::MotionDone, kX));
}

TEST(SimAnalyzer, HomingEndsHomedAtZeroOnEveryAxis)
{
    dev::sim::SimMachine m(dev::sim::analyzerConfig());
    Runner r{m, {}};
    ASSERT_FALSE(m.home(0));
    ASSERT_TRUE(r.runUntilIdle(60));
    const auto s = m.status();
    for (int i = 0; i < m.axisCount(); ++i) {
        const auto& a = s.axes[static_cast<std::size_t>(i)];
        const double resolution = m.hello(0).axes[static_cast<std::size_t>(i)].resolution;
        EXPECT_TRUE(a.flags & dev::proto::AxisHomed) << i;
        EXPECT_FALSE(a.flags & (dev::proto::AxisMoving | dev::proto::AxisHoming)) << i;
        EXPECT_EQ(a.commanded, 0) << i;
        EXPECT_LE(std::abs(a.measured), 3 * resolution) << "axis " << i << " measured " << a.measured;
        EXPECT_TRUE(r.find(EventKind::HomeDone, i)) << i;
    }
}

TEST(SimAnalyzer, HomesZBeforeXAndY)
{
    dev::sim::SimMachine m(dev::sim::analyzerConfig());
    Runner r{m, {}};
    const double x0 = commandedMm(m, kX), y0 = commandedMm(m, kY);
    double xFirstMovedS = -1, yFirstMovedS = -1;
    ASSERT_FALSE(m.home(0));
    // While Z homes, X and Y report that they take part in the homing…
    EXPECT_TRUE(m.status().axes[kX].flags & dev::proto::AxisHoming);
    ASSERT_TRUE(r.runUntilIdle(60, [&] {
        if (xFirstMovedS < 0 && commandedMm(m, kX) != x0)
            xFirstMovedS = m.timeS();
        if (yFirstMovedS < 0 && commandedMm(m, kY) != y0)
            yFirstMovedS = m.timeS();
    }));
    // …but do not move until Z's HomeDone.
    const auto* zDone = r.find(EventKind::HomeDone, kZ);
    const auto* xDone = r.find(EventKind::HomeDone, kX);
    const auto* yDone = r.find(EventKind::HomeDone, kY);
    ASSERT_TRUE(zDone && xDone && yDone);
    ASSERT_GT(xFirstMovedS, 0);
    ASSERT_GT(yFirstMovedS, 0);
    EXPECT_GE(xFirstMovedS * 1e6, static_cast<double>(zDone->deviceTimeUs));
    EXPECT_GE(yFirstMovedS * 1e6, static_cast<double>(zDone->deviceTimeUs));
    EXPECT_LT(zDone->deviceTimeUs, xDone->deviceTimeUs);
    EXPECT_LT(zDone->deviceTimeUs, yDone->deviceTimeUs);
}

TEST(SimAnalyzer, ASecondHomingDoesNotDropTheFirstOnesWaitingAxes)
{
    dev::sim::SimMachine m(dev::sim::analyzerConfig());
    Runner r{m, {}};
    ASSERT_FALSE(m.home(bit(kX) | bit(kZ)));  // Z now, X after it
    r.run(0.05);
    const auto e = m.home(bit(kP));
    ASSERT_TRUE(e);
    EXPECT_EQ(e->code, ErrorCode::Busy);
    ASSERT_TRUE(r.runUntilIdle(60));
    EXPECT_TRUE(m.homed(kZ));
    EXPECT_TRUE(m.homed(kX));
    EXPECT_FALSE(m.home(bit(kP)));
}

TEST(SimAnalyzer, ReportsHomedOnlyOnceHomeIsReached)
{
    // The homed lamp must not light while the axis is still travelling to zero.
    dev::sim::SimMachine m(dev::sim::analyzerConfig());
    Runner r{m, {}};
    ASSERT_FALSE(m.home(bit(kZ)));
    bool homedWhileMoving = false;
    ASSERT_TRUE(r.runUntilIdle(30, [&] {
        const auto f = m.status().axes[kZ].flags;
        if ((f & dev::proto::AxisHomed) && (f & dev::proto::AxisMoving))
            homedWhileMoving = true;
        if (f & dev::proto::AxisHomed)
            EXPECT_TRUE(r.find(EventKind::HomeDone, kZ) || (r.take(), r.find(EventKind::HomeDone, kZ)));
        else
            EXPECT_TRUE(f & dev::proto::AxisHoming);
    }));
    EXPECT_FALSE(homedWhileMoving);
    EXPECT_TRUE(m.homed(kZ));
}

TEST(SimAnalyzer, AxesWaitingForTheirHomingStageAreBusy)
{
    dev::sim::SimMachine m(dev::sim::analyzerConfig());
    Runner r{m, {}};
    ASSERT_FALSE(m.home(0));
    r.run(0.05);
    // X waits for Z: a jog or relative move now would fight the homing that follows.
    const auto e = m.move(relMove(bit(kX), {1}));
    ASSERT_TRUE(e);
    EXPECT_EQ(e->code, ErrorCode::Busy);
    dev::proto::JogVelocityRequest j;
    j.axisMask = bit(kY);
    j.velocities = {nm(5)};
    const auto ej = m.jogVelocity(j);
    ASSERT_TRUE(ej);
    EXPECT_EQ(ej->code, ErrorCode::Busy);
}

TEST_F(SimAnalyzerHomed, MoveAccuracyWithinTableOneTolerance)
{
    struct Case {
        int axis;
        double target;
    };
    // Seed 000 Table 1 allows 0.4 mm; the encoder reads lead error and backlash only.
    for (const Case c : {Case{kX, 150.0}, Case{kX, 20.5}, Case{kY, 199.0}, Case{kY, 3.25}, Case{kZ, 80.0}, Case{kZ, 7.0}}) {
        ASSERT_FALSE(m.move(absMove(bit(c.axis), {c.target})));
        ASSERT_TRUE(r.runUntilIdle(20));
        EXPECT_NEAR(commandedMm(m, c.axis), c.target, 1e-6);
        EXPECT_NEAR(measuredMm(m, c.axis), c.target, 0.05) << "axis " << c.axis << " to " << c.target;
    }
    EXPECT_EQ(r.count(EventKind::LostSteps), 0);
}

TEST_F(SimAnalyzerHomed, HealthyMechanicsNeverRaiseLostSteps)
{
    // Lead error and backlash are largest at the far end after a reversal; they are
    // not lost steps and must not be reported as such.
    double worstMm = 0;
    for (int axis : {kX, kY, kZ}) {
        const double travel = dev::sim::analyzerConfig().axes[static_cast<std::size_t>(axis)].travel;
        for (double target : {travel, travel - 1, travel - 0.5, travel, 1.0, 0.0, travel - 0.02}) {
            ASSERT_FALSE(m.move(absMove(bit(axis), {target})));
            ASSERT_TRUE(r.runUntilIdle(20));
            worstMm = std::max(worstMm, std::abs(measuredMm(m, axis) - commandedMm(m, axis)));
        }
    }
    EXPECT_EQ(r.count(EventKind::LostSteps), 0) << (r.find(EventKind::LostSteps, -1) ? r.find(EventKind::LostSteps, -1)->text : "");
    // …with a margin, not by a hair: X reads 50 µm off at 199 mm after a reversal.
    EXPECT_LE(1.5 * worstMm, m.config().lostStepTolerance) << "worst healthy error " << worstMm << " mm";
}

TEST_F(SimAnalyzerHomed, PumpMovesInMicrolitres)
{
    dev::proto::MoveRequest mv;
    mv.axisMask = bit(kP);
    mv.targets = {500000};  // nL
    ASSERT_FALSE(m.move(mv));
    ASSERT_TRUE(r.runUntilIdle(20));
    EXPECT_NEAR(measuredUl(m), 500.0, 0.1);
}

TEST_F(SimAnalyzerHomed, SoftLimitRefusalGivesReasonAndLimit)
{
    auto e = m.move(absMove(bit(kX), {200.5}));
    ASSERT_TRUE(e);
    EXPECT_EQ(e->code, ErrorCode::SoftLimit);
    EXPECT_EQ(e->axis, kX);
    EXPECT_EQ(e->value, nm(200));
    EXPECT_NE(e->message.find("upper soft limit"), std::string::npos) << e->message;
    EXPECT_NE(e->message.find("200.000 mm"), std::string::npos) << e->message;

    // A relative move that would end beyond the lower limit is refused the same way.
    e = m.move(relMove(bit(kZ), {-1}));
    ASSERT_TRUE(e);
    EXPECT_EQ(e->code, ErrorCode::SoftLimit);
    EXPECT_EQ(e->value, 0);
    EXPECT_NE(e->message.find("lower soft limit"), std::string::npos) << e->message;

    // Refused moves leave nothing moving.
    EXPECT_FALSE(anyMoving(m));
}

TEST_F(SimAnalyzerHomed, CoupledXyMoveRunsOnTheSeedLine)
{
    // Seed 000: target (30, 40), tan θ = 4/3. Both axes start and end together and
    // the commanded point stays on the line from the origin.
    double xStartS = -1, yStartS = -1, xEndS = -1, yEndS = -1, maxOffLineCmd = 0, maxOffLineMeas = 0;
    ASSERT_FALSE(m.move(absMove(bit(kX) | bit(kY), {30, 40})));
    ASSERT_TRUE(r.runUntilIdle(10, [&] {
        const double cx = commandedMm(m, kX), cy = commandedMm(m, kY);
        const double mx = measuredMm(m, kX), my = measuredMm(m, kY);
        if (xStartS < 0 && cx != 0)
            xStartS = m.timeS();
        if (yStartS < 0 && cy != 0)
            yStartS = m.timeS();
        if (xEndS < 0 && std::abs(cx - 30) < 1e-6)
            xEndS = m.timeS();
        if (yEndS < 0 && std::abs(cy - 40) < 1e-6)
            yEndS = m.timeS();
        // Distance from the line 4x − 3y = 0.
        maxOffLineCmd = std::max(maxOffLineCmd, std::abs(4 * cx - 3 * cy) / 5);
        maxOffLineMeas = std::max(maxOffLineMeas, std::abs(4 * mx - 3 * my) / 5);
    }));
    EXPECT_NEAR(xStartS, yStartS, 1e-3);
    EXPECT_NEAR(xEndS, yEndS, 1e-3);
    EXPECT_LT(maxOffLineCmd, 0.001);  // nm rounding only
    EXPECT_LT(maxOffLineMeas, 0.03);  // encoder counts, lead error, backlash
    EXPECT_NEAR(measuredMm(m, kX), 30, 0.05);
    EXPECT_NEAR(measuredMm(m, kY), 40, 0.05);
    RecordProperty("xy_line_max_offset_measured_um", std::to_string(maxOffLineMeas * 1e3));
}

TEST_F(SimAnalyzerHomed, ZStartsOnlyAfterXyArrived)
{
    ASSERT_FALSE(m.move(absMove(bit(kX) | bit(kY), {10, 10})));
    ASSERT_TRUE(r.runUntilIdle(10));
    r.events.clear();
    double zStartS = -1, xyArrivedS = -1;
    ASSERT_FALSE(m.move(absMove(bit(kX) | bit(kY) | bit(kZ), {60, 90, 50})));
    ASSERT_TRUE(r.runUntilIdle(20, [&] {
        if (xyArrivedS < 0 && std::abs(commandedMm(m, kX) - 60) < 1e-6 && std::abs(commandedMm(m, kY) - 90) < 1e-6)
            xyArrivedS = m.timeS();
        if (zStartS < 0 && commandedMm(m, kZ) != 0)
            zStartS = m.timeS();
    }));
    ASSERT_GT(xyArrivedS, 0);
    ASSERT_GT(zStartS, 0);
    EXPECT_GE(zStartS, xyArrivedS);
    const auto* xDone = r.find(EventKind::MotionDone, kX);
    const auto* zDone = r.find(EventKind::MotionDone, kZ);
    ASSERT_TRUE(xDone && zDone);
    EXPECT_GE(zStartS * 1e6, static_cast<double>(xDone->deviceTimeUs));
    EXPECT_NEAR(measuredMm(m, kZ), 50, 0.05);
}

TEST_F(SimAnalyzerHomed, XyRunsAtItsOwnSpeedWhenZIsInTheSameRequest)
{
    // Z's slower default (30 mm/s) must not slow the XY path (50 mm/s).
    double peakXyMmS = 0;
    ASSERT_FALSE(m.move(absMove(bit(kX) | bit(kY) | bit(kZ), {60, 80, 20})));
    ASSERT_TRUE(r.runUntilIdle(20, [&] {
        peakXyMmS = std::max(peakXyMmS, std::hypot(m.axis(kX).referenceVelocity(), m.axis(kY).referenceVelocity()));
    }));
    EXPECT_NEAR(peakXyMmS, dev::sim::analyzerConfig().axes[kX].defaultSpeed, 0.5);
}

TEST_F(SimAnalyzerHomed, SetZeroMakesTheCurrentPositionZero)
{
    ASSERT_FALSE(m.move(absMove(bit(kX), {50})));
    ASSERT_TRUE(r.runUntilIdle(5));
    ASSERT_FALSE(m.setZero(bit(kX)));
    EXPECT_EQ(commandedMm(m, kX), 0);
    EXPECT_NEAR(measuredMm(m, kX), 0, 0.01);
    // The soft limits stay where they are on the machine, so they shift in the new coordinates.
    const auto l = m.limits();
    EXPECT_NEAR(l.axes[kX].min, nm(-50), 10);
    EXPECT_NEAR(l.axes[kX].max, nm(150), 10);
    ASSERT_FALSE(m.move(absMove(bit(kX), {-20})));
    ASSERT_TRUE(r.runUntilIdle(5));
    EXPECT_NEAR(measuredMm(m, kX), -20, 0.05);
    const auto e = m.move(absMove(bit(kX), {-51}));
    ASSERT_TRUE(e);
    EXPECT_EQ(e->code, ErrorCode::SoftLimit);
}

TEST(SimAnalyzer, SetZeroWithEmptyMaskZeroesEveryAxis)
{
    // AxisMaskRequest: 0 = all axes.
    dev::sim::SimMachine m(dev::sim::analyzerConfig());
    Runner r{m, {}};
    ASSERT_FALSE(m.move(relMove(bit(kX) | bit(kY), {3, 4})));
    ASSERT_TRUE(r.runUntilIdle(5));
    ASSERT_FALSE(m.setZero(0));
    EXPECT_EQ(commandedMm(m, kX), 0);
    EXPECT_EQ(commandedMm(m, kY), 0);
}

TEST_F(SimAnalyzerHomed, SetAndGetLimitsValidates)
{
    dev::proto::SetLimitsRequest q;
    q.axis = kY;
    q.limits = {nm(10), nm(150)};
    ASSERT_FALSE(m.setLimits(q));
    const auto l = m.limits();
    ASSERT_EQ(l.axes.size(), 4u);
    EXPECT_EQ(l.axes[kY].min, nm(10));
    EXPECT_EQ(l.axes[kY].max, nm(150));
    EXPECT_EQ(l.axes[kX].max, nm(200));
    EXPECT_EQ(l.axes[kP].max, 1000000);  // nL

    auto e = m.move(absMove(bit(kY), {160}));
    ASSERT_TRUE(e);
    EXPECT_EQ(e->code, ErrorCode::SoftLimit);
    EXPECT_EQ(e->value, nm(150));
    EXPECT_NE(e->message.find("150.000 mm"), std::string::npos) << e->message;

    q.limits = {nm(100), nm(50)};  // min above max
    e = m.setLimits(q);
    ASSERT_TRUE(e);
    EXPECT_EQ(e->code, ErrorCode::OutOfRange);
    EXPECT_NE(e->message.find("axis Y"), std::string::npos);

    q.limits = {nm(-5), nm(50)};  // outside the travel
    e = m.setLimits(q);
    ASSERT_TRUE(e);
    EXPECT_EQ(e->code, ErrorCode::OutOfRange);
    EXPECT_EQ(e->value, nm(-5));

    q.limits = {nm(0), nm(201)};
    e = m.setLimits(q);
    ASSERT_TRUE(e);
    EXPECT_EQ(e->value, nm(201));

    q.axis = 7;
    e = m.setLimits(q);
    ASSERT_TRUE(e);
    EXPECT_EQ(e->code, ErrorCode::BadAxis);
    // Failed requests changed nothing.
    EXPECT_EQ(m.limits().axes[kY].max, nm(150));
}

TEST(SimAnalyzer, SoftLimitsBeforeHomingAreTheConfiguredOnesAndCannotBeSet)
{
    // Unhomed coordinates are wherever the axis was at power-up: limits given or
    // shown in them would mean nothing.
    dev::sim::SimMachine m(dev::sim::analyzerConfig());
    const auto l = m.limits();
    ASSERT_EQ(l.axes.size(), 4u);
    EXPECT_EQ(l.axes[kX].min, 0);
    EXPECT_EQ(l.axes[kX].max, nm(200));
    EXPECT_EQ(l.axes[kZ].max, nm(100));
    dev::proto::SetLimitsRequest q;
    q.axis = kZ;
    q.limits = {nm(5), nm(50)};
    const auto e = m.setLimits(q);
    ASSERT_TRUE(e);
    EXPECT_EQ(e->code, ErrorCode::NotHomed);
    EXPECT_NE(e->message.find("axis Z"), std::string::npos) << e->message;
}

TEST_F(SimAnalyzerHomed, MoveToItsOwnPositionFinishesAtOnce)
{
    const auto e = m.move(absMove(bit(kX), {0}));
    ASSERT_FALSE(e) << e->message;
    r.run(0.001);
    EXPECT_TRUE(r.find(EventKind::MotionDone, kX));
    EXPECT_FALSE(anyMoving(m));
}

TEST_F(SimAnalyzerHomed, SpeedAboveTheAxisMaximumIsRefused)
{
    const auto e = m.move(absMove(bit(kZ), {10}, 80));
    ASSERT_TRUE(e);
    EXPECT_EQ(e->code, ErrorCode::OutOfRange);
    EXPECT_EQ(e->axis, kZ);
    EXPECT_NE(e->message.find("axis Z"), std::string::npos) << e->message;
}

TEST_F(SimAnalyzerHomed, SecondMoveOnABusyAxisIsRefused)
{
    ASSERT_FALSE(m.move(absMove(bit(kX), {100})));
    const auto e = m.move(absMove(bit(kX), {10}));
    ASSERT_TRUE(e);
    EXPECT_EQ(e->code, ErrorCode::Busy);
    // Another axis is free.
    dev::proto::MoveRequest pump;
    pump.axisMask = bit(kP);
    pump.targets = {10000};  // nL
    const auto ep = m.move(pump);
    EXPECT_FALSE(ep) << ep->message;
}
