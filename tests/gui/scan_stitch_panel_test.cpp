// The Scan screen's Mosaic tab: a scan folder (run log and tile images) is stitched off
// the GUI thread into the mosaic, Fiji's registered TileConfiguration, the report and the
// quality map PNG; a tile the grating logged 4 µm off is put back by registration and
// shows the largest arrow; a folder with no scan in it is refused with why.
#include "device/camera/scan_camera.h"
#include "device/camera/sim_render.h"
#include "device/camera/specimen.h"
#include "device/camera/tile_tiff.h"
#include "device/files/scan_run_log.h"
#include "gui_wait.h"
#include "motion/message_print.h"
#include "widgets/scan/stitch_panel.h"
#include "widgets/scan/stitch_quality_map.h"

#include <QDir>
#include <QFile>
#include <QImage>
#include <QPushButton>
#include <QTemporaryDir>
#include <QTest>

#include <gtest/gtest.h>

#include <cmath>

using guitest::waitFor;

namespace {

/// 3 × 2 tiles of a 256 × 256 px sensor at 1 µm a pixel, 15 % overlap.
motion::scan::ScanPlan smallPlan()
{
    motion::scan::ScanPlan p;
    p.name = "stitch";
    p.camera.source = motion::scan::FieldSource::Sensor;
    p.camera.sensorWidthPx = p.camera.sensorHeightPx = 256;
    p.camera.sensorPixelUm = 10;
    p.camera.magnification = 10;
    return p;
}

/// Writes the folder a camera scan leaves: the images rendered where the stage truly was,
/// and a run log of where the grating said it was (tile `offTile` logged `offUm` off in x).
void writeScanFolder(const QString& folder, int offTile, double offUm)
{
    const motion::scan::ScanPlan plan = smallPlan();
    const dev::camera::CameraGeometry g = dev::camera::geometryOfPlan(plan);
    const dev::camera::Specimen slide(dev::camera::SpecimenKind::Slide, 3);
    std::string log = dev::files::scan::runLogHeader(plan.name, 1, 6);
    const double step = 0.256 * 0.85;
    for (int r = 0; r < 2; ++r)
        for (int c = 0; c < 3; ++c) {
            const int tile = r * 3 + c;
            const double x = 20 + c * step, y = 20 - r * step;
            const dev::camera::Frame f = dev::camera::renderSimFrame(slide, g, dev::camera::SimOptics{}, x, y, 10, 3);
            motion::PositionRecord rec;
            rec.target = tile;
            rec.label = QStringLiteral("tile_%1.tif").arg(tile + 1, 3, 10, QLatin1Char('0')).toStdString();
            rec.plannedMm = rec.commandedMm = {x, y};
            rec.measuredMm = {x + (tile == offTile ? offUm / 1000 : 0.0), y};
            dev::camera::TileMetadata meta;
            meta.tile = tile;
            meta.label = rec.label;
            meta.measuredMm = rec.measuredMm;
            std::string sha;
            motion::msg::Message error;
            ASSERT_TRUE(dev::camera::writeTileTiff(QDir(folder).filePath(QString::fromStdString(rec.label)).toStdString(), f, meta, &sha, &error)) << error;
            log += dev::files::scan::runLogLine(rec, {rec.label, sha});
        }
    QFile file(QDir(folder).filePath(QLatin1String(dev::files::scan::kRunLogFile)));
    ASSERT_TRUE(file.open(QIODevice::WriteOnly));
    file.write(QByteArray::fromStdString(log));
}

} // namespace

TEST(ScanStitchPanel, AScanFolderStitchesIntoTheMosaicAndItsQualityMap)
{
    QTemporaryDir dir;
    writeScanFolder(dir.path(), 4, 4.0);
    QString folder = dir.path();
    ui::StitchPanel panel([&] {
        dev::jobs::StitchRequest r;
        r.folder = folder;
        r.plan = smallPlan();
        return r;
    });
    panel.resize(700, 600);
    panel.show();
    QStringList problems, notices;
    QObject::connect(&panel, &ui::StitchPanel::problem, [&](const QString& m) { problems << m; });
    QObject::connect(&panel, &ui::StitchPanel::notice, [&](const QString& m) { notices << m; });
    auto* button = panel.findChild<QPushButton*>(QStringLiteral("stitchButton"));
    ASSERT_TRUE(button && button->isEnabled());
    button->click();
    EXPECT_TRUE(panel.isRunning()) << "the stitch works beside the GUI thread";
    EXPECT_FALSE(button->isEnabled()) << "one stitch at a time";
    ASSERT_TRUE(waitFor([&] { return !panel.isRunning(); }, 60000));
    ASSERT_TRUE(problems.isEmpty()) << problems.join(QLatin1Char('\n')).toStdString();

    for (const char* name : {"mosaic.ome.tif", "mosaic.stitch.json", "TileConfiguration.registered.txt", "quality-map.png"})
        EXPECT_TRUE(QFile::exists(QDir(folder).filePath(QLatin1String(name)))) << name;
    EXPECT_FALSE(QImage(QDir(folder).filePath(QStringLiteral("quality-map.png"))).isNull());
    EXPECT_EQ(panel.map()->tileCount(), 6);
    EXPECT_TRUE(panel.summaryText().contains(QLatin1String("6 tiles, 7 pairs: 7 trusted"))) << panel.summaryText().toStdString();
    ASSERT_FALSE(notices.isEmpty());

    // The tile logged 4 µm (4 px) off is moved back by about that much: its correction is
    // the largest, and clicking it says so.
    const ui::StitchQualityMap* map = panel.map();
    const int index = 4;
    QPointF centre;
    for (int y = 0; y < map->height() && centre.isNull(); y += 4)
        for (int x = 0; x < map->width(); x += 4)
            if (map->tileAt(QPointF(x, y)) == index) {
                centre = QPointF(x + 20, y + 20);
                break;
            }
    ASSERT_FALSE(centre.isNull());
    QTest::mouseClick(panel.map(), Qt::LeftButton, {}, centre.toPoint());
    EXPECT_EQ(map->selectedTile(), index);
    const QString tile = panel.tileText();
    EXPECT_TRUE(tile.startsWith(QLatin1String("Tile 5 (tile_005.tif): moved -"))) << tile.toStdString();
    EXPECT_TRUE(tile.contains(QLatin1String("with tile 2:")) && tile.contains(QLatin1String("trusted"))) << tile.toStdString();
}

TEST(ScanStitchPanel, AFolderWithNoScanIsRefusedWithWhy)
{
    QTemporaryDir dir;
    ui::StitchPanel panel([&] {
        dev::jobs::StitchRequest r;
        r.folder = dir.path();
        r.plan = smallPlan();
        return r;
    });
    QStringList problems;
    QObject::connect(&panel, &ui::StitchPanel::problem, [&](const QString& m) { problems << m; });
    EXPECT_FALSE(panel.stitch());
    ASSERT_EQ(problems.size(), 1);
    EXPECT_TRUE(problems[0].contains(QLatin1String("holds no scan run log"))) << problems[0].toStdString();
    EXPECT_FALSE(panel.isRunning());
}
