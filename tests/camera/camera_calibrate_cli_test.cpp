// benchpilot-cli camera calibrate on the simulated stage, with a simulated camera whose true
// pixel, rotation and mirror are not the nominal ones: the profile it writes has the truth,
// and a scan run with that profile stitches with no camera warning, where the plan's own
// camera is told which setting to change.
#include "device/files/camera/camera_profile_file.h"
#include "device/files/text_file.h"

#include "integration/programs.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>

#include <gtest/gtest.h>

using namespace itest;

namespace {

QJsonObject calJson(const itest::ProgramRun& r)
{
    const QByteArray text = r.out.toUtf8();
    return QJsonDocument::fromJson(text.mid(text.indexOf('{'))).object();
}

} // namespace

TEST(CameraCalibrateCli, FindsTheSimulatedCamerasTruePixelRotationAndMirror)
{
    QTemporaryDir dir;
    const QString profile = dir.filePath(QStringLiteral("cam.camera-profile.json"));
    const auto r = runProgram(binary("benchpilot-cli"),
                              {QStringLiteral("--sim"), QStringLiteral("stage"), QStringLiteral("--json"), QStringLiteral("camera"), QStringLiteral("calibrate"),
                               QStringLiteral("--camera"), QStringLiteral("sim"), QStringLiteral("--camera-true"),
                               QStringLiteral("pixel-um=0.70,rotation-deg=2.5,mirror"), QStringLiteral("--home"), QStringLiteral("--at"),
                               QStringLiteral("40,40"), QStringLiteral("--out"), profile},
                              180000);
    ASSERT_EQ(r.exitCode, 0) << r.describe();
    const QJsonObject o = calJson(r);
    // The camera says 0.65 µm (its nominal pixel); the truth is 0.70, turned 2.5°, mirrored.
    EXPECT_DOUBLE_EQ(o.value(QStringLiteral("nominal_pixel_um")).toDouble(), 0.65);
    EXPECT_NEAR(o.value(QStringLiteral("pixel_um")).toArray().at(0).toDouble(), 0.70, 0.70 * 0.003) << r.out.toStdString();
    EXPECT_NEAR(o.value(QStringLiteral("pixel_um")).toArray().at(1).toDouble(), 0.70, 0.70 * 0.003);
    EXPECT_NEAR(o.value(QStringLiteral("rotation_deg")).toDouble(), 2.5, 0.05);
    EXPECT_EQ(o.value(QStringLiteral("image_y")).toString(), QStringLiteral("stage-plus-y"));
    // The stage's grating reads in 0.5 µm steps (0.7 px): the residual is about that.
    EXPECT_LT(o.value(QStringLiteral("residual_rms_px")).toDouble(), 1.0);
    EXPECT_EQ(o.value(QStringLiteral("steps")).toArray().size(), 9);
    const auto read = dev::files::camera::loadCameraProfileFile(profile);
    ASSERT_TRUE(read.ok()) << motion::msg::debugFormat(read.problems());
    EXPECT_TRUE(read->imageYAlongPlusY);
    EXPECT_TRUE(read->calibrated);
    EXPECT_EQ(read->camera, "sim");
}

TEST(CameraCalibrateCli, RefusesAnUnhomedStageAndBadOptions)
{
    QTemporaryDir dir;
    const QString profile = dir.filePath(QStringLiteral("cam.camera-profile.json"));
    const QStringList base{QStringLiteral("--sim"), QStringLiteral("stage"), QStringLiteral("camera"), QStringLiteral("calibrate"),
                           QStringLiteral("--camera"), QStringLiteral("sim"), QStringLiteral("--out"), profile};
    const auto unhomed = runProgram(binary("benchpilot-cli"), base);
    EXPECT_EQ(unhomed.exitCode, 2) << unhomed.describe();
    EXPECT_TRUE(unhomed.err.contains(QStringLiteral("not homed"))) << unhomed.describe();
    EXPECT_FALSE(QFile::exists(profile));
    const auto badTrue = runProgram(binary("benchpilot-cli"), base + QStringList{QStringLiteral("--camera-true"), QStringLiteral("tilt=3")});
    EXPECT_EQ(badTrue.exitCode, 1) << badTrue.describe();
    EXPECT_TRUE(badTrue.err.contains(QStringLiteral("'tilt=3'"))) << badTrue.describe();
    const auto badStep = runProgram(binary("benchpilot-cli"), base + QStringList{QStringLiteral("--step-px"), QStringLiteral("0")});
    EXPECT_EQ(badStep.exitCode, 1) << badStep.describe();
}

