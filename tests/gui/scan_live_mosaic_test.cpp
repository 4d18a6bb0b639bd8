// The live mosaic on the Scan screen, as an operator meets it: a camera scan grows the
// Mosaic tab's map tile by tile (thumbnails, pairs coloured as they register), a stop
// leaves no mosaic, a resume reads the tiles taken before from the folder, and after the
// last tile the mosaic, the registered TileConfiguration, the report and the quality map
// are written without pressing Stitch — placed as a Stitch of the folder places them.
#include "device/jobs/scan_runner.h"
#include "gui_window.h"
#include "imaging/tile_configuration.h"
#include "widgets/camera/camera_session.h"
#include "widgets/scan/mosaic_viewer.h"
#include "widgets/scan/scan_screen.h"
#include "widgets/scan/stitch_panel.h"
#include "widgets/scan/stitch_quality_map.h"
#include "widgets/wording/translators.h"

#include <QDir>
#include <QFile>
#include <QImage>
#include <QLabel>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <map>

using guitest::waitFor;

namespace {

class LiveMosaicScreen : public ::testing::Test {
protected:
    void SetUp() override
    {
        ASSERT_TRUE(translators.setLanguage(QStringLiteral("en")));
        app::MainWindowOptions options = guitest::testWindowOptions();
        options.translators = &translators;
        w = guitest::openReadyWindow({1366, 768}, options);
        ASSERT_TRUE(w) << "the simulated instruments did not become ready";
    }
    void TearDown() override { w.reset(); }

    /// The stage homed, the Scan screen on a plan over the slide into `folder`, the
    /// simulated camera open and asked for at each tile; nullptr if any of it failed.
    ui::ScanScreen* cameraScan(double widthMm, double heightMm, const QString& folder)
    {
        dev::Instrument* stage = w->stage()->instrument();
        stage->home(0);
        if (!waitFor([&] { return !stage->status().axes.isEmpty() && stage->status().axes[0].homed && stage->status().axes[1].homed
                                  && !stage->status().anyMoving(); }, 60000)
            || !w->showScreen(QStringLiteral("scan")))
            return nullptr;
        ui::ScanScreen* scan = w->scanScreen();
        motion::scan::ScanPlan p;
        p.region.kind = motion::scan::RegionKind::CentreSize;
        p.region.centre = {42, 31};
        p.region.widthMm = widthMm;
        p.region.heightMm = heightMm;
        scan->setPlan(p);
        scan->setOutputFolder(folder);
        w->cameraSession()->open(QStringLiteral("sim"));
        if (!waitFor([&] { return w->cameraSession()->isOpen(); }, 5000))
            return nullptr;
        scan->setTakesImages(true);
        return scan;
    }

    static std::map<std::string, Eigen::Vector2d> registered(const QString& folder)
    {
        QFile f(QDir(folder).filePath(QStringLiteral("TileConfiguration.registered.txt")));
        std::map<std::string, Eigen::Vector2d> out;
        if (!f.open(QIODevice::ReadOnly))
            return out;
        auto tiles = imaging::parseTileConfiguration(f.readAll().toStdString(), "TileConfiguration.registered.txt");
        if (tiles)
            for (const imaging::TileEntry& t : *tiles)
                out[t.file] = t.positionPx;
        return out;
    }

    ui::words::Translators translators;
    std::unique_ptr<app::MainWindow> w;
};

} // namespace

