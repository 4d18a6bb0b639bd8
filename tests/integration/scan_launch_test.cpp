// The way from "Run" to a running scan (dev::jobs::ScanLaunch), below any widget: the
// Scan screen and the CLI's `scan run` both take their decisions from it, so what it
// says here is what both front ends do — a fresh run's first move and whether it is
// long, a resume at the next tile with no question about the approach, another plan's
// log and a complete run each waiting for a person's word, and a stage that is not
// ready keeping the run from starting.
#include "device/files/scan_run_log.h"
#include "device/jobs/scan_launch.h"
#include "sim_session.h"

#include <QDir>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <memory>

using namespace itest;
using dev::jobs::ScanDecision;
using dev::jobs::ScanLaunch;
using dev::jobs::ScanRunner;
using Kind = dev::jobs::ScanDecision::Kind;

namespace {

/// 3 × 3 fields of 1 mm around (41.4, 61.4) mm: far from home on a 100 mm stage.
motion::scan::ScanPlan launchPlan()
{
    motion::scan::ScanPlan p;
    p.name = "launch";
    p.region.cornerA = {40, 60};
    p.region.cornerB = {42.8, 62.8};
    p.camera.source = motion::scan::FieldSource::Direct;
    p.camera.fieldWidthMm = p.camera.fieldHeightMm = 1.0;
    p.camera.samplePixelUm = 0.5;
    p.overlapX = p.overlapY = 0.1;
    p.speedMmS = 10;
    p.settleS = 0.03;
    p.exposureS = 0.02;
    return p;
}

struct LaunchStage {
    LaunchStage() : session(dev::proto::DeviceKind::Stage, kUnpaced) {}
    bool ready()
    {
        if (!session.connect() || !session.homeAll())
            return false;
        session.link.host().setTimeScale(10);
        return true;
    }
    /// One front end: a runner and its launch, as the screen holds them or a CLI call makes them.
    struct FrontEnd {
        explicit FrontEnd(dev::Instrument* stage) : runner(stage), launch(&runner) {}
        ScanRunner runner;
        ScanLaunch launch;
    };
    std::unique_ptr<FrontEnd> frontEnd() { return std::make_unique<FrontEnd>(&session.client); }
    SimSession session;
    QTemporaryDir dir;
};

std::string launchText(const ScanDecision& d)
{
    std::string s = "kind " + std::to_string(static_cast<int>(d.kind)) + " " + d.error.id;
    for (const auto& m : d.blockers)
        s += " " + m.id;
    return s;
}

} // namespace

TEST(ScanLaunch, AFreshRunSaysWhereItsFirstMoveGoesAndThatItIsLong)
{
    LaunchStage s;
    ASSERT_TRUE(s.ready()) << s.session.linkErrors.join(QLatin1Char(' ')).toStdString();
    ASSERT_LT(s.session.client.status().axes[0].commanded, 10.0) << "homing leaves the stage near its origin";
    auto f = s.frontEnd();
    const ScanDecision d = f->launch.prepare(launchPlan(), s.dir.path());
    ASSERT_EQ(d.kind, Kind::Ready) << launchText(d);
    EXPECT_FALSE(d.outlook.resume);
    EXPECT_EQ(d.outlook.takenTiles, 0);
    EXPECT_EQ(d.outlook.totalTiles, 9);
    EXPECT_EQ(d.outlook.firstTileMm.xMm, f->runner.layout().path.front().target.xMm);
    EXPECT_EQ(d.outlook.firstTileMm.yMm, f->runner.layout().path.front().target.yMm);
    EXPECT_GT(d.outlook.etaS, 0.0);
    EXPECT_FALSE(d.outlook.longRun) << "nine small tiles take seconds";
    EXPECT_TRUE(d.outlook.longApproach) << "40 mm of a 100 mm travel is a long move";
    EXPECT_TRUE(d.outlook.needsConfirmation());

    // Standing next to the first tile, the same run is nothing to ask about.
    const auto first = d.outlook.firstTileMm;
    ASSERT_FALSE(s.session.call([&](auto cb) { s.session.client.move({{0, first.xMm - 1}, {1, first.yMm - 1}}, false, 20, cb); }));
    ASSERT_TRUE(s.session.waitStill());
    const ScanDecision near = f->launch.prepare(launchPlan(), s.dir.path());
    ASSERT_EQ(near.kind, Kind::Ready) << launchText(near);
    EXPECT_FALSE(near.outlook.longApproach);
    EXPECT_FALSE(near.outlook.needsConfirmation());
}

