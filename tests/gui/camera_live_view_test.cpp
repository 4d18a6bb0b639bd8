// The live view as an operator uses it, on the real widgets with a fake camera: frames
// are shown, a burst faster than the processing is dropped rather than queued, the
// focus figure rises as the picture sharpens, 16-bit auto-contrast maps its
// percentiles, the scale bar is as long as the pixel size says, and the camera's state
// (source, exposure, paused, contrast, the scan's option) survives a language switch.
#include "device/camera/sim_camera.h"
#include "device/camera/tile_tiff.h"
#include "device/jobs/scan_runner.h"
#include "fake_camera.h"
#include "gui_window.h"
#include "widgets/camera/camera_panel.h"
#include "widgets/camera/camera_session.h"
#include "widgets/camera/focus_plot.h"
#include "widgets/camera/live_view.h"
#include "widgets/common/button_key.h"
#include "widgets/common/number_field.h"
#include "widgets/jog_screen.h"
#include "widgets/scan/scan_screen.h"
#include "widgets/scan/stitch_panel.h"
#include "widgets/scan/stitch_quality_map.h"
#include "widgets/wording/translators.h"

#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QFileInfo>
#include <QImage>
#include <QPushButton>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTest>

#include <gtest/gtest.h>

#include <atomic>

using guitest::FakeCamera;
using guitest::waitFor;

namespace {

/// A camera panel on its own, shown, with a fake camera open.
struct PanelRig {
    ui::CameraSession session;
    ui::CameraPanel* panel = nullptr;
    QWidget window;

    PanelRig()
    {
        session.setFactory([](const QString& source, QString*) { return std::make_unique<FakeCamera>(source); });
        panel = new ui::CameraPanel(&session, nullptr, &window);
        window.resize(900, 700);
        panel->resize(900, 700);
        window.show();
    }
    bool open()
    {
        session.open(QStringLiteral("sim"));
        return waitFor([&] { return session.isOpen(); }, 2000);
    }
    FakeCamera* camera() { return static_cast<FakeCamera*>(session.camera()); }
    ui::LiveView* view() { return panel->liveView(); }
    /// Pushes `frame` and waits until the view has finished with it.
    bool show(const dev::camera::Frame& frame)
    {
        const auto before = view()->processor()->processedCount();
        camera()->push(frame);
        return waitFor([&] { return view()->processor()->processedCount() > before && !view()->processor()->busy(); }, 5000);
    }
};

std::uint8_t greyAt(const QImage& image, int x, int y) { return std::uint8_t(qGray(image.pixel(x, y))); }

} // namespace

TEST(CameraLiveView, ShowsTheFramesTheCameraSends)
{
    PanelRig rig;
    EXPECT_FALSE(rig.view()->hasPicture());
    ASSERT_TRUE(rig.open());
    EXPECT_TRUE(rig.camera()->live()) << "the live stream was not started";
    ASSERT_TRUE(rig.show(guitest::texture(320, 240, 0, 7)));
    ASSERT_TRUE(rig.view()->hasPicture());
    EXPECT_EQ(rig.view()->shown().frameSize, QSize(320, 240));
    EXPECT_EQ(rig.view()->shown().sequence, 7u);
    EXPECT_TRUE(rig.view()->overlayText().contains(QStringLiteral("320 × 240 px"))) << rig.view()->overlayText().toStdString();
    // Paused, a frame is not even processed; resumed, it is.
    QTest::mouseClick(rig.view()->findChild<QPushButton*>(QStringLiteral("livePause")), Qt::LeftButton);
    ASSERT_TRUE(rig.view()->isPaused());
    const auto taken = rig.view()->framesTaken();
    rig.camera()->push(guitest::texture(320, 240, 0, 8));
    QApplication::processEvents();
    EXPECT_EQ(rig.view()->framesTaken(), taken);
    EXPECT_EQ(rig.view()->shown().sequence, 7u) << "a paused view changed its picture";
    rig.view()->setPaused(false);
    ASSERT_TRUE(rig.show(guitest::texture(320, 240, 0, 9)));
    EXPECT_EQ(rig.view()->shown().sequence, 9u);
    // Closing the camera takes the picture away rather than leaving a stale one up.
    QTest::mouseClick(rig.panel->findChild<QPushButton*>(QStringLiteral("cameraOpen")), Qt::LeftButton);
    EXPECT_FALSE(rig.session.isOpen());
    EXPECT_FALSE(rig.view()->hasPicture());
}

