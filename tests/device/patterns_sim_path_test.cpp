// The simulator's path queue: contour following on both instruments, look-ahead through shallow
// junctions, flow control, soft limits per segment, and every way a path can end early.
#include "motion/plans/pattern.h"
#include "patterns_path_support.h"

#include <gtest/gtest.h>

using namespace pathtest;
using simtest::HomedMachine;

namespace {

using StagePath = HomedMachine<dev::sim::stageConfig>;
using AnalyzerPath = HomedMachine<dev::sim::analyzerConfig>;

}  // namespace

TEST_F(StagePath, TenMillimetreCircleAtTwoMmSIsFollowedWithinTwoMicrometres)
{
    // The runner's way: a positioning MOVE to the start, then the circle from rest.
    ASSERT_FALSE(m.move(simtest::absMove(simtest::bit(0) | simtest::bit(1), {55, 50})));
    ASSERT_TRUE(r.runUntilIdle(30));
    const Vec2 c{50, 50};
    auto path = circle(c, 5, true, 2.0);
    PathRun run{m, r, path};
    ASSERT_FALSE(run.begin());
    motion::path::ContourTracker tracker(path);
    ASSERT_TRUE(run.run(60, [&] { tracker.add(measuredXy(m)); }));
    const auto& s = tracker.summary();
    EXPECT_GT(s.samples, 150000u);  // 31.4 mm at 2 mm/s, every 100 µs tick
    EXPECT_LT(s.maxAbsMm, 0.002) << "max contour error " << s.maxAbsMm * 1e3 << " µm at " << s.atPathMm << " mm of " << tracker.totalMm();
    EXPECT_NEAR(run.maxSpeedSeen, 2.0, 1e-9);
    EXPECT_EQ(r.count(dev::proto::EventKind::PathSegmentDone), 4);
    EXPECT_EQ(r.count(dev::proto::EventKind::PathDone), 1);
    EXPECT_NEAR(m.commandedLogical(0), 55, 1e-3);
    EXPECT_NEAR(m.commandedLogical(1), 50, 1e-3);
}

TEST_F(AnalyzerPath, FiftyMillimetreLineAtSeed000sAngleStaysUnderFiftyMicrometres)
{
    // Seed 000 §4.1: XY together along tan θ = 4/3, here as a queued LINE from (20, 30) to (50, 70).
    std::vector<Segment> path = {line({m.commandedLogical(0), m.commandedLogical(1)}, {20, 30}, 50),
                                 line({20, 30}, {50, 70}, 50)};
    PathRun run{m, r, path};
    ASSERT_FALSE(run.begin());
    motion::path::ContourTracker tracker(path, 1);
    ASSERT_TRUE(run.run(30, [&] { tracker.add(measuredXy(m)); }));
    EXPECT_LT(tracker.summary().maxAbsMm, 0.05);
    EXPECT_NEAR(m.measuredLogical(0), 50, 0.05);
    EXPECT_NEAR(m.measuredLogical(1), 70, 0.05);
}

TEST_F(StagePath, ShallowJunctionsAreRunWithoutStopping)
{
    // A chord polyline bending 6° per segment: the speed stays up at every junction.
    std::vector<Segment> path;
    Vec2 p{20, 20};
    path.push_back(line({m.commandedLogical(0), m.commandedLogical(1)}, p, 10));
    for (int k = 0; k < 12; ++k) {
        const double a = k * 6.0 * 3.14159265358979 / 180;
        const Vec2 q{p.x + 1.5 * std::cos(a), p.y + 1.5 * std::sin(a)};
        path.push_back(line(p, q, 8));
        p = q;
    }
    PathRun run{m, r, path};
    ASSERT_FALSE(run.begin());
    double minInside = 1e9;
    std::uint32_t lastIndex = 0;
    ASSERT_TRUE(run.run(30, [&] {
        const auto st = m.paths().status();
        // From the middle of segment 2 to the middle of the last: every junction in between.
        if (st.executingIndex >= 2 && st.executingIndex < path.size() - 1)
            minInside = std::min(minInside, m.paths().speedMmS());
        lastIndex = st.executingIndex;
    }));
    EXPECT_GT(minInside, 4.0) << "the path slowed to " << minInside << " mm/s at a 6° junction";
    EXPECT_EQ(r.count(dev::proto::EventKind::PathUnderrun), 0);
}

TEST_F(StagePath, AReversalStopsButAShallowBendDoesNot)
{
    const Vec2 here{m.commandedLogical(0), m.commandedLogical(1)};
    std::vector<Segment> path = {line(here, {here.x + 5, here.y}, 10), line({here.x + 5, here.y}, {here.x, here.y}, 10)};
    PathRun run{m, r, path};
    ASSERT_FALSE(run.begin());
    bool stoppedBetween = false;
    ASSERT_TRUE(run.run(10, [&] {
        if (m.paths().status().executingIndex == 1 && m.paths().speedMmS() == 0 && m.commandedLogical(0) > here.x + 4.9)
            stoppedBetween = true;
    }));
    EXPECT_TRUE(stoppedBetween);
}

