// A message that comes or goes must not move the controls under
// the pointer (three clicks landed on the wrong control when banners pushed the
// screens down ~37 px and pulled them back when they faded).
#include "gui_wait.h"
#include "gui_window.h"

#include "app/gui/instrument_session.h"
#include "device/link/simulated_link.h"

#include "widgets/common/elided_label.h"
#include "widgets/connection_bar.h"
#include "widgets/jog_screen.h"
#include "widgets/message_banner.h"

#include <QApplication>
#include <QLayout>
#include <QPushButton>

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

// At 1366 px the connections' identities had some 40 px ("read…") while an empty message
// box kept half the row: with nothing to say the box gives its width away; a message takes
// it back from the identities, and no button moves either way.
TEST(TrustBanner, AnEmptyMessageBoxLeavesItsRoomToTheConnectionsIdentities)
{
    app::MainWindow w(guitest::testWindowOptions());
    w.resize(1366, 708);
    w.show();
    settle(&w);
    const auto bars = w.findChildren<ui::ConnectionBar*>();
    ASSERT_EQ(bars.size(), 2);
    auto identity = [](ui::ConnectionBar* bar) { return bar->findChild<ui::ElidedLabel*>(); };
    auto buttons = [&] {
        std::vector<QRect> out;
        for (ui::ConnectionBar* bar : bars)
            for (QPushButton* b : bar->findChildren<QPushButton*>())
                out.push_back(inWindow(b, &w));
        return out;
    };
    ASSERT_TRUE(identity(bars[0]));
    const auto before = buttons();
    EXPECT_FALSE(w.banner()->hasMessage());
    // "ready — BenchPilot analyzer manipulator (simulated)" and more: the state and the model whole.
    EXPECT_GT(identity(bars[0])->width(), 450) << identity(bars[0])->fullText().toStdString();

    w.banner()->show(ui::MessageBanner::Level::Error, QStringLiteral("Stage: link lost. Reconnect when the cable is back."));
    settle(&w);
    EXPECT_GT(w.banner()->width(), 300) << "a message needs its room back";
    EXPECT_EQ(buttons(), before) << "a message moved a connection's button";
    w.banner()->dismiss();
    settle(&w);
    EXPECT_EQ(buttons(), before) << "a dismissed message moved a connection's button";
    EXPECT_GT(identity(bars[0])->width(), 450);
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

TEST(TrustBanner, AMessageAboutAStateIsWithdrawnWhenTheStateEndsShownOrWaiting)
{
    ui::MessageBanner b;
    b.resize(800, b.sizeHint().height());
    b.QWidget::show();
    b.show(ui::MessageBanner::Level::Error, QStringLiteral("E-STOP: all motion halted."), QStringLiteral("estop"));
    b.show(ui::MessageBanner::Level::Error, QStringLiteral("Stage: link lost."));
    b.show(ui::MessageBanner::Level::Error, QStringLiteral("Analyzer: move refused: the E-stop is latched."), QStringLiteral("estop"));
    ASSERT_EQ(b.texts().size(), 3);
    b.withdraw(QStringLiteral("estop"));
    EXPECT_EQ(b.texts(), QStringList{QStringLiteral("Stage: link lost.")}) << "the unrelated error stays to be read";
    b.withdraw(QStringLiteral("estop"));
    EXPECT_EQ(b.text(), QStringLiteral("Stage: link lost."));
}

// Seen under Xvfb: a scan's cable pulled, put back, Connect pressed; the stage ran on while
// the banner still said "Stage: link lost … reconnect when the cable is back", three more
// errors of the same loss waiting behind it. Once the link is ready again they are gone;
// the analyzer's own error stays to be read.
TEST(TrustBanner, ALostLinksMessagesAreWithdrawnOnceItIsReadyAgain)
{
    auto w = guitest::openReadyWindow({1366, 708});
    auto* link = qobject_cast<dev::SimulatedLink*>(w->stage()->link());
    ASSERT_NE(link, nullptr);
    dev::Instrument* stage = w->stage()->instrument();
    ui::MessageBanner* b = w->banner();
    b->show(ui::MessageBanner::Level::Error, QStringLiteral("Analyzer: move refused."));
    link->pair().unplug();
    ASSERT_TRUE(guitest::waitFor([&] { return stage->state() == dev::LinkState::Lost; }, 3000));
    guitest::pump(50);
    const QString lost = b->texts().join(QLatin1Char('\n'));
    ASSERT_TRUE(lost.contains(QStringLiteral("Stage: link lost"))) << lost.toStdString();

    link->pair().replug();
    stage->connectLink();
    ASSERT_TRUE(guitest::waitFor([&] { return stage->isReady(); }, 5000));
    guitest::pump(50);
    const QString after = b->texts().join(QLatin1Char('\n'));
    EXPECT_FALSE(after.contains(QStringLiteral("Stage:"))) << after.toStdString();
    EXPECT_TRUE(after.contains(QStringLiteral("Analyzer: move refused."))) << "an unrelated error stays to be read";
}