TEST(CameraLiveView, ABurstFasterThanTheProcessingIsDroppedNotQueued)
{
    PanelRig rig;
    ASSERT_TRUE(rig.open());
    // 50 frames arrive while the GUI thread is busy: the first is taken, each later one
    // replaces the one waiting, so two are processed in all and the last is the one shown.
    const dev::camera::Frame big = guitest::texture(1024, 1024, 0);
    for (std::uint64_t s = 1; s <= 50; ++s) {
        dev::camera::Frame f = big;
        f.sequence = s;
        rig.camera()->push(f);
    }
    auto* p = rig.view()->processor();
    EXPECT_EQ(p->submittedCount(), 50u);
    ASSERT_TRUE(waitFor([&] { return !p->busy() && p->processedCount() >= 2; }, 10000));
    QApplication::processEvents();
    EXPECT_EQ(p->processedCount(), 2u) << "frames were queued rather than dropped";
    EXPECT_EQ(p->droppedCount(), 48u);
    EXPECT_EQ(rig.view()->shown().sequence, 50u) << "the picture shown is not the latest frame";
}

TEST(CameraLiveView, TheFocusFigureRisesAsThePictureSharpens)
{
    PanelRig rig;
    ASSERT_TRUE(rig.open());
    for (int blur : {6, 3, 1, 0})
        ASSERT_TRUE(rig.show(guitest::texture(400, 300, blur)));
    const QVector<double>& h = rig.view()->focusHistory();
    ASSERT_EQ(h.size(), 4);
    for (int i = 1; i < h.size(); ++i)
        EXPECT_GT(h[i], h[i - 1] * 1.2) << "step " << i << ": a sharper picture did not score clearly higher";
    // The history is bounded: the plot shows the recent frames, not the session's.
    for (int i = 0; i < ui::FocusPlot::kHistory + 10; ++i)
        ASSERT_TRUE(rig.show(guitest::texture(40, 30, 0)));
    EXPECT_EQ(rig.view()->focusHistory().size(), ui::FocusPlot::kHistory);
}

TEST(CameraLiveView, SixteenBitAutoContrastMapsThePercentiles)
{
    PanelRig rig;
    ASSERT_TRUE(rig.open());
    // 10 000 pixels with levels 1000 … 10 999: 0.1 % of them lie below 1010 and above 10 990.
    // The stretch reads every fourth pixel, so it may miss by up to four levels.
    ASSERT_TRUE(rig.show(guitest::ramp16(100, 100, 1000)));
    const ui::ProcessedFrame& f = rig.view()->shown();
    EXPECT_NEAR(f.stretch.low, 1010, 4);
    EXPECT_NEAR(f.stretch.high, 10990, 4);
    ASSERT_EQ(f.image.size(), QSize(100, 100)) << "a small frame is shown at its own size";
    EXPECT_EQ(greyAt(f.image, 0, 0), 0);          // level 1000: below the stretch, black
    EXPECT_EQ(greyAt(f.image, 99, 99), 255);      // level 10 999: above it, white
    EXPECT_NEAR(greyAt(f.image, 0, 50), 127.5, 1.5);  // level 6000, half way
    // Off, the whole 16-bit range maps to 0–255: the same picture is nearly black.
    auto* toggle = rig.view()->findChild<QCheckBox*>(QStringLiteral("liveAutoContrast"));
    toggle->click();
    EXPECT_FALSE(rig.session.autoContrast()) << "the toggle is the session's, shared with the other screen";
    ASSERT_TRUE(rig.show(guitest::ramp16(100, 100, 1000)));
    EXPECT_EQ(rig.view()->shown().stretch.low, 0);
    EXPECT_EQ(rig.view()->shown().stretch.high, 65535);
    EXPECT_NEAR(greyAt(rig.view()->shown().image, 0, 50), 6000.0 * 255 / 65535, 1.0);
}

