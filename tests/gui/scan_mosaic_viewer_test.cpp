// The mosaic viewer on the real widgets: zooming picks the pyramid level and reads only
// the blocks in view, drag and the arrow keys pan, T and Q toggle the overlays, and a
// double-click moves the simulated stage so that the point is under the objective —
// at a tile's centre, exactly where the run log says that tile was taken; far away only
// when the operator says yes; never when the stage is not homed or the point lies beyond
// its soft limits. After a stitch the Mosaic tab shows the mosaic in the viewer.
#include "device/camera/scan_camera.h"
#include "device/camera/sim_render.h"
#include "device/camera/specimen.h"
#include "device/camera/tile_tiff.h"
#include "device/files/scan_exports.h"
#include "device/files/scan_run_log.h"
#include "device/link/simulated_link.h"
#include "gui_window.h"
#include "imaging/stitch.h"
#include "widgets/report/stitch_quality_drawing.h"
#include "widgets/scan/mosaic_canvas.h"
#include "widgets/scan/mosaic_stage_frame.h"
#include "widgets/scan/mosaic_viewer.h"
#include "widgets/scan/scan_screen.h"
#include "widgets/scan/stitch_panel.h"
#include "widgets/scan/stitch_quality_map.h"

#include <QApplication>
#include <QDir>
#include <QFile>
#include <QPushButton>
#include <QTemporaryDir>
#include <QTest>
#include <QToolButton>
#include <QWheelEvent>

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

using guitest::waitFor;

namespace {

/// A sensor of `px` × `px` at 1 µm a pixel (or the simulated camera's 0.65 µm at 2048).
motion::scan::ScanPlan viewerPlan(int px)
{
    motion::scan::ScanPlan p;
    p.name = "viewer";
    p.camera.source = motion::scan::FieldSource::Sensor;
    p.camera.sensorWidthPx = p.camera.sensorHeightPx = px;
    p.camera.sensorPixelUm = px >= 2048 ? 6.5 : 10;
    p.camera.magnification = 10;
    return p;
}

struct ViewerScan {
    motion::scan::ScanPlan plan;
    std::vector<Eigen::Vector2d> stageMm;  ///< where each tile was taken, as logged
    double stepMm = 0;
};

/// The folder a camera scan leaves: `cols` × `rows` tiles, 15 % overlap, from (x0, y0) mm
/// rightwards and downwards (stage −Y), rendered from the simulated slide.
/// `offUm` (x, y) is how far the grating's log is off where the tile truly was, per tile.
ViewerScan writeViewerScan(const QString& folder, int cols, int rows, int px = 256, double x0 = 20, double y0 = 20,
                           std::function<Eigen::Vector2d(int tile)> offUm = {})
{
    ViewerScan s;
    s.plan = viewerPlan(px);
    const dev::camera::CameraGeometry g = dev::camera::geometryOfPlan(s.plan);
    const dev::camera::Specimen slide(dev::camera::SpecimenKind::Slide, 3);
    std::string log = dev::files::scan::runLogHeader(s.plan.name, 1, cols * rows);
    s.stepMm = px * motion::scan::pixelAtSampleUm(s.plan.camera) / 1000 * 0.85;
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < cols; ++c) {
            const int tile = r * cols + c;
            const double x = x0 + c * s.stepMm, y = y0 - r * s.stepMm;
            const dev::camera::Frame f = dev::camera::renderSimFrame(slide, g, dev::camera::SimOptics{}, x, y, 10, 3);
            motion::PositionRecord rec;
            rec.target = tile;
            rec.label = QStringLiteral("tile_%1.tif").arg(tile + 1, 3, 10, QLatin1Char('0')).toStdString();
            const Eigen::Vector2d off = offUm ? Eigen::Vector2d(offUm(tile) / 1000) : Eigen::Vector2d::Zero();
            rec.plannedMm = rec.commandedMm = {x, y};
            rec.measuredMm = {x + off.x(), y + off.y()};
            dev::camera::TileMetadata meta;
            meta.tile = tile;
            meta.label = rec.label;
            meta.measuredMm = rec.measuredMm;
            std::string sha;
            motion::msg::Message error;
            EXPECT_TRUE(dev::camera::writeTileTiff(QDir(folder).filePath(QString::fromStdString(rec.label)).toStdString(), f, meta, &sha, &error));
            log += dev::files::scan::runLogLine(rec, {rec.label, sha});
            s.stageMm.emplace_back(x + off.x(), y + off.y());
        }
    QFile file(QDir(folder).filePath(QLatin1String(dev::files::scan::kRunLogFile)));
    EXPECT_TRUE(file.open(QIODevice::WriteOnly));
    file.write(QByteArray::fromStdString(log));
    return s;
}

