// A scan that takes an image at every tile with the simulated camera on the simulated
// stage: the images agree with the measured positions (registration between neighbours),
// a wrong image_y or rotation shows, the images follow the TRUE work point, a killed run
// resumes with every image whole and none twice, and a camera that fails stops the run
// keeping everything taken.
#include "device/camera/scan_camera.h"
#include "device/camera/sim_camera.h"
#include "device/camera/tile_tiff.h"
#include "device/files/scan_run_log.h"
#include "device/files/text_file.h"
#include "device/jobs/scan_runner.h"

#include "integration/sim_session.h"
#include "phase_correlation.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <memory>
#include <set>

using namespace itest;
using dev::jobs::ScanRunner;
using motion::scan::ScanPlan;
namespace cam = dev::camera;

namespace {

/// 4 × 3 tiles of a 256 × 256 px sensor at 1 µm a pixel (10 µm pitch, 10×), 15 % overlap.
ScanPlan twelveTiles()
{
    ScanPlan p;
    p.name = "camera";
    p.camera.source = motion::scan::FieldSource::Sensor;
    p.camera.sensorWidthPx = p.camera.sensorHeightPx = 256;
    p.camera.sensorPixelUm = 10;
    p.camera.magnification = 10;
    const double field = 0.256, step = field * 0.85;
    // Where the simulated stage's pitch error changes slowly (seed 002's curves: about
    // 1 µm per mm there), so one step's worth of it stays well inside a pixel.
    p.region.cornerA = {20, 20};
    p.region.cornerB = {20 + field + 2.9 * step, 20 + field + 1.9 * step};
    p.overlapX = p.overlapY = 0.15;
    p.speedMmS = 10;
    p.settleS = 0.02;
    p.exposureS = 0.01;
    return p;
}

struct CameraScan {
    CameraScan() : session(dev::proto::DeviceKind::Stage, kUnpaced)
    {
        dev::sim::SimMachine* m = &session.link.machine();
        cam::SimCameraSettings s;
        s.seed = 11;
        simCamera = std::make_unique<cam::SimCamera>(
            [m]() -> std::optional<cam::WorkPoint> {
                return cam::WorkPoint{m->workPointLogical(0), m->workPointLogical(1), m->timeUs()};
            },
            s);
    }
    bool ready()
    {
        if (!session.connect() || !session.homeAll())
            return false;
        session.link.host().setTimeScale(10);
        return true;
    }
    std::unique_ptr<ScanRunner> runner(cam::Camera* camera = nullptr)
    {
        scanCamera = std::make_unique<cam::ScanCamera>(camera ? camera : simCamera.get());
        auto r = std::make_unique<ScanRunner>(&session.client);
        r->setCamera(scanCamera.get());
        return r;
    }
    SimSession session;
    std::unique_ptr<cam::SimCamera> simCamera;
    std::unique_ptr<cam::ScanCamera> scanCamera;
    QTemporaryDir dir;
};

bool waitState(ScanRunner& r, ScanRunner::State s, int ms = 60000)
{
    return waitFor([&] { return r.state() == s; }, ms);
}

struct LoggedTile {
    motion::PositionRecord record;
    dev::files::scan::TileImageRef image;
};

std::vector<LoggedTile> readLog(const QString& path)
{
    std::string text;
    motion::msg::Message error;
    EXPECT_TRUE(dev::files::readText(path, &text, &error)) << error;
    const auto log = dev::files::scan::parseRunLog(text);
    EXPECT_TRUE(log.log);
    std::vector<LoggedTile> out;
    if (log.log)
        for (std::size_t i = 0; i < log.log->records.size(); ++i)
            out.push_back({log.log->records[i], log.log->images[i]});
    return out;
}

cam::Frame readFrame(const QString& folder, const std::string& file)
{
    cam::Frame f;
    motion::msg::Message error;
    EXPECT_TRUE(cam::readTiff(QDir(folder).filePath(QString::fromStdString(file)).toStdString(), &f, nullptr, &error)) << error;
    return f;
}

/// The worst disagreement (px) over every pair of neighbours between the shift registration
/// finds and the one the measured positions give through `geometry`.
double worstMismatchPx(const ScanRunner& r, const QString& folder, const cam::CameraGeometry& geometry, int* pairs)
{
    double exX, exY, eyX, eyY;
    geometry.axes(&exX, &exY, &eyX, &eyY);
    const double px2 = geometry.pixelUm * geometry.pixelUm * 1e-6;
    const auto& tiles = r.layout().tiles;
    double worst = 0;
    *pairs = 0;
    for (std::size_t a = 0; a < tiles.size(); ++a)
        for (std::size_t b = 0; b < tiles.size(); ++b) {
            const bool right = tiles[b].row == tiles[a].row && tiles[b].col == tiles[a].col + 1;
            const bool below = tiles[b].col == tiles[a].col && tiles[b].row == tiles[a].row + 1;
            if (!right && !below)
                continue;
            const auto& ra = r.records()[a];
            const auto& rb = r.records()[b];
            const double dx = rb.measuredMm[0] - ra.measuredMm[0], dy = rb.measuredMm[1] - ra.measuredMm[1];
            const double tx = (dx * exX + dy * exY) / px2, ty = (dx * eyX + dy * eyY) / px2;
            const camtest::Shift s = camtest::phaseCorrelate(readFrame(folder, r.image(static_cast<int>(a)).file),
                                                             readFrame(folder, r.image(static_cast<int>(b)).file));
            if (std::getenv("BP_CAMERA_TEST_TRACE"))
                std::printf("%zu->%zu found %.2f %.2f ncc %.2f expected %.1f %.1f (ncc there %.2f)\n", a, b, s.x, s.y, s.ncc, tx, ty,
                            camtest::overlapNcc(camtest::grey(readFrame(folder, r.image(static_cast<int>(a)).file)),
                                                camtest::grey(readFrame(folder, r.image(static_cast<int>(b)).file)), 256, 256,
                                                static_cast<int>(std::lround(tx)), static_cast<int>(std::lround(ty))));
            worst = std::max({worst, std::fabs(s.x - tx), std::fabs(s.y - ty)});
            ++*pairs;
        }
    return worst;
}

} // namespace