TEST(CameraLiveView, TheScaleBarIsAsLongAsThePixelSizeSays)
{
    PanelRig rig;
    ASSERT_TRUE(rig.open());
    dev::camera::Frame f = guitest::texture(1000, 800, 0);
    f.pixelUm = 0.65;
    ASSERT_TRUE(rig.show(f));
    const ui::ScaleBar bar = rig.view()->scaleBar();
    const double shownWidth = rig.view()->pictureRect().width();
    ASSERT_GT(shownWidth, 100);
    // 1000 px of 0.65 µm are 650 µm across: a fifth is 130 µm, so the bar is 100 µm.
    EXPECT_DOUBLE_EQ(bar.lengthUm, 100);
    EXPECT_NEAR(bar.lengthPx, 100 / 0.65 * shownWidth / 1000, 0.01);
    // A frame that does not say its pixel takes the screen's; none at all: no bar.
    f.pixelUm = 0;
    ASSERT_TRUE(rig.show(f));
    EXPECT_EQ(rig.view()->scaleBar().lengthUm, 0);
    rig.view()->setFallbackPixelUm(2.0);
    EXPECT_DOUBLE_EQ(rig.view()->scaleBar().lengthUm, 200);  // 2000 µm across: a fifth is 400, so 200
    EXPECT_NEAR(rig.view()->scaleBar().lengthPx, 200 / 2.0 * shownWidth / 1000, 0.01);
    // The scale bar rounds to 1, 2 or 5 × 10ⁿ.
    EXPECT_DOUBLE_EQ(ui::scaleBarFor(1.0, 1000, 500).lengthUm, 200);
    EXPECT_DOUBLE_EQ(ui::scaleBarFor(0.1, 1000, 500).lengthUm, 20);
    EXPECT_DOUBLE_EQ(ui::scaleBarFor(0.3, 1000, 500).lengthUm, 50);
}

TEST(CameraLiveView, ASnapIsWrittenWithItsOwnBitDepth)
{
    PanelRig rig;
    ASSERT_TRUE(rig.open());
    QTemporaryDir dir;
    rig.camera()->captureFrame = guitest::ramp16(64, 32, 30000);
    const QString path = dir.filePath(QStringLiteral("snap.tif"));
    QString written;
    QObject::connect(rig.panel, &ui::CameraPanel::snapWritten, [&](const QString& p) { written = p; });
    ASSERT_TRUE(rig.panel->snapTo(path));
    EXPECT_EQ(rig.camera()->lastRequest.tile, -1);
    ASSERT_TRUE(waitFor([&] { return !written.isEmpty(); }, 5000));
    dev::camera::Frame back;
    std::string description;
    motion::msg::Message error;
    ASSERT_TRUE(dev::camera::readTiff(path.toStdString(), &back, &description, &error)) << error.id;
    EXPECT_EQ(back.width, 64);
    EXPECT_EQ(back.height, 32);
    EXPECT_EQ(back.format, dev::camera::PixelFormat::Grey16);
    EXPECT_EQ(back.pixels, rig.camera()->captureFrame.pixels);
    EXPECT_NE(description.find("sim"), std::string::npos) << description;
}

