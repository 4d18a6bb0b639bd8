#pragma once
// The main window with both simulators connected, shared by the patterns_* GUI tests (the
// Joystick and Patterns screens), and what those tests do over and over: drag the knob, home
// the stage, ask the simulated machine itself whether it moves.
#include "app/gui/instrument_session.h"
#include "app/gui/main_window.h"
#include "app/gui/motion_screens.h"
#include "device/link/simulated_link.h"
#include "gui_wait.h"
#include "gui_window.h"
#include "widgets/joystick/joystick_pad.h"
#include "widgets/joystick/joystick_screen.h"

#include <QTest>

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>

namespace guitest {

// Not in an anonymous namespace: several test files use the same fixture (one gtest suite).
class MotionScreensTest : public ::testing::Test {
protected:
    void SetUp() override
    {
        w = guitest::openReadyWindow({1500, 900});
        ASSERT_TRUE(w) << "the simulated instruments did not become ready";
    }
    dev::Instrument* stage() { return w->stage()->instrument(); }
    dev::SimulatedLink* stageLink() { return qobject_cast<dev::SimulatedLink*>(w->stage()->link()); }
    ui::JoystickScreen* joystick(int i) { return w->motionScreens()->joystick(i); }
    /// The stage's Joystick screen on show with its knob ready to grab (nullptr if it never is).
    ui::JoystickScreen* showStageJoystick()
    {
        if (!w->showScreen(QStringLiteral("joystick")))
            return nullptr;
        w->showInstrument(1);
        ui::JoystickScreen* j = joystick(1);
        return waitFor([&] { return j->pad()->isVisible() && j->pad()->isEnabled(); }, 2000) ? j : nullptr;
    }
    /// Mouse position on the pad for a deflection (x right, y up).
    static QPoint at(ui::JoystickPad* pad, double dx, double dy)
    {
        const double r = std::min(pad->width(), pad->height()) / 2.0 - 18;
        return QPoint(static_cast<int>(pad->width() / 2.0 + dx * r), static_cast<int>(pad->height() / 2.0 - dy * r));
    }
    /// Grabs the knob at the centre and pulls it out to (dx, dy) in small steps, as a hand
    /// would; the button stays down.
    static void drag(ui::JoystickPad* pad, double dx, double dy)
    {
        QTest::mousePress(pad, Qt::LeftButton, {}, at(pad, 0, 0));
        for (int k = 1; k <= 10; ++k) {
            QTest::mouseMove(pad, at(pad, dx * k / 10, dy * k / 10));
            pump(15);
        }
    }
    /// The simulated machine's own word (not the client's last status): is axis i moving?
    bool machineMoving(int i)
    {
        const auto st = stageLink()->machine().status();
        return (st.axes[static_cast<std::size_t>(i)].flags & (dev::proto::AxisMoving | dev::proto::AxisJogging)) != 0;
    }
    /// Homes the stage with its clock sped up, then puts the clock back to real time.
    bool homeStage()
    {
        dev::SimulatedLink* link = stageLink();
        if (!link)
            return false;
        // 10x: at 20x the simulated stage (true position beside the grating) outran one core
        // of a loaded machine now and then, and HOME went unanswered.
        link->host().setTimeScale(10);
        stage()->home(0);
        const bool homed = waitFor([&] {
            const auto& a = stage()->status().axes;
            return a.size() == 2 && a[0].homed && a[1].homed && !a[0].moving && !a[1].moving;
        }, 30000);
        link->host().setTimeScale(1);
        return homed;
    }
    std::unique_ptr<app::MainWindow> w;
};

} // namespace guitest
