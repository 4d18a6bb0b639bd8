// Issue 16, item 3: a message that comes or goes must not move the controls under
// the pointer (three clicks landed on the wrong control when banners pushed the
// screens down ~37 px and pulled them back when they faded).
#include "gui_window.h"

#include "widgets/jog_screen.h"
#include "widgets/message_banner.h"

#include <QApplication>
#include <QLayout>

#include <gtest/gtest.h>

namespace {
QRect inWindow(QWidget* w, QWidget* window) { return QRect(w->mapTo(window, QPoint(0, 0)), w->size()); }

void settle(QWidget* window)
{
    window->layout()->activate();
    guitest::pump(50);
}
} // namespace

TEST(TrustBanner, ControlsStayPutWhileMessagesComeAndGo)
{
    app::MainWindow w(guitest::testWindowOptions());
    w.resize(1366, 708);
    w.show();
    ASSERT_TRUE(w.showScreen(QStringLiteral("jog")));
    settle(&w);
    QWidget* jog = w.jogScreen(0);
    const QRect before = inWindow(jog, &w);
    ui::MessageBanner* b = w.banner();

    b->show(ui::MessageBanner::Level::Info, QStringLiteral("Homing done."));
    settle(&w);
    EXPECT_EQ(inWindow(jog, &w), before) << "a note moved the Jog screen";

    b->show(ui::MessageBanner::Level::Error,
            QString(QStringLiteral("Analyzer: link lost. Motion on the instrument stops by itself; reconnect when the cable is back. "))
                .repeated(4));
    settle(&w);
    EXPECT_EQ(inWindow(jog, &w), before) << "a long error moved the Jog screen";

    b->dismiss();
    b->dismiss();
    settle(&w);
    EXPECT_FALSE(b->hasMessage());
    EXPECT_EQ(inWindow(jog, &w), before) << "dismissing moved the Jog screen back";
}

TEST(TrustBanner, ErrorsStayUntilReadAndCountTheirRepeats)
{
    ui::MessageBanner b;
    b.resize(800, b.sizeHint().height());
    b.QWidget::show();
    b.show(ui::MessageBanner::Level::Error, QStringLiteral("Stage: link lost."));
    b.show(ui::MessageBanner::Level::Error, QStringLiteral("Stage: link lost."));
    b.show(ui::MessageBanner::Level::Error, QStringLiteral("Stage: link lost."));
    EXPECT_EQ(b.repeats(), 3);
    EXPECT_EQ(b.text(), QStringLiteral("Stage: link lost."));

    // A note that arrives meanwhile waits behind the unread error.
    b.show(ui::MessageBanner::Level::Info, QStringLiteral("E-stop cleared."));
    EXPECT_EQ(b.level(), ui::MessageBanner::Level::Error);
    EXPECT_EQ(b.text(), QStringLiteral("Stage: link lost."));
    EXPECT_EQ(b.waiting(), 1);

    b.dismiss();
    EXPECT_EQ(b.text(), QStringLiteral("E-stop cleared."));
    EXPECT_EQ(b.level(), ui::MessageBanner::Level::Info);
    b.dismiss();
    EXPECT_FALSE(b.hasMessage());
}