TEST(CameraLiveView, ACameraWithNothingToLookAtSaysSoInTheViewOnceAndRecovers)
{
    // The in-process simulated camera opened while no simulator is connected (the GUI on
    // a serial port): the view used to say "Opening the camera…" for ever.
    std::atomic<bool> stage{false};
    ui::CameraSession session;
    dev::camera::SimCameraSettings settings;
    settings.geometry.sensorWidthPx = settings.geometry.sensorHeightPx = 64;
    session.setFactory([&](const QString&, QString*) {
        return std::make_unique<dev::camera::SimCamera>(
            [&]() -> std::optional<dev::camera::WorkPoint> {
                if (!stage)
                    return std::nullopt;
                return dev::camera::WorkPoint{10, 10, std::nullopt};
            },
            settings);
    });
    QWidget window;
    auto* panel = new ui::CameraPanel(&session, nullptr, &window);
    window.resize(900, 700);
    panel->resize(900, 700);
    window.show();
    int said = 0;
    QObject::connect(&session, &ui::CameraSession::problem, [&](const QString&) { ++said; });
    session.open(QStringLiteral("sim"));
    ASSERT_TRUE(waitFor([&] { return !session.liveProblem().isEmpty(); }, 3000));
    const QString shown = panel->liveView()->message();
    EXPECT_TRUE(shown.contains(QStringLiteral("no simulated stage"))) << shown.toStdString();
    QTest::qWait(2500);  // two more looks at the stage
    EXPECT_EQ(said, 1) << "the banner is told once, not every look";

    stage = true;
    ASSERT_TRUE(waitFor([&] { return panel->liveView()->hasPicture(); }, 5000)) << panel->liveView()->message().toStdString();
    EXPECT_TRUE(session.liveProblem().isEmpty());
}

TEST(CameraLiveView, ASourceThatCannotBeReadIsRefusedWithTheForms)
{
    ui::CameraSession session;
    QString said;
    QObject::connect(&session, &ui::CameraSession::problem, [&](const QString& m) { said = m; });
    EXPECT_FALSE(session.open(QStringLiteral("webcam0")));
    EXPECT_TRUE(said.contains(QStringLiteral("webcam0")) && said.contains(QStringLiteral("uvc[:NAME]"))) << said.toStdString();
    EXPECT_FALSE(session.open(QStringLiteral("folder:")));
    EXPECT_TRUE(said.contains(QStringLiteral("folder:"))) << said.toStdString();
    EXPECT_FALSE(session.isOpen());
    EXPECT_TRUE(ui::CameraSession::sourceProblem(QStringLiteral("command:gphoto2 --capture-image-and-download --filename {file}")).isEmpty());
}

namespace {

class CameraScreens : public ::testing::Test {
protected:
    void SetUp() override
    {
        ASSERT_TRUE(translators.setLanguage(QStringLiteral("en")));
        app::MainWindowOptions options = guitest::testWindowOptions();
        options.translators = &translators;
        if (fakeCamera())
            options.cameraFactory = [](const QString& source, QString*) { return std::make_unique<FakeCamera>(source); };
        w = guitest::openReadyWindow({1366, 768}, options);
        ASSERT_TRUE(w) << "the simulated instruments did not become ready";
    }
    void TearDown() override
    {
        w.reset();
        translators.setLanguage(QStringLiteral("en"));
    }
    virtual bool fakeCamera() const { return true; }
    /// The Scan screen's Camera tab with "sim" typed and opened, as an operator would;
    /// nullptr if it did not open within `ms`.
    ui::CameraPanel* openTypedSimOnScan(int ms)
    {
        if (!w->showScreen(QStringLiteral("scan")))
            return nullptr;
        ui::ScanScreen* scan = w->scanScreen();
        scan->showTab(1);
        ui::CameraPanel* panel = scan->cameraPanel();
        panel->sourceField()->setCurrentText(QStringLiteral("sim"));
        panel->openTyped();
        return waitFor([&] { return w->cameraSession()->isOpen(); }, ms) ? panel : nullptr;
    }
    void chooseLanguage(const QString& code)
    {
        for (QAction* a : w->findChildren<QAction*>())
            if (a->data().toString() == code) {
                a->trigger();
                break;
            }
        QApplication::processEvents();
    }

    ui::words::Translators translators;
    std::unique_ptr<app::MainWindow> w;
};

/// The window with the GUI's own cameras: `sim` is the simulated camera on the simulated stage.
class SimulatedCameraScreens : public CameraScreens {
protected:
    bool fakeCamera() const override { return false; }
    /// The stage homed, the Scan screen showing a centre-and-size plan into `folder`, the
    /// simulated camera open and asked for at each tile; nullptr if any of it failed.
    ui::ScanScreen* cameraScan(motion::scan::Point2 centre, double widthMm, double heightMm, const QString& folder)
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
        p.region.centre = centre;
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
};

} // namespace

