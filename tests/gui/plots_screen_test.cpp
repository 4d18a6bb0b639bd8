// The Plots screen in the main window, streaming from the in-process simulators as a
// person would use it: channels ticked and unticked, plots added and removed, pause
// that freezes the view while the stage keeps moving, export and recording through
// the injected file chooser.
#include "gui_window.h"
#include "app/gui/instrument_session.h"
#include "app/gui/main_window.h"
#include "device/telemetry/telemetry_hub.h"
#include "gui_wait.h"
#include "widgets/channel_picker.h"
#include "widgets/plot_panel.h"
#include "widgets/plot_stack.h"
#include "widgets/plots_screen.h"
#include "widgets/xy_view.h"

#include <QApplication>
#include <QFile>
#include <QImage>
#include <QPushButton>
#include <QTemporaryDir>
#include <QWheelEvent>

#include <gtest/gtest.h>

using guitest::pump;
using guitest::waitFor;

using guitest::button;

namespace {

using dev::proto::ChannelKind;

dev::tele::ChannelKey key(int instrument, int axis, ChannelKind kind)
{
    return dev::tele::ChannelKey{instrument, dev::proto::ChannelRef{static_cast<std::uint8_t>(axis), kind}};
}

struct GraphSnapshot {
    QVector<double> keys, values;
    bool operator==(const GraphSnapshot& o) const { return keys == o.keys && values == o.values; }
};

GraphSnapshot snapshot(const QCPGraph* g)
{
    GraphSnapshot s;
    for (auto it = g->data()->constBegin(); it != g->data()->constEnd(); ++it) {
        s.keys << it->key;
        s.values << it->value;
    }
    return s;
}

/// Entries in a legend (the legend is a grid: itemCount() counts its empty cells too).
int legendEntries(const QCPLegend* legend)
{
    int n = 0;
    for (int i = 0; i < legend->itemCount(); ++i)
        n += legend->item(i) != nullptr;
    return n;
}

class PlotsScreenTest : public ::testing::Test {
protected:
    void SetUp() override
    {
        app::MainWindowOptions o;
        o.persistSettings = false;
        o.confirmDialogs = false;
        w = std::make_unique<app::MainWindow>(o);
        w->resize(1500, 950);
        ASSERT_TRUE(w->showScreen(QStringLiteral("plots")));
        w->show();
        ASSERT_TRUE(waitFor([&] { return w->analyzer()->instrument()->isReady() && w->stage()->instrument()->isReady(); }, 5000));
        screen = w->plotsScreen();
        ASSERT_NE(screen, nullptr);
        hub = w->telemetry();
        // The default plots fill in once the stage says what it has.
        ASSERT_TRUE(waitFor([&] { return screen->stack()->panel(0)->hasChannel(stageXMeasured); }, 3000));
    }
    dev::Instrument* stage() { return w->stage()->instrument(); }
    /// Waits until the stage's X has measured samples drawn in plot 1.
    bool streaming(int points = 10)
    {
        return waitFor([&] {
            const QCPGraph* g = screen->stack()->panel(0)->graph(stageXMeasured);
            return g && g->dataCount() > points;
        }, 5000);
    }