TEST_F(StagePath, ASegmentBeyondTheSoftLimitsIsRefusedByNameAndNothingIsQueued)
{
    const Vec2 here{m.commandedLogical(0), m.commandedLogical(1)};
    std::vector<Segment> path = {line(here, {20, 20}, 10), line({20, 20}, {20, 40}, 10),
                                 arc({20, 40}, {20, 60}, {20, 50}, false, 10),  // bulges to x = 30: fine
                                 arc({20, 60}, {20, 40}, {20, 50}, true, 10),   // bulges to x = 10: fine
                                 line({20, 40}, {101, 40}, 10)};                // X beyond 100
    ASSERT_FALSE(m.paths().begin({}));
    const auto e = m.paths().append(appendOf(path, 0, path.size(), 0, dev::proto::PathAppendStart));
    ASSERT_TRUE(e);
    EXPECT_EQ(e->code, dev::proto::ErrorCode::SoftLimit);
    EXPECT_EQ(e->axis, 0);
    EXPECT_EQ(e->value, 100000000);
    EXPECT_NE(e->message.find("segment 4 (LINE)"), std::string::npos) << e->message;
    EXPECT_EQ(m.paths().status().freeSlots, dev::sim::PathQueue::kCapacity);
    EXPECT_EQ(m.paths().status().nextIndex, 0u);
    EXPECT_EQ(m.paths().status().state, dev::proto::PathState::Filling);
}

TEST_F(StagePath, AnArcWhoseBulgeAloneLeavesTheLimitsIsRefused)
{
    // Both ends at x = 5, but counter-clockwise round (5, 50) the arc reaches x = -5.
    const Vec2 here{m.commandedLogical(0), m.commandedLogical(1)};
    std::vector<Segment> path = {line(here, {5, 60}, 10), arc({5, 60}, {5, 40}, {5, 50}, true, 10)};
    ASSERT_FALSE(m.paths().begin({}));
    const auto e = m.paths().append(appendOf(path, 0, 2, 0, dev::proto::PathAppendStart));
    ASSERT_TRUE(e);
    EXPECT_EQ(e->code, dev::proto::ErrorCode::SoftLimit);
    EXPECT_EQ(e->value, 0);
    EXPECT_NE(e->message.find("segment 1 (ARC CCW) reaches X = -5.000 mm"), std::string::npos) << e->message;
}

TEST_F(StagePath, FlowControlRefusesWhatDoesNotFitOrComesOutOfSequence)
{
    const Vec2 here{m.commandedLogical(0), m.commandedLogical(1)};
    std::vector<Segment> path;
    for (int k = 0; k < 40; ++k)
        path.push_back(line({here.x + k * 0.1, here.y}, {here.x + (k + 1) * 0.1, here.y}, 5));
    ASSERT_FALSE(m.paths().begin({}));
    auto st = m.paths().status();
    EXPECT_EQ(st.state, dev::proto::PathState::Filling);
    EXPECT_EQ(st.capacity, dev::sim::PathQueue::kCapacity);
    ASSERT_FALSE(m.paths().append(appendOf(path, 0, 30, 0, 0)));
    st = m.paths().status();
    EXPECT_EQ(st.freeSlots, 2);
    EXPECT_EQ(st.nextIndex, 30u);
    EXPECT_EQ(st.state, dev::proto::PathState::Filling);  // not started: waits for START, LAST or a full queue
    auto e = m.paths().append(appendOf(path, 30, 3, 30, 0));
    ASSERT_TRUE(e);
    EXPECT_EQ(e->code, dev::proto::ErrorCode::PathQueueFull);
    EXPECT_EQ(e->value, 2);
    e = m.paths().append(appendOf(path, 28, 2, 28, 0));  // a repeat of what was already queued
    ASSERT_TRUE(e);
    EXPECT_EQ(e->code, dev::proto::ErrorCode::PathSequence);
    EXPECT_EQ(e->value, 30);
    ASSERT_FALSE(m.paths().append(appendOf(path, 30, 2, 30, 0)));
    EXPECT_EQ(m.paths().status().state, dev::proto::PathState::Running);  // the full queue started it
}

