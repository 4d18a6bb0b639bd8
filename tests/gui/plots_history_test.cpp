// The Plots screen after an incident (docs/telemetry.md, "History"): what happened while no plot
// showed a channel is drawn when it is shown again, and the history export holds
// every instrument's positions and following errors, plotted or not. The real main
// window on its in-process simulators, offscreen.
#include "app/gui/instrument_session.h"
#include "app/gui/main_window.h"
#include "device/telemetry/telemetry_hub.h"
#include "gui_wait.h"
#include "widgets/plot_panel.h"
#include "widgets/plot_stack.h"
#include "widgets/plots_screen.h"

#include <QFile>
#include <QMenu>
#include <QPushButton>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <algorithm>

using guitest::pump;
using guitest::waitFor;

namespace {

using dev::proto::ChannelKind;

dev::tele::ChannelKey historyKey(int instrument, int axis, ChannelKind kind)
{
    return dev::tele::ChannelKey{instrument, dev::proto::ChannelRef{static_cast<std::uint8_t>(axis), kind}};
}

/// The oldest time (x, s before the anchor) and the spread of values a graph draws.
struct Drawn {
    double oldestX = 0;
    double spread = 0;
    int points = 0;
};

Drawn drawn(const QCPGraph* g)
{
    Drawn d;
    if (!g || g->dataCount() == 0)
        return d;
    double lo = 0, hi = 0;
    bool first = true;
    for (auto it = g->data()->constBegin(); it != g->data()->constEnd(); ++it) {
        if (std::isnan(it->value))
            continue;
        if (first) {
            d.oldestX = it->key;
            lo = hi = it->value;
            first = false;
        }
        d.oldestX = std::min(d.oldestX, it->key);
        lo = std::min(lo, it->value);
        hi = std::max(hi, it->value);
        ++d.points;
    }
    d.spread = hi - lo;
    return d;
}

class PlotsHistoryTest : public ::testing::Test {
protected:
    void SetUp() override
    {
        app::MainWindowOptions o;
        o.persistSettings = false;
        o.confirmDialogs = false;
        w = std::make_unique<app::MainWindow>(o);
        w->resize(1366, 768);
        ASSERT_TRUE(w->showScreen(QStringLiteral("plots")));
        w->show();
        ASSERT_TRUE(waitFor([&] { return w->analyzer()->instrument()->isReady() && w->stage()->instrument()->isReady(); }, 5000));
        screen = w->plotsScreen();
        hub = w->telemetry();
        ASSERT_TRUE(hub->historyEnabled()) << "the application records from connection on";
        ASSERT_TRUE(waitFor([&] { return screen->stack()->panel(1)->hasChannel(stageXError); }, 3000));
    }
    dev::Instrument* stage() { return w->stage()->instrument(); }

