// One source of truth per state. Failures this catches: the status bar said "ready" during
// an E-stop; "Device clock started again" stayed red for minutes; at a soft limit the joystick
// still said "Commanded speed 20.00 mm/s"; the circle preview became an ellipse after a resize.
#include "patterns_fixture.h"

#include "app/gui/motion_screens.h"
#include "device/telemetry/telemetry_hub.h"
#include "motion/plans/pattern.h"
#include "widgets/patterns/pattern_preview.h"
#include "widgets/patterns/pattern_screen.h"
#include "widgets/plots_screen.h"

#include <gtest/gtest.h>

using guitest::MotionScreensTest;
using guitest::pump;
using guitest::waitFor;

TEST_F(MotionScreensTest, TheStatusBarSaysEStopWhileItIsLatched)
{
    ASSERT_TRUE(waitFor([&] { return w->statusText(1).contains(QStringLiteral("ready")); }, 3000)) << w->statusText(1).toStdString();
    w->emergencyStop();
    ASSERT_TRUE(waitFor([&] { return stage()->status().estop; }, 3000));
    ASSERT_TRUE(waitFor([&] { return w->statusText(1).contains(QStringLiteral("E-STOP")); }, 3000)) << w->statusText(1).toStdString();
    EXPECT_FALSE(w->statusText(1).contains(QStringLiteral("ready"))) << w->statusText(1).toStdString();
    // The words name the button that clears it.
    EXPECT_TRUE(w->statusText(1).contains(QStringLiteral("Reset E-stop"))) << w->statusText(1).toStdString();
    w->resetEStop();
    ASSERT_TRUE(waitFor([&] { return !stage()->status().estop; }, 3000));
    EXPECT_TRUE(waitFor([&] { return w->statusText(1).contains(QStringLiteral("ready")); }, 3000)) << w->statusText(1).toStdString();
}

TEST_F(MotionScreensTest, ADeviceClockThatStartedAgainIsNewsNotAFault)
{
    emit w->telemetry()->problem(motion::msg::make("telemetry.clock_restarted", {motion::msg::verbatim("instrument", "Stage")}));
    EXPECT_TRUE(w->plotsScreen()->lastMessage().contains(QStringLiteral("clock"))) << w->plotsScreen()->lastMessage().toStdString();
    EXPECT_FALSE(w->plotsScreen()->messageIsProblem()) << "shown in red, as if something had failed";
}

TEST_F(MotionScreensTest, AtASoftLimitTheJoystickSaysTheAxisIsHeldNotTheStickSpeed)
{
    ASSERT_TRUE(homeStage());
    ui::JoystickScreen* j = showStageJoystick();
    ASSERT_TRUE(j);
    j->setFocus();
    const double lo = stage()->softLimits().value(0).min;
    // Toward X's lower soft limit until the machine stands at it.
    QTest::keyPress(j, Qt::Key_Left);
    ASSERT_TRUE(waitFor([&] { return stage()->status().axes[0].commanded <= lo + 1e-3 && !stage()->status().axes[0].moving; }, 20000))
        << "X at " << stage()->status().axes[0].commanded << ", its limit " << lo;
    pump(200);
    const QString said = j->speedText();
    QTest::keyRelease(j, Qt::Key_Left);
    EXPECT_TRUE(said.contains(QStringLiteral("0.00 mm/s"))) << said.toStdString();
    EXPECT_TRUE(said.contains(QStringLiteral("X held at its soft limit"))) << said.toStdString();
}

TEST_F(MotionScreensTest, TheCirclePreviewStaysRoundWhenItsShapeChanges)
{
    ASSERT_TRUE(w->showScreen(QStringLiteral("patterns")));
    ui::PatternScreen* p = w->motionScreens()->patterns();
    p->setInstrument(1);
    motion::plans::Pattern pat;
    pat.shape = motion::plans::PatternShape::Circle;
    p->setPattern(pat);
    pump(50);
    ui::PatternPreview* v = p->preview();
    v->fit();
    v->replot();
    EXPECT_NEAR(v->aspect(), 1.0, 0.02);
    // Shorter by a banner's height, then a lot narrower: still round.
    v->resize(v->width(), v->height() - 37);
    pump(30);
    EXPECT_NEAR(v->aspect(), 1.0, 0.02) << "after losing 37 px of height";
    v->resize(v->width() / 2, v->height());
    pump(30);
    EXPECT_NEAR(v->aspect(), 1.0, 0.02) << "after losing half its width";
}
