// benchpilot-sim --camera-socket with benchpilot-cli on its pty: a snap is taken at the
// stage's TRUE work point (the pitch error shows as it does in-process), a scan's neighbouring
// images agree with their measured positions, a camera that is not there is named, and a
// scan whose camera goes mid-run stops with the reason, keeps every tile taken and resumes.
#include "device/camera/sim_render.h"
#include "device/camera/tile_tiff.h"
#include "device/files/scan_run_log.h"
#include "device/files/text_file.h"

#include "integration/pty_simulator.h"
#include "integration/sim_session.h"
#include "phase_correlation.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <cmath>
#include <set>

using namespace itest;
namespace cam = dev::camera;

namespace {

/// The pixel shift (image x, image y) a stage displacement (dx, dy) mm makes through `g`.
void socketShiftPx(const cam::CameraGeometry& g, double dxMm, double dyMm, double* sx, double* sy)
{
    double exX, exY, eyX, eyY;
    g.axes(&exX, &exY, &eyX, &eyY);
    const double px2 = g.pixelUm * g.pixelUm * 1e-6;
    *sx = (dxMm * exX + dyMm * exY) / px2;
    *sy = (dxMm * eyX + dyMm * eyY) / px2;
}

cam::Frame socketTiff(const QString& path, std::string* description = nullptr)
{
    cam::Frame f;
    motion::msg::Message error;
    EXPECT_TRUE(cam::readTiff(path.toStdString(), &f, description, &error)) << error;
    return f;
}

/// A plan of `cols` × `rows` tiles of 256 × 256 px at 1 µm, 15 % overlap, written by the CLI.
QString socketPlan(const QTemporaryDir& dir, double exposureS, const char* roi)
{
    const auto made = runProgram(binary("benchpilot-cli"),
                                 {QStringLiteral("scan"), QStringLiteral("plan"), QStringLiteral("--roi"), QLatin1String(roi),
                                  QStringLiteral("--sensor"), QStringLiteral("256,256"), QStringLiteral("--sensor-um"), QStringLiteral("10"),
                                  QStringLiteral("--mag"), QStringLiteral("10"), QStringLiteral("--overlap"), QStringLiteral("0.15"),
                                  QStringLiteral("--exposure"), QString::number(exposureS)});
    EXPECT_EQ(made.exitCode, 0) << made.describe();
    const QString plan = dir.filePath(QStringLiteral("p.scan.json"));
    motion::msg::Message error;
    EXPECT_TRUE(dev::files::writeAtomically(plan, made.out.toStdString(), &error)) << error;
    return plan;
}

dev::files::scan::RunLog socketRunLog(const QString& folder)
{
    std::string text;
    motion::msg::Message error;
    EXPECT_TRUE(dev::files::readText(QDir(folder).filePath(QLatin1String(dev::files::scan::kRunLogFile)), &text, &error)) << error;
    const auto log = dev::files::scan::parseRunLog(text);
    EXPECT_TRUE(log.log) << text;
    return log.log ? *log.log : dev::files::scan::RunLog{};
}

} // namespace

