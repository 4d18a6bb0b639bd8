// The camera benchpilot-sim serves on a socket, chosen on the Scan screen as an operator
// types it (sim:PATH): its live frames are shown with the server's own camera, and when the
// server goes the camera closes with a message naming the socket.
#include "device/camera/sim_camera_server.h"
#include "gui_window.h"
#include "widgets/camera/camera_panel.h"
#include "widgets/camera/camera_session.h"
#include "widgets/camera/live_view.h"
#include "widgets/scan/scan_screen.h"
#include "widgets/wording/translators.h"

#include <QComboBox>
#include <QTemporaryDir>

#include <gtest/gtest.h>

using guitest::waitFor;
namespace cam = dev::camera;

namespace {

class SocketCameraScreen : public ::testing::Test {
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

    ui::words::Translators translators;
    std::unique_ptr<app::MainWindow> w;
};

} // namespace

TEST_F(SocketCameraScreen, TheCameraFieldTakesSimPathAndShowsItsFramesUntilTheServerGoes)
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("cam"));
    cam::SimCameraSettings settings;
    settings.geometry.sensorWidthPx = 160;
    settings.geometry.sensorHeightPx = 120;
    settings.geometry.pixelUm = 1.5;
    auto server = std::make_unique<cam::SimCameraServer>(
        []() -> std::optional<cam::WorkPoint> { return cam::WorkPoint{25, 30, std::nullopt}; }, settings);
    motion::msg::Message error;
    ASSERT_TRUE(server->listen(path, &error)) << motion::msg::debugString(error);

    ASSERT_TRUE(w->showScreen(QStringLiteral("scan")));
    ui::ScanScreen* scan = w->scanScreen();
    scan->showTab(1);
    ui::CameraPanel* panel = scan->cameraPanel();
    QStringList problems;
    QObject::connect(w->cameraSession(), &ui::CameraSession::problem, [&](const QString& p) { problems << p; });
    panel->sourceField()->setCurrentText(QStringLiteral("sim:") + path);
    panel->openTyped();
    ASSERT_TRUE(waitFor([&] { return w->cameraSession()->isOpen(); }, 10000)) << problems.join(QLatin1Char('\n')).toStdString();
    ASSERT_TRUE(waitFor([&] { return panel->liveView()->hasPicture(); }, 20000)) << "no live frame from the socket";
    EXPECT_EQ(panel->liveView()->shown().frameSize, QSize(160, 120)) << "the server's camera";
    EXPECT_DOUBLE_EQ(panel->liveView()->pixelUm(), 1.5);
    EXPECT_TRUE(problems.isEmpty()) << problems.join(QLatin1Char('\n')).toStdString();

    server.reset();
    ASSERT_TRUE(waitFor([&] { return !w->cameraSession()->isOpen() && !problems.isEmpty(); }, 10000));
    EXPECT_TRUE(problems.last().contains(path)) << problems.last().toStdString();
    EXPECT_TRUE(problems.last().contains(QStringLiteral("went away"))) << problems.last().toStdString();
}
