// A button's key survives its rewording (QAbstractButton::setText() replaces a button's
// own shortcut with the text's mnemonic), and works only while the button can be pressed.
#include "gui_wait.h"
#include "widgets/common/button_key.h"

#include <QApplication>
#include <QPushButton>
#include <QTest>
#include <QVBoxLayout>
#include <QWidget>

#include <gtest/gtest.h>

TEST(ButtonKey, ClicksThroughEveryRewordingOnlyWhileTheButtonCanBePressed)
{
    QWidget window;
    auto* layout = new QVBoxLayout(&window);
    auto* button = new QPushButton(QStringLiteral("Pause"));
    layout->addWidget(button);
    ui::setButtonKey(button, QKeySequence(Qt::Key_F6));
    int clicks = 0;
    QObject::connect(button, &QPushButton::clicked, [&] { ++clicks; });
    window.show();
    window.activateWindow();
    ASSERT_TRUE(QTest::qWaitForWindowActive(&window));

    QTest::keyClick(&window, Qt::Key_F6);
    EXPECT_EQ(clicks, 1);
    button->setText(QStringLiteral("Resume"));
    button->setText(QStringLiteral("&Weiter"));  // a mnemonic of its own, too
    QTest::keyClick(&window, Qt::Key_F6);
    EXPECT_EQ(clicks, 2) << "the rewording took the key away";
    EXPECT_EQ(ui::buttonKey(button), QKeySequence(Qt::Key_F6));

    button->setEnabled(false);
    QTest::keyClick(&window, Qt::Key_F6);
    EXPECT_EQ(clicks, 2) << "a disabled button was pressed by its key";
    button->setEnabled(true);
    button->hide();
    QTest::keyClick(&window, Qt::Key_F6);
    EXPECT_EQ(clicks, 2) << "a hidden button was pressed by its key";
    button->show();

    // Given again, the key replaces the old one rather than adding a second.
    ui::setButtonKey(button, QKeySequence(Qt::Key_F7));
    QTest::keyClick(&window, Qt::Key_F6);
    QTest::keyClick(&window, Qt::Key_F7);
    EXPECT_EQ(clicks, 3);
}