TEST(CameraScan, TwelveTilesAgreeWithTheirMeasuredPositionsAndAWrongGeometryShows)
{
    CameraScan s;
    ASSERT_TRUE(s.ready()) << s.session.linkErrors.join(QLatin1Char(' ')).toStdString();
    auto r = s.runner();
    const ScanPlan plan = twelveTiles();
    motion::msg::Message error;
    ASSERT_TRUE(r->prepare(plan, s.dir.path(), false, &error)) << error;
    ASSERT_EQ(r->totalTiles(), 12);
    std::vector<motion::msg::Message> problems;
    QObject::connect(r.get(), &ScanRunner::problem, [&](const motion::msg::Message& m) { problems.push_back(m); });
    ASSERT_TRUE(r->start(&error)) << error;
    ASSERT_TRUE(waitState(*r, ScanRunner::State::Finished)) << (problems.empty() ? motion::msg::Message{} : problems.back());
    for (const motion::msg::Message& m : problems)
        ADD_FAILURE() << "problem: " << m;

    // Every tile has its image, logged with the checksum of the file that is there.
    const auto logged = readLog(r->logPath());
    ASSERT_EQ(logged.size(), 12u);
    std::set<int> tiles;
    for (const auto& t : logged) {
        tiles.insert(t.record.target);
        EXPECT_EQ(t.image.file, t.record.label);
        EXPECT_EQ(cam::fileSha256(QDir(s.dir.path()).filePath(QString::fromStdString(t.image.file)).toStdString()).value_or(""),
                  t.image.sha256);
    }
    EXPECT_EQ(tiles.size(), 12u) << "each tile once";
    // The file says where it was taken.
    cam::Frame f;
    std::string description;
    ASSERT_TRUE(cam::readTiff(QDir(s.dir.path()).filePath(QString::fromStdString(logged[3].image.file)).toStdString(), &f, &description, &error));
    EXPECT_EQ(f.width, 256);
    EXPECT_NEAR(f.pixelUm, 1.0, 1e-4);
    EXPECT_NE(description.find("\"measured_mm\":["), std::string::npos);

    // Registration between neighbours agrees with the measured positions within a pixel…
    const cam::CameraGeometry truth = cam::geometryOfPlan(plan);
    int pairs = 0;
    EXPECT_LE(worstMismatchPx(*r, s.dir.path(), truth, &pairs), 1.0);
    EXPECT_EQ(pairs, 3 * 3 + 4 * 2);
    // … and a plan that has image_y or the rotation wrong does not.
    cam::CameraGeometry flipped = truth;
    flipped.imageYAlongMinusY = false;
    EXPECT_GT(worstMismatchPx(*r, s.dir.path(), flipped, &pairs), 10.0);
    cam::CameraGeometry turned = truth;
    turned.rotationDeg = 3;
    EXPECT_GT(worstMismatchPx(*r, s.dir.path(), turned, &pairs), 5.0);
}