/// Stitched here (not through the job) with small TIFF tiles and levels, so a mosaic of a
/// few hundred pixels has a pyramid of several levels.
std::optional<imaging::StitchResult> stitchViewerScan(const QString& folder, const ViewerScan& s, const QString& mosaic)
{
    std::vector<imaging::StitchTile> tiles;
    for (std::size_t i = 0; i < s.stageMm.size(); ++i) {
        const QString name = QStringLiteral("tile_%1.tif").arg(int(i) + 1, 3, 10, QLatin1Char('0'));
        const motion::scan::Point2 p = dev::files::scan::stageToPixels(s.plan.camera, {s.stageMm[i].x(), s.stageMm[i].y()});
        tiles.push_back({name.toStdString(), QDir(folder).filePath(name).toStdString(), Eigen::Vector2d(p.xMm, p.yMm)});
    }
    imaging::StitchOptions o;
    o.mosaicPath = mosaic.toStdString();
    o.mosaic.pixelSizeUm = motion::scan::pixelAtSampleUm(s.plan.camera);
    o.mosaic.tileSize = 64;
    o.mosaic.smallestLevelPx = 128;
    o.threads = 1;
    auto r = imaging::stitch(tiles, o);
    if (!r)
        return std::nullopt;
    return r.take();
}

struct ViewerRig {
    QTemporaryDir dir;
    ViewerScan scan;
    std::optional<imaging::StitchResult> result;
    ui::MosaicViewer viewer;
    QStringList problems, notices, questions;
    bool answer = false;

    explicit ViewerRig(int cols = 4, int rows = 3)
    {
        scan = writeViewerScan(dir.path(), cols, rows);
        result = stitchViewerScan(dir.path(), scan, dir.filePath(QStringLiteral("mosaic.ome.tif")));
        QObject::connect(&viewer, &ui::MosaicViewer::problem, [this](const QString& m) { problems << m; });
        QObject::connect(&viewer, &ui::MosaicViewer::notice, [this](const QString& m) { notices << m; });
        viewer.setConfirm([this](const QString& q) {
            questions << q;
            return answer;
        });
        viewer.resize(640, 440);
        viewer.show();
        viewer.activateWindow();
        EXPECT_TRUE(QTest::qWaitForWindowActive(&viewer));
        viewer.canvas()->setFocus();
    }
    bool show() { return result && viewer.showStitch(*result, scan.plan.camera, dir.filePath(QStringLiteral("mosaic.ome.tif"))); }
    ui::MosaicCanvas* canvas() { return viewer.canvas(); }
    /// Where tile `i`'s centre is on the canvas now.
    QPoint tileCentre(int i)
    {
        const auto& t = viewer.frame().tiles()[static_cast<std::size_t>(i)];
        const QPointF m(t.topLeftPx.x() + (viewer.frame().tileWidthPx() - 1) / 2.0, t.topLeftPx.y() + (viewer.frame().tileHeightPx() - 1) / 2.0);
        return canvas()->toWidget(m).toPoint();
    }
};

void wheel(QWidget* w, QPoint at, int steps)
{
    QWheelEvent e(at, w->mapToGlobal(at), QPoint(), QPoint(0, 120 * steps), Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(w, &e);
}

} // namespace

