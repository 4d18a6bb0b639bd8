// The camera maps the stage on a grid plate: the simulated stage's errors come from a
// file of the test's own (the map's code never sees them), the camera finds each dot,
// and the decomposition gives back each scale, the squareness and each straightness the
// file put there; a 2D table fitted from that map, uploaded and enabled, makes the same
// map's RMS error at least five times smaller. A dot the camera cannot find is that
// node's failure with its image, and the run goes on or stops as the test says; a run
// continued from its log never reads a node twice.
#include "device/camera/dot_reading_source.h"
#include "device/camera/sim_camera.h"
#include "device/client/compensation_2d_client.h"
#include "device/files/accuracy/grid/grid_map_test_file.h"
#include "integration/cli_in_process.h"
#include "integration/programs.h"
#include "device/sim/machine_config.h"
#include "device/jobs/accuracy/grid_map_runner.h"
#include "integration/accuracy_support.h"
#include "motion/message_print.h"
#include "motion/metrology/grid/compensation_table_2d.h"
#include "motion/metrology/grid/stage_errors.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace itest;
using dev::jobs::GridMapRunner;
namespace cam = dev::camera;
using motion::metrology::StageErrors;

namespace {

/// Not the docs' example: errors of this test's own, large enough to be seen apart.
StageErrors errorsOfThisTest()
{
    StageErrors e;
    e.x.pitchPolyUm = {0, 0.8, -0.006};
    e.x.straightnessPolyUm = {0, 0, 0.003};
    e.y.pitchPolyUm = {0, -0.4, 0.002};
    e.y.straightnessPolyUm = {0, 0, -0.002};
    e.squarenessUrad = -30;
    e.backlashXUm = 1.0;
    e.backlashYUm = 1.5;
    return e;
}

dev::sim::MachineConfig stageWithTheseErrors()
{
    auto c = dev::sim::stageConfig();
    dev::sim::applyStageErrors(c, errorsOfThisTest());
    return c;
}

struct PlateBench {
    SimSession session{stageWithTheseErrors(), kUnpaced};
    QTemporaryDir dir;
    std::unique_ptr<cam::SimCamera> camera;
    std::unique_ptr<cam::DotReadingSource> source;

    bool ready(cam::SpecimenKind specimen = cam::SpecimenKind::GridPlate)
    {
        if (!session.connect() || !session.homeAll())
            return false;
        session.link.host().setTimeScale(25);
        dev::sim::SimMachine* m = &session.link.machine();
        cam::SimCameraSettings s;
        s.specimen = specimen;
        camera = std::make_unique<cam::SimCamera>(
            [m]() -> std::optional<cam::WorkPoint> { return cam::WorkPoint{m->workPointLogical(0), m->workPointLogical(1), m->timeUs()}; }, s);
        source = std::make_unique<cam::DotReadingSource>(camera.get(), cam::DotReadingOptions{});
        return openSource(*source);
    }
    bool moveTo(double x, double y)
    {
        return !session.call([&](auto cb) { session.client.move({{0, x}, {1, y}}, false, 20, cb); }, 30000) && session.waitStill(30000);
    }
    /// Runs `test` into `folder` until it ends; the runner's last word in `said`.
    void run(GridMapRunner& r, const motion::metrology::GridMapTest& test, const QString& folder, motion::msg::Message* said)
    {
        source->setFailedImagesFolder(folder);
        motion::msg::Problems problems;
        ASSERT_TRUE(r.prepare(test, source.get(), folder, false, &problems)) << describe(problems);
        QObject::connect(&r, &GridMapRunner::problem, &r, [said](const motion::msg::Message& m) { *said = m; });
        if (r.state() == GridMapRunner::State::Finished)
            return;
        ASSERT_TRUE(r.start());
        waitFor([&] { return !r.isActive(); }, 300000);
    }
    bool compensate(const motion::metrology::GridMapResult& map)
    {
        const auto table = motion::metrology::compensationFromMap(map);
        if (!table)
            return false;
        dev::Compensation2dClient* c = session.client.compensation2d();
        if (!c || !c->available())
            return false;
        if (session.call([&](auto cb) { c->upload(*table, cb); }, 30000))
            return false;
        bool done = false, enabled = false;
        c->setEnabled(true, false, [&](const std::optional<dev::RequestError>& e, const dev::Compensation2dState& s) {
            enabled = !e && s.enabled;
            done = true;
        });
        waitFor([&] { return done; }, 30000);
        return enabled;
    }
};

/// A small map, coarse enough for CI: 5 × 5 nodes every 20 mm, 80 mm a side (the slopes
/// the figures are want the span; the nodes cost the time).
motion::metrology::GridMapTest smallGrid()
{
    motion::metrology::GridMapTest t;
    t.name = "small-grid";
    t.pitchXMm = t.pitchYMm = 20;
    t.columns = t.rows = 5;
    t.feedMmS = 20;
    t.dwellS = 0.5;
    return t;
}

/// The map of where the simulated stage's work point truly stood at the same nodes (the
/// file's errors, evaluated where its carriages are, with its gratings' own scale errors
/// and where each axis came to rest within its grating's count), as the simulator states it.
motion::metrology::GridMapResult truthAt(const GridMapRunner& r, const std::vector<double>& exUm, const std::vector<double>& eyUm)
{
    motion::metrology::GridMapInput in = r.input();
    in.exUm = exUm;
    in.eyUm = eyUm;
    return *motion::metrology::analyseGridMap(in);
}

} // namespace