TEST(CameraSocketCli, ASnapOverThePtyIsTakenAtTheStagesTrueWorkPoint)
{
    QTemporaryDir dir;
    const QString socket = dir.filePath(QStringLiteral("cam"));
    PtySimulator sim;
    ASSERT_TRUE(sim.start(QStringLiteral("stage"), 4,
                          {QStringLiteral("--camera-socket"), socket, QStringLiteral("--camera-sensor"), QStringLiteral("256,256"),
                           QStringLiteral("--camera-pixel-um"), QStringLiteral("2"), QStringLiteral("--camera-seed"), QStringLiteral("11")}))
        << qPrintable(sim.error());
    auto cli = [&](const QStringList& args) { return runProgram(binary("benchpilot-cli"), QStringList{QStringLiteral("--port"), sim.link()} + args, 60000); };
    ASSERT_EQ(cli({QStringLiteral("home")}).exitCode, 0);
    // Far from home the simulated stage's pitch error puts the work point tens of µm off the reading.
    ASSERT_EQ(cli({QStringLiteral("move"), QStringLiteral("X=80"), QStringLiteral("Y=85")}).exitCode, 0);
    const QString file = dir.filePath(QStringLiteral("snap.tif"));
    const auto snap = cli({QStringLiteral("--json"), QStringLiteral("camera"), QStringLiteral("snap"), QStringLiteral("--camera"),
                           QStringLiteral("sim:") + socket, QStringLiteral("--out"), file, QStringLiteral("--exposure-ms"), QStringLiteral("5")});
    ASSERT_EQ(snap.exitCode, 0) << snap.describe();
    const QJsonObject o = lastJson(snap.out);
    EXPECT_EQ(o.value(QStringLiteral("camera")).toString(), QStringLiteral("sim:") + socket);
    EXPECT_EQ(o.value(QStringLiteral("width")).toInt(), 256);
    const double readX = o.value(QStringLiteral("measured_mm")).toArray().at(0).toDouble();
    const double readY = o.value(QStringLiteral("measured_mm")).toArray().at(1).toDouble();
    ASSERT_NEAR(readX, 80, 0.01);
    const cam::Frame got = socketTiff(file);

    // Where the same stage's work point truly is when it reads (80, 85): the in-process simulator's.
    SimSession session(dev::proto::DeviceKind::Stage, kUnpaced);
    ASSERT_TRUE(session.connect() && session.homeAll());
    session.link.host().setTimeScale(10);
    ASSERT_FALSE(session.call([&](auto cb) { session.client.move({{0, 80.0}, {1, 85.0}}, false, 20, cb); }, 30000));
    ASSERT_TRUE(session.waitStill(30000));
    const dev::sim::SimMachine& m = session.link.machine();
    const double offX = m.workPointLogical(0) - m.measuredLogical(0), offY = m.workPointLogical(1) - m.measuredLogical(1);
    ASSERT_GT(std::hypot(offX, offY) * 1e3, 20.0) << "the simulated stage has a pitch error to show";

    cam::CameraGeometry g;
    g.sensorWidthPx = g.sensorHeightPx = 256;
    g.pixelUm = 2;
    const cam::Specimen specimen(cam::SpecimenKind::Slide, 11);
    const cam::Frame atReading = cam::renderSimFrame(specimen, g, cam::SimOptics{}, readX, readY, 5, 11);
    const camtest::Shift sh = camtest::phaseCorrelate(atReading, got);
    double wantX, wantY;
    socketShiftPx(g, offX, offY, &wantX, &wantY);
    if (std::getenv("BP_CAMERA_TEST_TRACE"))
        std::printf("snap found %.2f %.2f px, the work point's offset %.2f %.2f px\n", sh.x, sh.y, wantX, wantY);
    EXPECT_NEAR(sh.x, wantX, 1.0);
    EXPECT_NEAR(sh.y, wantY, 1.0);
    EXPECT_GT(std::hypot(sh.x, sh.y), 10.0) << "the image is the true work point's, not the grating's";
}