    std::unique_ptr<app::MainWindow> w;
    ui::PlotsScreen* screen = nullptr;
    dev::tele::TelemetryHub* hub = nullptr;
    const dev::tele::ChannelKey stageXError = historyKey(1, 0, ChannelKind::FollowingError);
    const dev::tele::ChannelKey stageXMeasured = historyKey(1, 0, ChannelKind::Measured);
};

TEST_F(PlotsHistoryTest, AChannelTickedAfterTheMotionShowsTheSamplesFromBefore)
{
    ASSERT_TRUE(waitFor([&] { return hub->store(stageXError) && hub->store(stageXError)->size() > 20; }, 5000)) << "plotted, streaming";
    ASSERT_TRUE(screen->removeChannel(1, stageXError));  // what unticking it in the picker does
    ASSERT_TRUE(waitFor([&] { return hub->store(stageXError) == nullptr; }, 3000)) << "no plot wants it now";
    const double untickedAtS = hub->latestTimeS(1);

    stage()->jogStep(0, 5.0, 20.0);  // a 5 mm step, as the device tests move the unhomed stage
    pump(1500);
    ASSERT_NE(hub->historyStore(stageXError), nullptr) << "recorded all the same";

    ASSERT_TRUE(screen->addChannel(1, stageXError));
    const QCPGraph* g = nullptr;
    ASSERT_TRUE(waitFor([&] {
        g = screen->stack()->panel(1)->graph(stageXError);
        return g && g->dataCount() > 0;
    }, 3000));
    const Drawn d = drawn(g);
    EXPECT_LT(screen->stack()->anchorS(1) + d.oldestX, untickedAtS - 0.05)
        << "samples from before it was unticked are drawn (a live store made at the tick cannot hold them); " << d.oldestX << " s";
}

TEST_F(PlotsHistoryTest, OpeningThePlotsAfterAnIncidentShowsWhatHappenedWhileAnotherScreenWasUp)
{
    w->showScreen(QStringLiteral("profiles"));
    ASSERT_TRUE(waitFor([&] { return hub->store(stageXMeasured) == nullptr; }, 3000)) << "nobody looks: no live store";
    stage()->jogStep(0, 5.0, 20.0);
    pump(1500);

    w->showScreen(QStringLiteral("plots"));
    const QCPGraph* g = nullptr;
    // Frames are coalesced on a timer: the step shows within a few of them.
    waitFor([&] {
        g = screen->stack()->panel(0)->graph(stageXMeasured);
        return g && drawn(g).spread > 2.0;
    }, 3000);
    ASSERT_NE(g, nullptr);
    const dev::tele::ChannelStore* kept = hub->historyStore(stageXMeasured);
    ASSERT_NE(kept, nullptr);
    EXPECT_GT(kept->at(kept->size() - 1).value - kept->at(0).value, 2.0f) << "recorded while no plot was shown";
    EXPECT_GT(drawn(g).spread, 2.0) << "the 5 mm step is on the plot though no plot was shown while it ran: "
                                    << drawn(g).oldestX << " s back, " << drawn(g).points << " points";
    EXPECT_TRUE(screen->statusText().contains(QStringLiteral("recorded"))) << screen->statusText().toStdString();
}

TEST_F(PlotsHistoryTest, HistoryExportHasEveryAxisColumnWithData)
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("history.csv"));
    screen->setFileChooser([&](const QString&, const QString&) { return path; });
    stage()->jogStep(1, 2.0, 20.0);
    pump(800);
    ASSERT_TRUE(waitFor([&] { return hub->historySpanS(0) > 0.5 && hub->historySpanS(1) > 0.5; }, 5000));

    auto* history = screen->findChild<QPushButton*>(QStringLiteral("historyButton"));
    ASSERT_NE(history, nullptr);
    ASSERT_TRUE(history->isVisible());
    ASSERT_NE(history->menu(), nullptr);
    history->menu()->actions().last()->trigger();  // everything recorded
    QFile f(path);
    ASSERT_TRUE(f.open(QIODevice::ReadOnly)) << screen->lastMessage().toStdString();
    const QList<QByteArray> header = f.readLine().trimmed().split(',');
    // The analyzer's X, Y, Z, P and the stage's X, Y: commanded, measured, following error each.
    ASSERT_EQ(header.size(), 2 + 4 * 3 + 2 * 3) << header.join(',').toStdString();
    EXPECT_TRUE(header.contains(QStringLiteral("Analyzer P following error [nL]").toUtf8()));
    EXPECT_TRUE(header.contains("Stage Y measured [mm]"));
    std::vector<int> filled(std::size_t(header.size()), 0);
    int rows = 0;
    while (!f.atEnd()) {
        const QList<QByteArray> cells = f.readLine().trimmed().split(',');
        ASSERT_EQ(cells.size(), header.size());
        for (int c = 0; c < cells.size(); ++c)
            filled[std::size_t(c)] += !cells[c].isEmpty();
        ++rows;
    }
    EXPECT_GT(rows, 50);
    for (int c = 2; c < header.size(); ++c)
        EXPECT_GT(filled[std::size_t(c)], 20) << "column " << header[c].toStdString() << " has data";
    EXPECT_TRUE(screen->lastMessage().contains(QStringLiteral("history"))) << screen->lastMessage().toStdString();
}

} // namespace