TEST(CameraGridMap, RecoversTheStagesErrorsAndATableFromItCutsTheSameMapFiveFold)
{
    PlateBench b;
    ASSERT_TRUE(b.ready());
    ASSERT_TRUE(b.moveTo(10.1, 10.0)) << "over the plate's dot near (10, 10)";
    motion::msg::Message said;
    GridMapRunner before(&b.session.client);
    // The truth: where the simulator's work point truly stood at each node when it was read.
    std::vector<double> trueExUm(25), trueEyUm(25);
    QObject::connect(&before, &GridMapRunner::nodeRead, &before, [&](int k) {
        const auto w = b.session.link.machine().trueWorkPoint();
        trueExUm[static_cast<std::size_t>(k)] = (w.xMm - before.stops()[k].xMm) * 1e3;
        trueEyUm[static_cast<std::size_t>(k)] = (w.yMm - before.stops()[k].yMm) * 1e3;
    });
    b.run(before, smallGrid(), b.dir.filePath(QStringLiteral("before")), &said);
    ASSERT_EQ(before.state(), GridMapRunner::State::Finished) << said;
    ASSERT_EQ(before.nodesRead(), 25);
    const auto map = before.result();
    ASSERT_TRUE(map);
    const auto truth = truthAt(before, trueExUm, trueEyUm);
    const auto& f = map->figures;
    const auto& t = truth.figures;
    std::printf("scale X %.2f (%.2f) ppm, scale Y %.2f (%.2f) ppm, squareness %.2f (%.2f) urad, straightness X %.3f (%.3f) um, Y %.3f (%.3f) um, "
                "rms %.3f um\n",
                f.scaleXPpm, t.scaleXPpm, f.scaleYPpm, t.scaleYPpm, f.squarenessUrad, t.squarenessUrad, f.straightnessXUm, t.straightnessXUm,
                f.straightnessYUm, t.straightnessYUm, f.rmsErrorUm);
    EXPECT_NEAR(f.scaleXPpm, t.scaleXPpm, 2.0);
    EXPECT_NEAR(f.scaleYPpm, t.scaleYPpm, 2.0);
    EXPECT_NEAR(f.squarenessUrad, t.squarenessUrad, 5.0);
    EXPECT_NEAR(f.straightnessXUm, t.straightnessXUm, 0.5);
    EXPECT_NEAR(f.straightnessYUm, t.straightnessYUm, 0.5);
    ASSERT_GT(std::fabs(t.scaleXPpm), 10) << "errors large enough that recovering them means something";
    ASSERT_GT(t.straightnessXUm, 1.0);
    // The files a person keeps.
    EXPECT_TRUE(QFileInfo::exists(before.basePath() + QStringLiteral(".readings.csv")));
    EXPECT_TRUE(QFileInfo::exists(before.basePath() + QStringLiteral(".grid-map-result.json")));

    ASSERT_TRUE(b.compensate(*map));
    ASSERT_TRUE(b.moveTo(10.1, 10.0));
    GridMapRunner after(&b.session.client);
    b.run(after, smallGrid(), b.dir.filePath(QStringLiteral("after")), &said);
    ASSERT_EQ(after.state(), GridMapRunner::State::Finished) << said;
    const auto compensated = after.result();
    ASSERT_TRUE(compensated);
    std::printf("rms before %.3f um, after %.3f um\n", f.rmsErrorUm, compensated->figures.rmsErrorUm);
    EXPECT_LT(compensated->figures.rmsErrorUm * 5, f.rmsErrorUm);
}