TEST(MosaicViewer, ZoomPicksThePyramidLevelAndReadsOnlyTheBlocksInView)
{
    ViewerRig rig;
    ASSERT_TRUE(rig.show()) << rig.problems.join(QLatin1Char('\n')).toStdString();
    ui::MosaicCanvas* canvas = rig.canvas();
    ASSERT_TRUE(waitFor([&] { return canvas->width() > 300; }, 2000));
    guitest::pump(50);
    const double fitted = canvas->zoom();
    EXPECT_LT(fitted, 1.0) << "a mosaic larger than the view is fitted";
    const int fittedLevel = canvas->level();

    // Zoomed out, a coarser level; zoomed in past 1:1, the full resolution.
    for (int i = 0; i < 3; ++i)
        QTest::keyClick(canvas, Qt::Key_Minus);
    EXPECT_LT(canvas->zoom(), fitted);
    EXPECT_GT(canvas->level(), fittedLevel) << "zoom " << canvas->zoom();
    const QPoint middle(canvas->width() / 2, canvas->height() / 2);
    const QPointF under = canvas->toMosaic(middle + QPoint(40, 20));
    wheel(canvas, middle + QPoint(40, 20), 12);
    EXPECT_GT(canvas->zoom(), 2.0);
    EXPECT_EQ(canvas->level(), 0);
    const QPointF still = canvas->toMosaic(middle + QPoint(40, 20));
    EXPECT_NEAR(still.x(), under.x(), 1.0) << "the wheel zooms about the cursor";
    EXPECT_NEAR(still.y(), under.y(), 1.0);

    // Drawn at that zoom, only the blocks of the full level in view are read: a view of
    // 640 / zoom mosaic pixels crosses at most 2 × 2 of the level's 256-px blocks, of 12.
    rig.show();  // a fresh cache
    wheel(canvas, middle, 12);
    const long before = canvas->blocksRead();
    canvas->repaint();
    const long read = canvas->blocksRead() - before;
    EXPECT_GT(read, 0);
    EXPECT_LE(read, 4);
    EXPECT_LE(canvas->cachedBlocks(), 4);
    canvas->repaint();
    EXPECT_EQ(canvas->blocksRead() - before, read) << "a second paint reads from the cache";

    QTest::keyClick(canvas, Qt::Key_F);
    EXPECT_DOUBLE_EQ(canvas->zoom(), fitted);
    EXPECT_TRUE(rig.problems.isEmpty()) << rig.problems.join(QLatin1Char('\n')).toStdString();
}

TEST(MosaicViewer, DragAndArrowKeysPanAndTheOverlaysToggle)
{
    ViewerRig rig;
    ASSERT_TRUE(rig.show());
    ui::MosaicCanvas* canvas = rig.canvas();
    guitest::pump(50);
    canvas->zoomBy(3);
    const QPointF c0 = canvas->centre();
    const QPoint from(200, 200);
    QTest::mousePress(canvas, Qt::LeftButton, {}, from);
    QTest::mouseMove(canvas, from + QPoint(60, -30));
    QTest::mouseRelease(canvas, Qt::LeftButton, {}, from + QPoint(60, -30));
    EXPECT_NEAR(canvas->centre().x(), c0.x() - 60 / canvas->zoom(), 0.01) << "the mosaic follows the mouse";
    EXPECT_NEAR(canvas->centre().y(), c0.y() + 30 / canvas->zoom(), 0.01);
    const QPointF c1 = canvas->centre();
    QTest::keyClick(canvas, Qt::Key_Right);
    EXPECT_GT(canvas->centre().x(), c1.x());
    EXPECT_DOUBLE_EQ(canvas->centre().y(), c1.y());

    // T and Q (and their buttons) switch the outlines and the quality overlay, and what is drawn changes.
    QTest::keyClick(canvas, Qt::Key_F);
    const QImage both = canvas->grab().toImage();
    QTest::keyClick(canvas, Qt::Key_T);
    EXPECT_FALSE(canvas->showsTiles());
    QTest::mouseClick(rig.viewer.findChild<QToolButton*>(QStringLiteral("mosaicQuality")), Qt::LeftButton);
    EXPECT_FALSE(canvas->showsQuality());
    const QImage neither = canvas->grab().toImage();
    EXPECT_NE(both, neither);
    QTest::keyClick(canvas, Qt::Key_Q);
    EXPECT_TRUE(canvas->showsQuality());
    EXPECT_TRUE(rig.viewer.findChild<QToolButton*>(QStringLiteral("mosaicQuality"))->isChecked());
    EXPECT_GT(canvas->scaleBarUm(), 0);
}