TEST(CameraSocketCli, AScansNeighbouringImagesAgreeWithTheirMeasuredPositions)
{
    QTemporaryDir dir;
    const QString socket = dir.filePath(QStringLiteral("cam"));
    PtySimulator sim;
    ASSERT_TRUE(sim.start(QStringLiteral("stage"), 4, {QStringLiteral("--camera-socket"), socket, QStringLiteral("--camera-seed"), QStringLiteral("11")}))
        << qPrintable(sim.error());
    const QString plan = socketPlan(dir, 0.01, "20,20,20.4,20.4");
    const QString out = dir.filePath(QStringLiteral("run"));
    const auto run = runProgram(binary("benchpilot-cli"),
                                {QStringLiteral("--port"), sim.link(), QStringLiteral("--json"), QStringLiteral("scan"), QStringLiteral("run"), plan,
                                 QStringLiteral("--camera"), QStringLiteral("sim:") + socket, QStringLiteral("--out"), out, QStringLiteral("--home")},
                                120000);
    ASSERT_EQ(run.exitCode, 0) << run.describe();
    const auto log = socketRunLog(out);
    ASSERT_EQ(log.records.size(), 4u);

    cam::CameraGeometry g;
    g.sensorWidthPx = g.sensorHeightPx = 256;
    g.pixelUm = 1;
    std::vector<cam::Frame> frames;
    for (std::size_t i = 0; i < 4; ++i) {
        EXPECT_EQ(cam::fileSha256(QDir(out).filePath(QString::fromStdString(log.images[i].file)).toStdString()).value_or(""), log.images[i].sha256);
        std::string description;
        frames.push_back(socketTiff(QDir(out).filePath(QString::fromStdString(log.images[i].file)), &description));
        EXPECT_NE(description.find(("\"camera\":\"sim:" + socket + "\"").toStdString()), std::string::npos) << description;
        EXPECT_EQ(frames.back().width, 256);
    }
    // Every pair of neighbours (the tiles sit 0.2176 mm apart in X or Y): registration
    // agrees with the measured positions within a pixel.
    int pairs = 0;
    for (std::size_t a = 0; a < 4; ++a)
        for (std::size_t b = 0; b < 4; ++b) {
            const double dx = log.records[b].measuredMm[0] - log.records[a].measuredMm[0];
            const double dy = log.records[b].measuredMm[1] - log.records[a].measuredMm[1];
            const bool neighbours = (std::fabs(dx) > 0.1 && std::fabs(dy) < 0.05 && dx > 0) || (std::fabs(dy) > 0.1 && std::fabs(dx) < 0.05 && dy > 0);
            if (!neighbours)
                continue;
            double wantX, wantY;
            socketShiftPx(g, dx, dy, &wantX, &wantY);
            const camtest::Shift s = camtest::phaseCorrelate(frames[a], frames[b]);
            EXPECT_NEAR(s.x, wantX, 1.0) << a << "->" << b;
            EXPECT_NEAR(s.y, wantY, 1.0) << a << "->" << b;
            ++pairs;
        }
    EXPECT_EQ(pairs, 4);
}

TEST(CameraSocketCli, ACameraThatIsNotThereIsNamedAndNothingIsWritten)
{
    QTemporaryDir dir;
    PtySimulator sim;
    ASSERT_TRUE(sim.start(QStringLiteral("stage"), 4)) << qPrintable(sim.error());
    const QString nobody = dir.filePath(QStringLiteral("nobody"));
    const QString file = dir.filePath(QStringLiteral("x.tif"));
    const auto r = runProgram(binary("benchpilot-cli"), {QStringLiteral("--port"), sim.link(), QStringLiteral("camera"), QStringLiteral("snap"),
                                                         QStringLiteral("--camera"), QStringLiteral("sim:") + nobody, QStringLiteral("--out"), file});
    EXPECT_NE(r.exitCode, 0) << r.describe();
    EXPECT_TRUE(r.err.contains(QStringLiteral("no simulated camera is served at ") + nobody)) << r.describe();
    EXPECT_FALSE(QFile::exists(file));
    // benchpilot-sim chose the specimen: one asked of the CLI is refused, not ignored.
    const auto specimen = runProgram(binary("benchpilot-cli"), {QStringLiteral("--port"), sim.link(), QStringLiteral("camera"), QStringLiteral("snap"),
                                                                QStringLiteral("--camera"), QStringLiteral("sim:") + nobody, QStringLiteral("--specimen"),
                                                                QStringLiteral("grid-plate"), QStringLiteral("--out"), file});
    EXPECT_EQ(specimen.exitCode, 1) << specimen.describe();
    EXPECT_TRUE(specimen.err.contains(QStringLiteral("--specimen"))) << specimen.describe();
    const auto list = runProgram(binary("benchpilot-cli"), {QStringLiteral("--json"), QStringLiteral("camera"), QStringLiteral("list"), QStringLiteral("--available")});
    ASSERT_EQ(list.exitCode, 0) << list.describe();
    EXPECT_TRUE(list.out.contains(QStringLiteral("\"source\":\"sim:PATH\""))) << "offered: " << list.out.toStdString();
    // The simulator refuses a camera socket on a path that is a file, and leaves the file.
    QFile plain(dir.filePath(QStringLiteral("notes")));
    ASSERT_TRUE(plain.open(QIODevice::WriteOnly));
    plain.close();
    PtySimulator refused;
    EXPECT_FALSE(refused.start(QStringLiteral("stage"), 4, {QStringLiteral("--camera-socket"), plain.fileName()}));
    EXPECT_TRUE(refused.error().contains(QStringLiteral("is not a socket"))) << qPrintable(refused.error());
    EXPECT_TRUE(QFile::exists(plain.fileName()));
}