TEST(CameraGridMap, ADotNotFoundIsThatNodesFailureWithItsImageAndTheRunGoesOnOrStops)
{
    PlateBench b;
    ASSERT_TRUE(b.ready());
    // The camera looks at the glass line scales instead of the plate, far from their
    // lines: bare glass, no dot anywhere.
    motion::metrology::GridMapTest t = smallGrid();
    t.columns = t.rows = 3;
    t.pitchXMm = t.pitchYMm = 1;
    t.startXMm = 20;
    t.startYMm = 20;
    b.camera.reset();
    cam::SimCameraSettings s;
    s.specimen = cam::SpecimenKind::LineScales;
    dev::sim::SimMachine* m = &b.session.link.machine();
    b.camera = std::make_unique<cam::SimCamera>(
        [m]() -> std::optional<cam::WorkPoint> { return cam::WorkPoint{m->workPointLogical(0), m->workPointLogical(1), m->timeUs()}; }, s);
    b.source = std::make_unique<cam::DotReadingSource>(b.camera.get(), cam::DotReadingOptions{});
    ASSERT_TRUE(openSource(*b.source));

    motion::msg::Message said;
    const QString goOn = b.dir.filePath(QStringLiteral("go-on"));
    GridMapRunner r(&b.session.client);
    int failed = 0;
    QObject::connect(&r, &GridMapRunner::nodeFailed, &r, [&](int, const motion::msg::Message&) { ++failed; });
    b.run(r, t, goOn, &said);
    EXPECT_EQ(r.state(), GridMapRunner::State::Finished) << "it went on past every failure";
    EXPECT_EQ(failed, 9) << r.nodesRead() << " nodes read on bare glass";
    EXPECT_EQ(said.id, "grid.run.incomplete") << said;
    EXPECT_FALSE(r.result()) << "a map with nodes missing is never a number";
    EXPECT_TRUE(QFileInfo::exists(QDir(goOn).filePath(QStringLiteral("node-001.tif"))));
    EXPECT_FALSE(QFileInfo::exists(r.basePath() + QStringLiteral(".grid-map-result.json")));
    QFile csv(r.basePath() + QStringLiteral(".readings.csv"));
    ASSERT_TRUE(csv.open(QIODevice::ReadOnly));
    const QByteArray readings = csv.readAll();
    EXPECT_TRUE(readings.contains("camera.reading.no_dot")) << "the readings say why, node by node:\n" << readings.toStdString();

    t.stopOnFailure = true;
    GridMapRunner stops(&b.session.client);
    failed = 0;
    QObject::connect(&stops, &GridMapRunner::nodeFailed, &stops, [&](int, const motion::msg::Message&) { ++failed; });
    b.run(stops, t, b.dir.filePath(QStringLiteral("stops")), &said);
    EXPECT_EQ(stops.state(), GridMapRunner::State::Stopped);
    EXPECT_EQ(failed, 1);
    EXPECT_EQ(said.id, "grid.run.node_failed") << said;
}

TEST(CameraGridMap, AStoppedRunContinuesFromItsLogWithoutReadingANodeTwice)
{
    PlateBench b;
    ASSERT_TRUE(b.ready());
    ASSERT_TRUE(b.moveTo(20.1, 20.0));
    motion::metrology::GridMapTest t = smallGrid();
    t.columns = t.rows = 3;
    const QString folder = b.dir.filePath(QStringLiteral("resumed"));
    motion::msg::Message said;
    int taken = 0;
    {
        GridMapRunner first(&b.session.client);
        b.source->setFailedImagesFolder(folder);
        motion::msg::Problems problems;
        ASSERT_TRUE(first.prepare(t, b.source.get(), folder, false, &problems)) << describe(problems);
        QObject::connect(&first, &GridMapRunner::nodeRead, &first, [&](int k) {
            ++taken;
            if (k == 3)
                first.abort();
        });
        ASSERT_TRUE(first.start());
        waitFor([&] { return !first.isActive(); }, 120000);
        ASSERT_EQ(first.state(), GridMapRunner::State::Stopped);
        ASSERT_EQ(first.nodesRead(), 4);
    }
    // Somewhere else entirely: the start comes from the log, not from the dot seen now.
    ASSERT_TRUE(b.moveTo(50.3, 60.2));
    GridMapRunner second(&b.session.client);
    std::vector<int> readAgain;
    QObject::connect(&second, &GridMapRunner::nodeRead, &second, [&](int k) { readAgain.push_back(k); });
    b.run(second, t, folder, &said);
    ASSERT_EQ(second.state(), GridMapRunner::State::Finished) << said;
    EXPECT_EQ(readAgain, (std::vector<int>{4, 5, 6, 7, 8}));
    EXPECT_NEAR(second.startXMm(), 20.1, 0.1);
    EXPECT_NEAR(second.startYMm(), 20.0, 0.1);
    EXPECT_TRUE(second.result());
}

