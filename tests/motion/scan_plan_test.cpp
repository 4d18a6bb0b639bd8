// What the scan plan's validator refuses, and how it says so: each problem names
// the plan field (which the file reader and the CLI turn into a line or an option).
#include "motion/message_print.h"
#include "motion/plans/scan/scan_layout.h"
#include "motion/plans/scan/scan_naming.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace motion::scan;

namespace {

/// The message for `field`, or "" when there is none.
std::string problemAt(const motion::msg::Problems& problems, const std::string& field)
{
    for (const auto& p : problems)
        if (p.path == field)
            return motion::msg::debugString(p.message);
    return {};
}

std::string all(const motion::msg::Problems& problems)
{
    std::string s;
    for (const auto& p : problems)
        s += p.path + ": " + motion::msg::debugString(p.message) + "\n";
    return s;
}

} // namespace

TEST(ScanPlan, DefaultsAreValid)
{
    const ScanPlan p;
    EXPECT_TRUE(validate(p).empty()) << all(validate(p));
    EXPECT_TRUE(validate(p, StageModel{}).empty()) << all(validate(p, StageModel{}));
    // 2048 px × 6.5 µm / 10× = 1.3312 mm; one pixel at the sample 0.65 µm.
    EXPECT_NEAR(fieldWidthMm(p.camera), 1.3312, 1e-12);
    EXPECT_NEAR(pixelAtSampleUm(p.camera), 0.65, 1e-12);
}

TEST(ScanPlan, OverlapOfAHundredPercentIsRefused)
{
    ScanPlan p;
    p.overlapX = 1.0;
    p.overlapY = -0.1;
    const auto problems = validate(p);
    EXPECT_NE(problemAt(problems, "overlap[0]").find("scan.overlap_out_of_range{value=1, max=0.9}"), std::string::npos) << all(problems);
    EXPECT_NE(problemAt(problems, "overlap[0]").find("value=1"), std::string::npos);
    EXPECT_FALSE(problemAt(problems, "overlap[1]").empty());
    EXPECT_TRUE(layoutScan(p).tiles.empty()) << "an invalid plan has no grid";
}

TEST(ScanPlan, FieldLargerThanTheStageIsRefused)
{
    ScanPlan p;
    p.camera.source = FieldSource::Direct;
    p.camera.fieldWidthMm = 120;
    p.camera.fieldHeightMm = 5;
    const auto problems = validate(p, StageModel{});
    const std::string m = problemAt(problems, "camera.field_mm");
    EXPECT_NE(m.find("scan.field_larger_than_travel"), std::string::npos) << all(problems);
}

TEST(ScanPlan, ZeroSizeRegionsAreRefused)
{
    ScanPlan p;
    p.region.cornerA = {10, 10};
    p.region.cornerB = {10, 30};
    EXPECT_NE(problemAt(validate(p), "region.corners_mm").find("scan.region.corners_zero_size"), std::string::npos);
    p.region.kind = RegionKind::CentreSize;
    p.region.widthMm = 5;
    p.region.heightMm = 0;
    EXPECT_NE(problemAt(validate(p), "region.size_mm").find("scan.region.size_zero"), std::string::npos);
    p.region.kind = RegionKind::Polygon;
    p.region.vertices = {{0, 0}, {1, 1}, {2, 2}};
    EXPECT_NE(problemAt(validate(p), "region.vertices_mm").find("scan.region.zero_area"), std::string::npos);
    p.region.vertices = {{0, 0}, {1, 1}};
    EXPECT_NE(problemAt(validate(p), "region.vertices_mm").find("scan.region.too_few_vertices"), std::string::npos);
}

TEST(ScanPlan, CrossedPolygonIsRefused)
{
    ScanPlan p;
    p.region.kind = RegionKind::Polygon;
    p.region.vertices = {{10, 10}, {20, 20}, {20, 10}, {10, 25}};  // a lopsided bow tie
    EXPECT_NE(problemAt(validate(p), "region.vertices_mm").find("scan.region.self_intersecting"), std::string::npos);
    p.region.vertices = {{10, 10}, {20, 10}, {20, 20}, {10, 20}};
    EXPECT_TRUE(validate(p).empty()) << all(validate(p));
    p.region.vertices = {{10, 10}, {20, 10}, {15, 10}, {15, 20}};  // folds back along itself
    EXPECT_FALSE(problemAt(validate(p), "region.vertices_mm").empty());
}

TEST(ScanPlan, RegionBeyondTheTravelIsRefused)
{
    ScanPlan p;
    p.region.cornerA = {90, 10};
    p.region.cornerB = {105, 20};
    EXPECT_TRUE(validate(p).empty()) << "on its own the plan is fine";
    const std::string m = problemAt(validate(p, StageModel{}), "region.corners_mm");
    EXPECT_NE(m.find("scan.region_beyond_travel"), std::string::npos) << m;
}