TEST(ScanLaunch, AStoppedRunResumesAtItsNextTileWithoutAskingAboutTheApproach)
{
    LaunchStage s;
    ASSERT_TRUE(s.ready());
    auto screen = s.frontEnd();
    ASSERT_EQ(screen->launch.prepare(launchPlan(), s.dir.path()).kind, Kind::Ready);
    motion::msg::Message error;
    ASSERT_TRUE(screen->launch.start(&error)) << error;
    ASSERT_TRUE(waitFor([&] { return screen->runner.takenTiles() >= 3; }, 20000));
    screen->runner.abort();
    ASSERT_TRUE(s.session.waitStill());
    const int taken = screen->runner.takenTiles();
    ASSERT_LT(taken, 9);

    // The screen: the run it holds is continued as it stands, not prepared again.
    const ScanDecision again = screen->launch.prepare(launchPlan(), s.dir.path());
    ASSERT_EQ(again.kind, Kind::Ready) << launchText(again);
    EXPECT_EQ(screen->runner.state(), ScanRunner::State::Stopped) << "kept, not prepared anew";
    EXPECT_TRUE(again.outlook.resume);
    EXPECT_EQ(again.outlook.takenTiles, taken);
    EXPECT_FALSE(again.outlook.longApproach) << "a resumed run's approach is its own";
    EXPECT_TRUE(screen->launch.holds(motion::scan::layoutFingerprint(launchPlan(), screen->runner.layout())));

    // The CLI run again on the same folder: a new runner reads the log and says the same.
    auto cli = s.frontEnd();
    const ScanDecision fromLog = cli->launch.prepare(launchPlan(), s.dir.path());
    ASSERT_EQ(fromLog.kind, Kind::Ready) << launchText(fromLog);
    EXPECT_TRUE(fromLog.outlook.resume);
    EXPECT_EQ(fromLog.outlook.takenTiles, taken);
    EXPECT_FALSE(fromLog.outlook.longApproach);
    EXPECT_EQ(fromLog.outlook.totalTiles, again.outlook.totalTiles);
}

TEST(ScanLaunch, AnotherPlansLogWaitsForAPersonAndBeginningAnewKeepsItAside)
{
    LaunchStage s;
    ASSERT_TRUE(s.session.connect());
    auto first = s.frontEnd();
    ASSERT_NE(first->launch.prepare(launchPlan(), s.dir.path()).kind, Kind::Refused);
    motion::scan::ScanPlan other = launchPlan();
    other.region.cornerB = {44, 64};
    auto second = s.frontEnd();
    const ScanDecision d = second->launch.prepare(other, s.dir.path());
    ASSERT_EQ(d.kind, Kind::OtherScansLog) << launchText(d);
    EXPECT_EQ(d.error.id, "scan.run.other_scans_log");
    EXPECT_FALSE(second->launch.holds(motion::scan::layoutFingerprint(other, motion::scan::layoutScan(other))));

    const ScanDecision anew = second->launch.beginAnew();
    // Not homed: prepared, and what keeps it from starting is said, not asked.
    ASSERT_EQ(anew.kind, Kind::Blocked) << launchText(anew);
    ASSERT_FALSE(anew.blockers.empty());
    EXPECT_EQ(anew.blockers.front().id, "scan.run.not_homed");
    EXPECT_EQ(second->runner.takenTiles(), 0);
    const QStringList aside = QDir(s.dir.path()).entryList({QStringLiteral("scan-run.*.jsonl")}, QDir::Files);
    EXPECT_EQ(aside.size(), 1) << "the other plan's log is kept under another name";
}

TEST(ScanLaunch, ACompleteRunAsksBeforeTakingItAgain)
{
    LaunchStage s;
    ASSERT_TRUE(s.ready());
    auto f = s.frontEnd();
    ASSERT_EQ(f->launch.prepare(launchPlan(), s.dir.path()).kind, Kind::Ready);
    motion::msg::Message error;
    ASSERT_TRUE(f->launch.start(&error)) << error;
    ASSERT_TRUE(waitFor([&] { return f->runner.state() == ScanRunner::State::Finished; }, 30000));

    const ScanDecision done = f->launch.prepare(launchPlan(), s.dir.path());
    ASSERT_EQ(done.kind, Kind::AllTaken) << launchText(done);
    const ScanDecision anew = f->launch.beginAnew();
    ASSERT_EQ(anew.kind, Kind::Ready) << launchText(anew);
    EXPECT_FALSE(anew.outlook.resume);
    EXPECT_EQ(anew.outlook.takenTiles, 0);
}

TEST(ScanLaunch, SoftLimitsSetAfterPreparingStillKeepThePlanFromStarting)
{
    LaunchStage s;
    ASSERT_TRUE(s.ready());
    auto f = s.frontEnd();
    ASSERT_EQ(f->launch.prepare(launchPlan(), s.dir.path()).kind, Kind::Ready);
    // The run's stage model follows the device's limits after prepare.
    ASSERT_FALSE(s.session.call([&](auto cb) { s.session.client.setSoftLimits(1, 0, 62, cb); }));
    ASSERT_TRUE(waitFor([&] { return s.session.client.softLimits().size() >= 2 && s.session.client.softLimits()[1].max < 62.5; }, 3000));
    const ScanDecision d = f->launch.prepare(launchPlan(), s.dir.path());
    ASSERT_EQ(d.kind, Kind::Blocked) << launchText(d);
    EXPECT_EQ(d.blockers.front().id, "scan.run.plan_problem");
    motion::msg::Message error;
    EXPECT_FALSE(f->launch.start(&error));
    EXPECT_EQ(error.id, "scan.run.plan_problem") << error;
}
