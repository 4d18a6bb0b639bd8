// Input traps. The wheel over a recipe panel turned a pump speed
// it was only passing over; after switching to Jog the focus sat in a Step box and
// ↑ changed the step instead of jogging Y.
#include "gui_window.h"

#include "widgets/jog_screen.h"
#include "widgets/tuning/tuning_screen.h"
#include "widgets/plates/plates_screen.h"

#include <QAbstractSpinBox>
#include <QApplication>
#include <QComboBox>
#include <QSlider>
#include <QSpinBox>
#include <QDoubleSpinBox>
#include <QTest>
#include <QWheelEvent>

#include <gtest/gtest.h>

using guitest::waitFor;

namespace {
void wheel(QWidget* target, int steps)
{
    const QPointF at(target->width() / 2.0, target->height() / 2.0);
    QWheelEvent e(at, target->mapToGlobal(at), QPoint(), QPoint(0, 120 * steps), Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase,
                  false);
    QApplication::sendEvent(target, &e);
}

QString valueOf(QAbstractSpinBox* s) { return s->text(); }

template <class T> T* firstShown(QWidget* root)
{
    for (T* t : root->findChildren<T*>())
        if (t->isVisible() && t->isEnabled())
            return t;
    return nullptr;
}
} // namespace

TEST(TrustInput, TheWheelTurnsOnlyAFocusedSpinBoxOrCombo)
{
    app::MainWindow w(guitest::testWindowOptions());
    w.resize(1366, 708);
    w.show();
    ASSERT_TRUE(QTest::qWaitForWindowActive(&w));
    // Typed numbers are entry fields now (they keep what was typed), so no screen has a spin
    // box of its own; the rule is the application's, for any spin box a screen gains. One
    // in the Tuning screen, as a panel would hold it.
    ASSERT_TRUE(w.showScreen(QStringLiteral("tuning")));
    auto* spin = new QDoubleSpinBox(w.tuningScreen());
    spin->setRange(0, 100);
    spin->setValue(50);  // somewhere in the middle of its range, so a turn would show
    spin->move(10, 10);
    spin->show();
    guitest::pump(50);
    w.setFocus();
    const QString before = valueOf(spin);
    wheel(spin, 3);
    EXPECT_EQ(valueOf(spin), before) << "the wheel turned an unfocused spin box";
    EXPECT_FALSE(spin->hasFocus()) << "the wheel gave the spin box the focus";

    // Focused, it turns: the operator meant it.
    spin->setFocus();
    ASSERT_TRUE(waitFor([&] { return spin->hasFocus(); }, 1000));
    wheel(spin, 3);
    EXPECT_NE(valueOf(spin), before);

    ASSERT_TRUE(w.showScreen(QStringLiteral("plates")));
    guitest::pump(50);
    auto* combo = firstShown<QComboBox>(w.platesScreen());
    ASSERT_NE(combo, nullptr);
    w.setFocus();
    if (combo->count() < 2)
        GTEST_SKIP() << "no combo with a choice on the Plates screen";
    combo->setCurrentIndex(0);
    wheel(combo, -1);
    EXPECT_EQ(combo->currentIndex(), 0) << "the wheel changed an unfocused combo";
}

TEST(TrustInput, JogKeysJogWheneverTheJogScreenShowsUnlessAFieldIsBeingEdited)
{
    auto w = guitest::openReadyWindow(QSize(1366, 708));
    ASSERT_TRUE(w);
    ASSERT_TRUE(QTest::qWaitForWindowActive(w.get()));
    dev::Instrument* analyzer = w->analyzer()->instrument();
    ASSERT_TRUE(w->showScreen(QStringLiteral("jog")));
    ui::JogScreen* jog = w->jogScreen(0);
    QComboBox* step = nullptr;
    for (auto* c : jog->findChildren<QComboBox*>())
        if (c->isEditable() && c->isVisible())
            step = c;
    ASSERT_NE(step, nullptr);

    // The focus left in a Step box, another screen, back to Jog: the keys jog.
    step->setFocus();
    ASSERT_TRUE(waitFor([&] { return jog->typing(); }, 1000));
    EXPECT_TRUE(jog->keysModeText().contains(QStringLiteral("Typing"))) << jog->keysModeText().toStdString();
    ASSERT_TRUE(w->showScreen(QStringLiteral("plots")));
    guitest::pump(20);
    ASSERT_TRUE(w->showScreen(QStringLiteral("jog")));
    guitest::pump(20);
    EXPECT_FALSE(jog->typing());
    EXPECT_EQ(jog->keysModeText(), QStringLiteral("Keys jog the axes"));
    const QString stepBefore = step->currentText();
    QTest::keyPress(QApplication::focusWidget(), Qt::Key_Up);
    EXPECT_TRUE(analyzer->isJogging(1)) << "↑ after coming back to Jog did not jog Y";
    QTest::keyRelease(QApplication::focusWidget(), Qt::Key_Up);
    EXPECT_FALSE(analyzer->isJogging(1));
    EXPECT_EQ(step->currentText(), stepBefore);

    // A control that takes arrow keys itself (the speed slider) does not keep them from jogging.
    auto* slider = firstShown<QSlider>(jog);
    ASSERT_NE(slider, nullptr);
    slider->setFocus();
    ASSERT_TRUE(waitFor([&] { return slider->hasFocus(); }, 1000));
    const int speed = slider->value();
    QTest::keyPress(slider, Qt::Key_Right);
    EXPECT_TRUE(analyzer->isJogging(0)) << "→ on the speed slider did not jog X";
    QTest::keyRelease(slider, Qt::Key_Right);
    EXPECT_FALSE(analyzer->isJogging(0));
    EXPECT_EQ(slider->value(), speed);

    // Typing in a field: the keys are the field's, and the screen says so.
    step->setFocus();
    ASSERT_TRUE(waitFor([&] { return jog->typing(); }, 1000));
    QTest::keyPress(step, Qt::Key_Up);
    EXPECT_FALSE(analyzer->isJogging(1));
    QTest::keyRelease(step, Qt::Key_Up);
    // Enter hands the keys back.
    QTest::keyClick(step, Qt::Key_Return);
    EXPECT_FALSE(jog->typing());
}
