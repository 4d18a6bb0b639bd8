// The Joystick and Patterns screens driven as a person would, against the in-process
// simulators: drag the knob, let go, keys; the pattern preview against the plan; a run.
#include "app/gui/instrument_session.h"
#include "app/gui/main_window.h"
#include "app/gui/motion_screens.h"
#include "device/link/simulated_link.h"
#include "device/client/joystick_driver.h"
#include "device/files/pattern_file.h"
#include "device/jobs/pattern_runner.h"
#include "gui_wait.h"
#include "patterns_fixture.h"
#include "widgets/common/number_field.h"
#include "widgets/joystick/joystick_pad.h"
#include "widgets/joystick/joystick_screen.h"
#include "widgets/joystick/travel_view.h"
#include "widgets/patterns/contour_plot.h"
#include "widgets/patterns/pattern_form.h"
#include "widgets/patterns/pattern_preview.h"
#include "widgets/patterns/pattern_screen.h"
#include "widgets/plot_panel.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QSlider>
#include <QTemporaryDir>
#include <QTest>

#include <gtest/gtest.h>

#include <cmath>

using guitest::MotionScreensTest;
using guitest::pump;
using guitest::waitFor;

TEST_F(MotionScreensTest, DraggingTheKnobMovesBothAxesAndLettingGoStopsThem)
{
    ui::JoystickScreen* j = showStageJoystick();
    ASSERT_NE(j, nullptr);
    ui::JoystickPad* pad = j->pad();
    const double x0 = stage()->status().axes[0].commanded, y0 = stage()->status().axes[1].commanded;
    drag(pad, 0.7, 0.7);  // out to the upper right
    EXPECT_GT(pad->deflection().x(), 0.6);
    EXPECT_GT(pad->deflection().y(), 0.6);
    ASSERT_TRUE(waitFor([&] {
        const auto& a = stage()->status().axes;
        return a[0].commanded > x0 + 0.2 && a[1].commanded > y0 + 0.2;
    }, 3000)) << "both axes must move at once";
    EXPECT_TRUE(stage()->status().axes[0].jogging && stage()->status().axes[1].jogging);
    QTest::mouseRelease(pad, Qt::LeftButton, {}, at(pad, 0.7, 0.7));
    EXPECT_TRUE(pad->deflection().isNull()) << "the knob springs back";
    ASSERT_TRUE(waitFor([&] { return !stage()->status().axes[0].moving && !stage()->status().axes[1].moving; }, 2000));
    const double xs = stage()->status().axes[0].commanded;
    pump(300);
    EXPECT_DOUBLE_EQ(stage()->status().axes[0].commanded, xs) << "an axis crept on after release";
    EXPECT_GT(j->travel()->trailSize(), 3u);
    EXPECT_FALSE(j->driver()->active());
}

TEST_F(MotionScreensTest, ArrowKeysPushTheStickAndFocusLossStopsIt)
{
    ASSERT_TRUE(w->showScreen(QStringLiteral("joystick")));
    w->showInstrument(1);
    ui::JoystickScreen* j = joystick(1);
    j->setFocus();
    ASSERT_TRUE(waitFor([&] { return j->hasFocus(); }, 1000));
    const double y0 = stage()->status().axes[1].commanded;
    QTest::keyPress(j, Qt::Key_Up);
    ASSERT_TRUE(waitFor([&] { return stage()->status().axes[1].commanded > y0 + 0.2; }, 3000));
    EXPECT_NEAR(j->pad()->deflection().y(), 1.0, 1e-9);
    j->clearFocus();  // the key-up will never come
    ASSERT_TRUE(waitFor([&] { return !stage()->status().axes[1].moving; }, 2000));
    EXPECT_FALSE(j->driver()->active());
}

