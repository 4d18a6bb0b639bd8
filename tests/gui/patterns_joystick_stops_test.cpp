// The Joystick screen's promises a person relies on with the knob held out: hiding the screen
// or the window stops the machine itself (not only the drawn knob), a pulled cable stops it
// and the stick does not come back to life after reconnecting, and the maximum speed is the
// speed full deflection gives.
#include "device/client/joystick_driver.h"
#include "motion/jog/joystick_curve.h"
#include "patterns_fixture.h"

#include "widgets/common/number_field.h"
#include "widgets/joystick/travel_view.h"
#include <QLabel>

#include <cmath>
#include <functional>

using guitest::MotionScreensTest;
using guitest::pump;
using guitest::waitFor;

namespace {

class JoystickStops : public MotionScreensTest {
protected:
    /// The stage's Joystick screen on show, the knob held out diagonally, both axes moving on
    /// the machine.
    ui::JoystickScreen* holdDiagonal()
    {
        ui::JoystickScreen* j = showStageJoystick();
        if (!j) {
            ADD_FAILURE() << "the Joystick screen never became ready";
            return nullptr;
        }
        drag(j->pad(), 0.7, 0.7);
        EXPECT_TRUE(waitFor([&] { return machineMoving(0) && machineMoving(1); }, 3000)) << "both axes must move";
        return j;
    }
    /// With the simulator's clock frozen, does `hide` stop both axes within 100 ms of machine
    /// time? The device's jog watchdog only trips after 200 ms without a refresh, so an axis at
    /// rest by then was stopped by the screen's own stop frame.
    void expectHidingStopsTheMachine(const std::function<void()>& hide)
    {
        ui::JoystickScreen* j = holdDiagonal();
        ASSERT_NE(j, nullptr);
        dev::SimulatedLink* link = stageLink();
        link->host().setManualClock(true);
        const quint64 frames = j->driver()->framesSent();
        hide();
        EXPECT_FALSE(j->isVisible());
        EXPECT_FALSE(j->driver()->active());
        EXPECT_GT(j->driver()->framesSent(), frames) << "no stop frame went out";
        pump(100);  // the frame crosses the loopback; no machine time passes meanwhile
        for (int k = 0; k < 10; ++k)
            link->host().advance(0.010);
        EXPECT_FALSE(machineMoving(0)) << "X still moving 100 ms after the screen was hidden";
        EXPECT_FALSE(machineMoving(1)) << "Y still moving 100 ms after the screen was hidden";
        const double x = link->machine().commandedLogical(0), y = link->machine().commandedLogical(1);
        link->host().advance(0.5);
        EXPECT_DOUBLE_EQ(link->machine().commandedLogical(0), x);
        EXPECT_DOUBLE_EQ(link->machine().commandedLogical(1), y);
        link->host().setManualClock(false);
    }
    /// Speed of axis i on the machine over `forS` of machine time, from its commanded position.
    double machineSpeed(int i, double forS)
    {
        dev::SimulatedLink* link = stageLink();
        const double t0 = link->machine().timeS(), p0 = link->machine().commandedLogical(i);
        EXPECT_TRUE(waitFor([&] { return link->machine().timeS() > t0 + forS; }, 5000));
        return (link->machine().commandedLogical(i) - p0) / (link->machine().timeS() - t0);
    }
};

}  // namespace

TEST_F(JoystickStops, SwitchingToAnotherScreenMidDragStopsBothAxes)
{
    expectHidingStopsTheMachine([&] { ASSERT_TRUE(w->showScreen(QStringLiteral("patterns"))); });
}

TEST_F(JoystickStops, HidingTheWindowMidDragStopsBothAxes)
{
    expectHidingStopsTheMachine([&] { w->hide(); });
}