TEST_F(CameraScreens, TheScanAndJogScreensShowTheOneCamera)
{
    ASSERT_TRUE(w->showScreen(QStringLiteral("scan")));
    ui::ScanScreen* scan = w->scanScreen();
    ui::CameraPanel* panel = scan->cameraPanel();
    ASSERT_NE(panel, nullptr);
    scan->showTab(1);
    panel->sourceField()->setCurrentText(QStringLiteral("sim"));
    QTest::mouseClick(panel->findChild<QPushButton*>(QStringLiteral("cameraOpen")), Qt::LeftButton);
    ASSERT_TRUE(waitFor([&] { return w->cameraSession()->isOpen(); }, 2000));
    auto* cam = static_cast<FakeCamera*>(w->cameraSession()->camera());
    dev::camera::Frame f = guitest::texture(800, 600, 1);
    cam->push(f);
    ASSERT_TRUE(waitFor([&] { return panel->liveView()->hasPicture(); }, 5000));
    // The plan's camera gives the pixel where the frame does not: 6.5 µm / 10× = 0.65 µm.
    EXPECT_DOUBLE_EQ(panel->liveView()->pixelUm(), 0.65);
    EXPECT_GT(panel->liveView()->scaleBar().lengthUm, 0);
    // The Jog screen's panel shows the same camera, once it is on screen.
    ASSERT_TRUE(w->showScreen(QStringLiteral("jog")));
    w->showInstrument(1);
    ui::CameraPanel* jogPanel = w->jogCameraPanel();
    ASSERT_NE(jogPanel, nullptr);
    ASSERT_TRUE(waitFor([&] { return jogPanel->isVisible(); }, 2000));
    cam->push(f);
    ASSERT_TRUE(waitFor([&] { return jogPanel->liveView()->hasPicture(); }, 5000));
    EXPECT_EQ(jogPanel->sourceText(), QStringLiteral("sim"));
    // The stage is homed on the simulator after a while; until then the view says it does not know.
    EXPECT_FALSE(jogPanel->liveView()->overlayText().isEmpty());
    guitest::keepPicture(w.get(), QStringLiteral("camera-jog.png"));
}

TEST_F(CameraScreens, ARunAskedForImagesWithNoCameraOpenDoesNotStart)
{
    ASSERT_TRUE(w->showScreen(QStringLiteral("scan")));
    ui::ScanScreen* scan = w->scanScreen();
    QString said;
    QObject::connect(scan, &ui::ScanScreen::problem, [&](const QString& m) { said = m; });
    scan->setTakesImages(true);
    EXPECT_FALSE(scan->run());
    EXPECT_TRUE(said.contains(QStringLiteral("Open a camera"))) << said.toStdString();
    EXPECT_EQ(scan->runCamera(), nullptr);
}

TEST_F(CameraScreens, TheRunIsHandedTheOpenCameraOnlyWhenAskedForImages)
{
    ASSERT_TRUE(w->showScreen(QStringLiteral("scan")));
    ui::ScanScreen* scan = w->scanScreen();
    QTemporaryDir dir;
    scan->setOutputFolder(dir.filePath(QStringLiteral("run")));
    w->cameraSession()->open(QStringLiteral("sim"));
    ASSERT_TRUE(waitFor([&] { return w->cameraSession()->isOpen(); }, 2000));
    scan->setTakesImages(true);
    scan->run();  // the stage is not homed: it may refuse to start, but the camera is handed over first
    ASSERT_NE(scan->runner()->camera(), nullptr);
    EXPECT_EQ(QString::fromStdString(scan->runner()->camera()->sourceName()), QStringLiteral("sim"));
    scan->abort();
    scan->setTakesImages(false);
    scan->run();
    EXPECT_EQ(scan->runner()->camera(), nullptr) << "a run without images was handed the camera";
    scan->abort();
}

