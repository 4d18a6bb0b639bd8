// The Scan screen at work for `benchpilot --screenshot … --screen scan --exercise`:
// a polygon region on the stage, homed, the scan running for a few seconds so the
// picture shows taken tiles, the tile in progress, the stage and the time left.
#include "screenshot_scan.h"

#include "instrument_session.h"
#include "main_window.h"
#include "screenshot.h"
#include "device/jobs/scan_runner.h"
#include "widgets/scan/scan_screen.h"
#include "widgets/scan/scan_stage_map.h"

#include <QDir>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QTimer>

namespace app {

/// The screenshot scripts wait on the GUI's own event loop (screenshot.h).
bool runUntil(const std::function<bool()>& done, int ms)
{
    QElapsedTimer t;
    t.start();
    while (!done() && t.elapsed() < ms) {
        QEventLoop loop;
        QTimer::singleShot(10, &loop, &QEventLoop::quit);
        loop.exec();
    }
    return done();
}

bool showScanAtWork(MainWindow& w, const QString& scratchFolder)
{
    using namespace motion::scan;
    ui::ScanScreen* screen = w.scanScreen();
    dev::Instrument* stage = w.stage()->instrument();
    ScanPlan p;
    p.name = QObject::tr("Tissue section, 2.5x overview").toStdString();
    p.region.kind = RegionKind::Polygon;
    p.region.vertices = {{22, 28}, {48, 18}, {76, 30}, {80, 58}, {55, 74}, {26, 64}};
    p.camera.magnification = 2.5;  // 2048 px × 6.5 µm / 2.5: a 5.3 mm field
    p.overlapX = p.overlapY = 0.15;
    p.order = ScanOrder::SnakeRows;
    p.start = StartCorner::TopLeft;
    p.speedMmS = 20;
    p.exposureS = 0.03;
    screen->setPlan(p);
    screen->map()->fitStage();
    screen->setOutputFolder(QDir(scratchFolder).filePath(QStringLiteral("scan")));
    stage->home(0);
    if (!runUntil([&] { return !stage->status().axes.isEmpty() && stage->status().axes[0].homed && stage->status().axes[1].homed
                             && !stage->status().anyMoving(); },
                  30000))
        return false;
    if (!screen->run())
        return false;
    return runUntil([&] { return screen->runner()->takenTiles() >= 9; }, 30000);
}

} // namespace app
