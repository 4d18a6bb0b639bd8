// What the keys do and what the lamps say, as an afternoon at the GUI found them: on Plots
// the arrow keys turned the Window setting instead of jogging; the stage's key hint offered
// PgUp/PgDn for a Z it does not have; a disconnected stage kept its green Homed lamps.
#include "patterns_fixture.h"

#include "widgets/axis_row.h"
#include "widgets/jog_screen.h"
#include "widgets/status_lamp.h"

#include <QAbstractItemView>
#include <QComboBox>
#include <QLabel>
#include <QLineEdit>

#include <gtest/gtest.h>

using guitest::MotionScreensTest;
using guitest::pump;
using guitest::waitFor;

namespace {

/// The lamps of `jog`'s axis rows.
QList<ui::StatusLamp*> lampsOf(ui::JogScreen* jog) { return jog->findChildren<ui::StatusLamp*>(); }

/// The screen `name`'s widget inside the window's stack.
QWidget* screenWidget(app::MainWindow* w, const QString& name)
{
    return w->findChild<QWidget*>(QStringLiteral("screenScroll_%1").arg(name));
}

} // namespace

TEST_F(MotionScreensTest, OnPlotsTheArrowKeysJogAndLeaveTheWindowSettingAlone)
{
    ASSERT_TRUE(w->showScreen(QStringLiteral("plots")));
    pump(50);
    QComboBox* setting = nullptr;
    for (auto* c : screenWidget(w.get(), QStringLiteral("plots"))->findChildren<QComboBox*>())
        if (c->isVisible() && !c->isEditable() && c->count() > 2 && c->currentIndex() > 0 && c->currentIndex() < c->count() - 1) {
            setting = c;
            break;
        }
    ASSERT_NE(setting, nullptr) << "no combo on Plots the arrow keys could turn";
    w->activateWindow();
    setting->setFocus();
    ASSERT_TRUE(setting->hasFocus());
    const int index = setting->currentIndex();
    dev::Instrument* analyzer = w->analyzer()->instrument();  // the Jog screen's tab
    const double before = analyzer->status().axes[0].commanded;
    QTest::keyPress(setting, Qt::Key_Right);
    const bool moved = waitFor([&] { return analyzer->status().axes[0].commanded > before + 0.3; }, 3000);
    QTest::keyRelease(setting, Qt::Key_Right);
    EXPECT_TRUE(moved) << "Right on Plots did not jog X";
    EXPECT_TRUE(waitFor([&] { return !analyzer->status().axes[0].moving; }, 3000)) << "X kept moving after the key came up";
    EXPECT_FALSE(analyzer->isJogging(0));
    EXPECT_EQ(setting->currentIndex(), index) << "the key turned " << setting->objectName().toStdString();
}