/// Where the simulator's work point truly stood at each reading of `r`, by node and pass.
struct TruthBothWays {
    std::vector<double> ex, ey, rex, rey;
    /// Over the nodes, the mean of (grating − target) forward less the same in reverse:
    /// the part of the reversal the stage's own gratings show (an axis may rest a count
    /// off a target that is not on its count).
    double gratingReversalXUm = 0, gratingReversalYUm = 0;
    void watch(const GridMapRunner& r, PlateBench& b, int nodes)
    {
        ex.assign(static_cast<std::size_t>(nodes), 0);
        ey = rex = rey = ex;
        QObject::connect(&r, &GridMapRunner::nodeRead, &r, [this, &r, &b](int k) {
            const auto w = b.session.link.machine().trueWorkPoint();
            const auto& s = r.stops()[static_cast<std::size_t>(k)];
            const auto& axes = b.session.client.status().axes;
            const double sign = (s.reverse ? -1.0 : 1.0) / static_cast<double>(ex.size());
            gratingReversalXUm += sign * (axes[0].measured - s.xMm) * 1e3;
            gratingReversalYUm += sign * (axes[1].measured - s.yMm) * 1e3;
            const auto node = static_cast<std::size_t>(s.node(r.test().columns));
            (s.reverse ? rex : ex)[node] = (w.xMm - s.xMm) * 1e3;
            (s.reverse ? rey : ey)[node] = (w.yMm - s.yMm) * 1e3;
        });
    }
    motion::metrology::GridMapResult map(const GridMapRunner& r) const
    {
        motion::metrology::GridMapInput in = r.input();
        in.exUm = ex;
        in.eyUm = ey;
        in.reverseExUm = rex;
        in.reverseEyUm = rey;
        return *motion::metrology::analyseGridMap(in);
    }
};

TEST(CameraGridMap, BothWaysGiveTheSetBacklashAsTheMeanReversalAndTheMeanMapStillTheStagesErrors)
{
    PlateBench b;
    ASSERT_TRUE(b.ready());
    ASSERT_TRUE(b.moveTo(10.1, 10.0));
    // 3 × 3 nodes every 30 mm, read forward and back: 18 readings.
    motion::metrology::GridMapTest t = smallGrid();
    t.name = "both-ways";
    t.columns = t.rows = 3;
    t.pitchXMm = t.pitchYMm = 30;
    t.bidirectional = true;
    GridMapRunner r(&b.session.client);
    TruthBothWays truth;
    truth.watch(r, b, 9);
    motion::msg::Message said;
    b.run(r, t, b.dir.filePath(QStringLiteral("both-ways")), &said);
    ASSERT_EQ(r.state(), GridMapRunner::State::Finished) << said;
    ASSERT_EQ(r.totalNodes(), 18);
    ASSERT_EQ(r.nodesRead(), 18);
    const auto map = r.result();
    ASSERT_TRUE(map);
    const auto real = truth.map(r);
    const auto& f = map->figures;
    const auto& tf = real.figures;
    ASSERT_TRUE(f.meanReversalXUm && f.meanReversalYUm && f.maxReversalUm && tf.meanReversalXUm && tf.meanReversalYUm);
    const StageErrors set = errorsOfThisTest();
    std::printf("mean reversal X %.3f um (truth %.3f, set backlash %.2f), Y %.3f um (truth %.3f, set %.2f), max %.3f um\n",
                *f.meanReversalXUm, *tf.meanReversalXUm, set.backlashXUm, *f.meanReversalYUm, *tf.meanReversalYUm, set.backlashYUm,
                *f.maxReversalUm);
    std::printf("mean map: scale X %.2f (%.2f) ppm, scale Y %.2f (%.2f) ppm, squareness %.2f (%.2f) urad, straightness X %.3f (%.3f), "
                "Y %.3f (%.3f) um\n",
                f.scaleXPpm, tf.scaleXPpm, f.scaleYPpm, tf.scaleYPpm, f.squarenessUrad, tf.squarenessUrad, f.straightnessXUm,
                tf.straightnessXUm, f.straightnessYUm, tf.straightnessYUm);
    // Where each reading was taken: an axis rests where its grating reads a count near the
    // target (the targets, from the dot found at the start, are not on the 0.5 µm counts,
    // and the loop may settle a count off), and its carriage anywhere within half a count
    // of that reading. So a node's reversal is −b + (grating − target, forward less
    // reverse) + the difference of two sub-count rests: the mean over the nodes, less the
    // gratings' part, is −b within one count whatever the rests do, plus what the camera
    // adds (its reading against the truth's, checked first).
    constexpr double kCountUm = 0.5;
    constexpr double kCameraUm = 0.1;
    std::printf("the gratings' part of the mean reversal: X %.3f um, Y %.3f um\n", truth.gratingReversalXUm, truth.gratingReversalYUm);
    EXPECT_NEAR(*f.meanReversalXUm, *tf.meanReversalXUm, kCameraUm) << "the camera sees the reversal the work point made";
    EXPECT_NEAR(*f.meanReversalYUm, *tf.meanReversalYUm, kCameraUm);
    EXPECT_NEAR(-(*f.meanReversalXUm - truth.gratingReversalXUm), set.backlashXUm, kCountUm + kCameraUm) << "backlash b = −B̄";
    EXPECT_NEAR(-(*f.meanReversalYUm - truth.gratingReversalYUm), set.backlashYUm, kCountUm + kCameraUm);
    for (const auto& n : map->nodes)
        ASSERT_TRUE(n.bidirectional() && n.forwardExUm && n.reverseExUm);
    // The mean of both directions still gives the stage's errors, as one way does.
    EXPECT_NEAR(f.scaleXPpm, tf.scaleXPpm, 2.0);
    EXPECT_NEAR(f.scaleYPpm, tf.scaleYPpm, 2.0);
    EXPECT_NEAR(f.squarenessUrad, tf.squarenessUrad, 5.0);
    EXPECT_NEAR(f.straightnessXUm, tf.straightnessXUm, 0.5);
    EXPECT_NEAR(f.straightnessYUm, tf.straightnessYUm, 0.5);
    ASSERT_GT(std::fabs(tf.scaleXPpm), 10);
    // The result file carries it.
    QFile json(r.basePath() + QStringLiteral(".grid-map-result.json"));
    ASSERT_TRUE(json.open(QIODevice::ReadOnly));
    const QJsonObject o = QJsonDocument::fromJson(json.readAll()).object();
    const QJsonObject figures = o.value(QStringLiteral("figures")).toObject();
    EXPECT_NEAR(figures.value(QStringLiteral("mean_reversal_x_um")).toDouble(99), *f.meanReversalXUm, 1e-6);
    EXPECT_TRUE(figures.value(QStringLiteral("max_reversal_um")).isDouble());
    EXPECT_TRUE(o.value(QStringLiteral("nodes")).toArray().first().toObject().value(QStringLiteral("reversal_um")).isDouble());
}