TEST(CameraScan, ImagesFollowTheTrueWorkPointNotTheGrating)
{
    CameraScan s;
    ASSERT_TRUE(s.ready());
    // Far from home the simulated stage's pitch error puts the work point tens of µm off the reading.
    ASSERT_FALSE(s.session.call([&](auto cb) { s.session.client.move({{0, 80.0}, {1, 85.0}}, false, 20, cb); }, 30000));
    ASSERT_TRUE(s.session.waitStill(30000));
    dev::sim::SimMachine& m = s.session.link.machine();
    const double workX = m.workPointLogical(0), workY = m.workPointLogical(1);
    const double readX = m.measuredLogical(0), readY = m.measuredLogical(1);
    const double offUm = std::hypot(workX - readX, workY - readY) * 1e3;
    ASSERT_GT(offUm, 20.0) << "the simulated stage has a pitch error to show";

    cam::CameraGeometry g;
    g.sensorWidthPx = g.sensorHeightPx = 256;
    g.pixelUm = 2;
    s.simCamera->open();
    std::optional<cam::Frame> got;
    QObject::connect(s.simCamera.get(), &cam::Camera::captured, [&](std::uint64_t, const cam::Frame& f) { got = f; });
    cam::CaptureRequest req;
    req.id = 1;
    req.geometry = g;
    s.simCamera->capture(req);
    ASSERT_TRUE(waitFor([&] { return got.has_value(); }, 10000));
    // What the grating says against what the camera saw: the offset is the work point's.
    const cam::Specimen specimen(cam::SpecimenKind::Slide, 11);
    const cam::Frame atReading = cam::renderSimFrame(specimen, g, cam::SimOptics{}, readX, readY, got->exposureMs, 11);
    const camtest::Shift sh = camtest::phaseCorrelate(atReading, *got);
    double exX, exY, eyX, eyY;
    g.axes(&exX, &exY, &eyX, &eyY);
    const double px2 = g.pixelUm * g.pixelUm * 1e-6;
    const double dx = workX - readX, dy = workY - readY;
    EXPECT_NEAR(sh.x, (dx * exX + dy * exY) / px2, 1.0);
    EXPECT_NEAR(sh.y, (dx * eyX + dy * eyY) / px2, 1.0);
    EXPECT_GT(std::hypot(sh.x, sh.y), 10.0);
}

TEST(CameraScan, AKilledRunResumesWithEveryImageWholeAndNoneTakenTwice)
{
    CameraScan s;
    ASSERT_TRUE(s.ready());
    motion::msg::Message error;
    {
        auto first = s.runner();
        ASSERT_TRUE(first->prepare(twelveTiles(), s.dir.path(), false, &error)) << error;
        ASSERT_TRUE(first->start(&error)) << error;
        ASSERT_TRUE(waitFor([&] { return first->takenTiles() >= 5; }, 30000));
        // The program dies here: no abort, no goodbye.
    }
    s.session.client.stop(0);
    ASSERT_TRUE(s.session.waitStill());
    const auto before = readLog(QDir(s.dir.path()).filePath(QLatin1String(dev::files::scan::kRunLogFile)));
    ASSERT_GE(before.size(), 5u);
    // By hand: one image deleted, one cut short.
    const QString deleted = QDir(s.dir.path()).filePath(QString::fromStdString(before[1].image.file));
    const QString cut = QDir(s.dir.path()).filePath(QString::fromStdString(before[3].image.file));
    ASSERT_TRUE(QFile::remove(deleted));
    QFile c(cut);
    ASSERT_TRUE(c.open(QIODevice::ReadWrite));
    ASSERT_TRUE(c.resize(c.size() / 2));
    c.close();

    auto second = s.runner();
    ASSERT_TRUE(second->prepare(twelveTiles(), s.dir.path(), false, &error)) << error;
    EXPECT_EQ(second->takenTiles(), static_cast<int>(before.size()) - 2);
    EXPECT_FALSE(second->isTaken(before[1].record.target));
    EXPECT_FALSE(second->isTaken(before[3].record.target));
    std::vector<int> now;
    QObject::connect(second.get(), &ScanRunner::tileTaken, [&](int t) { now.push_back(t); });
    ASSERT_TRUE(second->start(&error)) << error;
    ASSERT_TRUE(waitState(*second, ScanRunner::State::Finished));
    EXPECT_EQ(static_cast<int>(now.size()), 12 - (static_cast<int>(before.size()) - 2));
    EXPECT_NE(std::find(now.begin(), now.end(), before[1].record.target), now.end()) << "the deleted image is taken again";
    EXPECT_NE(std::find(now.begin(), now.end(), before[3].record.target), now.end()) << "the cut one too";

    const auto after = readLog(second->logPath());
    ASSERT_EQ(after.size(), 12u) << "every tile once";
    std::map<int, int> count;
    for (const auto& t : after) {
        ++count[t.record.target];
        EXPECT_EQ(cam::fileSha256(QDir(s.dir.path()).filePath(QString::fromStdString(t.image.file)).toStdString()).value_or(""),
                  t.image.sha256)
            << t.image.file << " tile " << t.record.target << " (deleted " << before[1].record.target << ", cut "
            << before[3].record.target << ", taken before " << before.size() << ")";
    }
    EXPECT_EQ(count.size(), 12u);
    EXPECT_EQ(QDir(s.dir.path()).entryList({QStringLiteral("*.part")}, QDir::Files).size(), 0);
}