TEST_F(MotionScreensTest, TheZSliderSpringsBackAndStopsZ)
{
    ASSERT_TRUE(w->showScreen(QStringLiteral("joystick")));
    w->showInstrument(0);
    ui::JoystickScreen* j = joystick(0);
    QSlider* z = j->zSlider();
    ASSERT_TRUE(waitFor([&] { return z->isVisible() && z->isEnabled(); }, 2000));
    EXPECT_FALSE(joystick(1)->zSlider()->isVisibleTo(joystick(1)));  // the stage has no Z
    dev::Instrument* an = w->analyzer()->instrument();
    const int zi = an->identity().axisIndex(QLatin1Char('Z'));
    const double z0 = an->status().axes[zi].commanded;
    z->setSliderDown(true);
    z->setValue(80);
    ASSERT_TRUE(waitFor([&] { return an->status().axes[zi].commanded > z0 + 0.2; }, 3000));
    z->setSliderDown(false);  // sliderReleased: back to the centre
    EXPECT_EQ(z->value(), 0);
    ASSERT_TRUE(waitFor([&] { return !an->status().axes[zi].moving; }, 2000));
}

TEST_F(MotionScreensTest, ThePreviewShowsThePlanAndItsStepsWhenZoomedIn)
{
    ASSERT_TRUE(w->showScreen(QStringLiteral("patterns")));
    ui::PatternScreen* p = w->motionScreens()->patterns();
    p->setInstrument(1);
    motion::plans::Pattern pat;
    pat.shape = motion::plans::PatternShape::Spiral;
    pat.spiral.turns = 2;
    p->setPattern(pat);
    pump(200);
    const auto plan = motion::plans::plan(p->pattern());
    ASSERT_EQ(plan.size(), p->preview()->path().size());
    for (std::size_t k = 0; k < plan.size(); ++k) {
        EXPECT_EQ(plan[k].kind, p->preview()->path()[k].kind) << k;
        EXPECT_DOUBLE_EQ(plan[k].end.x, p->preview()->path()[k].end.x) << k;
        EXPECT_DOUBLE_EQ(plan[k].end.y, p->preview()->path()[k].end.y) << k;
    }
    EXPECT_GT(p->preview()->pathPoints(), 100);
    EXPECT_EQ(p->preview()->walkPoints(), 0);  // the whole pattern in view: steps far below a pixel
    // Before a run the contour-error plot spans the path (it showed 0 … 5 mm, an Xvfb session found).
    EXPECT_NEAR(p->contour()->xAxis->range().upper, motion::path::pathLengthMm(plan), 1e-6);
    // Zoomed onto a few micrometres of the start, the walk's steps appear, each one step long.
    const auto s = plan.front().start;
    p->preview()->yAxis->setRange(s.y - 0.004, s.y + 0.004);
    p->preview()->xAxis->setRange(s.x - 0.004, s.x + 0.004);
    pump(100);
    ASSERT_GT(p->preview()->walkPoints(), 4);
    // Changing the form changes the preview with it.
    p->form()->shapeBox()->setCurrentIndex(0);  // line
    ASSERT_TRUE(waitFor([&] { return p->preview()->path().size() == 1; }, 2000));
    EXPECT_DOUBLE_EQ(p->preview()->path()[0].end.x, p->pattern().line.endMm.x);
}

TEST_F(MotionScreensTest, APatternOutsideTheSoftLimitsIsRefusedByName)
{
    ASSERT_TRUE(w->showScreen(QStringLiteral("patterns")));
    ui::PatternScreen* p = w->motionScreens()->patterns();
    p->setInstrument(1);
    ASSERT_FALSE(p->run());  // not homed yet
    EXPECT_TRUE(p->statusText().contains(QStringLiteral("not homed"))) << p->statusText().toStdString();
    motion::plans::Pattern pat;
    pat.shape = motion::plans::PatternShape::Line;
    pat.line.endMm = {120, 60};
    p->setPattern(pat);
    ASSERT_FALSE(p->run());
    EXPECT_TRUE(p->statusText().contains(QStringLiteral("segment 0 (LINE) reaches X = 120.000 mm"))) << p->statusText().toStdString();
}