TEST(CameraCalibrateCli, AStitchNamesThePlanSettingToChangeAndAProfileSetsItRight)
{
    QTemporaryDir dir;
    // 4 × 3 tiles of 256 × 256 px at 1 µm, 15 % overlap; the camera truly mirrored and turned 1°.
    const auto made = runProgram(binary("benchpilot-cli"),
                                 {QStringLiteral("scan"), QStringLiteral("plan"), QStringLiteral("--roi"), QStringLiteral("20,20,20.7,20.5"),
                                  QStringLiteral("--sensor"), QStringLiteral("256,256"), QStringLiteral("--sensor-um"), QStringLiteral("10"),
                                  QStringLiteral("--mag"), QStringLiteral("10"), QStringLiteral("--overlap"), QStringLiteral("0.15")});
    ASSERT_EQ(made.exitCode, 0) << made.describe();
    const QString plan = dir.filePath(QStringLiteral("p.scan.json"));
    motion::msg::Message error;
    ASSERT_TRUE(dev::files::writeAtomically(plan, made.out.toStdString(), &error));
    const QString truth = QStringLiteral("mirror,rotation-deg=1");
    const auto scanAndStitch = [&](const QString& planFile, const QString& out, const QStringList& extra) {
        const auto run = runProgram(binary("benchpilot-cli"),
                                    QStringList{QStringLiteral("--sim"), QStringLiteral("stage"), QStringLiteral("scan"), QStringLiteral("run"), planFile,
                                                QStringLiteral("--out"), out, QStringLiteral("--home"), QStringLiteral("--camera"), QStringLiteral("sim"),
                                                QStringLiteral("--camera-true"), truth}
                                        + extra,
                                    180000);
        EXPECT_EQ(run.exitCode, 0) << run.describe();
        return runProgram(binary("benchpilot-cli"), {QStringLiteral("--json"), QStringLiteral("stitch"), out, QStringLiteral("--plan"), planFile,
                                                     QStringLiteral("--out"), QDir(out).filePath(QStringLiteral("m.ome.tif"))},
                          180000);
    };
    const auto wrong = scanAndStitch(plan, dir.filePath(QStringLiteral("wrong")), {});
    ASSERT_EQ(wrong.exitCode, 0) << wrong.describe();
    const QJsonObject check = calJson(wrong).value(QStringLiteral("camera_check")).toObject();
    ASSERT_TRUE(check.value(QStringLiteral("measured")).toBool()) << wrong.out.toStdString();
    EXPECT_EQ(check.value(QStringLiteral("image_y")).toString(), QStringLiteral("stage-plus-y"));
    EXPECT_NEAR(check.value(QStringLiteral("rotation_deg")).toDouble(), 1.0, 0.15);
    const QJsonArray change = check.value(QStringLiteral("change")).toArray();
    EXPECT_TRUE(change.contains(QStringLiteral("camera.image_y"))) << wrong.out.toStdString();
    EXPECT_TRUE(change.contains(QStringLiteral("camera.rotation_deg"))) << wrong.out.toStdString();
    EXPECT_FALSE(change.contains(QStringLiteral("camera.pixel_um"))) << wrong.out.toStdString();

    // The profile as calibration would write it, named by a copy of the plan.
    dev::files::camera::CameraProfile p;
    p.camera = "sim";
    p.sensorWidthPx = p.sensorHeightPx = 256;
    p.pixelXUm = p.pixelYUm = 1.0;
    p.rotationDeg = 1.0;
    p.imageYAlongPlusY = true;
    ASSERT_TRUE(dev::files::camera::saveCameraProfileFile(dir.filePath(QStringLiteral("scope.camera-profile.json")), p, &error));
    QString planText = made.out;
    planText.replace(QStringLiteral("\"camera\": {"), QStringLiteral("\"camera\": {\"profile\": \"scope.camera-profile.json\", "));
    ASSERT_TRUE(planText.contains(QStringLiteral("scope.camera-profile.json"))) << planText.toStdString();
    const QString profiled = dir.filePath(QStringLiteral("profiled.scan.json"));
    ASSERT_TRUE(dev::files::writeAtomically(profiled, planText.toStdString(), &error));
    const auto right = scanAndStitch(profiled, dir.filePath(QStringLiteral("right")), {});
    ASSERT_EQ(right.exitCode, 0) << right.describe();
    const QJsonObject ok = calJson(right).value(QStringLiteral("camera_check")).toObject();
    EXPECT_TRUE(ok.value(QStringLiteral("measured")).toBool()) << right.out.toStdString();
    EXPECT_TRUE(ok.value(QStringLiteral("change")).toArray().isEmpty()) << right.out.toStdString();
}