class MosaicViewerStage : public ::testing::Test {
protected:
    void SetUp() override
    {
        w = guitest::openReadyWindow({1366, 768});
        ASSERT_TRUE(w);
        auto* link = qobject_cast<dev::SimulatedLink*>(w->stage()->link());
        ASSERT_NE(link, nullptr);
        link->host().setTimeScale(10);
    }
    dev::Instrument* stage() { return w->stage()->instrument(); }
    bool home()
    {
        stage()->home(0);
        return waitFor([&] { return stage()->status().axes.size() >= 2 && stage()->status().axes[0].homed && stage()->status().axes[1].homed
                                    && !stage()->status().anyMoving(); }, 60000);
    }
    bool settledAt(const Eigen::Vector2d& mm)
    {
        return waitFor([&] { return !stage()->status().anyMoving() && std::abs(stage()->status().axes[0].commanded - mm.x()) < 1e-6
                                    && std::abs(stage()->status().axes[1].commanded - mm.y()) < 1e-6; }, 30000);
    }
    std::unique_ptr<app::MainWindow> w;
};

TEST_F(MosaicViewerStage, ADoubleClickTakesTheStageBackToWhereATileWasTaken)
{
    ViewerRig rig;
    ASSERT_TRUE(rig.show());
    rig.viewer.setStage(stage());
    guitest::pump(50);

    // Not homed: refused with why, and nothing moves.
    ASSERT_FALSE(stage()->status().axes[0].homed);
    QTest::mouseDClick(rig.canvas(), Qt::LeftButton, {}, rig.tileCentre(5));
    ASSERT_EQ(rig.problems.size(), 1);
    EXPECT_TRUE(rig.problems[0].startsWith(QLatin1String("Home the stage first"))) << rig.problems[0].toStdString();
    EXPECT_TRUE(rig.questions.isEmpty());

    ASSERT_TRUE(home());
    stage()->move({{0, rig.scan.stageMm[5].x()}, {1, rig.scan.stageMm[5].y()}}, false);
    ASSERT_TRUE(settledAt(rig.scan.stageMm[5]));
    ASSERT_TRUE(waitFor([&] { return rig.canvas()->stageMm().has_value(); }, 2000)) << "the stage's place is not drawn";
    EXPECT_NEAR(rig.canvas()->stageMm()->x(), rig.scan.stageMm[5].x(), 0.002);

    // Near (the next tile, 0.85 of a field away): no question; the stage goes to where
    // the run log says tile 7 was taken.
    QTest::mouseDClick(rig.canvas(), Qt::LeftButton, {}, rig.tileCentre(6));
    EXPECT_TRUE(rig.questions.isEmpty()) << rig.questions.join(QLatin1Char('\n')).toStdString();
    ASSERT_EQ(rig.notices.size(), 1) << rig.problems.join(QLatin1Char('\n')).toStdString();
    const double pxMm = rig.viewer.frame().pixelUm() / 1000 / rig.canvas()->zoom();  // a screen pixel, in mm
    ASSERT_TRUE(waitFor([&] { return std::abs(stage()->status().axes[0].commanded - rig.scan.stageMm[6].x()) < pxMm + 1e-4 && !stage()->status().anyMoving(); }, 30000))
        << stage()->status().axes[0].commanded;
    EXPECT_NEAR(stage()->status().axes[0].commanded, rig.scan.stageMm[6].x(), pxMm + 1e-4);
    EXPECT_NEAR(stage()->status().axes[1].commanded, rig.scan.stageMm[6].y(), pxMm + 1e-4);

    // Far (tile 1, across the mosaic): asked first; No leaves the stage where it is.
    const double x = stage()->status().axes[0].commanded, y = stage()->status().axes[1].commanded;
    rig.answer = false;
    QTest::mouseDClick(rig.canvas(), Qt::LeftButton, {}, rig.tileCentre(0));
    ASSERT_EQ(rig.questions.size(), 1);
    EXPECT_TRUE(rig.questions[0].contains(QLatin1String("farther than one camera field (0.26 mm)"))) << rig.questions[0].toStdString();
    guitest::pump(200);
    EXPECT_FALSE(stage()->status().anyMoving());
    EXPECT_DOUBLE_EQ(stage()->status().axes[0].commanded, x);
    EXPECT_DOUBLE_EQ(stage()->status().axes[1].commanded, y);
    // Yes goes there.
    rig.answer = true;
    QTest::mouseDClick(rig.canvas(), Qt::LeftButton, {}, rig.tileCentre(0));
    ASSERT_EQ(rig.questions.size(), 2);
    ASSERT_TRUE(waitFor([&] { return std::abs(stage()->status().axes[0].commanded - rig.scan.stageMm[0].x()) < pxMm + 1e-4 && !stage()->status().anyMoving(); }, 30000));
    EXPECT_NEAR(stage()->status().axes[1].commanded, rig.scan.stageMm[0].y(), pxMm + 1e-4);
}

