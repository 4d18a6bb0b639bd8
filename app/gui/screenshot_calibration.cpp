// The Calibration screen at work for `benchpilot --screenshot … --screen calibration
// --exercise`: the stage's X, read by the in-process simulator's gauge at the work
// point, compensated with the fit of that run and measured again, on the simulator's
// clock sped up so the picture takes seconds.
#include "screenshot_calibration.h"

#include "instrument_session.h"
#include "main_window.h"
#include "screenshot.h"
#include "device/jobs/accuracy/accuracy_runner.h"
#include "device/link/simulated_link.h"
#include "widgets/calibration/calibration_screen.h"
#include "widgets/calibration/fit_panel.h"
#include "widgets/calibration/test_form.h"

#include <QDir>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QPushButton>
#include <QTabWidget>
#include <QTimer>

namespace app {

bool showCalibrationAtWork(MainWindow& w, const QString& scratchFolder)
{
    ui::CalibrationScreen* screen = w.calibrationScreen();
    dev::Instrument* stage = w.stage()->instrument();
    w.stage()->connectTo(ui::ConnectionChoice{});
    if (!runUntil([&] { return stage->isReady(); }, 5000))
        return false;
    auto* link = qobject_cast<dev::SimulatedLink*>(w.stage()->link());
    if (!link)
        return false;
    stage->home(0);
    if (!runUntil([&] { return !stage->status().axes.isEmpty() && stage->status().axes[0].homed && stage->status().axes[1].homed
                             && !stage->status().anyMoving(); },
                  30000))
        return false;
    link->host().setTimeScale(20);
    screen->setInstrument(1);
    motion::metrology::AxisTest t;
    t.name = "stage-x";
    t.axis = "X";
    t.grid = motion::metrology::TargetGrid{5, 95, 7, true};
    t.cycles = 3;
    t.feedMmS = 15;
    t.overrunMm = 1;
    t.dwellS = 0.1;
    t.settle = {1, 0.05, 2};
    t.tolerances.aMm = 0.01;
    t.tolerances.rMm = 0.005;
    screen->form()->setTest(t);
    screen->setSource(QStringLiteral("gauge"), QStringLiteral("sim"));
    screen->setOutputFolder(QDir(scratchFolder).filePath(QStringLiteral("accuracy")));
    auto finished = [&] { return screen->runner() && screen->runner()->state() == dev::jobs::AccuracyRunner::State::Finished; };
    if (!screen->run() || !runUntil(finished, 120000))
        return false;
    // The fit of those readings to the stage, enabled, and the same test again.
    screen->fitPanel()->findChild<QPushButton*>(QStringLiteral("fitUpload"))->click();
    if (!runUntil([&] { return screen->fitPanel()->findChild<QPushButton*>(QStringLiteral("fitEnable"))->isEnabled(); }, 10000))
        return false;
    screen->fitPanel()->findChild<QPushButton*>(QStringLiteral("fitEnable"))->click();
    if (!runUntil([&] { return screen->fitPanel()->findChild<QPushButton*>(QStringLiteral("fitDisable"))->isEnabled(); }, 10000))
        return false;
    screen->setOutputFolder(QDir(scratchFolder).filePath(QStringLiteral("accuracy-after")));
    if (!screen->run() || !runUntil(finished, 120000))
        return false;
    link->host().setTimeScale(1);
    screen->tabs()->setCurrentIndex(3);
    return true;
}

} // namespace app