namespace {

/// A camera that answers as told: frames of a given size, or a failure.
class FakeCamera : public cam::Camera {
public:
    int width = 256, height = 256;
    bool fail = false;
    QString source() const override { return QStringLiteral("command:fake-capture"); }
    cam::Capabilities capabilities() const override { return {}; }
    void open() override { m_open = true; }
    void close() override { m_open = false; }
    bool isOpen() const override { return m_open; }
    void setExposureMs(double) override {}
    double exposureMs() const override { return 5; }
    void capture(const cam::CaptureRequest& r) override
    {
        QTimer::singleShot(0, this, [this, r] {
            if (fail || r.tile >= failFrom) {
                emit failed(r.id, motion::msg::Problem("", motion::msg::make("camera.command.failed", {motion::msg::verbatim("command", "fake-capture"),
                                                                                    motion::msg::integer("code", 1, motion::msg::Unit::None),
                                                                                    motion::msg::verbatim("stderr", "no camera found")})));
                return;
            }
            cam::Frame f;
            f.width = width;
            f.height = height;
            f.format = cam::PixelFormat::Grey8;
            f.bitDepth = 8;
            f.pixels.assign(static_cast<std::size_t>(width * height), static_cast<std::uint8_t>(r.tile));
            emit captured(r.id, f);
        });
    }
    int failFrom = 1000;

private:
    bool m_open = false;
};

} // namespace

TEST(CameraScan, AFailingCameraStopsTheRunAndKeepsEveryTileTaken)
{
    CameraScan s;
    ASSERT_TRUE(s.ready());
    FakeCamera fake;
    fake.failFrom = 4;
    auto r = s.runner(&fake);
    motion::msg::Message error;
    ASSERT_TRUE(r->prepare(twelveTiles(), s.dir.path(), false, &error)) << error;
    std::vector<motion::msg::Message> problems;
    QObject::connect(r.get(), &ScanRunner::problem, [&](const motion::msg::Message& m) { problems.push_back(m); });
    ASSERT_TRUE(r->start(&error)) << error;
    ASSERT_TRUE(waitState(*r, ScanRunner::State::Stopped));
    ASSERT_FALSE(problems.empty());
    EXPECT_EQ(problems.back().id, "scan.run.camera_failed");
    EXPECT_NE(motion::msg::debugString(problems.back()).find("no camera found"), std::string::npos) << "the command's own words";
    ASSERT_TRUE(waitFor([&] { return s.scanCamera->pendingWrites() == 0; }, 10000));
    EXPECT_EQ(r->takenTiles(), 4);
    EXPECT_EQ(readLog(r->logPath()).size(), 4u) << "the tiles before it are kept";
    EXPECT_FALSE(r->isTaken(4));
}

TEST(CameraScan, ACameraWhoseSensorIsNotThePlansIsRefusedAtTheFirstTile)
{
    CameraScan s;
    ASSERT_TRUE(s.ready());
    FakeCamera fake;
    fake.width = 640;
    fake.height = 480;
    auto r = s.runner(&fake);
    motion::msg::Message error;
    ASSERT_TRUE(r->prepare(twelveTiles(), s.dir.path(), false, &error)) << error;
    std::vector<motion::msg::Message> problems;
    QObject::connect(r.get(), &ScanRunner::problem, [&](const motion::msg::Message& m) { problems.push_back(m); });
    ASSERT_TRUE(r->start(&error)) << error;
    ASSERT_TRUE(waitState(*r, ScanRunner::State::Stopped));
    ASSERT_FALSE(problems.empty());
    const std::string text = motion::msg::debugString(problems.back());
    EXPECT_NE(text.find("camera.sensor_mismatch"), std::string::npos) << text;
    EXPECT_NE(text.find("640"), std::string::npos) << text;
    EXPECT_EQ(r->takenTiles(), 0);
    EXPECT_EQ(QDir(s.dir.path()).entryList({QStringLiteral("*.tif"), QStringLiteral("*.part")}, QDir::Files).size(), 0) << "nothing half-written";
}