TEST_F(CameraScreens, F9SnapsFromTheScreenShown)
{
    // Both the Scan screen and the stage's Jog screen have a Snap button on F9: only the
    // one on screen may take it, or Qt calls the key ambiguous and neither snaps.
    ASSERT_TRUE(w->showScreen(QStringLiteral("scan")));
    ui::ScanScreen* scan = w->scanScreen();
    scan->showTab(1);
    w->cameraSession()->open(QStringLiteral("sim"));
    ASSERT_TRUE(waitFor([&] { return w->cameraSession()->isOpen(); }, 2000));
    auto* cam = static_cast<FakeCamera*>(w->cameraSession()->camera());
    cam->captureFrame = guitest::ramp16(32, 16, 100);
    QTemporaryDir dir;
    int asked = 0;
    for (ui::CameraPanel* p : {scan->cameraPanel(), w->jogCameraPanel()})
        p->setFileChooser([&](const QString&, const QString&) {
            ++asked;
            return dir.filePath(QStringLiteral("f9"));
        });
    QString written;
    QObject::connect(scan->cameraPanel(), &ui::CameraPanel::snapWritten, [&](const QString& p) { written = p; });
    w->activateWindow();
    QTest::keyClick(w.get(), Qt::Key_F9);
    auto* snapButton = scan->cameraPanel()->findChild<QPushButton*>(QStringLiteral("cameraSnap"));
    ASSERT_TRUE(waitFor([&] { return !written.isEmpty(); }, 5000)) << "F9 did not snap; asked " << asked << ", button enabled "
                                                                    << snapButton->isEnabled() << " visible " << snapButton->isVisible()
                                                                    << " shortcut " << ui::buttonKey(snapButton).toString().toStdString()
                                                                    << " active " << (QApplication::activeWindow() == w.get());
    EXPECT_EQ(asked, 1);
    EXPECT_EQ(written, dir.filePath(QStringLiteral("f9.tif"))) << "the TIFF's extension is added";
    // A language switch rewords the button; the key stays.
    chooseLanguage(QStringLiteral("zh_CN"));
    chooseLanguage(QStringLiteral("en"));
    guitest::pump(50);
    written.clear();
    QTest::keyClick(w.get(), Qt::Key_F9);
    ASSERT_TRUE(waitFor([&] { return !written.isEmpty(); }, 5000)) << "F9 did not snap after a language switch";
    EXPECT_EQ(asked, 2);
}

// Found beside the camera's F9: the Scan screen's Run (Ctrl+R) lost its key once its text
// was reworded (Resume, or another language), because a button's setText() resets it.
TEST_F(CameraScreens, TheScanScreensKeysSurviveALanguageSwitch)
{
    ASSERT_TRUE(w->showScreen(QStringLiteral("scan")));
    ui::ScanScreen* scan = w->scanScreen();
    auto* run = scan->findChild<QPushButton*>(QStringLiteral("scanRun"));
    ASSERT_NE(run, nullptr);
    chooseLanguage(QStringLiteral("zh_CN"));
    guitest::pump(50);
    EXPECT_EQ(ui::buttonKey(run), QKeySequence(Qt::CTRL | Qt::Key_R)) << "in Chinese";
    chooseLanguage(QStringLiteral("en"));
    guitest::pump(50);
    EXPECT_EQ(ui::buttonKey(run), QKeySequence(Qt::CTRL | Qt::Key_R)) << "back in English";
}