TEST_F(MotionScreensTest, SaveAndLoadKeepThePattern)
{
    ui::PatternScreen* p = w->motionScreens()->patterns();
    motion::plans::Pattern pat;
    pat.name = "saved";
    pat.shape = motion::plans::PatternShape::Cosine;
    pat.wave.amplitudeMm = 3.5;
    p->setPattern(pat);
    QTemporaryDir tmp;
    const QString f = tmp.filePath(QStringLiteral("x.pattern.json"));
    QString error;
    ASSERT_TRUE(p->savePattern(f, &error)) << error.toStdString();
    p->setPattern(motion::plans::Pattern{});
    ASSERT_TRUE(p->loadPattern(f, &error)) << error.toStdString();
    EXPECT_EQ(p->pattern().shape, motion::plans::PatternShape::Cosine);
    EXPECT_DOUBLE_EQ(p->pattern().wave.amplitudeMm, 3.5);
    EXPECT_EQ(p->form()->field(QStringLiteral("cosine.amplitude_mm"))->value().value_or(-1), 3.5);
    EXPECT_FALSE(p->exportRun(tmp.filePath(QStringLiteral("run.csv")), &error));  // nothing run yet
    EXPECT_FALSE(error.isEmpty());
}

TEST_F(MotionScreensTest, ARunFromTheScreenEndsWithItsContourSummaryAndExportsCsv)
{
    // Home the stage with its clock sped up, then run a short line at real time.
    ASSERT_TRUE(homeStage());
    ASSERT_TRUE(w->showScreen(QStringLiteral("patterns")));
    ui::PatternScreen* p = w->motionScreens()->patterns();
    p->setInstrument(1);
    motion::plans::Pattern pat;
    pat.shape = motion::plans::PatternShape::Line;
    pat.feedMmS = 1;
    pat.line = {{0.5, 0.5}, {1.7, 2.1}};
    p->setPattern(pat);
    pump(300);
    ASSERT_TRUE(p->run()) << p->statusText().toStdString();
    ASSERT_TRUE(waitFor([&] { return p->runner()->state() == dev::jobs::PatternRunner::State::Done; }, 15000)) << p->statusText().toStdString();
    pump(200);
    EXPECT_TRUE(p->summaryText().contains(QStringLiteral("Contour error"))) << p->summaryText().toStdString();
    EXPECT_TRUE(p->summaryText().contains(QStringLiteral(" Hz"))) << "the sample rate is said: " << p->summaryText().toStdString();
    EXPECT_FALSE(p->summaryText().contains(QStringLiteral("Too few samples"))) << p->summaryText().toStdString();
    EXPECT_GT(p->runner()->summary().samples, 100u);  // 2 s at 250 Hz through the hub
    EXPECT_LT(p->runner()->summary().maxContourMm, 0.002);
    EXPECT_GT(p->contour()->samples(), 100);
    EXPECT_GT(p->preview()->runPoints(), 100);
    QTemporaryDir tmp;
    QString error;
    const QString f = tmp.filePath(QStringLiteral("run.csv"));
    ASSERT_TRUE(p->exportRun(f, &error)) << error.toStdString();
    QFile in(f);
    ASSERT_TRUE(in.open(QIODevice::ReadOnly));
    const QByteArray csv = in.readAll();
    EXPECT_TRUE(csv.startsWith("time_s,commanded_x_mm"));
    EXPECT_EQ(csv.count('\n'), static_cast<qsizetype>(p->runner()->samples().size()) + 1);
}

TEST(PlotPanelLegend, RemovingAChannelTakesItOutOfThePanelsOwnLegend)
{
    // Found when the Jog screen's strip rebuilt its channels while the Patterns screen made
    // start-up slower: the panel's legend kept an item of a deleted graph and the next
    // layout crashed.
    QCustomPlot plot;
    auto* margins = new QCPMarginGroup(&plot);
    ui::PlotPanel panel(&plot, margins);
    const dev::tele::ChannelKey a{0, {0, dev::proto::ChannelKind::Measured}}, b{0, {1, dev::proto::ChannelKind::Measured}};
    ASSERT_TRUE(panel.addChannel(a, QStringLiteral("A"), QStringLiteral("mm")));
    ASSERT_TRUE(panel.addChannel(b, QStringLiteral("B"), QStringLiteral("mm")));
    EXPECT_EQ(panel.legend()->itemCount(), 2);
    ASSERT_TRUE(panel.removeChannel(a));
    EXPECT_EQ(panel.legend()->itemCount(), 1);
    plot.resize(400, 300);
    plot.replot();  // lays the legend out: with a stale item this read freed memory
}