TEST_F(StagePath, RunningDryStopsAtRestAndMoreSegmentsCarryOn)
{
    const Vec2 here{m.commandedLogical(0), m.commandedLogical(1)};
    std::vector<Segment> path = {line(here, {here.x + 2, here.y}, 5), line({here.x + 2, here.y}, {here.x + 4, here.y}, 5)};
    ASSERT_FALSE(m.paths().begin({}));
    ASSERT_FALSE(m.paths().append(appendOf(path, 0, 1, 0, dev::proto::PathAppendStart)));
    r.run(2);
    EXPECT_EQ(m.paths().status().state, dev::proto::PathState::Starved);
    EXPECT_EQ(r.count(dev::proto::EventKind::PathUnderrun), 1);
    EXPECT_EQ(m.paths().status().underruns, 1);
    ASSERT_FALSE(m.paths().append(appendOf(path, 1, 1, 1, dev::proto::PathAppendLast)));
    r.run(2);
    EXPECT_EQ(m.paths().status().state, dev::proto::PathState::Done);
    EXPECT_NEAR(m.commandedLogical(0), here.x + 4, 1e-3);
}

TEST_F(StagePath, HoldStopsOnThePathAndResumeFinishesIt)
{
    const Vec2 here{m.commandedLogical(0), m.commandedLogical(1)};
    const auto path = std::vector<Segment>{line(here, {20, 20}, 10)};
    PathRun run{m, r, path};
    ASSERT_FALSE(run.begin());
    ASSERT_FALSE(run.topUp());
    motion::path::ContourTracker tracker(path);
    r.run(0.5, [&] { tracker.add(measuredXy(m)); });
    ASSERT_FALSE(m.paths().hold());
    r.run(0.5, [&] { tracker.add(measuredXy(m)); });
    EXPECT_EQ(m.paths().status().state, dev::proto::PathState::Held);
    EXPECT_EQ(r.count(dev::proto::EventKind::PathHeld), 1);
    const double heldAt = m.commandedLogical(0);
    r.run(0.5);
    EXPECT_EQ(m.commandedLogical(0), heldAt);
    EXPECT_FALSE(simtest::moving(m, 0));
    EXPECT_TRUE(m.move(simtest::absMove(simtest::bit(0), {50})));  // still reserved: Busy
    ASSERT_FALSE(m.paths().resume());
    ASSERT_TRUE(run.run(20, [&] { tracker.add(measuredXy(m)); }));
    EXPECT_LT(tracker.summary().maxAbsMm, 0.002);
    EXPECT_FALSE(m.move(simtest::absMove(simtest::bit(0), {50})));  // released when done
}

TEST_F(StagePath, StopSlowsDownAlongThePathThenEndsIt)
{
    const Vec2 here{m.commandedLogical(0), m.commandedLogical(1)};
    const auto path = std::vector<Segment>{line(here, {20, 80}, 15)};
    PathRun run{m, r, path};
    ASSERT_FALSE(run.begin());
    ASSERT_FALSE(run.topUp());
    motion::path::ContourTracker tracker(path);
    r.run(1.0, [&] { tracker.add(measuredXy(m)); });
    ASSERT_FALSE(m.stop(0));
    EXPECT_TRUE(m.paths().moving());  // slowing, not frozen
    r.run(1.0, [&] { tracker.add(measuredXy(m)); });
    const auto st = m.paths().status();
    EXPECT_EQ(st.state, dev::proto::PathState::Aborted);
    EXPECT_EQ(st.reason, dev::proto::PathReason::Stop);
    EXPECT_EQ(st.executingIndex, 0u);
    EXPECT_EQ(r.count(dev::proto::EventKind::PathAborted), 1);
    EXPECT_LT(tracker.summary().maxAbsMm, 0.002);  // it stayed on the line while braking
    EXPECT_TRUE(m.paths().append(appendOf(path, 0, 1, 0, 0)));  // PathState: begin again
}

TEST_F(StagePath, EStopEndsThePathAtOnce)
{
    const Vec2 here{m.commandedLogical(0), m.commandedLogical(1)};
    PathRun run{m, r, {line(here, {20, 80}, 15)}};
    ASSERT_FALSE(run.begin());
    ASSERT_FALSE(run.topUp());
    r.run(0.5);
    ASSERT_FALSE(m.estop());
    EXPECT_EQ(m.paths().status().state, dev::proto::PathState::Aborted);
    EXPECT_EQ(m.paths().status().reason, dev::proto::PathReason::EStop);
    const double x = m.commandedLogical(0);
    r.run(0.2);
    EXPECT_EQ(m.commandedLogical(0), x);
    EXPECT_EQ(m.paths().begin({})->code, dev::proto::ErrorCode::EStopActive);
}

TEST(PatternsSimPath, BeginNeedsHomedIdleAxes)
{
    dev::sim::SimMachine m(dev::sim::stageConfig());
    const auto e = m.paths().begin({});
    ASSERT_TRUE(e);
    EXPECT_EQ(e->code, dev::proto::ErrorCode::NotHomed);
}