TEST_F(CameraScreens, TheCameraKeepsItsStateAcrossALanguageSwitch)
{
    ui::CameraPanel* panel = openTypedSimOnScan(2000);
    ASSERT_TRUE(panel);
    ui::ScanScreen* scan = w->scanScreen();
    auto* cam = static_cast<FakeCamera*>(w->cameraSession()->camera());
    cam->push(guitest::texture(640, 480, 0, 3));
    ASSERT_TRUE(waitFor([&] { return panel->liveView()->hasPicture(); }, 5000));
    auto* exposure = panel->findChild<ui::NumberField*>(QStringLiteral("cameraExposure"));
    exposure->setFocus();
    exposure->selectAll();
    QTest::keyClicks(exposure, QStringLiteral("35"));
    QTest::keyClick(exposure, Qt::Key_Return);
    ASSERT_DOUBLE_EQ(w->cameraSession()->exposureMs(), 35);
    panel->liveView()->setAutoContrast(false);
    panel->liveView()->setPaused(true);
    scan->setTakesImages(true);
    auto* pause = panel->liveView()->findChild<QPushButton*>(QStringLiteral("livePause"));
    auto* openButton = panel->findChild<QPushButton*>(QStringLiteral("cameraOpen"));
    const QString resumeEn = pause->text(), closeEn = openButton->text();
    EXPECT_EQ(resumeEn, QStringLiteral("Resume"));

    chooseLanguage(QStringLiteral("zh_CN"));
    guitest::pump(100);
    EXPECT_NE(pause->text(), resumeEn) << "the pause button was not reworded";
    EXPECT_NE(openButton->text(), closeEn);
    EXPECT_EQ(panel->findChild<QComboBox*>(QStringLiteral("cameraSource"))->currentText(), QStringLiteral("sim"));
    chooseLanguage(QStringLiteral("en"));
    guitest::pump(100);

    EXPECT_TRUE(w->cameraSession()->isOpen());
    EXPECT_EQ(w->cameraSession()->camera(), cam) << "the camera was reopened";
    EXPECT_EQ(panel->sourceText(), QStringLiteral("sim"));
    EXPECT_EQ(exposure->text(), QStringLiteral("35"));
    EXPECT_DOUBLE_EQ(cam->exposureMs(), 35);
    EXPECT_TRUE(panel->liveView()->isPaused());
    EXPECT_FALSE(panel->liveView()->autoContrast());
    EXPECT_TRUE(scan->takesImages());
    EXPECT_EQ(panel->liveView()->shown().sequence, 3u) << "the picture was lost";
    EXPECT_EQ(pause->text(), resumeEn);
    EXPECT_EQ(openButton->text(), closeEn);
}

TEST_F(SimulatedCameraScreens, TheSimulatedCameraShowsWhatIsUnderTheObjective)
{
    ui::CameraPanel* panel = openTypedSimOnScan(5000);
    ASSERT_TRUE(panel);
    ASSERT_TRUE(waitFor([&] { return panel->liveView()->hasPicture(); }, 20000)) << "no live frame from the simulated camera";
    const ui::ProcessedFrame& f = panel->liveView()->shown();
    EXPECT_EQ(f.frameSize, QSize(2048, 2048));
    EXPECT_DOUBLE_EQ(panel->liveView()->pixelUm(), 0.65) << "the frame's own pixel size";
    EXPECT_GT(f.stretch.high, f.stretch.low);
    EXPECT_GT(f.focus, 0);
    // A source this build cannot make is refused, and the simulated camera stays closed after Close.
    QTest::mouseClick(panel->findChild<QPushButton*>(QStringLiteral("cameraOpen")), Qt::LeftButton);
    EXPECT_FALSE(w->cameraSession()->isOpen());
}

