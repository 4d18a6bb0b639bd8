// The scan's exports read back through readers written from the tools' published
// rules (scan_format_readers.h): Fiji's TileConfiguration, Micro-Manager's
// position list, and CSV.
#include "device/english_words.h"
#include "device/files/scan_exports.h"
#include "scan_format_readers.h"

#include <gtest/gtest.h>

#include <QFile>
#include <QTemporaryDir>

#include <cmath>
#include <map>

using namespace motion::scan;

namespace {

ScanPlan plan3x2()
{
    ScanPlan p;
    p.name = "exports";
    p.region.cornerA = {20, 30};
    p.region.cornerB = {23.2, 31.2};
    p.camera.source = FieldSource::Direct;
    p.camera.fieldWidthMm = 1.3;
    p.camera.fieldHeightMm = 1.0;
    p.camera.samplePixelUm = 0.65;  // 2000 × ~1538 px
    p.overlapX = p.overlapY = 0.2;
    p.order = ScanOrder::SnakeRows;
    return p;
}

} // namespace

TEST(ScanExports, TileConfigurationParsesByFijisRules)
{
    const ScanPlan p = plan3x2();
    const ScanLayout l = layoutScan(p);
    ASSERT_EQ(l.grid.columns, 3);
    ASSERT_EQ(l.grid.rows, 2);
    const auto records = dev::files::scan::plannedRecords(p, l);
    const auto fiji = scanread::readTileConfiguration(dev::files::scan::tileConfiguration(p, records));
    ASSERT_TRUE(fiji.error.empty()) << fiji.error;
    EXPECT_EQ(fiji.dim, 2);
    ASSERT_EQ(fiji.tiles.size(), 6u);
    // Snake rows from the top left: 001 002 003 on the top row, then 004 at the right below.
    EXPECT_EQ(fiji.tiles[0].file, "tile_001.tif");
    EXPECT_EQ(fiji.tiles[5].file, "tile_006.tif");
    const double stepPx = 1.3 * 0.8 * 1000 / 0.65;  // 1600 px: the step over one pixel
    const double rowPx = 1.0 * 0.8 * 1000 / 0.65;
    EXPECT_NEAR(fiji.tiles[0].coords[0], 0, 1e-3);
    EXPECT_NEAR(fiji.tiles[0].coords[1], 0, 1e-3);
    EXPECT_NEAR(fiji.tiles[1].coords[0], stepPx, 1e-3);
    EXPECT_NEAR(fiji.tiles[2].coords[0], 2 * stepPx, 1e-3);
    // The second row lies lower on the stage (−Y): further down the image.
    EXPECT_NEAR(fiji.tiles[3].coords[0], 2 * stepPx, 1e-3);
    EXPECT_NEAR(fiji.tiles[3].coords[1], rowPx, 1e-3);
    EXPECT_NEAR(fiji.tiles[5].coords[0], 0, 1e-3);
}

TEST(ScanExports, TileConfigurationUsesMeasuredPositionsAndTheCameraRotation)
{
    ScanPlan p = plan3x2();
    p.camera.rotationDeg = 90;  // image x along stage +Y, image y (down) along stage +X
    const ScanLayout l = layoutScan(p);
    auto records = dev::files::scan::plannedRecords(p, l);
    for (auto& r : records)
        r.measuredMm = {r.plannedMm[0] + 0.00065, r.plannedMm[1]};  // one pixel off in X
    records[1].measuredMm[0] += 0.0065;                               // ten more for tile 2
    const auto fiji = scanread::readTileConfiguration(dev::files::scan::tileConfiguration(p, records));
    ASSERT_TRUE(fiji.error.empty()) << fiji.error;
    // Tile 1 → tile 2 is +1.04 mm in X plus the extra 6.5 µm: 1610 px down the image, nothing across.
    EXPECT_NEAR(fiji.tiles[1].coords[1] - fiji.tiles[0].coords[1], 1610, 1e-3);
    EXPECT_NEAR(fiji.tiles[1].coords[0] - fiji.tiles[0].coords[0], 0, 1e-3);
    // Rows step −0.8 mm in Y: 1230.8 px to the left.
    EXPECT_NEAR(fiji.tiles[5].coords[0] - fiji.tiles[0].coords[0], -0.8 * 1000 / 0.65, 1e-3);
}

TEST(ScanExports, TileConfigurationNamesWithCommasAndRowsSurvive)
{
    ScanPlan p = plan3x2();
    p.naming.filePattern = "scan, r{row}c{col}.tif";
    const ScanLayout l = layoutScan(p);
    const auto fiji = scanread::readTileConfiguration(dev::files::scan::tileConfiguration(p, dev::files::scan::plannedRecords(p, l)));
    ASSERT_TRUE(fiji.error.empty()) << fiji.error;
    EXPECT_EQ(fiji.tiles[3].file, "scan, r1c2.tif");
}

TEST(ScanExports, FijiRulesRefuseWhatFijiRefuses)
{
    // The reader is not a rubber stamp: each of these stops Fiji's loader.
    EXPECT_FALSE(scanread::readTileConfiguration("a.tif; ; (1, 2)\n").error.empty()) << "no dim line first";
    EXPECT_FALSE(scanread::readTileConfiguration("dim = 2\na.tif; (1, 2)\n").error.empty()) << "two fields";
    EXPECT_FALSE(scanread::readTileConfiguration("dim = 2\na.tif; ; (1, 2, 3)\n").error.empty()) << "three coordinates";
    EXPECT_FALSE(scanread::readTileConfiguration("dim = 2\na.tif; ; 1, 2\n").error.empty()) << "no parentheses";
    EXPECT_FALSE(scanread::readTileConfiguration("dim = 2\na.tif; ; (1, x)\n").error.empty()) << "not a number";
    EXPECT_FALSE(scanread::readTileConfiguration("dim = 4\na.tif; ; (1, 2)\n").error.empty()) << "dim 4";
    const auto ok = scanread::readTileConfiguration("# c\ndim=2\n\n a.tif ;  ; ( 1.5 , -2e3 ) \n");
    EXPECT_TRUE(ok.error.empty()) << ok.error;
    ASSERT_EQ(ok.tiles.size(), 1u);
    EXPECT_EQ(ok.tiles[0].coords[1], -2000);
}