TEST_F(MosaicViewerStage, APointBeyondTheSoftLimitsOrDuringAScanIsRefusedWithWhy)
{
    ViewerRig rig;
    ASSERT_TRUE(rig.show());
    rig.viewer.setStage(stage());
    ASSERT_TRUE(home());
    stage()->move({{0, rig.scan.stageMm[0].x()}, {1, rig.scan.stageMm[0].y()}}, false);
    ASSERT_TRUE(settledAt(rig.scan.stageMm[0]));
    // X may go no further than just past the first column.
    stage()->setSoftLimits(0, 0, rig.scan.stageMm[0].x() + 0.05);
    ASSERT_TRUE(waitFor([&] { return std::abs(stage()->softLimits()[0].max - (rig.scan.stageMm[0].x() + 0.05)) < 1e-9; }, 5000));
    QTest::mouseDClick(rig.canvas(), Qt::LeftButton, {}, rig.tileCentre(1));
    ASSERT_EQ(rig.problems.size(), 1);
    EXPECT_TRUE(rig.problems[0].contains(QLatin1String("is outside the stage's soft limits (X 0.000 to 20.050 mm"))) << rig.problems[0].toStdString();
    guitest::pump(100);
    EXPECT_DOUBLE_EQ(stage()->status().axes[0].commanded, rig.scan.stageMm[0].x());

    rig.viewer.setScanRunning(true);
    QTest::mouseDClick(rig.canvas(), Qt::LeftButton, {}, rig.tileCentre(0) + QPoint(3, 3));
    ASSERT_EQ(rig.problems.size(), 2);
    EXPECT_TRUE(rig.problems[1].startsWith(QLatin1String("A scan is running"))) << rig.problems[1].toStdString();
    EXPECT_TRUE(rig.notices.isEmpty());
}

TEST(MosaicViewer, TheMosaicTabShowsTheStitchedMosaic)
{
    QTemporaryDir dir;
    const ViewerScan scan = writeViewerScan(dir.path(), 3, 2);
    ui::StitchPanel panel([&] {
        dev::jobs::StitchRequest r;
        r.folder = dir.path();
        r.plan = scan.plan;
        return r;
    });
    panel.resize(800, 700);
    panel.show();
    QStringList problems;
    QObject::connect(&panel, &ui::StitchPanel::problem, [&](const QString& m) { problems << m; });
    ASSERT_NE(panel.viewer(), nullptr);
    EXPECT_FALSE(panel.viewer()->hasMosaic());
    ASSERT_TRUE(panel.stitch());
    ASSERT_TRUE(waitFor([&] { return !panel.isRunning(); }, 60000));
    ASSERT_TRUE(problems.isEmpty()) << problems.join(QLatin1Char('\n')).toStdString();
    EXPECT_TRUE(panel.viewer()->hasMosaic());
    EXPECT_EQ(panel.viewer()->frame().tiles().size(), 6u);
    EXPECT_TRUE(panel.map()->isVisible()) << "the quality map stays beside the viewer";
    // Tile 5's centre is where the stage was for tile 5.
    const Eigen::Vector2d at = panel.viewer()->frame().stageMmAt(panel.viewer()->frame().tiles()[4].topLeftPx + Eigen::Vector2d(127.5, 127.5));
    EXPECT_NEAR(at.x(), scan.stageMm[4].x(), 1e-6);
    EXPECT_NEAR(at.y(), scan.stageMm[4].y(), 1e-6);
    ui::MosaicCanvas* canvas = panel.viewer()->canvas();
    QTest::mouseMove(canvas, QPoint(canvas->width() / 2, canvas->height() / 2));
    EXPECT_TRUE(panel.viewer()->statusText().contains(QLatin1String("mm under the cursor"))) << panel.viewer()->statusText().toStdString();
}