TEST_F(LiveMosaicScreen, ACameraScanGrowsTheMosaicAndWritesItAfterTheLastTileEvenWhenStoppedAndResumed)
{
    QTemporaryDir dir;
    const QString run = dir.filePath(QStringLiteral("run"));
    ui::ScanScreen* scan = cameraScan(2.4, 2.4, run);  // 2 × 2 fields of 1.33 mm
    ASSERT_TRUE(scan);
    const int tiles = int(scan->layout().tiles.size());
    ASSERT_EQ(tiles, 4);
    ui::StitchPanel* mosaic = scan->stitchPanel();
    ASSERT_TRUE(mosaic);
    QStringList problems;
    QObject::connect(mosaic, &ui::StitchPanel::problem, [&](const QString& m) { problems << m; });

    ASSERT_TRUE(scan->run());
    EXPECT_TRUE(mosaic->job()->isLive()) << "a camera scan stitches as it goes";
    ASSERT_TRUE(waitFor([&] { return scan->runner()->takenTiles() >= 1; }, 120000));
    scan->abort();
    ASSERT_TRUE(waitFor([&] { return scan->runner()->state() == dev::jobs::ScanRunner::State::Stopped; }, 30000));
    EXPECT_FALSE(mosaic->job()->isLive()) << "a stop drops the live stitch";
    guitest::pump(300);
    EXPECT_TRUE(QDir(run).entryList({QStringLiteral("mosaic*")}, QDir::Files).isEmpty()) << "a stopped scan leaves no mosaic";
    EXPECT_FALSE(mosaic->isRunning());
    EXPECT_EQ(mosaic->findChild<QLabel*>(QStringLiteral("stitchState"))->text(),
              QStringLiteral("The scan stopped: nothing is written; the live mosaic begins again when the scan resumes."));

    // Resumed: the tiles of the first session come back from the folder.
    scan->showTab(2);
    ASSERT_TRUE(scan->run());
    EXPECT_TRUE(mosaic->job()->isLive());
    // BP_GUI_SHOTS=DIR keeps the growing mosaic (docs/stitching.md) once a pair is drawn,
    // if the scan is still going then; nothing is asserted on how far it has got.
    waitFor([&] { return mosaic->map()->pairCount() >= 1 || !scan->runner()->isActive(); }, 180000);
    if (scan->runner()->isActive())
        guitest::keepPicture(w.get(), QStringLiteral("scan-mosaic-live.png"));
    ASSERT_TRUE(waitFor([&] { return scan->runner()->state() == dev::jobs::ScanRunner::State::Finished; }, 180000));
    ASSERT_TRUE(waitFor([&] { return !mosaic->summaryText().isEmpty(); }, 60000)) << "no Stitch was pressed: the live stitch finishes alone";
    ASSERT_TRUE(problems.isEmpty()) << problems.join(QLatin1Char('\n')).toStdString();
    EXPECT_TRUE(mosaic->summaryText().startsWith(QLatin1String("4 tiles, 4 pairs"))) << mosaic->summaryText().toStdString();
    EXPECT_TRUE(mosaic->summaryText().contains(QLatin1String("Stitched live during the scan: placed "))) << mosaic->summaryText().toStdString();
    for (const char* name : {"mosaic.ome.tif", "mosaic.stitch.json", "TileConfiguration.registered.txt", "quality-map.png"})
        EXPECT_TRUE(QFile::exists(QDir(run).filePath(QLatin1String(name)))) << name;
    EXPECT_FALSE(QImage(QDir(run).filePath(QStringLiteral("quality-map.png"))).isNull());
    // The map grew: every tile has its thumbnail, every pair its colour.
    EXPECT_EQ(mosaic->map()->picturedTiles(), tiles);
    EXPECT_EQ(mosaic->map()->pairCount(), 4);
    EXPECT_TRUE(mosaic->viewer()->hasMosaic()) << "the viewer shows the mosaic the live stitch wrote";

    // A Stitch of the folder afterwards places the tiles where the live stitch did.
    const auto live = registered(run);
    ASSERT_EQ(live.size(), 4u);
    ASSERT_TRUE(mosaic->stitch());
    ASSERT_TRUE(waitFor([&] { return !mosaic->isRunning(); }, 60000));
    ASSERT_TRUE(problems.isEmpty()) << problems.join(QLatin1Char('\n')).toStdString();
    EXPECT_FALSE(mosaic->job()->lastWasLive());
    const auto batch = registered(run);
    ASSERT_EQ(batch.size(), 4u);
    for (const auto& [file, at] : live) {
        ASSERT_TRUE(batch.count(file)) << file;
        EXPECT_LT((batch.at(file) - at).norm(), 0.05) << file;
    }
}
