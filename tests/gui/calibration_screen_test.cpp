// The Calibration screen driven as a person would, on the simulated stage with its
// clock sped up: a small axis test read by the simulator's gauge at the work point,
// the deviations arriving on the live plot, the ISO figures and the fit; the fit
// uploaded and enabled, the test again, and before/after showing the improvement;
// a manual test answered at its prompt; Run held back with the reason.
#include "app/gui/instrument_session.h"
#include "app/gui/main_window.h"
#include "device/jobs/accuracy/accuracy_runner.h"
#include "device/jobs/accuracy/circle_telemetry.h"
#include "device/link/simulated_link.h"
#include "gui_window.h"
#include "widgets/calibration/calibration_screen.h"
#include "widgets/calibration/deviation_plot.h"
#include "widgets/calibration/fit_panel.h"
#include "widgets/calibration/test_form.h"
#include "widgets/camera/camera_session.h"

#include <QDir>

#include <qcustomplot.h>
#include <QFile>
#include <QFileInfo>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QTabWidget>
#include <QTableWidget>
#include <QTemporaryDir>

#include <gtest/gtest.h>

using guitest::pump;
using guitest::waitFor;

namespace {

/// X at 20, 50 and 80 mm, two cycles both ways, fast stops.
motion::metrology::AxisTest smallXTest(const char* name = "gui-x")
{
    motion::metrology::AxisTest t;
    t.name = name;
    t.axis = "X";
    t.targetsMm = {20, 50, 80};
    t.cycles = 2;
    t.feedMmS = 15;
    t.overrunMm = 0.5;
    t.dwellS = 0.05;
    t.settle = {1, 0.05, 2};
    return t;
}

class CalibrationScreenTest : public ::testing::Test {
protected:
    void SetUp() override
    {
        w = guitest::openReadyWindow(QSize(1366, 768));
        ASSERT_NE(w, nullptr);
        ASSERT_TRUE(w->showScreen(QStringLiteral("calibration")));
        screen = w->calibrationScreen();
        ASSERT_NE(screen, nullptr);
        screen->setInstrument(1);
        screen->setOutputFolder(dir.path());
    }
    /// The stage homed, its clock sped up.
    bool homedStage()
    {
        w->stage()->connectTo(ui::ConnectionChoice{});
        dev::Instrument* stage = w->stage()->instrument();
        if (!waitFor([&] { return stage->isReady(); }, 5000))
            return false;
        auto* link = qobject_cast<dev::SimulatedLink*>(w->stage()->link());
        if (!link)
            return false;
        link->host().setTimeScale(20);
        stage->home(0);
        const bool ok = waitFor([&] { return stage->status().axes.size() >= 2 && stage->status().axes[0].homed && stage->status().axes[1].homed
                                             && !stage->status().anyMoving(); },
                                30000);
        link->host().setTimeScale(25);
        return ok;
    }
    static motion::metrology::AxisTest smallTest() { return smallXTest(); }
    template <class T>
    T* child(const char* name) { return screen->findChild<T*>(QLatin1String(name)); }
    /// Shown and not clipped away by a scroll area or the window's edge.
    bool inView(QWidget* widget)
    {
        if (!widget || !widget->isVisible() || widget->visibleRegion().isEmpty())
            return false;
        const QRect r(widget->mapTo(w.get(), QPoint(0, 0)), widget->size());
        return w->rect().contains(r);
    }
    void keepPicture(const char* name) { guitest::keepPicture(w.get(), QLatin1String(name)); }
    bool waitFinished()
    {
        return waitFor([&] { return screen->runner() && screen->runner()->state() == dev::jobs::AccuracyRunner::State::Finished; }, 60000);
    }

