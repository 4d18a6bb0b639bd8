#include "screenshot.h"

#include "instrument_session.h"
#include "main_window.h"
#include "screenshot_scan.h"

#include <QElapsedTimer>
#include <QTemporaryDir>
#include <QEventLoop>
#include <QTimer>

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
    w.resize(1600, 1000);
    w.show();
    InstrumentSession* s = index ? w.stage() : w.analyzer();
    if (!spinUntil([&] { return w.analyzer()->client()->isReady() && w.stage()->client()->isReady(); }, 5000)) {
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
    if (r.homeFirst && !scan) {
        s->client()->home(0);
        spin(300);
        spinUntil([&] { return !s->client()->status().anyMoving(); }, 30000);
        if (index == 0)
            s->client()->move({{0, 30}, {1, 40}}, false);
        else
            s->client()->move({{0, 12.5}, {1, 30}}, false);
        spin(300);
        spinUntil([&] { return !s->client()->status().anyMoving(); }, 30000);
    }
    if (r.exercise && !scan) {
        // A jog of X, then a diagonal and a move back in X: the plots and the XY path
        // show a jog and a move, commanded against measured.
        dev::InstrumentClient* c = s->client();
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
    spin(r.settleMs);
    if (!w.grab().save(r.file)) {
        std::fprintf(stderr, "benchpilot: cannot write %s\n", qPrintable(r.file));
        return 4;
    }
    return 0;
}

} // namespace app
