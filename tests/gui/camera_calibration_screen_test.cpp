// Camera calibration from the Scan screen's Camera tab, end to end on the simulated stage:
// the simulated camera is truly 0.70 µm a pixel, turned 2.5° and mirrored where it says
// 0.65 µm, square and not mirrored; "Calibrate camera…" asks before moving, shows the
// truth with its residual, and "Save as profile…" writes a profile that reads back.
#include "app/gui/instrument_session.h"
#include "device/camera/sim_camera.h"
#include "device/files/camera/camera_profile_file.h"
#include "device/link/simulated_link.h"
#include "gui_window.h"
#include "widgets/camera/camera_calibration_panel.h"
#include "widgets/camera/camera_panel.h"
#include "widgets/camera/camera_session.h"
#include "widgets/scan/scan_screen.h"

#include <QComboBox>
#include <QDir>
#include <QPointer>
#include <QPushButton>
#include <QTemporaryDir>
#include <QtTest/QTest>

#include <gtest/gtest.h>

using guitest::waitFor;

namespace {

/// The simulated camera on the window's simulated stage, truly other than it says.
std::unique_ptr<dev::camera::Camera> untrueSimCamera(app::MainWindow* const* window)
{
    dev::camera::SimCameraSettings s;
    s.geometry.sensorWidthPx = 512;
    s.geometry.sensorHeightPx = 512;
    s.trueGeometry.pixelXUm = 0.70;
    s.trueGeometry.pixelYUm = 0.70;
    s.trueGeometry.rotationDeg = 2.5;
    s.trueGeometry.mirrored = true;
    auto workPoint = [window]() -> std::optional<dev::camera::WorkPoint> {
        auto* link = *window ? qobject_cast<dev::SimulatedLink*>((*window)->stage()->link()) : nullptr;
        if (!link || link->machine().axisCount() < 2)
            return std::nullopt;
        const auto& m = link->machine();
        return dev::camera::WorkPoint{m.workPointLogical(0), m.workPointLogical(1), m.timeUs()};
    };
    return std::make_unique<dev::camera::SimCamera>(workPoint, s);
}

} // namespace

