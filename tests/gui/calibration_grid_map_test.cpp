// The grid map by camera on the Calibration screen, driven through its buttons: refused
// with what to do while no camera is open; then a map of the simulated stage on the grid
// plate, a 2D table fitted, uploaded and enabled with one button, and the same map again
// with the table: before and after side by side, the after's error far smaller.
#include "app/gui/instrument_session.h"
#include "app/gui/main_window.h"
#include "device/link/simulated_link.h"
#include "gui_window.h"
#include "widgets/calibration/calibration_screen.h"
#include "widgets/calibration/grid_map_panel.h"
#include "widgets/camera/camera_session.h"

#include <QPushButton>
#include <QTabWidget>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>

#include <gtest/gtest.h>

#include <cmath>

using guitest::waitFor;

TEST(CalibrationGridMap, MapsTheStageWithTheCameraAndShowsBeforeAndAfterSideBySide)
{
    app::MainWindowOptions options = guitest::testWindowOptions();
    options.specimen = dev::camera::SpecimenKind::GridPlate;
    auto w = guitest::openReadyWindow(QSize(1366, 768), options);
    ASSERT_NE(w, nullptr);
    ASSERT_TRUE(w->showScreen(QStringLiteral("calibration")));
    ui::CalibrationScreen* screen = w->calibrationScreen();
    QTemporaryDir dir;
    screen->setInstrument(1);
    screen->setOutputFolder(dir.path());
    ui::GridMapPanel* panel = screen->gridMapPanel();
    ASSERT_TRUE(panel);
    screen->tabs()->setCurrentWidget(panel);
    panel->setGrid(20, 3, 3);
    auto* run = panel->findChild<QPushButton*>(QStringLiteral("gridMapRun"));
    auto* compensate = panel->findChild<QPushButton*>(QStringLiteral("gridMapCompensate"));
    ASSERT_TRUE(run && compensate);
    EXPECT_FALSE(compensate->isEnabled()) << "nothing to fit before a map";
    QStringList said;
    QObject::connect(screen, &ui::CalibrationScreen::problem, [&](const QString& m) { said << m; });
    QTest::mouseClick(run, Qt::LeftButton);
    ASSERT_FALSE(said.isEmpty());
    EXPECT_TRUE(said.back().contains(QLatin1String("Open a camera first"))) << said.back().toStdString();

    dev::Instrument* stage = w->stage()->instrument();
    auto* link = qobject_cast<dev::SimulatedLink*>(w->stage()->link());
    ASSERT_TRUE(link);
    link->host().setTimeScale(20);
    stage->home(0);
    ASSERT_TRUE(waitFor([&] { return stage->status().axes.size() >= 2 && stage->status().axes[0].homed && stage->status().axes[1].homed
                                  && !stage->status().anyMoving(); }, 60000));
    stage->move({{0, 10.1}, {1, 10.0}}, false);  // over the plate's dot near (10, 10)
    ASSERT_TRUE(waitFor([&] { return !stage->status().anyMoving() && std::abs(stage->status().axes[1].measured - 10.0) < 0.01; }, 30000));
    w->cameraSession()->open(QStringLiteral("sim"));
    ASSERT_TRUE(waitFor([&] { return w->cameraSession()->isOpen(); }, 5000));

    QTest::mouseClick(run, Qt::LeftButton);
    ASSERT_TRUE(panel->runner() && panel->runner()->isActive()) << said.join(QLatin1Char('\n')).toStdString();
    ASSERT_TRUE(waitFor([&] { return !panel->runner()->isActive(); }, 120000));
    ASSERT_TRUE(panel->before()) << said.join(QLatin1Char('\n')).toStdString();
    auto* figures = panel->findChild<QTableWidget*>(QStringLiteral("gridMapFigures"));
    ASSERT_TRUE(figures && figures->item(5, 0));
    EXPECT_FALSE(figures->item(5, 0)->text().isEmpty()) << "the RMS error is shown beside the map";

    ASSERT_TRUE(compensate->isEnabled());
    QTest::mouseClick(compensate, Qt::LeftButton);
    ASSERT_TRUE(waitFor([&] { return panel->tableEnabled(); }, 30000)) << said.join(QLatin1Char('\n')).toStdString();
    const double beforeX = panel->runner()->startXMm(), beforeY = panel->runner()->startYMm();
    // The operator looks elsewhere before asking for the after map (found by hand: the after
    // map was read from wherever the stage stood, a grid the table had never seen).
    stage->move({{0, 37.0}, {1, 33.0}}, false);
    ASSERT_TRUE(waitFor([&] { return !stage->status().anyMoving() && std::abs(stage->status().axes[1].measured - 33.0) < 0.01; }, 30000));
    panel->setGrid(20, 4, 3);
    QTest::mouseClick(run, Qt::LeftButton);
    ASSERT_FALSE(panel->runner()->isActive()) << "an after map on another grid than the before's";
    EXPECT_TRUE(said.back().contains(QStringLiteral("3 × 3 nodes"))) << said.back().toStdString();
    panel->setGrid(20, 3, 3);
    QTest::mouseClick(run, Qt::LeftButton);
    ASSERT_TRUE(panel->runner() && panel->runner()->isActive());
    ASSERT_TRUE(waitFor([&] { return !panel->runner()->isActive(); }, 120000));
    ASSERT_TRUE(panel->after()) << said.join(QLatin1Char('\n')).toStdString();
    EXPECT_DOUBLE_EQ(panel->runner()->startXMm(), beforeX) << "the after map starts where the before map did";
    EXPECT_DOUBLE_EQ(panel->runner()->startYMm(), beforeY);
    EXPECT_TRUE(panel->before()) << "the before stays beside the after";
    EXPECT_EQ(figures->columnCount(), 2);
    EXPECT_LT(panel->after()->figures.rmsErrorUm * 5, panel->before()->figures.rmsErrorUm)
        << panel->before()->figures.rmsErrorUm << " → " << panel->after()->figures.rmsErrorUm;
    guitest::pump(200);
    // BP_GUI_SHOTS=DIR keeps the tab for docs/accuracy.md as DIR/calibration-grid-map.png.
    if (!qEnvironmentVariable("BP_GUI_SHOTS").isEmpty())
        guitest::keepPicture(w.get(), QStringLiteral("calibration-grid-map.png"));
    link->host().setTimeScale(1);
}