// The picture in docs/stitching.md: BP_GUI_SHOTS=DIR keeps DIR/scan-mosaic-viewer.png, the
// Scan screen's Mosaic tab after stitching 3 × 3 tiles of the simulated camera (2048 px at
// 0.65 µm) over the slide, the stage homed and standing over the middle tile.
TEST_F(MosaicViewerStage, PictureForTheDocs)
{
    if (qEnvironmentVariable("BP_GUI_SHOTS").isEmpty())
        GTEST_SKIP() << "only with BP_GUI_SHOTS=DIR";
    QTemporaryDir dir;
    // The grating's log a few micrometres off for two tiles, as a stage's error would be.
    const ViewerScan scan = writeViewerScan(dir.path(), 3, 3, 2048, 41.2, 32.2, [](int tile) {
        return tile == 2 ? Eigen::Vector2d(3, 1) : tile == 6 ? Eigen::Vector2d(-1, -2.5) : Eigen::Vector2d(0, 0);
    });
    ASSERT_TRUE(home());
    ASSERT_TRUE(w->showScreen(QStringLiteral("scan")));
    ui::ScanScreen* screen = w->scanScreen();
    screen->setPlan(scan.plan);
    screen->setOutputFolder(dir.path());
    screen->showTab(2);
    ui::StitchPanel* panel = screen->stitchPanel();
    ASSERT_TRUE(panel && panel->stitch());
    ASSERT_TRUE(waitFor([&] { return !panel->isRunning(); }, 180000));
    ASSERT_TRUE(panel->viewer()->hasMosaic());
    const Eigen::Vector2d over = scan.stageMm[4] + Eigen::Vector2d(0.3, -0.2);
    stage()->move({{0, over.x()}, {1, over.y()}}, false);
    ASSERT_TRUE(settledAt(over));
    guitest::pump(300);
    ui::MosaicCanvas* canvas = panel->viewer()->canvas();
    canvas->zoomBy(1.6, canvas->toWidget(QPointF(canvas->frame().widthPx() * 0.55, canvas->frame().heightPx() * 0.5)));
    QTest::mouseMove(canvas, canvas->toWidget(QPointF(canvas->frame().widthPx() * 0.6, canvas->frame().heightPx() * 0.45)).toPoint());
    guitest::pump(300);
    guitest::keepPicture(w.get(), QStringLiteral("scan-mosaic-viewer.png"));
}

TEST(MosaicViewer, AFolderStitchedEarlierOpensInTheViewerWithTheSameStagePlaces)
{
    QTemporaryDir dir;
    const ViewerScan scan = writeViewerScan(dir.path(), 3, 2, 256, 20, 20, [](int tile) { return tile == 4 ? Eigen::Vector2d(4, 0) : Eigen::Vector2d(0, 0); });
    auto source = [&] {
        dev::jobs::StitchRequest r;
        r.folder = dir.path();
        r.plan = scan.plan;
        return r;
    };
    ui::StitchPanel first(source);
    ASSERT_TRUE(first.stitch());
    ASSERT_TRUE(waitFor([&] { return !first.isRunning(); }, 60000));
    ASSERT_TRUE(first.viewer()->hasMosaic());

    // Another day: a new panel opens what the folder holds.
    ui::StitchPanel later(source);
    later.resize(800, 600);
    later.show();
    QStringList problems;
    QObject::connect(&later, &ui::StitchPanel::problem, [&](const QString& m) { problems << m; });
    QTest::mouseClick(later.viewer()->findChild<QToolButton*>(QStringLiteral("mosaicOpen")), Qt::LeftButton);
    ASSERT_TRUE(problems.isEmpty()) << problems.join(QLatin1Char('\n')).toStdString();
    ASSERT_TRUE(later.viewer()->hasMosaic());
    EXPECT_EQ(later.map()->tileCount(), 6) << "the quality map comes back too";
    const ui::MosaicStageFrame& was = first.viewer()->frame();
    const ui::MosaicStageFrame& is = later.viewer()->frame();
    ASSERT_EQ(is.tiles().size(), was.tiles().size());
    EXPECT_EQ(is.tileWidthPx(), 256);
    for (std::size_t i = 0; i < was.tiles().size(); ++i) {
        EXPECT_EQ(is.tiles()[i].topLeftPx, was.tiles()[i].topLeftPx) << i;
        EXPECT_NEAR((is.tiles()[i].correctionPx - was.tiles()[i].correctionPx).norm(), 0, 0.002) << i;
    }
    for (const Eigen::Vector2d& m : {Eigen::Vector2d(10, 20), Eigen::Vector2d(300, 200), Eigen::Vector2d(600, 400)})
        EXPECT_NEAR((is.stageMmAt(m) - was.stageMmAt(m)).norm(), 0, 1e-5) << m.transpose();
    const Eigen::Vector2d centre4 = is.tiles()[4].topLeftPx + Eigen::Vector2d(127.5, 127.5);
    EXPECT_NEAR((is.stageMmAt(centre4) - scan.stageMm[4]).norm(), 0, 1e-5) << "tile 5's centre is where the log says it was taken";

    // A report cut short is refused naming the file and where; a folder with none says so.
    QFile report(QDir(dir.path()).filePath(QStringLiteral("mosaic.stitch.json")));
    ASSERT_TRUE(report.open(QIODevice::ReadOnly));
    const QByteArray text = report.readAll();
    report.close();
    ASSERT_TRUE(report.open(QIODevice::WriteOnly | QIODevice::Truncate));
    report.write(text.left(text.size() / 2));
    report.close();
    QTest::mouseClick(later.viewer()->findChild<QToolButton*>(QStringLiteral("mosaicOpen")), Qt::LeftButton);
    ASSERT_EQ(problems.size(), 1);
    EXPECT_TRUE(problems[0].startsWith(QLatin1String("mosaic.stitch.json, line 1, column "))) << problems[0].toStdString();
    QTemporaryDir empty;
    ui::StitchPanel none([&] {
        dev::jobs::StitchRequest r;
        r.folder = empty.path();
        r.plan = scan.plan;
        return r;
    });
    QObject::connect(&none, &ui::StitchPanel::problem, [&](const QString& m) { problems << m; });
    QTest::mouseClick(none.viewer()->findChild<QToolButton*>(QStringLiteral("mosaicOpen")), Qt::LeftButton);
    ASSERT_EQ(problems.size(), 2);
    EXPECT_TRUE(problems[1].contains(QLatin1String("holds no stitched mosaic"))) << problems[1].toStdString();
    EXPECT_FALSE(none.viewer()->hasMosaic());
}