    QTemporaryDir dir;
    std::unique_ptr<app::MainWindow> w;
    ui::CalibrationScreen* screen = nullptr;
};

TEST_F(CalibrationScreenTest, RunIsHeldBackWithTheReason)
{
    screen->form()->setTest(smallTest());
    auto* run = child<QPushButton>("calibrationRun");
    ASSERT_NE(run, nullptr);
    EXPECT_TRUE(run->isEnabled()) << run->toolTip().toStdString();
    auto t = smallTest();
    t.targetsMm = {20, 80, 50};
    screen->form()->setTest(t);
    pump(20);
    EXPECT_FALSE(run->isEnabled());
    EXPECT_TRUE(run->toolTip().contains(QStringLiteral("targets must increase"))) << run->toolTip().toStdString();
    EXPECT_TRUE(child<QLabel>("calibrationFormProblems")->isVisible());
    // Nothing runs, so nothing can be paused, and the disabled buttons say so.
    EXPECT_FALSE(child<QPushButton>("calibrationPause")->isEnabled());
    EXPECT_FALSE(child<QPushButton>("calibrationPause")->toolTip().isEmpty());
    // At 1366 × 768 the whole definition need not fit, but Run and E-STOP are in view.
    EXPECT_LE(screen->minimumSizeHint().width(), 1366 - 200) << "beside the navigation list";
    EXPECT_LE(screen->minimumSizeHint().height(), 768 - 300) << "below the connection bars, above the event log";
    EXPECT_TRUE(inView(run));
    EXPECT_TRUE(inView(w->findChild<QPushButton*>(QStringLiteral("estop"))));
    keepPicture("calibration-held-back.png");
}

TEST_F(CalibrationScreenTest, AGaugeRunThenItsCompensationShowBeforeAndAfter)
{
    ASSERT_TRUE(homedStage());
    screen->form()->setTest(smallTest());
    screen->setSource(QStringLiteral("gauge"), QStringLiteral("sim"));
    int liveUpdates = 0;
    QObject::connect(screen->livePlot(), &QCustomPlot::afterReplot, [&] { ++liveUpdates; });
    ASSERT_TRUE(screen->run());
    ASSERT_TRUE(waitFinished());
    EXPECT_GE(liveUpdates, 4) << "the live plot follows the readings";
    ASSERT_TRUE(screen->latest());
    EXPECT_GT(*screen->latest()->evaluation.figures.aMm, 0.04) << "the gauge sees seed 002's curve";
    EXPECT_TRUE(screen->figuresText().contains(QStringLiteral("A\t"))) << screen->figuresText().toStdString();
    EXPECT_TRUE(QFileInfo::exists(QDir(dir.path()).filePath(QStringLiteral("gui-x/gui-x.readings.csv"))));
    // The compensation panel: the fit, uploaded and enabled through the instrument.
    ui::FitPanel* fit = screen->fitPanel();
    ASSERT_TRUE(fit->model());
    auto* upload = fit->findChild<QPushButton*>(QStringLiteral("fitUpload"));
    auto* enable = fit->findChild<QPushButton*>(QStringLiteral("fitEnable"));
    ASSERT_TRUE(waitFor([&] { return upload->isEnabled(); }, 5000)) << upload->toolTip().toStdString();
    upload->click();
    ASSERT_TRUE(waitFor([&] { return enable->isEnabled(); }, 5000)) << fit->deviceText().toStdString();
    enable->click();
    ASSERT_TRUE(waitFor([&] { return fit->deviceText().contains(QStringLiteral("enabled")); }, 5000)) << fit->deviceText().toStdString();
    // The same test again, in a folder of its own.
    screen->setOutputFolder(QDir(dir.path()).filePath(QStringLiteral("after")));
    ASSERT_TRUE(screen->run());
    ASSERT_TRUE(waitFinished());
    ASSERT_TRUE(screen->previous());
    const double before = *screen->previous()->evaluation.figures.aMm, after = *screen->latest()->evaluation.figures.aMm;
    EXPECT_GE(before / after, 5) << before << " → " << after;
    auto* table = child<QTableWidget>("calibrationBeforeAfter");
    ASSERT_GT(table->rowCount(), 3);
    EXPECT_EQ(table->item(0, 0)->text(), QStringLiteral("A"));
    EXPECT_TRUE(table->item(0, 3)->text().endsWith(QStringLiteral("×")));
    EXPECT_TRUE(child<QLabel>("calibrationBeforeAfterNote")->text().contains(QStringLiteral("times better")));
    screen->tabs()->setCurrentIndex(3);
    keepPicture("calibration-before-after.png");
}

// Run on a test whose folder holds a finished run did nothing but say where its results
// were. The operator wants the run after (compensation): asked first, it goes into a
// numbered folder beside the first, both are kept, and Before / after compares them.
TEST_F(CalibrationScreenTest, RunOnAFinishedTestOffersANewRunBesideItAndComparesBoth)
{
    ASSERT_TRUE(homedStage());
    screen->form()->setTest(smallTest());
    screen->setSource(QStringLiteral("gauge"), QStringLiteral("sim"));
    ASSERT_TRUE(screen->run());
    ASSERT_TRUE(waitFinished());
    const QString first = QDir(dir.path()).filePath(QStringLiteral("gui-x"));
    const QString second = QDir(dir.path()).filePath(QStringLiteral("gui-x-2"));
    ASSERT_TRUE(QFileInfo::exists(first + QStringLiteral("/gui-x.readings.csv")));
    const QByteArray firstReadings = [&] {
        QFile f(first + QStringLiteral("/gui-x.readings.csv"));
        return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
    }();

    // Declined: nothing runs, nothing is written, and the run is not compared with itself.
    QStringList asked;
    screen->setConfirm([&](const QString& q) {
        asked << q;
        return false;
    });
    ASSERT_TRUE(screen->run());
    ASSERT_TRUE(waitFor([&] { return !asked.isEmpty(); }, 5000)) << "Run on a finished test asked nothing";
    EXPECT_TRUE(asked.front().contains(QStringLiteral("gui-x-2"))) << asked.front().toStdString();
    pump(100);
    EXPECT_FALSE(QFileInfo::exists(second));
    EXPECT_FALSE(screen->previous()) << "a run compared with itself";

    // Accepted: the test runs again into gui-x-2; the first run's files stay as they were.
    asked.clear();
    screen->setConfirm([&](const QString& q) {
        asked << q;
        return true;
    });
    ASSERT_TRUE(screen->run());
    ASSERT_TRUE(waitFor([&] { return screen->runner() && QDir(screen->runner()->folder()) == QDir(second)
                                     && screen->runner()->state() == dev::jobs::AccuracyRunner::State::Finished; },
                        60000))
        << asked.join(QLatin1Char('\n')).toStdString();
    pump(100);
    EXPECT_TRUE(QFileInfo::exists(second + QStringLiteral("/gui-x.readings.csv")));
    QFile f(first + QStringLiteral("/gui-x.readings.csv"));
    ASSERT_TRUE(f.open(QIODevice::ReadOnly));
    EXPECT_EQ(f.readAll(), firstReadings) << "the first run's readings changed";
    ASSERT_TRUE(screen->previous());
    ASSERT_TRUE(screen->latest());
    EXPECT_GT(child<QTableWidget>("calibrationBeforeAfter")->rowCount(), 3) << "Before / after compares the two runs";

    // A third Run offers gui-x-3 and compares with gui-x-2, the newest.
    asked.clear();
    screen->setConfirm([&](const QString& q) {
        asked << q;
        return false;
    });
    ASSERT_TRUE(screen->run());
    ASSERT_TRUE(waitFor([&] { return !asked.isEmpty(); }, 5000));
    EXPECT_TRUE(asked.front().contains(QStringLiteral("gui-x-3"))) << asked.front().toStdString();
}

TEST_F(CalibrationScreenTest, AManualTestAsksAtEachStopAndTakesWhatIsTyped)
{
    ASSERT_TRUE(homedStage());
    auto t = smallTest();
    t.targetsMm = {30, 60};
    screen->form()->setTest(t);
    screen->setSource(QStringLiteral("manual"));
    ASSERT_TRUE(screen->run());
    auto* prompt = child<QLabel>("calibrationManualPrompt");
    auto* value = child<QLineEdit>("calibrationManualValue");
    for (int k = 0; k < 8; ++k) {
        ASSERT_TRUE(waitFor([&] { return prompt->isVisible(); }, 20000)) << "stop " << k;
        EXPECT_TRUE(prompt->text().contains(QStringLiteral("Reading %1 of 8").arg(k + 1))) << prompt->text().toStdString();
        if (k == 0) {
            // Someone at a dial indicator types without scrolling to find the field.
            EXPECT_TRUE(inView(prompt));
            EXPECT_TRUE(inView(value));
            keepPicture("calibration-manual.png");
        }
        EXPECT_FALSE(screen->enterManual(QStringLiteral("twelve"))) << "not a reading: asked again";
        const double target = screen->runner()->stops()[static_cast<std::size_t>(k)].targetMm[0];
        value->setText(QString::number(target + 0.001 * (k % 3)));
        QMetaObject::invokeMethod(value, "returnPressed");
        ASSERT_TRUE(waitFor([&] { return !prompt->isVisible() || screen->runner()->readingsTaken() > k; }, 5000));
    }
    ASSERT_TRUE(waitFinished());
    EXPECT_EQ(screen->latest()->reference, "manual");
}

// A file opened while a test runs would replace the test that runs.
// Open… is held back, saying why, until the test has ended; a manual test waits at its
// first stop, so the hold is seen while the runner is certainly active.
TEST_F(CalibrationScreenTest, OpenIsHeldBackWhileATestRuns)
{
    ASSERT_TRUE(homedStage());
    auto t = smallTest();
    t.targetsMm = {30, 60};
    screen->form()->setTest(t);
    screen->setSource(QStringLiteral("manual"));
    QPushButton* open = guitest::button(screen, QObject::tr("Open…"));
    ASSERT_NE(open, nullptr);
    EXPECT_TRUE(open->isEnabled());
    ASSERT_TRUE(screen->run());
    ASSERT_TRUE(waitFor([&] { return child<QLabel>("calibrationManualPrompt")->isVisible(); }, 20000));
    EXPECT_FALSE(open->isEnabled()) << "Open… offered while a test runs";
    EXPECT_FALSE(open->toolTip().isEmpty()) << "held back without saying why";
    screen->abort();
    ASSERT_TRUE(waitFor([&] { return open->isEnabled(); }, 10000)) << "Open… still held after the abort";
    EXPECT_TRUE(open->toolTip().isEmpty());
}

// Found in an Xvfb session: before the first reading the live plot spanned 0 … 5 mm for a
// test of 10 … 90 mm. Between runs it spans the test on screen.
TEST_F(CalibrationScreenTest, BetweenRunsTheLivePlotSpansTheTestOnScreen)
{
    auto* plot = screen->findChild<ui::DeviationPlot*>(QStringLiteral("calibrationLivePlot"));
    ASSERT_NE(plot, nullptr);
    motion::metrology::AxisTest t;
    t.name = "preview";
    t.grid = motion::metrology::TargetGrid{20, 140, 7, false};
    screen->form()->setTest(t);
    pump(20);
    EXPECT_LT(plot->xAxis->range().lower, 20);
    EXPECT_GT(plot->xAxis->range().lower, 15);
    EXPECT_GT(plot->xAxis->range().upper, 140);
    EXPECT_LT(plot->xAxis->range().upper, 145);
}

TEST_F(CalibrationScreenTest, ACircularTestIsSampledFromTheStagesTelemetry)
{
    // The screen's instruments stream their measured positions for the telemetry history;
    // the circle runner takes its samples from them, on the device's clock: at 25x every
    // 1° bin of both revolutions is filled (status polls on the host's clock fill a third).
    ASSERT_TRUE(homedStage());
    motion::metrology::CircularTest t;
    t.name = "gui-circle";
    t.centreMm = {50, 50};
    t.radiusMm = 10;
    t.feedMmS = 10;
    t.samplesPerRevolution = 360;
    screen->form()->setTest(t);
    pump(20);
    dev::Instrument* stage = w->stage()->instrument();
    const int historyRate = stage->subscribedRateHz();
    ASSERT_TRUE(screen->run());
    // For the run the stage streams at the test's own rate, not the history's.
    int runRate = 0;
    ASSERT_TRUE(waitFor(
        [&] {
            runRate = std::max(runRate, stage->subscribedRateHz());
            return screen->circleRunner() && !screen->circleRunner()->isActive();
        },
        60000));
    ASSERT_EQ(screen->circleRunner()->state(), dev::jobs::CircleRunner::State::Finished);
    EXPECT_EQ(runRate, dev::jobs::kCircleSampleRateHz) << "history streams at " << historyRate << " Hz";
    EXPECT_LT(historyRate, dev::jobs::kCircleSampleRateHz);
    EXPECT_TRUE(waitFor([&] { return stage->subscribedRateHz() == historyRate; }, 5000)) << "the run's rate outlived it";
    ASSERT_EQ(screen->circleRunner()->runs().size(), 2u);
    for (const auto& run : screen->circleRunner()->runs())
        EXPECT_EQ(run.samplesMm.size(), 360u);
    keepPicture("calibration-circle.png");
}

} // namespace