TEST(CameraSocketCli, AScanWhoseCameraGoesStopsWithTheReasonKeepsEveryTileAndResumes)
{
    QTemporaryDir dir;
    const QString socket = dir.filePath(QStringLiteral("cam"));
    PtySimulator stage;
    ASSERT_TRUE(stage.start(QStringLiteral("stage"), 4)) << qPrintable(stage.error());
    // The camera from a second simulator, so that it can go while the stage stays.
    auto camera = std::make_unique<PtySimulator>();
    const QStringList cameraArgs{QStringLiteral("--camera-socket"), socket};
    ASSERT_TRUE(camera->start(QStringLiteral("stage"), 4, cameraArgs)) << qPrintable(camera->error());
    // 3 × 3 tiles exposed 0.3 s each: the camera goes long before the last.
    const QString plan = socketPlan(dir, 0.3, "20,20,20.6,20.6");
    const QString out = dir.filePath(QStringLiteral("run"));
    const QStringList runArgs{QStringLiteral("--port"), stage.link(), QStringLiteral("--json"), QStringLiteral("scan"), QStringLiteral("run"), plan,
                              QStringLiteral("--camera"), QStringLiteral("sim:") + socket, QStringLiteral("--out"), out, QStringLiteral("--home")};
    QProcess p;
    p.start(binary("benchpilot-cli"), runArgs);
    ASSERT_TRUE(p.waitForStarted());
    QByteArray seen;
    ASSERT_TRUE(waitFor(
        [&] {
            seen += p.readAllStandardOutput();
            return seen.count("\"image\"") >= 2;
        },
        90000))
        << seen.toStdString();
    camera.reset();  // SIGTERM: the camera's simulator stops, the stage's does not
    EXPECT_FALSE(QFile::exists(socket)) << "the simulator removes its socket when it stops";
    const ProgramRun stopped = collectRun(p, p.waitForFinished(60000));
    EXPECT_NE(stopped.exitCode, 0) << stopped.describe();
    EXPECT_TRUE(stopped.err.contains(QStringLiteral("the simulated camera at ") + socket)) << stopped.describe();
    const auto kept = socketRunLog(out);
    ASSERT_GE(kept.records.size(), 2u);
    ASSERT_LT(kept.records.size(), 9u);
    for (std::size_t i = 0; i < kept.records.size(); ++i)
        EXPECT_EQ(cam::fileSha256(QDir(out).filePath(QString::fromStdString(kept.images[i].file)).toStdString()).value_or(""), kept.images[i].sha256);
    EXPECT_EQ(QDir(out).entryList({QStringLiteral("*.part")}, QDir::Files).size(), 0);

    // The camera back: the run goes on from where it stopped, each tile once.
    PtySimulator again;
    ASSERT_TRUE(again.start(QStringLiteral("stage"), 4, cameraArgs)) << qPrintable(again.error());
    const auto resumed = runProgram(binary("benchpilot-cli"), runArgs, 120000);
    ASSERT_EQ(resumed.exitCode, 0) << resumed.describe();
    const auto all = socketRunLog(out);
    ASSERT_EQ(all.records.size(), 9u);
    std::set<int> tiles;
    for (std::size_t i = 0; i < all.records.size(); ++i) {
        tiles.insert(all.records[i].target);
        EXPECT_EQ(cam::fileSha256(QDir(out).filePath(QString::fromStdString(all.images[i].file)).toStdString()).value_or(""), all.images[i].sha256);
    }
    EXPECT_EQ(tiles.size(), 9u) << "each tile once";
}
