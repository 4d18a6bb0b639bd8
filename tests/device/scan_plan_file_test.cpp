// The scan plan file: round trip, the examples people start from, and errors that
// name file, line, column and field — the plan's own rules included.
#include "device/english_words.h"
#include "device/files/scan_plan_file.h"
#include "motion/plans/scan/scan_layout.h"

#include <gtest/gtest.h>

#include <QDir>
#include <QFile>
#include <QTemporaryDir>

#include <string>

using namespace motion::scan;

namespace {

QString examplesDir()
{
    return QStringLiteral(BP_SOURCE_DIR "/resources/examples");
}

std::string errors(std::string_view text)
{
    return i18ntest::englishFormat(dev::files::scan::parsePlan(text).problems, "plan.scan.json");
}

ScanPlan unusualPlan()
{
    ScanPlan p;
    p.name = "Odd \"one\" é";
    p.region.kind = RegionKind::Polygon;
    p.region.vertices = {{10.5, 11.25}, {30, 12}, {22.125, 29.0625}};
    p.camera.source = FieldSource::Direct;
    p.camera.fieldWidthMm = 0.83;
    p.camera.fieldHeightMm = 0.7;
    p.camera.samplePixelUm = 0.4321;
    p.camera.rotationDeg = -1.25;
    p.camera.imageY = ImageY::StagePlusY;
    p.overlapX = 0.17;
    p.overlapY = 0.33;
    p.order = ScanOrder::SnakeColumns;
    p.start = StartCorner::BottomRight;
    p.approach = {true, 0.35};
    p.speedMmS = 7.5;
    p.settleS = 0.2;
    p.exposureS = 0.125;
    p.toleranceUm = 0.75;
    p.settleTimeoutS = 3;
    p.compensation.enabled = true;
    p.naming = {"img-{row}-{col}.png", 0, "XY"};
    return p;
}

} // namespace

TEST(ScanPlanFile, EveryFieldRoundTrips)
{
    const ScanPlan p = unusualPlan();
    const std::string text = dev::files::scan::writePlan(p);
    const auto r = dev::files::scan::parsePlan(text);
    ASSERT_TRUE(r.plan) << i18ntest::englishFormat(r.problems, "x");
    EXPECT_EQ(dev::files::scan::writePlan(*r.plan), text);
    EXPECT_EQ(r.plan->name, p.name);
    EXPECT_EQ(r.plan->region.vertices.size(), 3u);
    EXPECT_EQ(r.plan->region.vertices[2].yMm, 29.0625);
    EXPECT_EQ(r.plan->camera.imageY, ImageY::StagePlusY);
    EXPECT_EQ(r.plan->order, ScanOrder::SnakeColumns);
    EXPECT_EQ(r.plan->start, StartCorner::BottomRight);
    EXPECT_TRUE(r.plan->compensation.enabled);
    EXPECT_EQ(r.plan->naming.mmXyStage, "XY");
    EXPECT_EQ(layoutFingerprint(*r.plan, layoutScan(*r.plan)), layoutFingerprint(p, layoutScan(p)));
}

TEST(ScanPlanFile, ExamplesLoadAndPlan)
{
    const QStringList names = QDir(examplesDir()).entryList({QStringLiteral("*.scan.json")}, QDir::Files);
    ASSERT_GE(names.size(), 3) << examplesDir().toStdString();
    for (const QString& name : names) {
        ScanPlan p;
        dev::files::json::Problems problems;
        ASSERT_TRUE(dev::files::scan::loadPlan(QDir(examplesDir()).filePath(name), &p, &problems)) << i18ntest::englishFormat(problems, name.toStdString());
        EXPECT_TRUE(validate(p, StageModel{}).empty()) << name.toStdString() << " does not fit the stage";
        EXPECT_GT(layoutScan(p).tiles.size(), 10u) << name.toStdString();
    }
}

TEST(ScanPlanFile, ShortFilesTakeTheDefaults)
{
    const auto r = dev::files::scan::parsePlan(R"({"schema": "benchpilot.scan-plan", "version": 1,
        "region": {"kind": "centre-size", "centre_mm": [50, 50], "size_mm": [5, 4]},
        "camera": {"fov_from": "field", "field_mm": [1, 1]}, "overlap": 0.25})");
    ASSERT_TRUE(r.plan) << i18ntest::englishFormat(r.problems, "x");
    EXPECT_EQ(r.plan->overlapX, 0.25);
    EXPECT_EQ(r.plan->overlapY, 0.25);
    const ScanPlan defaults;
    EXPECT_EQ(r.plan->order, defaults.order);
    EXPECT_EQ(r.plan->toleranceUm, 1.0);
    EXPECT_EQ(r.plan->naming.filePattern, "tile_{i:03}.tif");
}

TEST(ScanPlanFile, PlanRulesPointAtTheirField)
{
    const std::string text = "{\n"
                             "  \"schema\": \"benchpilot.scan-plan\",\n"
                             "  \"version\": 1,\n"
                             "  \"region\": {\"kind\": \"rectangle\", \"corners_mm\": [[10, 10], [10, 20]]},\n"
                             "  \"camera\": {\"fov_from\": \"field\", \"field_mm\": [1, 1]},\n"
                             "  \"overlap\": [0.1, 1.2],\n"
                             "  \"export\": {\"file_pattern\": \"a;{i}.tif\"}\n"
                             "}\n";
    const std::string e = errors(text);
    EXPECT_NE(e.find("plan.scan.json:4:49: region.corners_mm: the region has zero size"), std::string::npos) << e;
    EXPECT_NE(e.find("plan.scan.json:6:20: overlap[1]: must be from 0 to 0.9, a share of the field (got 1.2)"), std::string::npos) << e;
    EXPECT_NE(e.find("plan.scan.json:7:30: export.file_pattern: must not contain ';'"), std::string::npos) << e;
}

