// The Calibration screen's grid map read both ways, driven through its widgets: the
// "Both directions" box asks for the reverse pass, the run reads every node twice, the
// figures gain the reversal's rows, and the arrows switch between the errors and each
// node's reversal; the box keeps its state for the next run.
#include "app/gui/instrument_session.h"
#include "app/gui/main_window.h"
#include "device/link/simulated_link.h"
#include "gui_window.h"
#include "widgets/calibration/calibration_screen.h"
#include "widgets/calibration/grid_map_panel.h"
#include "widgets/camera/camera_session.h"

#include <QCheckBox>
#include <QComboBox>
#include <QPushButton>
#include <QTabWidget>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>

#include <gtest/gtest.h>

#include <cmath>

using guitest::waitFor;

TEST(CalibrationGridMapReversal, BothDirectionsReadsEveryNodeTwiceAndShowsTheReversalOnAChoice)
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
    auto* both = panel->findChild<QCheckBox*>(QStringLiteral("gridMapBidirectional"));
    auto* show = panel->findChild<QComboBox*>(QStringLiteral("gridMapShow"));
    auto* figures = panel->findChild<QTableWidget*>(QStringLiteral("gridMapFigures"));
    ASSERT_TRUE(run && both && show && figures);
    EXPECT_FALSE(both->isChecked()) << "one way unless asked";
    EXPECT_FALSE(show->isEnabled()) << "no reversal to show before a map read both ways";
    EXPECT_TRUE(figures->isRowHidden(8));
    QStringList said;
    QObject::connect(screen, &ui::CalibrationScreen::problem, [&](const QString& m) { said << m; });

    dev::Instrument* stage = w->stage()->instrument();
    auto* link = qobject_cast<dev::SimulatedLink*>(w->stage()->link());
    ASSERT_TRUE(link);
    link->host().setTimeScale(20);
    stage->home(0);
    ASSERT_TRUE(waitFor([&] { return stage->status().axes.size() >= 2 && stage->status().axes[0].homed && stage->status().axes[1].homed
                                  && !stage->status().anyMoving(); }, 60000));
    stage->move({{0, 10.1}, {1, 10.0}}, false);
    ASSERT_TRUE(waitFor([&] { return !stage->status().anyMoving() && std::abs(stage->status().axes[1].measured - 10.0) < 0.01; }, 30000));
    w->cameraSession()->open(QStringLiteral("sim"));
    ASSERT_TRUE(waitFor([&] { return w->cameraSession()->isOpen(); }, 5000));

    // On its box, where a person clicks (the widget spans the form; its label does not).
    QTest::mouseClick(both, Qt::LeftButton, {}, QPoint(6, both->height() / 2));
    ASSERT_TRUE(both->isChecked());
    QTest::mouseClick(run, Qt::LeftButton);
    ASSERT_TRUE(panel->runner() && panel->runner()->isActive()) << said.join(QLatin1Char('\n')).toStdString();
    EXPECT_FALSE(both->isEnabled()) << "not changed under a running map";
    ASSERT_TRUE(waitFor([&] { return !panel->runner()->isActive(); }, 180000));
    EXPECT_EQ(panel->runner()->nodesRead(), 18) << "every node read both ways";
    ASSERT_TRUE(panel->before()) << said.join(QLatin1Char('\n')).toStdString();
    ASSERT_TRUE(panel->before()->figures.meanReversalXUm);
    EXPECT_TRUE(both->isChecked() && both->isEnabled()) << "kept for the next run";
    // The reversal's figures: shown, with their numbers.
    for (int r = 8; r < 11; ++r) {
        EXPECT_FALSE(figures->isRowHidden(r)) << r;
        ASSERT_TRUE(figures->item(r, 0)) << r;
        EXPECT_NE(figures->item(r, 0)->text(), QStringLiteral("—")) << r;
    }
    // The arrows: the errors first, the reversals on a choice, and the view draws another picture.
    ASSERT_TRUE(show->isEnabled());
    EXPECT_EQ(panel->view()->vectors(), ui::report::GridVectors::Error);
    guitest::pump(100);
    const QImage errors = panel->view()->grab().toImage();
    show->setCurrentIndex(show->findData(static_cast<int>(ui::report::GridVectors::Reversal)));
    EXPECT_EQ(panel->view()->vectors(), ui::report::GridVectors::Reversal);
    guitest::pump(100);
    EXPECT_NE(panel->view()->grab().toImage(), errors) << "the reversal map is drawn";
    // BP_GUI_SHOTS=DIR keeps the tab for docs/accuracy.md.
    if (!qEnvironmentVariable("BP_GUI_SHOTS").isEmpty())
        guitest::keepPicture(w.get(), QStringLiteral("calibration-grid-map-reversal.png"));
    link->host().setTimeScale(1);
}
