// The Scan screen asks what dev::jobs::ScanLaunch decides, nothing of its own: the question
// before a fresh run far from the stage names the tile count and the first tile from the
// launch's outlook (the data the CLI's `scan run` reads too), and the same run, declined,
// reads the same outlook from a launch over the screen's runner without any widget.
#include "app/gui/instrument_session.h"
#include "app/gui/main_window.h"
#include "device/jobs/scan_launch.h"
#include "device/link/simulated_link.h"
#include "gui_wait.h"
#include "gui_window.h"
#include "widgets/scan/scan_screen.h"

#include <QTemporaryDir>

#include <gtest/gtest.h>

using guitest::pump;
using guitest::waitFor;

TEST(ScanLaunchScreen, TheQuestionBeforeAFarRunIsWordedFromTheLaunchsOutlook)
{
    auto o = guitest::testWindowOptions();
    o.confirmDialogs = false;
    auto w = std::make_unique<app::MainWindow>(o);
    w->resize(1500, 950);
    w->show();
    dev::Instrument* stage = w->stage()->instrument();
    ASSERT_TRUE(waitFor([&] { return stage->isReady(); }, 5000));
    auto* link = qobject_cast<dev::SimulatedLink*>(w->stage()->link());
    ASSERT_NE(link, nullptr);
    link->host().setTimeScale(10);
    stage->home(0);
    ASSERT_TRUE(waitFor([&] { return stage->status().axes.size() >= 2 && stage->status().axes[0].homed && stage->status().axes[1].homed
                                     && !stage->status().anyMoving(); }, 30000));
    link->host().setTimeScale(1);
    ASSERT_TRUE(w->showScreen(QStringLiteral("scan")));

    // 2 × 2 fields of 1 mm at least 40 mm from the stage: short to take, long to reach.
    const double x = stage->status().axes[0].commanded, y = stage->status().axes[1].commanded;
    const double at = (x < 50 && y < 50) ? 60 : 5;
    motion::scan::ScanPlan p;
    p.region.cornerA = {at, at};
    p.region.cornerB = {at + 1.8, at + 1.8};
    p.camera.source = motion::scan::FieldSource::Direct;
    p.camera.fieldWidthMm = p.camera.fieldHeightMm = 1;
    p.exposureS = 0.01;
    QTemporaryDir dir;
    ui::ScanScreen* screen = w->scanScreen();
    screen->setPlan(p);
    screen->setOutputFolder(dir.path());
    pump(100);  // the screen replans on a short timer
    QStringList asked;
    screen->setConfirm([&](const QString& q) {
        asked << q;
        return false;
    });
    EXPECT_FALSE(screen->run());
    ASSERT_EQ(asked.size(), 1);

    dev::jobs::ScanLaunch launch(screen->runner());
    const dev::jobs::ScanDecision d = launch.prepare(p, dir.path());
    ASSERT_EQ(d.kind, dev::jobs::ScanDecision::Kind::Ready);
    EXPECT_TRUE(d.outlook.longApproach);
    EXPECT_FALSE(d.outlook.longRun);
    EXPECT_FALSE(d.outlook.resume);
    const QString firstMove = QStringLiteral("(%1, %2) mm").arg(d.outlook.firstTileMm.xMm, 0, 'f', 2).arg(d.outlook.firstTileMm.yMm, 0, 'f', 2);
    EXPECT_TRUE(asked[0].contains(firstMove)) << asked[0].toStdString() << " / " << firstMove.toStdString();
    EXPECT_TRUE(asked[0].contains(QStringLiteral("Run %1 tiles").arg(d.outlook.totalTiles))) << asked[0].toStdString();
}