TEST(CameraGridMap, ARunStoppedInTheReversePassContinuesWithoutReadingANodeOfEitherPassAgain)
{
    PlateBench b;
    ASSERT_TRUE(b.ready());
    ASSERT_TRUE(b.moveTo(20.1, 20.0));
    motion::metrology::GridMapTest t = smallGrid();
    t.columns = t.rows = 3;
    t.pitchXMm = t.pitchYMm = 10;
    t.bidirectional = true;
    const QString folder = b.dir.filePath(QStringLiteral("resumed-both"));
    double gratingReversalYUm = 0;  // the gratings' part of the mean reversal, both sessions
    {
        GridMapRunner first(&b.session.client);
        TruthBothWays truth;
        truth.watch(first, b, 9);
        b.source->setFailedImagesFolder(folder);
        motion::msg::Problems problems;
        ASSERT_TRUE(first.prepare(t, b.source.get(), folder, false, &problems)) << describe(problems);
        QObject::connect(&first, &GridMapRunner::nodeRead, &first, [&](int k) {
            if (k == 11)  // the third reading of the reverse pass
                first.abort();
        });
        ASSERT_TRUE(first.start());
        waitFor([&] { return !first.isActive(); }, 120000);
        ASSERT_EQ(first.state(), GridMapRunner::State::Stopped);
        ASSERT_EQ(first.nodesRead(), 12);
        gratingReversalYUm += truth.gratingReversalYUm;
    }
    // Every reading is in the log, each pass's by its node.
    QFile log(QDir(folder).filePath(QStringLiteral("grid-map.run-log.jsonl")));
    ASSERT_TRUE(log.open(QIODevice::ReadOnly));
    const QByteArray lines = log.readAll();
    EXPECT_EQ(lines.count("\"measured_x_mm\""), 12);
    EXPECT_EQ(lines.count("\"pass\":\"reverse\""), 3) << lines.toStdString();
    log.close();

    ASSERT_TRUE(b.moveTo(50.3, 60.2));
    GridMapRunner second(&b.session.client);
    std::vector<int> readAgain;
    QObject::connect(&second, &GridMapRunner::nodeRead, &second, [&](int k) { readAgain.push_back(k); });
    TruthBothWays truth;
    truth.watch(second, b, 9);
    motion::msg::Message said;
    b.run(second, t, folder, &said);
    gratingReversalYUm += truth.gratingReversalYUm;
    ASSERT_EQ(second.state(), GridMapRunner::State::Finished) << said;
    EXPECT_EQ(readAgain, (std::vector<int>{12, 13, 14, 15, 16, 17}));
    EXPECT_NEAR(second.startXMm(), 20.1, 0.1);
    const auto map = second.result();
    ASSERT_TRUE(map);
    ASSERT_TRUE(map->figures.meanReversalYUm);
    for (const auto& n : map->nodes)
        EXPECT_TRUE(n.bidirectional()) << n.xMm << ", " << n.yMm;
    // The readings before the stop and after it make one map: its mean reversal of Y, less
    // the gratings' part, is the set backlash within a count and the camera (as above).
    EXPECT_NEAR(-(*map->figures.meanReversalYUm - gratingReversalYUm), errorsOfThisTest().backlashYUm, 0.5 + 0.1);
}