TEST_F(JoystickStops, APulledCableStopsTheAxesAndTheStickStaysDeadAfterReconnecting)
{
    ui::JoystickScreen* j = holdDiagonal();
    ASSERT_NE(j, nullptr);
    ui::JoystickPad* pad = j->pad();
    auto* travel = j->findChild<ui::TravelView*>();
    ASSERT_NE(travel, nullptr);
    ASSERT_TRUE(waitFor([&] { return travel->showsLivePosition(); }, 2000));
    dev::SimulatedLink* link = stageLink();
    link->pair().unplug();
    ASSERT_TRUE(waitFor([&] { return stage()->state() == dev::LinkState::Lost; }, 2000));
    EXPECT_FALSE(travel->showsLivePosition()) << "the travel view must not show the last position as where the axes are";
    EXPECT_FALSE(j->driver()->active());
    EXPECT_FALSE(pad->dragging()) << "the knob must let go when the link goes";
    EXPECT_TRUE(pad->deflection().isNull());
    EXPECT_FALSE(pad->isEnabled());
    // No stop can cross a pulled cable: the device's jog watchdog ends the motion.
    ASSERT_TRUE(waitFor([&] { return !machineMoving(0) && !machineMoving(1); }, 2000));

    link->pair().replug();
    stage()->connectLink();
    ASSERT_TRUE(waitFor([&] { return stage()->isReady(); }, 5000));
    ASSERT_TRUE(waitFor([&] { return pad->isEnabled(); }, 2000));
    EXPECT_TRUE(travel->showsLivePosition());
    const double x = link->machine().commandedLogical(0), y = link->machine().commandedLogical(1);
    const quint64 frames = j->driver()->framesSent();
    // The hand never let go of the mouse and keeps pushing: nothing may move by itself.
    for (int k = 0; k < 10; ++k) {
        QTest::mouseMove(pad, at(pad, 0.8 - 0.03 * k, 0.6 + 0.03 * k));
        pump(30);
    }
    pump(300);
    EXPECT_FALSE(machineMoving(0));
    EXPECT_FALSE(machineMoving(1));
    EXPECT_DOUBLE_EQ(link->machine().commandedLogical(0), x);
    EXPECT_DOUBLE_EQ(link->machine().commandedLogical(1), y);
    EXPECT_EQ(j->driver()->framesSent(), frames) << "the stick sent jog frames nobody asked for";
    EXPECT_FALSE(j->driver()->active());
    QTest::mouseRelease(pad, Qt::LeftButton, {}, at(pad, 0.5, 0.9));

    // A fresh grab works again, and letting go stops it.
    drag(pad, 0.7, 0.0);
    ASSERT_TRUE(waitFor([&] { return link->machine().commandedLogical(0) > x + 0.1; }, 3000));
    QTest::mouseRelease(pad, Qt::LeftButton, {}, at(pad, 0.7, 0.0));
    ASSERT_TRUE(waitFor([&] { return !machineMoving(0) && !machineMoving(1); }, 2000));
}

TEST_F(JoystickStops, FullDeflectionRunsAtTheMaximumSpeedAndChangingItChangesTheSpeed)
{
    ui::JoystickScreen* j = showStageJoystick();
    ASSERT_NE(j, nullptr);
    ui::JoystickPad* pad = j->pad();
    auto* maxSpeed = j->findChild<ui::NumberField*>(QStringLiteral("joystickMaxSpeed"));
    auto* speedLabel = j->findChild<QLabel*>(QStringLiteral("joystickSpeed"));
    ASSERT_NE(maxSpeed, nullptr);
    ASSERT_NE(speedLabel, nullptr);
    // The operator types a maximum speed and presses Enter.
    auto setMax = [&](const char* text) {
        maxSpeed->setFocus();
        maxSpeed->selectAll();
        QTest::keyClicks(maxSpeed, QString::fromLatin1(text));
        QTest::keyClick(maxSpeed, Qt::Key_Return);
        j->setFocus();
    };
    // Knob pulled past the rim along +X, held until the axis runs steadily; speeds measured on
    // the machine against its own clock.
    auto speedsAtFullX = [&](double* vx, double* vy) {
        drag(pad, 1.3, 0.0);
        EXPECT_NEAR(std::hypot(pad->deflection().x(), pad->deflection().y()), 1.0, 1e-9) << "the rim is full deflection";
        pump(200);  // the ramp up (200 mm/s² reaches 5 mm/s in 25 ms)
        *vx = machineSpeed(0, 0.3);
        *vy = machineSpeed(1, 0.3);
        QTest::mouseRelease(pad, Qt::LeftButton, {}, at(pad, 1.3, 0.0));
        EXPECT_TRUE(waitFor([&] { return !machineMoving(0) && !machineMoving(1); }, 2000));
    };
    setMax("4");
    ASSERT_DOUBLE_EQ(j->settings().maxSpeedMmS, 4.0);
    double vx = 0, vy = 0;
    speedsAtFullX(&vx, &vy);
    // Full deflection is 1 through any dead-band and expo; a pixel off the axis may give Y a
    // little of the speed, never more than a few per cent.
    EXPECT_NEAR(vx, 4.0, 0.04);
    EXPECT_LT(std::fabs(vy), 0.2);

    setMax("1.5");
    ASSERT_DOUBLE_EQ(j->settings().maxSpeedMmS, 1.5);
    speedsAtFullX(&vx, &vy);
    EXPECT_NEAR(vx, 1.5, 0.015);

    // Part way out the speed follows the shaping curve, scaled by the same maximum.
    drag(pad, 0.5, 0.0);
    const motion::path::Vec2 shaped = motion::jog::shapeStick({pad->deflection().x(), pad->deflection().y()}, j->settings().shaping);
    const double expected = 1.5 * shaped.x;
    EXPECT_GT(expected, 0.1);
    EXPECT_LT(expected, 1.0);
    const QString shown = QString::number(1.5 * std::hypot(shaped.x, shaped.y), 'f', 2);
    EXPECT_TRUE(speedLabel->text().contains(shown)) << speedLabel->text().toStdString();
    pump(200);
    EXPECT_NEAR(machineSpeed(0, 0.3), expected, 0.01 * 1.5);
    QTest::mouseRelease(pad, Qt::LeftButton, {}, at(pad, 0.5, 0.0));
}
