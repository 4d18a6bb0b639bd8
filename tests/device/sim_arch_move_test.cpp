// ARCH_MOVE on the simulated analyzer (docs/protocol.md): Z up to a clearance, XY
// across, Z down as one blended move. Sampled every tick against the two circles the
// request names: outside both, the tip is never below the clearance; XY starts before
// Z has reached the clearance and Z starts down before XY has arrived; the move lasts
// what motion::archTiming says (what the recipe planner counts); Z reports once.
#include "sim_test_support.h"

#include "device/protocol/messages_arch.h"
#include "motion/arch_timing.h"
#include "motion/seed_scurve.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using namespace simtest;
using dev::proto::ErrorCode;
using dev::proto::EventKind;

constexpr int kX = 0, kY = 1, kZ = 2;

struct SimArchMove : HomedMachine<dev::sim::analyzerConfig> {
    /// Puts the tip at (x, y) and Z `z` with ordinary moves.
    void standAt(double x, double y, double z)
    {
        ASSERT_FALSE(m.move(absMove(bit(kX) | bit(kY), {x, y})));
        ASSERT_TRUE(r.runUntilIdle(10));
        ASSERT_FALSE(m.move(absMove(bit(kZ), {z})));
        ASSERT_TRUE(r.runUntilIdle(10));
        r.events.clear();
    }
};

dev::proto::ArchMoveRequest arch(double x, double y, double clearZ, double z, double departMm, double approachMm)
{
    dev::proto::ArchMoveRequest a;
    a.x = nm(x);
    a.y = nm(y);
    a.clearZ = nm(clearZ);
    a.z = nm(z);
    a.departRadius = static_cast<std::uint32_t>(nm(departMm));
    a.approachRadius = static_cast<std::uint32_t>(nm(approachMm));
    return a;
}

} // namespace

TEST_F(SimArchMove, NeverBelowTheClearanceOutsideTheTwoCirclesAndBlended)
{
    // Two neighbouring wells of a 96-well plate: 9 mm apart, openings of 2.93 mm.
    const double x0 = 20, y0 = 30, x1 = 29, y1 = 30, depth = 70, clear = 55.78, radius = 2.93;
    standAt(x0, y0, depth);
    const double t0 = m.timeS();
    ASSERT_FALSE(m.archMove(arch(x1, y1, clear, depth, radius, radius)));
    double lowestOutside = -1e300, xyMovedWhenZAtClear = -1, zWhenXyArrived = -1, lastEndS = t0;
    bool zReachedClear = false;
    int zDone = 0, xyDone = 0;
    r.run(3.0, [&] {
        const double x = commandedMm(m, kX), y = commandedMm(m, kY), z = commandedMm(m, kZ);
        const bool inDepart = std::hypot(x - x0, y - y0) <= radius + 1e-6;
        const bool inApproach = std::hypot(x - x1, y - y1) <= radius + 1e-6;
        if (!inDepart && !inApproach)
            lowestOutside = std::max(lowestOutside, z);
        if (!zReachedClear && z <= clear + 1e-6) {
            zReachedClear = true;
            xyMovedWhenZAtClear = std::hypot(x - x0, y - y0);
        }
        if (zWhenXyArrived < 0 && std::hypot(x - x1, y - y1) < 1e-6)
            zWhenXyArrived = z;
        for (const auto& e : m.takeEvents()) {
            r.events.push_back(e);
            if (e.kind == EventKind::MotionDone) {
                zDone += e.axis == kZ;
                xyDone += e.axis == kX || e.axis == kY;
                lastEndS = m.timeS();
            }
        }
    });
    EXPECT_EQ(zDone, 1) << "Z reports once, at the bottom, not at the clearance";
    EXPECT_EQ(xyDone, 2);
    EXPECT_NEAR(commandedMm(m, kX), x1, 1e-6);
    EXPECT_NEAR(commandedMm(m, kZ), depth, 1e-6);
    EXPECT_LE(lowestOutside, clear + 1e-6) << "outside both openings the tip went down to Z " << lowestOutside;
    EXPECT_GT(xyMovedWhenZAtClear, 0.5) << "XY had not started when Z reached the clearance";
    EXPECT_LE(xyMovedWhenZAtClear, radius + 1e-3);
    EXPECT_GT(zWhenXyArrived, clear + 1) << "Z had not started down when XY arrived";

    // The move lasts what the planner's timing says (to a tick or two).
    const auto& c = dev::sim::analyzerConfig();
    auto prof = [&](int axis, double d) {
        const auto& a = c.axes[static_cast<std::size_t>(axis)];
        return *motion::SeedSCurve::plan(d, a.defaultSpeed, std::max(a.accelTimeS, 1.5 * a.defaultSpeed / a.maxAccel));
    };
    const auto up = prof(kZ, depth - clear), xy = prof(kX, 9), down = prof(kZ, depth - clear);
    const motion::ArchTiming t = motion::archTiming(&up, &xy, &down, radius, radius);
    EXPECT_NEAR(lastEndS - t0, t.durationS, 0.0005);
    EXPECT_LT(t.durationS, up.duration() + xy.duration() + down.duration() - 0.2) << "blended, not one after another";
}