TEST_F(MotionScreensTest, TheJogKeysWorkOnEveryScreenAndATextFieldKeepsThem)
{
    w->activateWindow();
    for (const QString& name : w->screenNames()) {
        if (name == QLatin1String("joystick"))
            continue;  // its arrow keys are its stick's (patterns_joystick tests)
        ASSERT_TRUE(w->showScreen(name));
        pump(30);
        // The screen about one instrument jogs that one; the others the Jog tab's (the analyzer).
        dev::Instrument* c = name == QLatin1String("scan") ? stage() : w->analyzer()->instrument();
        QWidget* screen = screenWidget(w.get(), name);
        screen->setFocus();
        QWidget* target = QApplication::focusWidget() ? QApplication::focusWidget() : screen;
        const double before = c->status().axes[1].commanded;
        QTest::keyPress(target, Qt::Key_Up);
        const bool moved = waitFor([&] { return c->status().axes[1].commanded > before + 0.2; }, 3000);
        QTest::keyRelease(target, Qt::Key_Up);
        EXPECT_TRUE(moved) << name.toStdString() << ": Up did not jog Y";
        EXPECT_TRUE(waitFor([&] { return !c->status().axes[1].moving; }, 3000)) << name.toStdString();
    }
    // A field being typed in keeps its arrow keys: the cursor moves, the machine does not.
    ASSERT_TRUE(w->showScreen(QStringLiteral("jog")));
    ASSERT_TRUE(w->showScreen(QStringLiteral("plates")));
    QLineEdit* field = nullptr;
    for (auto* e : screenWidget(w.get(), QStringLiteral("plates"))->findChildren<QLineEdit*>())
        if (e->isVisible() && e->isEnabled() && !e->isReadOnly()) {
            field = e;
            break;
        }
    ASSERT_NE(field, nullptr);
    field->setFocus();
    dev::Instrument* analyzer = w->analyzer()->instrument();
    const double before = analyzer->status().axes[0].commanded;
    QTest::keyPress(field, Qt::Key_Left);
    pump(300);
    QTest::keyRelease(field, Qt::Key_Left);
    EXPECT_DOUBLE_EQ(analyzer->status().axes[0].commanded, before) << "Left in a text field jogged X";

    // So does a list or table: Down there means the next row, never a move of the machine.
    QAbstractItemView* list = nullptr;
    for (const QString& name : w->screenNames()) {
        ASSERT_TRUE(w->showScreen(name));
        pump(30);
        for (auto* v : screenWidget(w.get(), name)->findChildren<QAbstractItemView*>())
            if (v->isVisible() && v->isEnabled() && v->focusPolicy() != Qt::NoFocus) {
                list = v;
                break;
            }
        if (list)
            break;
    }
    ASSERT_NE(list, nullptr) << "no screen has a list to try";
    list->setFocus();
    ASSERT_TRUE(list->hasFocus());
    const double y = analyzer->status().axes[1].commanded;
    const double sy = stage()->status().axes[1].commanded;
    QTest::keyPress(list, Qt::Key_Down);
    pump(300);
    QTest::keyRelease(list, Qt::Key_Down);
    EXPECT_DOUBLE_EQ(analyzer->status().axes[1].commanded, y) << "Down in a list jogged the analyzer's Y";
    EXPECT_DOUBLE_EQ(stage()->status().axes[1].commanded, sy) << "Down in a list jogged the stage's Y";
}

TEST_F(MotionScreensTest, TheKeyHintNamesOnlyTheInstrumentsAxes)
{
    auto hint = [&](int i) {
        auto* l = w->jogScreen(i)->findChild<QLabel*>(QStringLiteral("jogKeys"));
        return l ? l->text() : QString();
    };
    EXPECT_TRUE(hint(0).contains(QStringLiteral("PgUp/PgDn Z"))) << hint(0).toStdString();
    EXPECT_TRUE(hint(1).contains(QStringLiteral("←/→ X"))) << hint(1).toStdString();
    EXPECT_FALSE(hint(1).contains(QStringLiteral("PgUp"))) << "the stage has no Z: " << hint(1).toStdString();
    ASSERT_TRUE(w->showScreen(QStringLiteral("joystick")));
    w->showInstrument(1);
    pump(30);
    for (auto* l : joystick(1)->findChildren<QLabel*>())
        EXPECT_FALSE(l->isVisible() && l->text().contains(QStringLiteral("PgUp"))) << l->text().toStdString();
}

TEST_F(MotionScreensTest, ADisconnectedStageShowsItsLampsAsUnknownNotAsTheyWere)
{
    ASSERT_TRUE(homeStage());
    ui::JogScreen* jog = w->jogScreen(1);
    ASSERT_TRUE(waitFor([&] {
        int green = 0;
        for (auto* l : lampsOf(jog))
            green += l->tone() == ui::StatusLamp::Tone::Ok;
        return green == 2;
    }, 3000)) << "both Homed lamps green while connected";
    w->stage()->disconnectLink();
    ASSERT_TRUE(waitFor([&] { return stage()->state() == dev::LinkState::Disconnected; }, 3000));
    pump(50);
    for (auto* l : lampsOf(jog)) {
        EXPECT_EQ(l->tone(), ui::StatusLamp::Tone::Unknown) << l->toolTip().toStdString();
        EXPECT_TRUE(l->toolTip().contains(QStringLiteral("not connected"))) << l->toolTip().toStdString();
    }
    for (auto* r : jog->findChildren<ui::AxisRow*>())
        EXPECT_TRUE(r->stale());
    // Live again once the link is: the lamps say what the machine says.
    w->stage()->connectTo(ui::ConnectionChoice{});
    ASSERT_TRUE(waitFor([&] { return stage()->isReady(); }, 5000));
    ASSERT_TRUE(waitFor([&] {
        for (auto* l : lampsOf(jog))
            if (l->tone() == ui::StatusLamp::Tone::Unknown)
                return false;
        return true;
    }, 3000));
}