TEST(CameraGridMapCli, BidirectionalIsAnOptionOrTheTestFilesPassesAndAnythingElseIsRefused)
{
    QTemporaryDir dir;
    const auto example =
        dev::files::accuracy::loadGridMapTestFile(QStringLiteral(BP_SOURCE_DIR "/resources/examples/stage-grid-bidirectional.grid-map-test.json"));
    ASSERT_TRUE(example.ok()) << motion::msg::debugFormat(example.problems());
    EXPECT_TRUE(example->bidirectional);
    EXPECT_FALSE(dev::files::accuracy::loadGridMapTestFile(QStringLiteral(BP_SOURCE_DIR "/resources/examples/stage-grid-10mm.grid-map-test.json"))
                     ->bidirectional)
        << "a test that does not say is one way, as before";
    // Written and read again.
    const auto again = dev::files::accuracy::gridMapTestFromJson(dev::files::accuracy::gridMapTestToJson(*example), "again.json");
    ASSERT_TRUE(again.ok());
    EXPECT_TRUE(again->bidirectional);
    // A pass that is neither, at its line and column.
    const QString bad = dir.filePath(QStringLiteral("both.grid-map-test.json"));
    QFile f(bad);
    ASSERT_TRUE(f.open(QIODevice::WriteOnly));
    f.write("{\"schema\": \"benchpilot.grid-map-test\", \"version\": 1,\n"
            " \"pitch_mm\": {\"x\": 10, \"y\": 10},\n"
            " \"nodes\": {\"columns\": 3, \"rows\": 3},\n"
            " \"passes\": \"both\"}\n");
    f.close();
    const QString out = dir.filePath(QStringLiteral("run"));
    const auto r = runCliInProcess({QStringLiteral("--sim"), QStringLiteral("stage"), QStringLiteral("grid-map"), QStringLiteral("run"),
                                    QStringLiteral("--test"), bad, QStringLiteral("--out"), out});
    EXPECT_EQ(r.code, 1) << qPrintable(r.err);
    EXPECT_TRUE(r.err.contains(QStringLiteral("both.grid-map-test.json:4:"))) << qPrintable(r.err);
    EXPECT_TRUE(r.err.contains(QStringLiteral("bidirectional"))) << "it says what is allowed: " << qPrintable(r.err);
    EXPECT_FALSE(QFileInfo::exists(out));
    // The test file says the passes: --bidirectional beside it is refused.
    const auto both = runCliInProcess({QStringLiteral("--sim"), QStringLiteral("stage"), QStringLiteral("grid-map"), QStringLiteral("run"),
                                       QStringLiteral("--test"),
                                       QStringLiteral(BP_SOURCE_DIR "/resources/examples/stage-grid-10mm.grid-map-test.json"),
                                       QStringLiteral("--bidirectional"), QStringLiteral("--out"), out});
    EXPECT_EQ(both.code, 1) << qPrintable(both.err);
    EXPECT_TRUE(both.err.contains(QStringLiteral("--bidirectional"))) << qPrintable(both.err);
    EXPECT_FALSE(QFileInfo::exists(out));
    // A bidirectional grid whose reverse lead-in leaves the travel: 3 nodes every 10 mm
    // from 80 mm end at 100 mm, and the lead-in above it at 100.05.
    const auto far = runCliInProcess({QStringLiteral("--sim"), QStringLiteral("stage"), QStringLiteral("grid-map"), QStringLiteral("run"),
                                      QStringLiteral("--pitch"), QStringLiteral("10"), QStringLiteral("--nodes"), QStringLiteral("3,3"),
                                      QStringLiteral("--start"), QStringLiteral("80,10"), QStringLiteral("--bidirectional"),
                                      QStringLiteral("--out"), out});
    EXPECT_EQ(far.code, 1) << qPrintable(far.err);
    EXPECT_TRUE(far.err.contains(QStringLiteral("--nodes"))) << qPrintable(far.err);
    EXPECT_FALSE(QFileInfo::exists(out));
}