// Seen under Xvfb: once a run started the live plot spanned -0.5 … 1.5 mm until the first
// reading, then grew with each. It keeps the test's span throughout; and a stopped run
// says how many readings it has ("Stopped at reading 7" over seven read as if the seventh
// was lost).
TEST_F(CalibrationScreenTest, DuringARunTheLivePlotKeepsTheTestsSpanAndAStopCountsWhatWasTaken)
{
    ASSERT_TRUE(homedStage());
    auto* plot = screen->findChild<ui::DeviationPlot*>(QStringLiteral("calibrationLivePlot"));
    ASSERT_NE(plot, nullptr);
    screen->form()->setTest(smallTest());
    screen->setSource(QStringLiteral("gauge"), QStringLiteral("sim"));
    ASSERT_TRUE(screen->run());
    ASSERT_TRUE(waitFor([&] { return screen->runner() && screen->runner()->isActive(); }, 5000));  // the gauge opens first
    EXPECT_LT(plot->xAxis->range().lower, 20);
    EXPECT_GT(plot->xAxis->range().upper, 80);
    ASSERT_TRUE(waitFor([&] { return screen->runner()->readingsTaken() >= 1; }, 20000));
    pump(20);
    EXPECT_LT(plot->xAxis->range().lower, 20);
    EXPECT_GT(plot->xAxis->range().upper, 80) << "the frame shrank to the first reading";
    auto* link = qobject_cast<dev::SimulatedLink*>(w->stage()->link());
    link->pair().unplug();
    ASSERT_TRUE(waitFor([&] { return screen->runner()->state() == dev::jobs::AccuracyRunner::State::Stopped; }, 5000));
    pump(20);
    const int taken = screen->runner()->readingsTaken();
    const QString state = child<QLabel>("calibrationState")->text();
    EXPECT_TRUE(state.startsWith(QStringLiteral("Stopped after %1 of %2 readings").arg(taken).arg(screen->runner()->totalReadings())))
        << state.toStdString();
}