    std::unique_ptr<app::MainWindow> w;
    ui::PlotsScreen* screen = nullptr;
    dev::tele::TelemetryHub* hub = nullptr;
    dev::tele::ChannelKey stageXMeasured = key(1, 0, ChannelKind::Measured);
};

TEST_F(PlotsScreenTest, StartsWithTheStagesPositionsAndFollowingErrorsAndStreams)
{
    EXPECT_EQ(w->screenNames().indexOf(QStringLiteral("plots")), w->screenNames().indexOf(QStringLiteral("jog")) + 1);
    ui::PlotStack* stack = screen->stack();
    ASSERT_EQ(screen->plotCount(), 3);
    EXPECT_TRUE(stack->panel(0)->hasChannel(key(1, 0, ChannelKind::Commanded)));
    EXPECT_TRUE(stack->panel(0)->hasChannel(key(1, 1, ChannelKind::Measured)));
    EXPECT_TRUE(stack->panel(1)->hasChannel(key(1, 0, ChannelKind::FollowingError)));
    ASSERT_TRUE(waitFor([&] { return stack->panel(2)->hasChannel(key(0, 2, ChannelKind::Measured)); }, 3000));
    EXPECT_EQ(stack->panel(0)->leftAxis()->label(), QStringLiteral("mm"));
    EXPECT_EQ(stack->panel(1)->leftAxis()->label(), QStringLiteral("µm"));
    EXPECT_TRUE(screen->picker()->isChecked(stageXMeasured)) << "the picker shows plot 1's channels";

    stage()->startJog(0, 5.0);
    ASSERT_TRUE(streaming());
    pump(400);
    stage()->stopJog(0);
    const QCPGraph* g = stack->panel(0)->graph(stageXMeasured);
    EXPECT_LE(g->dataCount(), 2 * stack->columns() + 2);
    EXPECT_GT(screen->framesDrawn(), 0);
    EXPECT_TRUE(screen->statusText().contains(QStringLiteral("Stage"))) << screen->statusText().toStdString();
    EXPECT_TRUE(screen->statusText().contains(QStringLiteral("0 lost"))) << screen->statusText().toStdString();
    // The XY view draws the stage's path.
    EXPECT_GT(screen->xyView()->measuredPoints(), 0);
    EXPECT_GT(screen->xyView()->commandedPoints(), 0);
}

TEST_F(PlotsScreenTest, TickingAndUntickingChannelsAddsAndRemovesThemAndTheirSubscription)
{
    ui::ChannelPicker* picker = screen->picker();
    const dev::tele::ChannelKey velocity = key(1, 0, ChannelKind::Velocity);
    const dev::tele::ChannelKey analyzerX = key(0, 0, ChannelKind::Measured);
    ASSERT_TRUE(waitFor([&] { return picker->channelCount(0) > 0 && picker->channelCount(1) > 0; }, 3000));
    ASSERT_EQ(picker->currentPlot(), 0);

    // One plot, channels of both instruments.
    ASSERT_TRUE(picker->setChecked(velocity, true));
    ASSERT_TRUE(picker->setChecked(analyzerX, true));
    ui::PlotPanel* p = screen->stack()->panel(0);
    EXPECT_TRUE(p->hasChannel(velocity));
    EXPECT_TRUE(p->hasChannel(analyzerX));
    EXPECT_TRUE(p->rightAxis()->visible()) << "mm/s goes on the right-hand axis";
    EXPECT_EQ(p->rightAxis()->label(), QStringLiteral("mm/s"));
    EXPECT_EQ(legendEntries(p->legend()), 6);
    ASSERT_TRUE(waitFor([&] { return hub->store(velocity) && hub->store(analyzerX); }, 3000)) << "the hub collects them";
    ASSERT_TRUE(waitFor([&] { return p->graph(velocity)->dataCount() > 0; }, 3000));

    ASSERT_TRUE(picker->setChecked(velocity, false));
    EXPECT_FALSE(p->hasChannel(velocity));
    EXPECT_EQ(p->graph(velocity), nullptr);
    EXPECT_FALSE(p->rightAxis()->visible());
    EXPECT_EQ(legendEntries(p->legend()), 5);
    EXPECT_TRUE(waitFor([&] { return hub->store(velocity) == nullptr; }, 3000)) << "nobody wants it: no longer collected";

    // Another plot: the picker follows the chosen plot.
    const int added = screen->addPlot();
    EXPECT_EQ(added, 3);
    EXPECT_EQ(picker->plotCount(), 4);
    EXPECT_EQ(picker->currentPlot(), 3);
    EXPECT_FALSE(picker->isChecked(stageXMeasured));
    ASSERT_TRUE(picker->setChecked(velocity, true));
    EXPECT_TRUE(screen->stack()->panel(3)->hasChannel(velocity));
    EXPECT_FALSE(screen->stack()->panel(0)->hasChannel(velocity));
    ASSERT_TRUE(screen->removePlot(3));
    EXPECT_EQ(screen->plotCount(), 3);
    EXPECT_EQ(picker->plotCount(), 3);
    EXPECT_TRUE(waitFor([&] { return hub->store(velocity) == nullptr; }, 3000)) << "its plot is gone";
}

TEST_F(PlotsScreenTest, PauseFreezesTheViewWhileDataKeepsArriving)
{
    stage()->startJog(0, 5.0);
    ASSERT_TRUE(streaming());
    pump(300);
    screen->setPaused(true);
    ASSERT_TRUE(hub->paused());
    pump(50);  // a frame already scheduled may still land; it draws the frozen view
    ui::PlotStack* stack = screen->stack();
    const QCPRange range = stack->timeRange();
    const double anchor = stack->anchorS(1);
    const GraphSnapshot frozen = snapshot(stack->panel(0)->graph(stageXMeasured));
    const quint64 received = hub->samplesReceived(1);
    const double latest = hub->latestTimeS(1);

    pump(700);
    EXPECT_GT(hub->samplesReceived(1), received) << "the stage keeps streaming";
    EXPECT_GT(hub->latestTimeS(1), latest + 0.4);
    EXPECT_EQ(stack->timeRange().lower, range.lower);
    EXPECT_EQ(stack->timeRange().upper, range.upper);
    EXPECT_EQ(stack->anchorS(1), anchor);
    EXPECT_TRUE(snapshot(stack->panel(0)->graph(stageXMeasured)) == frozen) << "the plotted data did not move";
    EXPECT_TRUE(screen->statusText().contains(QStringLiteral("paused")));

    screen->setPaused(false);
    EXPECT_FALSE(hub->paused());
    EXPECT_TRUE(waitFor([&] { return stack->anchorS(1) > anchor + 0.4; }, 2000)) << "live again";
    stage()->stopJog(0);
}

TEST_F(PlotsScreenTest, ZoomingTheTimeAxisWithTheWheelPausesTheView)
{
    ASSERT_TRUE(streaming());
    ui::PlotStack* stack = screen->stack();
    const QCPRange before = stack->timeRange();
    const QPoint at = stack->panel(0)->rect()->center();
    QWheelEvent e(QPointF(at), QPointF(stack->mapToGlobal(at)), QPoint(), QPoint(0, 120), Qt::NoButton, Qt::NoModifier,
                  Qt::NoScrollPhase, false);
    QApplication::sendEvent(stack, &e);
    EXPECT_LT(stack->timeRange().size(), before.size()) << "zoomed in";
    EXPECT_TRUE(screen->isPaused()) << "a view the user moved stays where they put it";
    EXPECT_EQ(stack->panel(1)->timeAxis()->range().lower, stack->timeRange().lower) << "one time axis for all plots";

    // Ctrl+wheel zooms the values of that plot, and auto-scale lets go of them.
    ASSERT_TRUE(stack->autoScaleValues());
    const QCPRange values = stack->panel(0)->leftAxis()->range();
    QWheelEvent ctrl(QPointF(at), QPointF(stack->mapToGlobal(at)), QPoint(), QPoint(0, 120), Qt::NoButton,
                     Qt::ControlModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(stack, &ctrl);
    EXPECT_LT(stack->panel(0)->leftAxis()->range().size(), values.size());
    EXPECT_FALSE(stack->autoScaleValues());
    EXPECT_EQ(stack->timeRange().size(), stack->panel(1)->timeAxis()->range().size()) << "time untouched by Ctrl+wheel";
}

TEST_F(PlotsScreenTest, HiddenPlotsLetGoOfTheLinkUnlessPaused)
{
    const dev::tele::ChannelKey following = key(1, 0, ChannelKind::FollowingError);  // only the plots want it
    ASSERT_TRUE(waitFor([&] { return hub->store(following) != nullptr; }, 3000));
    w->showScreen(QStringLiteral("profiles"));
    EXPECT_TRUE(waitFor([&] { return hub->store(following) == nullptr; }, 3000)) << "nobody looks: not collected";
    w->showScreen(QStringLiteral("plots"));
    ASSERT_TRUE(waitFor([&] { return hub->store(following) != nullptr; }, 3000)) << "shown again: collected again";

    ASSERT_TRUE(streaming());
    screen->setPaused(true);
    w->showScreen(QStringLiteral("profiles"));
    pump(300);
    EXPECT_NE(hub->store(following), nullptr) << "a paused view keeps its data while another screen is up";
    screen->setPaused(false);
    EXPECT_TRUE(waitFor([&] { return hub->store(following) == nullptr; }, 3000));
}

TEST_F(PlotsScreenTest, WindowChoiceSetsTheTimeRangeAndTheHubsWindow)
{
    screen->setWindowS(60);
    EXPECT_DOUBLE_EQ(hub->windowS(), 60);
    ASSERT_TRUE(streaming());
    pump(100);
    EXPECT_DOUBLE_EQ(screen->stack()->timeRange().lower, -60);
    EXPECT_DOUBLE_EQ(screen->stack()->timeRange().upper, 0);
    screen->setWindowS(0.1);
    EXPECT_DOUBLE_EQ(hub->windowS(), 1) << "at least one second";
}

TEST_F(PlotsScreenTest, ExportAndRecordThroughTheInjectedFileChooser)
{
    QTemporaryDir dir;
    QStringList asked;
    QString next;
    screen->setFileChooser([&](const QString& title, const QString&) {
        asked << title;
        return next;
    });
    ASSERT_TRUE(streaming(30)) << "enough in view for the export's rows, however slow the machine";
    screen->setPaused(true);

    next = dir.filePath(QStringLiteral("view.csv"));
    button(screen, QStringLiteral("CSV…"))->click();
    ASSERT_EQ(asked.size(), 1);
    QFile csv(next);
    ASSERT_TRUE(csv.open(QIODevice::ReadOnly));
    const QByteArray text = csv.readAll();
    EXPECT_TRUE(text.contains("raw samples"));
    EXPECT_TRUE(text.contains("time_s,instrument,Stage X commanded [mm],Stage X measured [mm]"));
    EXPECT_GT(text.count('\n'), 20);
    EXPECT_TRUE(screen->lastMessage().contains(QStringLiteral("raw"))) << screen->lastMessage().toStdString();

    next = dir.filePath(QStringLiteral("view.png"));
    button(screen, QStringLiteral("PNG…"))->click();
    EXPECT_FALSE(QImage(next).isNull());
    next = dir.filePath(QStringLiteral("view.pdf"));
    button(screen, QStringLiteral("PDF…"))->click();
    EXPECT_TRUE(QFile::exists(next));

    next.clear();  // cancelled: nothing written, no complaint
    button(screen, QStringLiteral("CSV…"))->click();
    EXPECT_TRUE(screen->lastMessage().contains(QStringLiteral("PDF")) || screen->lastMessage().contains(QStringLiteral(".pdf")));

    // Recording goes on while the view is paused.
    next = dir.filePath(QStringLiteral("rec.csv"));
    QPushButton* record = screen->findChild<QPushButton*>(QStringLiteral("recordButton"));
    ASSERT_NE(record, nullptr);
    record->click();
    ASSERT_TRUE(hub->recording());
    EXPECT_TRUE(record->isChecked());
    ASSERT_TRUE(waitFor([&] { return hub->recordedRows() > 20; }, 3000));
    record->click();
    EXPECT_FALSE(hub->recording());
    EXPECT_FALSE(record->isChecked());
    QFile rec(next);
    ASSERT_TRUE(rec.open(QIODevice::ReadOnly));
    EXPECT_TRUE(rec.readLine().startsWith("time_s,instrument,"));
    EXPECT_TRUE(screen->lastMessage().contains(QStringLiteral("Recorded")));
}

} // namespace
