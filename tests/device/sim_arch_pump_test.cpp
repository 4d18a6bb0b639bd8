// ARCH_MOVE's pump block on the simulated analyzer (docs/protocol.md): the plunger runs
// inside the arched move, only while the tip is below the liquid height (a well's rim)
// and inside the approach circle, and Z rises after it, passing the liquid height again
// only once the plunger has stopped. Sampled every tick from the machine's true
// positions; the move lasts what motion::archTiming says with the pump parts.
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

constexpr int kPx = 0, kPy = 1, kPz = 2, kPp = 3;

struct SimArchPump : HomedMachine<dev::sim::analyzerConfig> {
    void standAt(double x, double y, double z, double plungerUl)
    {
        ASSERT_FALSE(m.move(absMove(bit(kPx) | bit(kPy), {x, y})));
        ASSERT_TRUE(r.runUntilIdle(10));
        ASSERT_FALSE(m.move(absMove(bit(kPz), {z})));
        ASSERT_TRUE(r.runUntilIdle(10));
        dev::proto::MoveRequest p;
        p.axisMask = bit(kPp);
        p.targets = {static_cast<dev::proto::WireUnits>(std::lround(plungerUl * 1000))};
        ASSERT_FALSE(m.move(p));
        ASSERT_TRUE(r.runUntilIdle(10));
        r.events.clear();
    }
};

dev::proto::ArchMoveRequest pumpArch(double x, double y, double clearZ, double z, double radius, double pumpUl, double liquidZ, double leaveZ)
{
    dev::proto::ArchMoveRequest a;
    a.x = nm(x);
    a.y = nm(y);
    a.clearZ = nm(clearZ);
    a.z = nm(z);
    a.departRadius = static_cast<std::uint32_t>(nm(radius));
    a.approachRadius = static_cast<std::uint32_t>(nm(radius));
    dev::proto::ArchPump p;
    p.delta = static_cast<std::int32_t>(std::lround(pumpUl * 1000));
    p.liquidZ = nm(liquidZ);
    p.leaveZ = nm(leaveZ);
    a.pump = p;
    return a;
}

} // namespace

