#include "screenshot.h"

#include "instrument_session.h"
#include "main_window.h"
#include "widgets/tuning/step_test_panel.h"
#include "widgets/tuning/tuning_screen.h"
#include "widgets/tuning/zn_panel.h"
#include "motion_screens.h"
#include "device/client/joystick_driver.h"
#include "device/jobs/pattern_runner.h"
#include "widgets/joystick/joystick_screen.h"
#include "widgets/patterns/pattern_screen.h"
#include "device/link/simulated_link.h"
#include "widgets/plates/plates_screen.h"
#include "screenshot_calibration.h"
#include "screenshot_scan.h"

#include <QElapsedTimer>
#include <QTemporaryDir>
#include <QEventLoop>
#include <QTimer>

#include <cmath>
#include <cstdio>

namespace app {
namespace {
void spin(int ms)
{
    QEventLoop loop;
    QTimer::singleShot(ms, &loop, &QEventLoop::quit);
    loop.exec();
}
bool spinUntil(const std::function<bool()>& done, int ms)
{
    QElapsedTimer t;
    t.start();
    while (!done() && t.elapsed() < ms)
        spin(10);
    return done();
}
} // namespace

int takeScreenshot(const ScreenshotRequest& r)
{
    MainWindowOptions o;
    o.persistSettings = false;
    o.confirmDialogs = false;
    MainWindow w(o);
    if (!w.showScreen(r.screen)) {
        std::fprintf(stderr, "benchpilot: no screen '%s' (screens: %s)\n", qPrintable(r.screen),
                     qPrintable(w.screenNames().join(QStringLiteral(", "))));
        return 2;
    }
    if (r.instrument != QLatin1String("analyzer") && r.instrument != QLatin1String("stage")) {
        std::fprintf(stderr, "benchpilot: --sim must be analyzer or stage\n");
        return 2;
    }
    const int index = r.instrument == QLatin1String("stage") ? 1 : 0;
    w.showInstrument(index);
    w.resize(r.size);
    w.show();
    InstrumentSession* s = index ? w.stage() : w.analyzer();
    if (!spinUntil([&] { return w.analyzer()->instrument()->isReady() && w.stage()->instrument()->isReady(); }, 5000)) {
        std::fprintf(stderr, "benchpilot: the simulated instruments did not become ready\n");
        return 3;
    }
    // The Scan screen shows a scan at work instead of the generic motion below.
    const bool scan = r.screen == QLatin1String("scan");
    QTemporaryDir scratch;
    if (scan && (r.homeFirst || r.exercise) && !showScanAtWork(w, scratch.path())) {
        std::fprintf(stderr, "benchpilot: the scan did not get going on the simulated stage\n");
        return 3;
    }
    // So does the Calibration screen: a test before and after compensation.
    const bool calibration = r.screen == QLatin1String("calibration");
    if (calibration && (r.homeFirst || r.exercise) && !showCalibrationAtWork(w, scratch.path())) {
        std::fprintf(stderr, "benchpilot: the calibration run did not finish on the simulated stage\n");
        return 3;
    }
    if (r.homeFirst && !scan && !calibration) {
        s->instrument()->home(0);
        spin(300);
        spinUntil([&] { return !s->instrument()->status().anyMoving(); }, 30000);
        if (index == 0)
            s->instrument()->move({{0, 30}, {1, 40}}, false);
        else
            s->instrument()->move({{0, 12.5}, {1, 30}}, false);
        spin(300);
        spinUntil([&] { return !s->instrument()->status().anyMoving(); }, 30000);
    }
    if (r.exercise && r.screen == QLatin1String("patterns")) {
        // The screen's pattern run to the end: the overlay, the contour plot and the summary.
        ui::PatternScreen* p = w.motionScreens()->patterns();
        p->setInstrument(index);
        spin(300);
        if (p->run())
            spinUntil([&] { return !p->runner()->busy(); }, 120000);
    } else if (r.exercise && r.screen == QLatin1String("joystick")) {
        // The stick pushed round a loop: the trail on the travel view.
        ui::JoystickScreen* j = w.motionScreens()->joystick(index);
        const double v = 0.4 * s->instrument()->identity().axes[0].maxSpeed;
        for (int k = 0; k < 60; ++k) {
            const double a = k * 6.2832 / 60;
            j->driver()->setVelocities({{0, v * std::cos(a)}, {1, v * std::sin(a)}});
            spin(50);
        }
        j->driver()->stop();
        spin(500);
    } else if (r.exercise && !scan && !calibration) {
        // A jog of X, then a diagonal and a move back in X: the plots and the XY path
        // show a jog and a move, commanded against measured.
        dev::Instrument* c = s->instrument();
        const auto& x = c->identity().axes[0];
        const auto& y = c->identity().axes[1];
        c->startJog(0, 0.5 * x.maxSpeed);
        spin(1000);
        c->stopJog(0);
        spin(400);
        c->move({{0, 0.08 * (x.travelMax - x.travelMin)}, {1, 0.12 * (y.travelMax - y.travelMin)}}, true);
        spin(300);
        spinUntil([&] { return !c->status().anyMoving(); }, 10000);
        c->move({{0, -0.1 * (x.travelMax - x.travelMin)}}, true);
        spin(300);
    }
    if (r.tune) {
        // The stage's X: a step test under the seed's gains, the relay assistant
        // (its verification adds the Z-N PID step beside it), the assistant shown.
        ui::TuningScreen* t = w.tuningScreen();
        InstrumentSession* stage = w.stage();
        if (!stage->instrument()->status().axes.value(0).homed) {
            stage->instrument()->home(0);
            spin(300);
            spinUntil([&] { return !stage->instrument()->status().anyMoving(); }, 30000);
        }
        stage->instrument()->move({{0, 50}}, false);
        spin(300);
        spinUntil([&] { return !stage->instrument()->status().anyMoving(); }, 10000);
        w.showScreen(QStringLiteral("tuning"));
        spinUntil([&] { return t->targetNames().contains(QStringLiteral("Stage X")); }, 5000);
        t->selectTarget(QStringLiteral("Stage X"));
        spin(300);
        t->runStepTest();
        spinUntil([&] { return !t->runner()->busy(); }, 10000);
        auto zn = t->assistant()->options();
        zn.method = motion::control::TuningMethod::Relay;
        t->assistant()->setOptions(zn);
        t->startAssistant();
        spinUntil([&] { return !t->runner()->busy(); }, 30000);
        t->tabs()->setCurrentWidget(qEnvironmentVariableIsSet("BP_SHOT_STEP_TAB") ? static_cast<QWidget*>(t->stepTests())
                                                                                  : static_cast<QWidget*>(t->assistant()));
    }
    if (!r.recipe.isEmpty()) {
        // The Plates screen at work: the recipe open, the analyzer homed (on an
        // unpaced link with a faster clock, to be quick) and part-way through it.
        ui::PlatesScreen* plates = w.platesScreen();
        if (!plates->openRecipe(r.recipe)) {
            std::fprintf(stderr, "benchpilot: cannot open %s\n", qPrintable(r.recipe));
            return 2;
        }
        ui::ConnectionChoice fast;
        fast.simulator = true;
        fast.baud = 0;
        w.analyzer()->connectTo(fast);
        dev::Instrument* c = w.analyzer()->instrument();
        if (!spinUntil([&] { return c->isReady(); }, 5000))
            return 3;
        auto* link = qobject_cast<dev::SimulatedLink*>(w.analyzer()->link());
        if (link)
            link->host().setTimeScale(20);
        c->home(0);
        spin(300);
        spinUntil([&] { return !c->status().anyMoving(); }, 30000);
        if (link)
            link->host().setTimeScale(4);
        if (!plates->runRecipe())
            return 2;
    }
    spin(r.settleMs);
    w.resize(r.size);  // what the screen asked for while it settled may have grown it
    spin(50);
    if (w.size() != r.size)
        std::fprintf(stderr, "benchpilot: the window cannot be %dx%d; it is %dx%d\n", r.size.width(), r.size.height(), w.width(),
                     w.height());
    if (!w.grab().save(r.file)) {
        std::fprintf(stderr, "benchpilot: cannot write %s\n", qPrintable(r.file));
        return 4;
    }
    return 0;
}

} // namespace app