// The camera reading a glass scale, from the Calibration screen: refused with what to do
// while no camera is open, then a run on the simulated stage's X scale (benchpilot
// --specimen line-scales) read by the GUI's camera.
TEST(CalibrationCamera, TheGuisCameraReadsTheGlassScaleOnceOneIsOpen)
{
    app::MainWindowOptions options = guitest::testWindowOptions();
    options.specimen = dev::camera::SpecimenKind::LineScales;
    auto w = guitest::openReadyWindow(QSize(1366, 768), options);
    ASSERT_NE(w, nullptr);
    ASSERT_TRUE(w->showScreen(QStringLiteral("calibration")));
    ui::CalibrationScreen* screen = w->calibrationScreen();
    QTemporaryDir dir;
    screen->setInstrument(1);
    screen->setOutputFolder(dir.path());
    screen->form()->setTest(smallXTest("gui-camera"));
    screen->setSource(QStringLiteral("camera"));
    QStringList said;
    QObject::connect(screen, &ui::CalibrationScreen::problem, [&](const QString& m) { said << m; });
    EXPECT_FALSE(screen->run());
    ASSERT_FALSE(said.isEmpty());
    EXPECT_TRUE(said.back().contains(QLatin1String("Open a camera first"))) << said.back().toStdString();

    dev::Instrument* stage = w->stage()->instrument();
    auto* link = qobject_cast<dev::SimulatedLink*>(w->stage()->link());
    ASSERT_TRUE(link);
    link->host().setTimeScale(20);
    stage->home(0);
    ASSERT_TRUE(waitFor([&] { return stage->status().axes.size() >= 2 && stage->status().axes[0].homed && stage->status().axes[1].homed
                                  && !stage->status().anyMoving(); }, 30000));
    stage->move({{1, 50.075}}, false);  // the X scale's lines run from Y 50 to 50.15 mm
    ASSERT_TRUE(waitFor([&] { return !stage->status().anyMoving() && std::abs(stage->status().axes[1].measured - 50.075) < 0.01; }, 30000));
    link->host().setTimeScale(25);
    w->cameraSession()->open(QStringLiteral("sim"));
    ASSERT_TRUE(waitFor([&] { return w->cameraSession()->isOpen(); }, 5000));
    ASSERT_TRUE(screen->run()) << said.join(QLatin1Char('\n')).toStdString();
    ASSERT_TRUE(waitFor([&] { return screen->runner() && screen->runner()->state() == dev::jobs::AccuracyRunner::State::Finished; }, 60000))
        << said.join(QLatin1Char('\n')).toStdString();
    ASSERT_TRUE(screen->latest());
    EXPECT_GT(*screen->latest()->evaluation.figures.aMm, 0.04) << "the camera sees the work point's error, as the gauge does";
}