TEST(CameraCalibrationScreen, CalibrateCameraFindsTheTrueCameraAndSavesItsProfile)
{
    app::MainWindow* raw = nullptr;
    app::MainWindowOptions options = guitest::testWindowOptions();
    options.cameraFactory = [&raw](const QString&, QString*) { return untrueSimCamera(&raw); };
    auto w = guitest::openReadyWindow({1366, 768}, options);
    ASSERT_TRUE(w);
    raw = w.get();
    dev::Instrument* stage = w->stage()->instrument();
    stage->home(0);
    ASSERT_TRUE(waitFor([&] { return stage->status().axes.size() >= 2 && stage->status().axes[0].homed && stage->status().axes[1].homed
                                     && !stage->status().anyMoving(); }, 60000));
    stage->move({{0, 40.0}, {1, 40.0}}, false);
    ASSERT_TRUE(waitFor([&] { return !stage->status().anyMoving() && std::fabs(stage->status().axes[0].commanded - 40) < 1e-3
                                     && std::fabs(stage->status().axes[1].commanded - 40) < 1e-3; }, 60000));
    ASSERT_TRUE(w->showScreen(QStringLiteral("scan")));
    ui::ScanScreen* scan = w->scanScreen();
    scan->showTab(1);
    ui::CameraPanel* panel = scan->cameraPanel();
    panel->sourceField()->setCurrentText(QStringLiteral("sim"));
    panel->openTyped();
    ASSERT_TRUE(waitFor([&] { return w->cameraSession()->isOpen(); }, 5000));

    QString asked;
    panel->setConfirm([&](const QString& q) {
        asked = q;
        return true;
    });
    QTemporaryDir dir;
    const QString file = dir.filePath(QStringLiteral("scope.camera-profile.json"));
    panel->setFileChooser([&](const QString&, const QString&) { return file; });
    auto* calibrate = panel->findChild<QPushButton*>(QStringLiteral("cameraCalibrate"));
    ASSERT_TRUE(calibrate);
    ASSERT_TRUE(waitFor([&] { return calibrate->isEnabled(); }, 5000));
    QTest::mouseClick(calibrate, Qt::LeftButton);
    EXPECT_TRUE(asked.contains(QStringLiteral("stage moves"))) << asked.toStdString();
    ui::CameraCalibrationPanel* cal = panel->calibration();
    ASSERT_TRUE(cal->isVisible());
    ASSERT_TRUE(waitFor([&] { return cal->result().has_value() || !cal->isRunning(); }, 120000));
    ASSERT_TRUE(cal->result()) << cal->stateText().toStdString();
    const imaging::CameraStageFit& f = cal->result()->fit;
    EXPECT_NEAR(f.pixelXUm, 0.70, 0.70 * 0.003);
    EXPECT_NEAR(f.pixelYUm, 0.70, 0.70 * 0.003);
    EXPECT_NEAR(f.rotationDeg, 2.5, 0.05);
    EXPECT_TRUE(f.imageYAlongPlusY);
    EXPECT_TRUE(cal->stateText().contains(QStringLiteral("residual"))) << cal->stateText().toStdString();
    EXPECT_TRUE(cal->stateText().contains(QStringLiteral("mirrored"))) << cal->stateText().toStdString();
    // Back where it began.
    EXPECT_NEAR(stage->status().axes[0].commanded, 40, 1e-3);
    EXPECT_NEAR(stage->status().axes[1].commanded, 40, 1e-3);

    // BP_GUI_SHOTS=DIR: the Camera tab with the result, for the docs and for a person to judge.
    if (qEnvironmentVariableIsSet("BP_GUI_SHOTS"))
        w->grab().save(QDir(qEnvironmentVariable("BP_GUI_SHOTS")).filePath(QStringLiteral("camera-calibration.png")));
    auto* save = cal->findChild<QPushButton*>(QStringLiteral("cameraCalibrationSave"));
    ASSERT_TRUE(save && save->isVisible() && save->isEnabled());
    QTest::mouseClick(save, Qt::LeftButton);
    const auto read = dev::files::camera::loadCameraProfileFile(file);
    ASSERT_TRUE(read.ok()) << motion::msg::debugFormat(read.problems());
    EXPECT_TRUE(read->imageYAlongPlusY);
    EXPECT_NEAR(read->rotationDeg, 2.5, 0.05);
    EXPECT_EQ(read->sensorWidthPx, 512);
}

TEST(CameraCalibrationScreen, AnUnhomedStageIsSaidAndNothingMoves)
{
    app::MainWindow* raw = nullptr;
    app::MainWindowOptions options = guitest::testWindowOptions();
    options.cameraFactory = [&raw](const QString&, QString*) { return untrueSimCamera(&raw); };
    auto w = guitest::openReadyWindow({1366, 768}, options);
    ASSERT_TRUE(w);
    raw = w.get();
    ASSERT_TRUE(w->showScreen(QStringLiteral("scan")));
    ui::ScanScreen* scan = w->scanScreen();
    scan->showTab(1);
    ui::CameraPanel* panel = scan->cameraPanel();
    panel->sourceField()->setCurrentText(QStringLiteral("sim"));
    panel->openTyped();
    ASSERT_TRUE(waitFor([&] { return w->cameraSession()->isOpen(); }, 5000));
    bool asked = false;
    panel->setConfirm([&](const QString&) { return asked = true; });
    QString problem;
    QObject::connect(panel, &ui::CameraPanel::problem, [&](const QString& m) { problem = m; });
    QTest::mouseClick(panel->findChild<QPushButton*>(QStringLiteral("cameraCalibrate")), Qt::LeftButton);
    EXPECT_FALSE(asked) << "refused before asking";
    EXPECT_TRUE(problem.contains(QStringLiteral("not homed"))) << problem.toStdString();
    EXPECT_FALSE(panel->calibration()->isRunning());
}