TEST(CameraGridMapCli, BadInputIsRefusedByFileLineAndColumnAndNothingIsWritten)
{
    QTemporaryDir dir;
    // The example reads as it is.
    const auto example = dev::files::accuracy::loadGridMapTestFile(QStringLiteral(BP_SOURCE_DIR "/resources/examples/stage-grid-10mm.grid-map-test.json"));
    ASSERT_TRUE(example.ok()) << motion::msg::debugFormat(example.problems());
    EXPECT_EQ(example->columns, 9);
    // From 10 mm, 12 nodes every 10 mm reach 120 mm: beyond the stage's 100 mm travel.
    const QString bad = dir.filePath(QStringLiteral("far.grid-map-test.json"));
    QFile f(bad);
    ASSERT_TRUE(f.open(QIODevice::WriteOnly));
    f.write("{\"schema\": \"benchpilot.grid-map-test\", \"version\": 1,\n"
            " \"pitch_mm\": {\"x\": 10, \"y\": 10},\n"
            " \"nodes\": {\"columns\": 12, \"rows\": 3},\n"
            " \"start_mm\": {\"x_mm\": 10, \"y_mm\": 10}}\n");
    f.close();
    const QString out = dir.filePath(QStringLiteral("run"));
    const auto r = runCliInProcess({QStringLiteral("--sim"), QStringLiteral("stage"), QStringLiteral("grid-map"), QStringLiteral("run"),
                                    QStringLiteral("--test"), bad, QStringLiteral("--out"), out});
    EXPECT_EQ(r.code, 1) << qPrintable(r.err);
    EXPECT_TRUE(r.err.contains(QStringLiteral("far.grid-map-test.json:3:"))) << qPrintable(r.err);
    EXPECT_FALSE(QFileInfo::exists(out)) << "nothing half-written";
    // A pitch between the plate's dots.
    const auto pitch = runCliInProcess({QStringLiteral("--sim"), QStringLiteral("stage"), QStringLiteral("grid-map"), QStringLiteral("run"),
                                        QStringLiteral("--pitch"), QStringLiteral("2.5"), QStringLiteral("--nodes"), QStringLiteral("3,3"),
                                        QStringLiteral("--out"), out});
    EXPECT_EQ(pitch.code, 1);
    EXPECT_TRUE(pitch.err.contains(QStringLiteral("--pitch"))) << qPrintable(pitch.err);
    EXPECT_FALSE(QFileInfo::exists(out));
}

TEST(CameraGridMapCli, WritesTheReadingsAndTheResultWithFiguresAndNodes)
{
    QTemporaryDir dir;
    const QString out = dir.filePath(QStringLiteral("run"));
    const auto r = runCliInProcess({QStringLiteral("--sim"), QStringLiteral("stage"), QStringLiteral("--json"), QStringLiteral("grid-map"),
                                    QStringLiteral("run"), QStringLiteral("--home"), QStringLiteral("--at"), QStringLiteral("X=20.1,Y=20"),
                                    QStringLiteral("--pitch"), QStringLiteral("10"), QStringLiteral("--nodes"), QStringLiteral("3,3"),
                                    QStringLiteral("--dwell"), QStringLiteral("0.05"), QStringLiteral("--time-scale"), QStringLiteral("20"),
                                    QStringLiteral("--out"), out});
    ASSERT_EQ(r.code, 0) << qPrintable(r.err);
    const QJsonObject o = r.json();
    const QJsonObject figures = o.value(QStringLiteral("figures")).toObject();
    for (const char* k : {"scale_x_ppm", "scale_y_ppm", "squareness_urad", "straightness_x_um", "straightness_y_um", "rms_error_um",
                          "max_error_um", "rms_residual_um"})
        EXPECT_TRUE(figures.contains(QLatin1String(k))) << k;
    const QJsonArray nodes = o.value(QStringLiteral("nodes")).toArray();
    ASSERT_EQ(nodes.size(), 9);
    for (const char* k : {"x_mm", "y_mm", "ex_um", "ey_um"})
        EXPECT_TRUE(nodes.first().toObject().contains(QLatin1String(k))) << k;
    EXPECT_TRUE(QFileInfo::exists(QDir(out).filePath(QStringLiteral("grid-map.readings.csv"))));
    EXPECT_TRUE(QFileInfo::exists(QDir(out).filePath(QStringLiteral("grid-map.grid-map-result.json"))));
}