TEST(ScanExports, PositionListParsesByMicroManagersRules)
{
    const ScanPlan p = plan3x2();
    const ScanLayout l = layoutScan(p);
    const auto mm = scanread::readMicroManagerPositions(dev::files::scan::microManagerPositions(p, l));
    ASSERT_TRUE(mm.error.empty()) << mm.error;
    ASSERT_EQ(mm.positions.size(), l.tiles.size());
    std::map<std::string, int> labels;
    for (std::size_t i = 0; i < mm.positions.size(); ++i) {
        const auto& pos = mm.positions[i];
        ++labels[pos.label];
        EXPECT_EQ(pos.defaultXyStage, "XYStage");
        ASSERT_EQ(pos.devices.size(), 1u) << "one XY device position per tile";
        EXPECT_EQ(pos.devices[0].name, "XYStage");
        ASSERT_EQ(pos.devices[0].positionUm.size(), 2u);
        EXPECT_NEAR(pos.devices[0].positionUm[0], l.tiles[i].centre.xMm * 1000, 1e-6);
        EXPECT_NEAR(pos.devices[0].positionUm[1], l.tiles[i].centre.yMm * 1000, 1e-6);
        EXPECT_EQ(pos.gridRow, l.tiles[i].row);
        EXPECT_EQ(pos.gridCol, l.tiles[i].col);
    }
    EXPECT_EQ(labels.size(), l.tiles.size()) << "labels are unique";
    EXPECT_EQ(mm.positions[0].label, "tile_001");
}

TEST(ScanExports, MicroManagerRulesRefuseWhatMicroManagerRefuses)
{
    const std::string good = dev::files::scan::microManagerPositions(plan3x2(), layoutScan(plan3x2()));
    auto replaced = [&](const std::string& from, const std::string& to) {
        std::string s = good;
        s.replace(s.find(from), from.size(), to);
        return scanread::readMicroManagerPositions(s).error;
    };
    EXPECT_FALSE(replaced("\"major_version\": 2", "\"major_version\": 3").empty());
    EXPECT_FALSE(replaced("Micro-Manager Property Map", "Property Map").empty());
    EXPECT_FALSE(replaced("\"type\": \"DOUBLE\"", "\"type\": \"REAL\"").empty());
    EXPECT_FALSE(replaced("\"type\": \"INTEGER\",\n", "").empty());
    EXPECT_FALSE(scanread::readMicroManagerPositions("{").error.empty());
}

TEST(ScanExports, CsvHasPlannedAndMeasuredPositions)
{
    ScanPlan p = plan3x2();
    p.compensation.enabled = true;
    const ScanLayout l = layoutScan(p);
    auto records = dev::files::scan::plannedRecords(p, l);
    records[0].measuredMm = {records[0].commandedMm[0] + 0.0005, records[0].commandedMm[1] - 0.001};
    records[0].deviceTimeUs = 123456789;
    records[0].settleS = 0.031;
    const auto rows = scanread::readCsv(dev::files::scan::scanCsv(p, l, records));
    ASSERT_EQ(rows.size(), 7u);
    const auto& h = rows[0];
    auto col = [&](const char* name) {
        const auto it = std::find(h.begin(), h.end(), name);
        EXPECT_NE(it, h.end()) << name;
        return static_cast<std::size_t>(it - h.begin());
    };
    for (const auto& r : rows)
        EXPECT_EQ(r.size(), h.size());
    EXPECT_EQ(rows[1][col("label")], "tile_001.tif");
    EXPECT_NEAR(std::stod(rows[1][col("planned_x_mm")]), l.tiles[0].centre.xMm, 1e-9);
    EXPECT_NEAR(std::stod(rows[1][col("commanded_x_mm")]), records[0].commandedMm[0], 1e-6);
    EXPECT_NEAR(std::stod(rows[1][col("measured_y_mm")]), records[0].measuredMm[1], 1e-6);
    EXPECT_EQ(rows[1][col("error_x_um")], "0.500");
    EXPECT_EQ(rows[1][col("error_y_um")], "-1.000");
    EXPECT_EQ(rows[1][col("device_time_us")], "123456789");
    EXPECT_EQ(rows[2][col("measured_x_mm")], "") << "a tile not yet taken has no measurement";
    EXPECT_EQ(rows[4][col("row")], "1");
    // A compensated stage reports its grating at the work point: the reading is where the tile is.
    EXPECT_NEAR(std::stod(rows[1][col("stitch_x_mm")]), l.tiles[0].centre.xMm, 0.001);
}

TEST(ScanExports, WritesAllThreeFiles)
{
    QTemporaryDir dir;
    const ScanPlan p = plan3x2();
    const ScanLayout l = layoutScan(p);
    QStringList written;
    motion::msg::Message error;
    ASSERT_TRUE(dev::files::scan::writeExports(dir.filePath(QStringLiteral("out")), p, l, dev::files::scan::plannedRecords(p, l), &written, &error))
        << error;
    ASSERT_EQ(written.size(), 3);
    for (const QString& f : written) {
        QFile file(f);
        ASSERT_TRUE(file.open(QIODevice::ReadOnly)) << f.toStdString();
        EXPECT_GT(file.size(), 100);
    }
}
