// The Jog screen's live strip: position and following error of the axis last jogged,
// streaming from the simulated stage, and no subscription of its own while hidden.
#include "app/gui/instrument_session.h"
#include "app/gui/main_window.h"
#include "device/telemetry/telemetry_hub.h"
#include "gui_wait.h"
#include "widgets/jog_screen.h"
#include "widgets/live_strip.h"
#include "widgets/plot_panel.h"
#include "widgets/plot_stack.h"

#include <QTest>
#include <QToolButton>

#include <gtest/gtest.h>

using guitest::pump;
using guitest::waitFor;

namespace {

using dev::proto::ChannelKind;

dev::tele::ChannelKey key(int instrument, int axis, ChannelKind kind)
{
    return dev::tele::ChannelKey{instrument, dev::proto::ChannelRef{static_cast<std::uint8_t>(axis), kind}};
}

TEST(PlotsLiveStrip, ShowsTheAxisLastJoggedWhileTheJogScreenIsShown)
{
    app::MainWindowOptions o;
    o.persistSettings = false;
    o.confirmDialogs = false;
    app::MainWindow w(o);
    w.resize(1500, 950);
    w.showScreen(QStringLiteral("jog"));
    w.showInstrument(1);
    w.show();
    ASSERT_TRUE(waitFor([&] { return w.analyzer()->instrument()->isReady() && w.stage()->instrument()->isReady(); }, 5000));
    ui::LiveStrip* strip = w.jogScreen(1)->findChild<ui::LiveStrip*>();
    ASSERT_NE(strip, nullptr);
    ASSERT_TRUE(strip->isVisible());
    EXPECT_EQ(strip->axis(), 0);
    const auto yFollowing = key(1, 1, ChannelKind::FollowingError);
    const auto yMeasured = key(1, 1, ChannelKind::Measured);

    // Hold Y+ (the second "▶▶" of the stage's two rows): the strip switches to Y.
    QList<QToolButton*> holdPlus;
    for (auto* b : w.jogScreen(1)->findChildren<QToolButton*>())
        if (b->text() == QStringLiteral("▶▶"))
            holdPlus << b;
    ASSERT_EQ(holdPlus.size(), 2);
    QTest::mousePress(holdPlus[1], Qt::LeftButton);
    EXPECT_EQ(strip->axis(), 1);
    ui::PlotStack* plot = strip->stack();
    EXPECT_TRUE(plot->panel(0)->hasChannel(yMeasured));
    EXPECT_TRUE(plot->panel(1)->hasChannel(yFollowing));
    ASSERT_TRUE(waitFor([&] { return plot->panel(0)->graph(yMeasured)->dataCount() > 10; }, 4000));
    QTest::mouseRelease(holdPlus[1], Qt::LeftButton);
    EXPECT_GT(strip->framesDrawn(), 0);
    EXPECT_LE(plot->panel(0)->graph(yMeasured)->dataCount(), 2 * plot->columns() + 2);
    EXPECT_DOUBLE_EQ(plot->timeRange().lower, -ui::LiveStrip::kWindowS);

    // A strip that is not shown asks the hub for nothing. The analyzer's tab is
    // hidden, and no one else wants the analyzer's X following error.
    EXPECT_FALSE(w.jogScreen(0)->findChild<ui::LiveStrip*>()->isVisible());
    EXPECT_EQ(w.telemetry()->store(key(0, 0, ChannelKind::FollowingError)), nullptr)
        << "a hidden strip subscribes nothing";
    w.showInstrument(0);
    EXPECT_TRUE(waitFor([&] { return w.telemetry()->store(key(0, 0, ChannelKind::FollowingError)) != nullptr; }, 3000))
        << "shown, it subscribes its axis";
    w.showScreen(QStringLiteral("profiles"));
    EXPECT_TRUE(waitFor([&] { return w.telemetry()->store(key(0, 0, ChannelKind::FollowingError)) == nullptr; }, 3000))
        << "hidden again, it lets go";
}

} // namespace