TEST_F(SimulatedCameraScreens, AScanFromTheScreenWritesAnImageForEachTile)
{
    QTemporaryDir dir;
    ui::ScanScreen* scan = cameraScan({40, 40}, 2.4, 1.0, dir.filePath(QStringLiteral("run")));  // two 1.33 mm fields across, one down
    ASSERT_TRUE(scan);
    const int tiles = int(scan->layout().tiles.size());
    ASSERT_GE(tiles, 2);
    ASSERT_TRUE(scan->run());
    EXPECT_TRUE(w->cameraSession()->inUse()) << "the camera could be closed under the run";
    ASSERT_TRUE(waitFor([&] { return scan->runner()->state() == dev::jobs::ScanRunner::State::Finished; }, 120000));
    for (int t = 0; t < tiles; ++t) {
        const auto& image = scan->runner()->image(t);
        ASSERT_FALSE(image.file.empty()) << "tile " << t << " has no image";
        EXPECT_TRUE(QFileInfo::exists(QDir(dir.filePath(QStringLiteral("run"))).filePath(QString::fromStdString(image.file))));
    }
    EXPECT_FALSE(w->cameraSession()->inUse());

    // The Mosaic tab stitches what the run took: live, then again on Ctrl+T.
    scan->showTab(2);
    ui::StitchPanel* mosaic = scan->stitchPanel();
    ASSERT_TRUE(mosaic);
    ASSERT_TRUE(waitFor([&] { return !mosaic->isRunning(); }, 60000)) << "the live stitch did not finish";
    QTest::keyClick(w.get(), Qt::Key_T, Qt::ControlModifier);
    ASSERT_TRUE(mosaic->isRunning()) << "Ctrl+T did not stitch";
    ASSERT_TRUE(waitFor([&] { return !mosaic->isRunning() && !mosaic->summaryText().isEmpty(); }, 60000));
    EXPECT_TRUE(mosaic->summaryText().startsWith(QStringLiteral("%1 tiles, %2 pairs: %2 trusted").arg(tiles).arg(tiles - 1)))
        << mosaic->summaryText().toStdString();
    EXPECT_TRUE(QFileInfo::exists(QDir(dir.filePath(QStringLiteral("run"))).filePath(QStringLiteral("quality-map.png"))));
}

// The picture in docs/stitching.md: BP_GUI_SHOTS=DIR keeps DIR/scan-mosaic.png, the Mosaic
// tab after a 3 × 3 camera scan of the slide, with a tile clicked.
TEST_F(SimulatedCameraScreens, MosaicPictureForTheDocs)
{
    if (qEnvironmentVariable("BP_GUI_SHOTS").isEmpty())
        GTEST_SKIP() << "only with BP_GUI_SHOTS=DIR";
    QTemporaryDir dir;
    ui::ScanScreen* scan = cameraScan({42, 31}, 3.4, 3.4, dir.filePath(QStringLiteral("run")));
    ASSERT_TRUE(scan);
    ASSERT_TRUE(scan->run());
    ASSERT_TRUE(waitFor([&] { return scan->runner()->state() == dev::jobs::ScanRunner::State::Finished; }, 300000));
    scan->showTab(2);
    // The scan stitched itself live; the picture is of what it wrote.
    ASSERT_TRUE(waitFor([&] { return !scan->stitchPanel()->isRunning() && !scan->stitchPanel()->summaryText().isEmpty(); }, 120000));
    ui::StitchQualityMap* map = scan->stitchPanel()->map();
    map->selectTile(4);
    emit map->tileClicked(4);
    guitest::pump(200);
    guitest::keepPicture(w.get(), QStringLiteral("scan-mosaic.png"));
}

// The picture in docs/camera.md: BP_GUI_SHOTS=DIR keeps it as DIR/camera-live-view.png
// (the Scan screen's Camera tab on the simulated camera, the stage homed and moved onto
// the slide, the focus figure's history).
TEST_F(SimulatedCameraScreens, PictureForTheDocs)
{
    if (qEnvironmentVariable("BP_GUI_SHOTS").isEmpty())
        GTEST_SKIP() << "only with BP_GUI_SHOTS=DIR";
    dev::Instrument* stage = w->stage()->instrument();
    stage->home(0);
    ASSERT_TRUE(waitFor([&] { return !stage->status().axes.isEmpty() && stage->status().axes[0].homed && stage->status().axes[1].homed
                                  && !stage->status().anyMoving(); }, 60000));
    stage->move({{0, 42.5}, {1, 31.25}}, false);
    ASSERT_TRUE(waitFor([&] { return !stage->status().anyMoving() && std::abs(stage->status().axes[0].measured - 42.5) < 0.01; }, 30000));
    ui::CameraPanel* panel = openTypedSimOnScan(5000);
    ASSERT_TRUE(panel);
    ASSERT_TRUE(waitFor([&] { return panel->liveView()->focusHistory().size() >= 20; }, 60000));
    guitest::pump(200);
    guitest::keepPicture(w.get(), QStringLiteral("camera-live-view.png"));
}