TEST(ScanPlan, OvertravelOutsideTheTravelNamesTheTile)
{
    ScanPlan p;
    p.camera.source = FieldSource::Direct;
    p.camera.fieldWidthMm = p.camera.fieldHeightMm = 2;
    p.region.cornerA = {0, 10};
    p.region.cornerB = {2, 12};  // one field centred at (1, 11)
    p.approach.unidirectional = true;
    p.approach.overtravelMm = 1.5;  // from the left: X = −0.5
    const std::string m = problemAt(validate(p, StageModel{}), "approach.overtravel_mm");
    EXPECT_NE(m.find("scan.overtravel_outside_travel{tile=1, x=-0.5 mm, y=12.5 mm"), std::string::npos) << m;
    p.approach.overtravelMm = 0.5;
    EXPECT_TRUE(validate(p, StageModel{}).empty()) << all(validate(p, StageModel{}));
}

TEST(ScanPlan, SpeedAboveTheStageIsRefused)
{
    ScanPlan p;
    p.speedMmS = 25;
    EXPECT_NE(problemAt(validate(p, StageModel{}), "motion.speed_mm_s").find("max=20 mm/s"), std::string::npos);
}

TEST(ScanPlan, TooManyTilesIsRefusedBeforeAnythingIsBuilt)
{
    ScanPlan p;
    p.camera.source = FieldSource::Direct;
    p.camera.fieldWidthMm = p.camera.fieldHeightMm = 0.01;
    p.region.cornerA = {0, 0};
    p.region.cornerB = {100, 100};
    const std::string m = problemAt(validate(p), "camera.field_mm");
    EXPECT_NE(m.find("max=250000"), std::string::npos) << m;
}

TEST(ScanPlan, EveryProblemIsReportedAtOnce)
{
    ScanPlan p;
    p.overlapX = 2;
    p.speedMmS = -1;
    p.exposureS = NAN;
    p.naming.filePattern = "tile.tif";
    EXPECT_EQ(validate(p).size(), 4u) << all(validate(p));
}

TEST(ScanNaming, PatternsFillInIndexRowAndColumn)
{
    ExportNaming n;
    EXPECT_EQ(tileFileName(n, 0, 0, 0), "tile_001.tif");
    EXPECT_EQ(tileFileName(n, 41, 3, 5), "tile_042.tif");
    n.filePattern = "r{row:02}_c{col}_{i}.png";
    n.firstIndex = 0;
    EXPECT_EQ(tileFileName(n, 7, 3, 12), "r03_c12_7.png");
    EXPECT_FALSE(checkFilePattern(n.filePattern));
}

TEST(ScanNaming, PatternsFijiCouldNotReadAreRefused)
{
    EXPECT_TRUE(checkFilePattern("tile_{i};x.tif"));     // ';' splits Fiji's fields
    EXPECT_TRUE(checkFilePattern("#tile_{i}.tif"));      // a comment line to Fiji
    EXPECT_TRUE(checkFilePattern(" tile_{i}.tif"));      // Fiji trims
    EXPECT_TRUE(checkFilePattern("tile.tif"));           // every tile the same name
    EXPECT_TRUE(checkFilePattern("tile_{row}.tif"));
    EXPECT_TRUE(checkFilePattern("tile_{x}.tif"));
    EXPECT_TRUE(checkFilePattern("tile_{i:3}.tif"));
    EXPECT_TRUE(checkFilePattern("tile_{i.tif"));
    EXPECT_TRUE(checkFilePattern("sub/tile_{i}.tif"));
    EXPECT_TRUE(checkFilePattern(""));
    EXPECT_FALSE(checkFilePattern("tile_{row}_{col}.tif"));
    const auto m = checkFilePattern("tile_{x}.tif");
    EXPECT_EQ(motion::msg::debugString(*m), "scan.naming.unknown_placeholder{placeholder=\"{x}\"}");
}

TEST(ScanPlan, NamesOfOrdersAndCornersRoundTrip)
{
    for (ScanOrder o : {ScanOrder::Rows, ScanOrder::Columns, ScanOrder::SnakeRows, ScanOrder::SnakeColumns})
        EXPECT_EQ(orderFromName(orderName(o)), o);
    for (StartCorner c : {StartCorner::TopLeft, StartCorner::TopRight, StartCorner::BottomLeft, StartCorner::BottomRight})
        EXPECT_EQ(startCornerFromName(startCornerName(c)), c);
    EXPECT_FALSE(orderFromName("zigzag"));
}

TEST(ScanPlan, AVanishingSpeedIsRefused)
{
    // Found by fuzz_files: a speed of 1e-320 mm/s passed "above 0" and made the
    // estimate infinite.
    ScanPlan p;
    p.speedMmS = 1e-320;
    EXPECT_NE(problemAt(validate(p), "motion.speed_mm_s").find("min=0.01 mm/s, max=1000 mm/s"), std::string::npos);
    p.speedMmS = 10;
    p.compensation.enabled = true;
    EXPECT_TRUE(validate(p).empty()) << "the device's compensation is checked when the run starts" << all(validate(p));
}