TEST(CameraGridMapCli, BidirectionalWritesEachReadingWithItsPassAndTheReversalInTheResultAndReport)
{
    QTemporaryDir dir;
    const QString out = dir.filePath(QStringLiteral("both"));
    const auto r = runProgram(binary("benchpilot-cli"),
                              {QStringLiteral("--sim"), QStringLiteral("stage"), QStringLiteral("--json"), QStringLiteral("grid-map"),
                               QStringLiteral("run"), QStringLiteral("--home"), QStringLiteral("--at"), QStringLiteral("X=20.1,Y=20"),
                               QStringLiteral("--pitch"), QStringLiteral("10"), QStringLiteral("--nodes"), QStringLiteral("3,3"),
                               QStringLiteral("--bidirectional"), QStringLiteral("--dwell"), QStringLiteral("0.05"),
                               QStringLiteral("--time-scale"), QStringLiteral("20"), QStringLiteral("--out"), out},
                              120000);
    ASSERT_EQ(r.exitCode, 0) << r.describe();
    const QJsonObject o = QJsonDocument::fromJson(r.out.toUtf8()).object();
    const QJsonObject figures = o.value(QStringLiteral("figures")).toObject();
    for (const char* k : {"max_reversal_um", "mean_reversal_x_um", "mean_reversal_y_um"})
        EXPECT_TRUE(figures.value(QLatin1String(k)).isDouble()) << k << " in " << r.out.toStdString();
    const QJsonArray nodes = o.value(QStringLiteral("nodes")).toArray();
    ASSERT_EQ(nodes.size(), 9) << "one node a place, both directions in it";
    for (const char* k : {"reversal_um", "forward_ex_um", "reverse_ey_um"})
        EXPECT_TRUE(nodes.first().toObject().value(QLatin1String(k)).isDouble()) << k;
    QFile csv(QDir(out).filePath(QStringLiteral("grid-map.readings.csv")));
    ASSERT_TRUE(csv.open(QIODevice::ReadOnly));
    const QByteArray readings = csv.readAll();
    EXPECT_TRUE(readings.startsWith("node,pass,column,row,"));
    EXPECT_EQ(readings.count(",forward,"), 9);
    EXPECT_EQ(readings.count(",reverse,"), 9);
    QFile pdf(QDir(out).filePath(QStringLiteral("grid-map.report.pdf")));
    ASSERT_TRUE(pdf.open(QIODevice::ReadOnly));
    EXPECT_TRUE(pdf.read(5).startsWith("%PDF-"));
}

TEST(CameraGridMapCli, TheReportShowsTheMapBeforeAndAfterSideBySide)
{
    QTemporaryDir dir;
    const QString cli = binary("benchpilot-cli");
    auto run = [&](const QString& out, const QStringList& more) {
        return runProgram(cli,
                          QStringList{QStringLiteral("--sim"), QStringLiteral("stage"), QStringLiteral("--json"), QStringLiteral("grid-map"),
                                      QStringLiteral("run"), QStringLiteral("--home"), QStringLiteral("--at"), QStringLiteral("X=20.1,Y=20"),
                                      QStringLiteral("--pitch"), QStringLiteral("10"), QStringLiteral("--nodes"), QStringLiteral("3,3"),
                                      QStringLiteral("--dwell"), QStringLiteral("0.05"), QStringLiteral("--time-scale"), QStringLiteral("20"),
                                      QStringLiteral("--out"), out}
                              + more,
                          120000);
    };
    const QString first = dir.filePath(QStringLiteral("first"));
    const auto a = run(first, {});
    ASSERT_EQ(a.exitCode, 0) << a.describe();
    const QString second = dir.filePath(QStringLiteral("second"));
    const auto b = run(second, {QStringLiteral("--before"), QDir(first).filePath(QStringLiteral("grid-map.grid-map-result.json"))});
    ASSERT_EQ(b.exitCode, 0) << b.describe();
    for (const QString& folder : {first, second}) {
        QFile pdf(QDir(folder).filePath(QStringLiteral("grid-map.report.pdf")));
        ASSERT_TRUE(pdf.open(QIODevice::ReadOnly)) << folder.toStdString();
        EXPECT_TRUE(pdf.read(5).startsWith("%PDF-"));
    }
    // A --before that cannot be read stops the run before anything is written.
    const QString third = dir.filePath(QStringLiteral("third"));
    const auto c = run(third, {QStringLiteral("--before"), dir.filePath(QStringLiteral("missing.grid-map-result.json"))});
    EXPECT_EQ(c.exitCode, 1) << c.describe();
    EXPECT_FALSE(QFileInfo::exists(third));
}