TEST(ScanPlanFile, StructureProblemsAreAllReported)
{
    const std::string text = "{\n"
                             "  \"schema\": \"benchpilot.scan-plan\", \"version\": 1,\n"
                             "  \"region\": {\"kind\": \"polygon\", \"vertices_mm\": [[1, 2], [3, \"x\"], [5]]},\n"
                             "  \"camera\": {\"fov_from\": \"sensor\", \"sensor_px\": [2048.5, 2048], \"magnification\": 10},\n"
                             "  \"order\": \"zigzag\",\n"
                             "  \"timing\": {\"exposure\": 0.1}\n"
                             "}\n";
    const std::string e = errors(text);
    EXPECT_NE(e.find(":3:61: region.vertices_mm[1][1]: must be a number, not a string"), std::string::npos) << e;
    EXPECT_NE(e.find(":3:67: region.vertices_mm[2]: must be an array of 2 numbers"), std::string::npos) << e;
    EXPECT_NE(e.find("camera.sensor_px[0]: must be a whole number (got 2048.5)"), std::string::npos) << e;
    EXPECT_NE(e.find("camera.sensor_pixel_um: is missing"), std::string::npos) << e;
    EXPECT_NE(e.find(":5:12: order: \"zigzag\" is not one of \"rows\", \"cols\", \"snake-rows\", \"snake-cols\""), std::string::npos) << e;
    EXPECT_NE(e.find("timing.exposure: unknown field; did you mean \"exposure_s\"?"), std::string::npos) << e;
}

TEST(ScanPlanFile, NewerVersionsAndOtherKindsAreRefused)
{
    EXPECT_NE(errors(R"({"schema": "benchpilot.scan-plan", "version": 2})").find("written by a newer BenchPilot"), std::string::npos);
    EXPECT_NE(errors(R"({"schema": "benchpilot.recipe", "version": 1})").find("expected \"benchpilot.scan-plan\""), std::string::npos);
    EXPECT_NE(errors("{\"schema\": \"benchpilot.scan-plan\",}").find("plan.scan.json:1:"), std::string::npos);
}

TEST(ScanPlanFile, SavesAtomicallyAndLoadsBack)
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("p.scan.json"));
    motion::msg::Message error;
    ASSERT_TRUE(dev::files::scan::savePlan(path, unusualPlan(), &error)) << error;
    ScanPlan back;
    dev::files::json::Problems problems;
    ASSERT_TRUE(dev::files::scan::loadPlan(path, &back, &problems)) << i18ntest::englishFormat(problems, "p.scan.json");
    EXPECT_EQ(dev::files::scan::writePlan(back), dev::files::scan::writePlan(unusualPlan()));
    QFile f(path);
    ASSERT_TRUE(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
    f.write("{\"schema\": \"benchpilot.scan-plan\", \"version\": 1, \"region\": {}}");
    f.close();
    EXPECT_FALSE(dev::files::scan::loadPlan(path, &back, &problems));
    EXPECT_EQ(i18ntest::englishFormat(problems, "p.scan.json").rfind("p.scan.json:1:", 0), 0u) << i18ntest::englishFormat(problems, "p.scan.json");
}

TEST(ScanPlanFile, FingerprintFollowsTheTilesNotTheName)
{
    ScanPlan p;
    const auto a = layoutFingerprint(p, layoutScan(p));
    p.name = "renamed";
    p.exposureS = 0.5;
    EXPECT_EQ(layoutFingerprint(p, layoutScan(p)), a);
    p.overlapX = 0.11;
    EXPECT_NE(layoutFingerprint(p, layoutScan(p)), a);
    p.overlapX = 0.1;
    p.compensation.enabled = true;
    EXPECT_NE(layoutFingerprint(p, layoutScan(p)), a) << "the stage's compensation changes where the work point lands";
}

TEST(ScanPlanFile, SeedTwosCurvesInAnOlderPlanAreReadAndNoLongerUsed)
{
    // Older plan files carry seed 002's curves (from before the stage kept its own
    // compensation); such a file still opens, and the plan asks for the device's compensation.
    ScanPlan p;
    p.compensation.enabled = true;
    std::string text = dev::files::scan::writePlan(p);
    const std::string key = "\"enabled\": true";
    const auto at = text.find(key);
    ASSERT_NE(at, std::string::npos) << text;
    text.insert(at + key.size(), ",\n    \"x_error_poly_um\": [1.563, 0.9473, -0.0006],\n    \"y_error_poly_um\": [1.021, 0.6397, 0.0168]");
    const auto r = dev::files::scan::parsePlan(text);
    ASSERT_TRUE(r.plan) << r.problems.format("old.scan.json");
    EXPECT_TRUE(r.plan->compensation.enabled);
    EXPECT_EQ(dev::files::scan::writePlan(*r.plan).find("error_poly"), std::string::npos) << "written without them";
}