TEST(MosaicViewer, ItsArrowsAreTheQualityMapsBeyondTheStageModel)
{
    // A grating 1 % long in x and 0.5 % short in y: placement fits it as the stage model,
    // and what registration found beyond it is a few tenths of a pixel per tile. The
    // viewer's arrows must be those (as the quality map draws them), not the model's
    // pixels, which point out of the mosaic and grow with the distance from its middle.
    imaging::StitchResult r;
    r.tileWidth = r.tileHeight = 256;
    r.placement.stageModel.used = true;
    r.placement.stageModel.m << 1.01, 0, 0, 0.995;
    r.placement.stageModel.centrePx = Eigen::Vector2d(217.6, 108.8);
    std::vector<Eigen::Vector2d> beyond;
    for (int i = 0; i < 6; ++i) {
        const Eigen::Vector2d stage((i % 3) * 217.6, (i / 3) * 217.6);
        r.tiles.push_back({"tile_" + std::to_string(i) + ".tif", "", stage});
        beyond.emplace_back(0.3 * std::sin(i + 1.0), -0.2 * std::cos(2.0 * i));
        r.placement.positionsPx.push_back(r.placement.stageModel.apply(stage) + beyond.back());
        r.placement.placedByStage.push_back(false);
    }
    r.frame = imaging::mosaicFrame(r.placement.positionsPx, r.tileWidth, r.tileHeight);
    Eigen::Vector2d mean(0, 0);
    for (const Eigen::Vector2d& b : beyond)
        mean += b / 6.0;
    const ui::MosaicStageFrame frame(r, viewerPlan(256).camera);
    const std::vector<Eigen::Vector2d> mapArrows = ui::qualityArrowsPx(r);
    ASSERT_EQ(frame.tiles().size(), 6u);
    ASSERT_EQ(mapArrows.size(), 6u);
    for (std::size_t i = 0; i < 6; ++i) {
        EXPECT_NEAR((frame.tiles()[i].correctionPx - (beyond[i] - mean)).norm(), 0, 1e-9) << "tile " << i;
        EXPECT_NEAR((frame.tiles()[i].correctionPx - mapArrows[i]).norm(), 0, 1e-9) << "tile " << i;
    }
}