TEST_F(SimArchMove, WithoutRadiiTheLegsFollowEachOther)
{
    standAt(20, 30, 70);
    ASSERT_FALSE(m.archMove(arch(40, 30, 50, 65, 0, 0)));
    double lowestAway = -1e300;  // the lowest Z while XY is away from both ends
    r.run(3.0, [&] {
        const double x = commandedMm(m, kX), z = commandedMm(m, kZ);
        if (x > 20 + 1e-6 && x < 40 - 1e-6)
            lowestAway = std::max(lowestAway, z);
    });
    EXPECT_LE(lowestAway, 50 + 1e-5) << "XY moved with Z below the clearance";
    EXPECT_NEAR(commandedMm(m, kZ), 65, 1e-6);
    EXPECT_EQ(r.count(EventKind::MotionDone, kZ), 1);
}

TEST_F(SimArchMove, AlreadyAboveTheClearanceItDoesNotRiseFirst)
{
    standAt(20, 30, 10);
    ASSERT_FALSE(m.archMove(arch(30, 30, 50, 60, 0, 2)));
    ASSERT_TRUE(r.runUntilIdle(5));
    EXPECT_NEAR(commandedMm(m, kZ), 60, 1e-6);
    EXPECT_EQ(r.count(EventKind::MotionDone, kZ), 1);
    EXPECT_EQ(r.count(EventKind::MotionDone, kX), 1);
}

TEST_F(SimArchMove, RefusesWhatAMoveRefusesAndMovesNothing)
{
    standAt(20, 30, 70);
    auto e = m.archMove(arch(20, 30, -5, 70, 0, 0));
    ASSERT_TRUE(e);
    EXPECT_EQ(e->code, ErrorCode::SoftLimit);
    EXPECT_EQ(e->axis, kZ);
    ASSERT_FALSE(m.archMove(arch(30, 30, 50, 70, 0, 0)));
    e = m.archMove(arch(30, 30, 50, 70, 0, 0));
    ASSERT_TRUE(e);
    EXPECT_EQ(e->code, ErrorCode::Busy);
}

TEST_F(SimArchMove, AStopEndsEveryPart)
{
    standAt(20, 30, 70);
    ASSERT_FALSE(m.archMove(arch(60, 30, 50, 70, 2, 2)));
    r.run(0.3);
    ASSERT_FALSE(m.stop(0));
    ASSERT_TRUE(r.runUntilIdle(5));
    r.run(1.0);
    EXPECT_FALSE(anyMoving(m));
    EXPECT_LT(commandedMm(m, kX), 59) << "the way across did not run on after the stop";
    EXPECT_LT(commandedMm(m, kZ), 70 - 1) << "the way down never started";
}

TEST(SimArchMoveStage, AStageHasNoArchedMove)
{
    dev::sim::SimMachine m(dev::sim::stageConfig());
    EXPECT_FALSE(m.hello(115200).capabilities & dev::proto::kCapArchMove);
    dev::sim::SimMachine a(dev::sim::analyzerConfig());
    EXPECT_TRUE(a.hello(115200).capabilities & dev::proto::kCapArchMove);
}