TEST_F(AnalyzerPath, ZFollowsXyAndTheSpeedIsZeroOnlyThere)
{
    const Vec2 here{m.commandedLogical(0), m.commandedLogical(1)};
    const double z0 = m.commandedLogical(2);
    std::vector<Segment> path = {line(here, {40, 40}, 40), line({40, 40}, {60, 40}, 40)};
    path[0].zMm = z0 + 20;  // once XY is at (40, 40), Z goes down 20 mm, then XY goes on
    PathRun run{m, r, path};
    ASSERT_FALSE(run.begin());
    bool zMovedWhileXy = false, zMovedAtCorner = false;
    ASSERT_TRUE(run.run(20, [&] {
        const double dz = std::fabs(m.commandedLogical(2) - z0);
        if (dz > 1e-3 && dz < 19.99 && m.paths().speedMmS() > 0)
            zMovedWhileXy = true;
        if (dz > 1e-3 && std::fabs(m.commandedLogical(0) - 40) < 0.02)  // the cross-coupled correction steers a few µm
            zMovedAtCorner = true;
    }));
    EXPECT_FALSE(zMovedWhileXy);
    EXPECT_TRUE(zMovedAtCorner);
    EXPECT_NEAR(m.commandedLogical(2), z0 + 20, 1e-3);
    EXPECT_NEAR(m.commandedLogical(0), 60, 1e-2);
}


TEST_F(AnalyzerPath, CrossCouplingFromTheEncodersTakesOutTheScrewsLeadError)
{
    // Seed 000's cross-coupled XY: the same 50 mm line with and without the correction. The
    // screws' lead errors (X +150 ppm, Y −100 ppm) put the carriage ~10 µm off the line by its
    // end; the encoders see that and the correction steers both motors back across the line.
    auto runLine = [&](double gain) {
        dev::sim::SimMachine mm(dev::sim::analyzerConfig());
        simtest::Runner rr{mm, {}};
        EXPECT_FALSE(mm.home(0));
        EXPECT_TRUE(rr.runUntilIdle(60));
        mm.paths().setCrossCouplingGain(gain);
        std::vector<Segment> path = {line({mm.commandedLogical(0), mm.commandedLogical(1)}, {20, 30}, 50),
                                     line({20, 30}, {50, 70}, 50)};
        PathRun run{mm, rr, path};
        EXPECT_FALSE(run.begin());
        motion::path::ContourTracker tracker(path, 1);
        EXPECT_TRUE(run.run(30, [&] { tracker.add(measuredXy(mm)); }));
        return tracker.summary();
    };
    const auto without = runLine(0);
    const auto with = runLine(dev::sim::PathQueue::kDefaultCrossCouplingGain);
    EXPECT_GT(without.maxAbsMm, 0.008);
    EXPECT_LT(with.maxAbsMm, 0.006);
    EXPECT_LT(with.rmsMm, 0.5 * without.rmsMm);
}

TEST_F(AnalyzerPath, ARectangleRoundAPlateWithTheCorrectionStaysStableAtItsCorners)
{
    const Vec2 here{m.commandedLogical(0), m.commandedLogical(1)};
    std::vector<Segment> path = {line(here, {40, 40}, 80), line({40, 40}, {160, 40}, 80), line({160, 40}, {160, 120}, 80),
                                 line({160, 120}, {40, 120}, 80), line({40, 120}, {40, 40}, 80)};
    PathRun run{m, r, path};
    ASSERT_FALSE(run.begin());
    motion::path::ContourTracker tracker(path, 1);
    ASSERT_TRUE(run.run(30, [&] { tracker.add(measuredXy(m)); }));
    EXPECT_LT(tracker.summary().maxAbsMm, 0.05);  // play reverses at every corner
    EXPECT_EQ(r.count(dev::proto::EventKind::LostSteps), 0);
}

TEST_F(StagePath, AHostThatKeepsTheQueueToppedUpNeverLetsItRunDry)
{
    // 41 raster segments through a 32-slot queue, topped up every 10 ms as the runner does.
    motion::plans::Pattern p;
    p.shape = motion::plans::PatternShape::Raster;
    p.feedMmS = 20;
    p.raster.spacingMm = 1;
    PathRun run{m, r, motion::plans::plan(p)};
    ASSERT_EQ(run.path.size(), 41u);
    ASSERT_FALSE(m.move(simtest::absMove(simtest::bit(0) | simtest::bit(1), {30, 30})));
    ASSERT_TRUE(r.runUntilIdle(30));
    ASSERT_FALSE(run.begin());
    ASSERT_TRUE(run.run(120));
    EXPECT_EQ(r.count(dev::proto::EventKind::PathUnderrun), 0);
    EXPECT_EQ(r.count(dev::proto::EventKind::PathSegmentDone), 41);
}