TEST_F(SimArchPump, ThePlungerMovesOnlyWithTheTipBelowTheRimInsideTheOpeningAndOverlapsZ)
{
    // From one well of a 96-well plate to the next (9 mm, openings of 2.93 mm), 50 µL out.
    const double x0 = 20, y0 = 30, x1 = 29, y1 = 30, depth = 70, clear = 55.78, rim = 60.78, radius = 2.93;
    standAt(x0, y0, depth, 500);
    const double t0 = m.timeS();
    ASSERT_FALSE(m.archMove(pumpArch(x1, y1, clear, depth, radius, -50, rim, clear)));
    double outsideUl = 0, insideUl = 0, lastEndS = t0, pumpStartS = -1, pumpEndS = -1, zAtPumpEnd = -1;
    double plungerBefore = m.workPointLogical(kPp);
    int zDone = 0, pDone = 0;
    r.run(4.0, [&] {
        const double x = m.workPointLogical(kPx), y = m.workPointLogical(kPy), z = m.workPointLogical(kPz);
        const double plunger = m.workPointLogical(kPp);
        const double moved = plungerBefore - plunger;
        if (std::abs(moved) > 1e-12) {
            if (pumpStartS < 0)
                pumpStartS = m.timeS();
            pumpEndS = m.timeS();
            zAtPumpEnd = z;
            (z > rim && std::hypot(x - x1, y - y1) <= radius + 1e-6 ? insideUl : outsideUl) += moved;
        }
        plungerBefore = plunger;
        for (const auto& e : m.takeEvents()) {
            if (e.kind == EventKind::MotionDone) {
                zDone += e.axis == kPz;
                pDone += e.axis == kPp;
                lastEndS = m.timeS();
            }
        }
    });
    EXPECT_NEAR(insideUl, 50, 0.01) << "the whole volume left with the tip below the rim, inside the opening";
    EXPECT_NEAR(outsideUl, 0, 1e-9);
    EXPECT_EQ(zDone, 1) << "Z reports once, at the top of its rise after the plunger";
    EXPECT_EQ(pDone, 1);
    EXPECT_NEAR(commandedMm(m, kPz), clear, 1e-6);
    EXPECT_NEAR(m.workPointLogical(kPp), 450, 0.01);
    EXPECT_LT(zAtPumpEnd, depth - 1) << "the plunger was still running while Z rose: the two overlap";

    // The move lasts what the planner's timing says (to a tick or two), and less than the
    // arch, the plunger and the rise one after another.
    const auto& c = dev::sim::analyzerConfig();
    auto prof = [&](int axis, double d) {
        const auto& a = c.axes[static_cast<std::size_t>(axis)];
        return *motion::SeedSCurve::plan(d, a.defaultSpeed, std::max(a.accelTimeS, 1.5 * a.defaultSpeed / a.maxAccel));
    };
    const auto up = prof(kPz, depth - clear), xy = prof(kPx, 9), down = prof(kPz, depth - clear), plunger = prof(kPp, 50),
               leave = prof(kPz, depth - clear);
    motion::ArchPumpParts parts;
    parts.plunger = &plunger;
    parts.liquidMm = rim - clear;
    parts.leave = &leave;
    parts.leaveLiquidMm = depth - rim;
    const motion::ArchTiming t = motion::archTiming(&up, &xy, &down, radius, radius, parts);
    EXPECT_NEAR(lastEndS - t0, t.durationS, 0.0005);
    // The plunger's first whole step (1/48 µL) comes a few ms after its reference starts.
    EXPECT_NEAR(pumpStartS - t0, t.pumpStartS, 0.01);
    const motion::ArchTiming plain = motion::archTiming(&up, &xy, &down, radius, radius);
    EXPECT_LT(t.durationS, plain.durationS + plunger.duration() + leave.duration() - 0.5) << "the plunger hides behind Z";
}

TEST_F(SimArchPump, RefusesALiquidHeightBelowTheTargetOrAPlungerWithoutAWayDown)
{
    standAt(20, 30, 70, 500);
    auto e = m.archMove(pumpArch(29, 30, 55.78, 70, 2.93, -50, 72, 55.78));
    ASSERT_TRUE(e);
    EXPECT_EQ(e->code, ErrorCode::OutOfRange);
    e = m.archMove(pumpArch(20, 30, 70, 70, 0, -50, 60.78, 55.78));
    ASSERT_TRUE(e) << "already at the bottom: no way down passes the liquid height";
    EXPECT_EQ(e->code, ErrorCode::OutOfRange);
    e = m.archMove(pumpArch(29, 30, 55.78, 70, 2.93, -600, 60.78, 55.78));
    ASSERT_TRUE(e) << "the plunger past its end";
    EXPECT_EQ(e->code, ErrorCode::SoftLimit);
    EXPECT_FALSE(anyMoving(m)) << "a refused move moves nothing";
}

TEST_F(SimArchPump, AStopEndsThePlungerToo)
{
    standAt(20, 30, 70, 500);
    ASSERT_FALSE(m.archMove(pumpArch(29, 30, 55.78, 70, 2.93, -200, 60.78, 55.78)));
    r.run(1.4);
    ASSERT_FALSE(m.stop(0));
    ASSERT_TRUE(r.runUntilIdle(5));
    r.run(1.0);
    EXPECT_FALSE(anyMoving(m));
    EXPECT_GT(m.workPointLogical(kPp), 300 + 1) << "the plunger did not run on after the stop";
}

TEST(SimArchPumpHello, TheAnalyzerSaysSoAndAStageDoesNot)
{
    dev::sim::SimMachine s(dev::sim::stageConfig());
    EXPECT_FALSE(s.hello(115200).capabilities & dev::proto::kCapArchPump);
    dev::sim::SimMachine a(dev::sim::analyzerConfig());
    EXPECT_TRUE(a.hello(115200).capabilities & dev::proto::kCapArchPump);
}
