// The camera profile file (docs/camera.md, "The camera profile file"): the example reads,
// a profile writes and reads back the same, and a bad one is refused with every problem
// at its line and column.
#include "device/files/camera/camera_profile_file.h"
#include "device/files/scan_plan_file.h"
#include "device/files/text_file.h"

#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

using namespace dev::files::camera;

namespace {

std::string profileExample(const std::string& name)
{
    std::ifstream f(std::string(BP_SOURCE_DIR) + "/resources/examples/" + name, std::ios::binary);
    std::stringstream s;
    s << f.rdbuf();
    return s.str();
}

} // namespace

TEST(CameraProfileFile, TheExampleReads)
{
    const auto r = cameraProfileFromJson(profileExample("sim-stage-camera.camera-profile.json"), "sim-stage-camera.camera-profile.json");
    ASSERT_TRUE(r.ok()) << motion::msg::debugFormat(r.problems());
    EXPECT_EQ(r->camera, "sim");
    EXPECT_EQ(r->sensorWidthPx, 2048);
    EXPECT_DOUBLE_EQ(r->pixelXUm, 0.6502);
    EXPECT_DOUBLE_EQ(r->pixelYUm, 0.6497);
    EXPECT_DOUBLE_EQ(r->rotationDeg, 0.42);
    EXPECT_FALSE(r->imageYAlongPlusY);
    ASSERT_TRUE(r->calibrated);
    EXPECT_EQ(r->calibration.images, 8);
    EXPECT_DOUBLE_EQ(r->calibration.residualRmsPx, 0.04);
}

TEST(CameraProfileFile, AProfileWritesAndReadsBackTheSame)
{
    CameraProfile p;
    p.camera = "uvc:Microscope";
    p.sensorWidthPx = 1920;
    p.sensorHeightPx = 1080;
    p.pixelXUm = 1.234;
    p.pixelYUm = 1.236;
    p.rotationDeg = -179.5;
    p.imageYAlongPlusY = true;
    const std::string once = cameraProfileToJson(p);
    const auto r = cameraProfileFromJson(once, "p.json");
    ASSERT_TRUE(r.ok()) << motion::msg::debugFormat(r.problems());
    EXPECT_FALSE(r->calibrated);
    EXPECT_TRUE(r->imageYAlongPlusY);
    EXPECT_EQ(cameraProfileToJson(*r), once);
}

TEST(CameraProfileFile, EveryProblemIsNamedAtItsLineAndColumn)
{
    const std::string text = "{\"schema\": \"benchpilot.camera-profile\", \"version\": 1,\n"
                             " \"sensor_px\": [2048.5, 2048],\n"
                             " \"pixel_um\": [0.65, -1],\n"
                             " \"rotation_deg\": \"two\",\n"
                             " \"image_y\": \"stage-up\", \"pixel\": 1}";
    const auto r = cameraProfileFromJson(text, "bad.camera-profile.json");
    EXPECT_FALSE(r.ok());
    ASSERT_EQ(r.problems().size(), 5u) << motion::msg::debugFormat(r.problems());
    for (const auto& p : r.problems())
        EXPECT_EQ(p.file, "bad.camera-profile.json");
    EXPECT_EQ(r.problems()[0].path, "sensor_px[0]");
    EXPECT_EQ(r.problems()[0].line, 2);
    EXPECT_EQ(r.problems()[0].column, 16);
    EXPECT_EQ(r.problems()[1].path, "pixel_um[1]");
    EXPECT_EQ(r.problems()[1].line, 3);
    EXPECT_EQ(r.problems()[2].path, "rotation_deg");
    EXPECT_EQ(r.problems()[2].line, 4);
    EXPECT_EQ(r.problems()[3].path, "image_y");
    EXPECT_EQ(r.problems()[3].line, 5);
    EXPECT_EQ(r.problems()[4].path, "pixel");
}

TEST(CameraProfileFile, AnotherSchemaOrANewerVersionIsRefused)
{
    EXPECT_FALSE(cameraProfileFromJson("{\"schema\": \"benchpilot.scan-plan\", \"version\": 1}", "x.json").ok());
    const auto r = cameraProfileFromJson("{\"schema\": \"benchpilot.camera-profile\", \"version\": 2}", "x.json");
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.problems()[0].message.id, "file.json_field");
}

TEST(CameraProfileFile, APlanNamingAProfileTakesItsCameraAndOneWithoutLoadsAsBefore)
{
    QTemporaryDir dir;
    motion::msg::Message error;
    ASSERT_TRUE(dev::files::writeAtomically(dir.filePath(QStringLiteral("scope.camera-profile.json")),
                                            profileExample("sim-stage-camera.camera-profile.json"), &error));
    const std::string plan = profileExample("slide-overview.scan.json");
    ASSERT_NE(plan.find("\"camera\": {"), std::string::npos);
    std::string named = plan;
    named.replace(named.find("\"camera\": {"), 11, "\"camera\": {\"profile\": \"scope.camera-profile.json\",");
    ASSERT_TRUE(dev::files::writeAtomically(dir.filePath(QStringLiteral("plain.scan.json")), plan, &error));
    ASSERT_TRUE(dev::files::writeAtomically(dir.filePath(QStringLiteral("named.scan.json")), named, &error));

    motion::scan::ScanPlan plain, withProfile;
    dev::files::json::Problems problems;
    ASSERT_TRUE(dev::files::scan::loadPlan(dir.filePath(QStringLiteral("plain.scan.json")), &plain, &problems));
    EXPECT_TRUE(plain.camera.profile.empty());
    ASSERT_TRUE(dev::files::scan::loadPlan(dir.filePath(QStringLiteral("named.scan.json")), &withProfile, &problems));
    EXPECT_EQ(withProfile.camera.profile, "scope.camera-profile.json");
    EXPECT_DOUBLE_EQ(withProfile.camera.rotationDeg, 0.42);
    EXPECT_NEAR(motion::scan::pixelAtSampleUm(withProfile.camera), (0.6502 + 0.6497) / 2, 1e-12);
    EXPECT_NEAR(motion::scan::fieldWidthMm(withProfile.camera), 2048 * (0.6502 + 0.6497) / 2 / 1000, 1e-12);
    // Written again, it still names the profile.
    EXPECT_NE(dev::files::scan::writePlan(withProfile).find("\"profile\": \"scope.camera-profile.json\""), std::string::npos);
}

TEST(CameraProfileFile, APlanNamingAMissingProfileSaysWhichAndWhere)
{
    QTemporaryDir dir;
    motion::msg::Message error;
    std::string named = profileExample("slide-overview.scan.json");
    named.replace(named.find("\"camera\": {"), 11, "\"camera\": {\"profile\": \"gone.camera-profile.json\",");
    ASSERT_TRUE(dev::files::writeAtomically(dir.filePath(QStringLiteral("named.scan.json")), named, &error));
    motion::scan::ScanPlan plan;
    dev::files::json::Problems problems;
    EXPECT_FALSE(dev::files::scan::loadPlan(dir.filePath(QStringLiteral("named.scan.json")), &plan, &problems));
    ASSERT_FALSE(problems.empty());
    EXPECT_EQ(problems.list().front().path, "camera.profile");
    EXPECT_EQ(problems.list().front().message.id, "scan.plan.camera_profile_problem");
    EXPECT_GT(problems.list().front().line, 1);
}
