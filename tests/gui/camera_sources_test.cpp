// The camera choice offers the USB cameras found, and finding them (which asks the system's
// multimedia backend, a fraction of a second on a machine's first run) happens only when the
// operator opens the choice: never while the window is built.
#include "app/gui/camera_wiring.h"
#include "fake_camera.h"
#include "gui_window.h"
#include "widgets/camera/camera_panel.h"
#include "widgets/camera/camera_session.h"

#include <QApplication>
#include <QComboBox>

#include <gtest/gtest.h>

namespace {

QStringList itemsOf(const QComboBox* box)
{
    QStringList out;
    for (int i = 0; i < box->count(); ++i)
        out << box->itemText(i);
    return out;
}

} // namespace

TEST(CameraSources, TheUsbCamerasAreListedWhenTheChoiceIsOpenedNotBefore)
{
    ui::CameraSession session;
    int asked = 0;
    session.setLister([&] {
        ++asked;
        return QStringList{QStringLiteral("sim"), QStringLiteral("uvc:HD Webcam")};
    });
    session.setRecentSources({QStringLiteral("folder:/data/in")});
    QWidget window;
    auto* panel = new ui::CameraPanel(&session, nullptr, &window);
    window.resize(800, 600);
    window.show();
    QApplication::processEvents();
    EXPECT_EQ(asked, 0) << "the system was asked for its cameras while the panel was built";
    EXPECT_EQ(itemsOf(panel->sourceField()), (QStringList{QStringLiteral("sim"), QStringLiteral("folder:/data/in")}));
    EXPECT_EQ(panel->sourceText(), QStringLiteral("sim"));

    panel->sourceField()->showPopup();
    EXPECT_EQ(asked, 1);
    EXPECT_EQ(itemsOf(panel->sourceField()), (QStringList{QStringLiteral("sim"), QStringLiteral("uvc:HD Webcam"), QStringLiteral("folder:/data/in")}));
    EXPECT_EQ(panel->sourceText(), QStringLiteral("sim")) << "opening the list does not change what is chosen";
    panel->sourceField()->hidePopup();
    panel->sourceField()->setCurrentIndex(1);
    EXPECT_EQ(panel->sourceText(), QStringLiteral("uvc:HD Webcam"));
}

TEST(CameraSources, TheMainWindowStartsWithoutLookingForCameras)
{
    int asked = 0;
    app::MainWindowOptions options = guitest::testWindowOptions();
    options.cameraFactory = [](const QString& source, QString*) { return std::make_unique<guitest::FakeCamera>(source); };
    options.cameraLister = [&] {
        ++asked;
        return QStringList{QStringLiteral("sim")};
    };
    auto w = guitest::openReadyWindow({1366, 768}, options);
    ASSERT_TRUE(w) << "the simulated instruments did not become ready";
    EXPECT_EQ(asked, 0);
}

TEST(CameraSources, AUsbCameraThatIsNotThereIsSaidAtOnceAndNothingStaysOpening)
{
    // The GUI's own factory: no camera is attached here, so a name none has is refused as
    // the operator would see it, naming what was typed; the panel is not left "opening".
    ui::CameraSession session;
    session.setFactory([](const QString& source, QString* error) { return app::makeCamera(source, nullptr, error); });
    QStringList said;
    QObject::connect(&session, &ui::CameraSession::problem, [&](const QString& m) { said << m; });
    const QString source = QStringLiteral("uvc:BenchPilot test camera that is not there");
    EXPECT_TRUE(session.open(source));
    QApplication::processEvents();
    ASSERT_EQ(said.size(), 1) << said.join(QLatin1Char('\n')).toStdString();
    EXPECT_TRUE(said[0].contains(source)) << said[0].toStdString();
    EXPECT_FALSE(session.isOpen());
    EXPECT_FALSE(session.isOpening());
}
