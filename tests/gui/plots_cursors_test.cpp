// The stacked plots fed from stores with known data (no device): the cursors read
// the stored samples at their times, per instrument clock; a drag moves a cursor and
// not the view; the min/max reduction never loses a spike and hands QCustomPlot at
// most two points per pixel column.
#include "gui_wait.h"
#include "widgets/plot_cursors.h"
#include "widgets/plot_panel.h"
#include "widgets/plot_stack.h"

#include <QApplication>
#include <QMouseEvent>

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

namespace {

using dev::proto::ChannelKind;

dev::tele::ChannelKey key(int instrument, int axis, ChannelKind kind)
{
    return dev::tele::ChannelKey{instrument, dev::proto::ChannelRef{static_cast<std::uint8_t>(axis), kind}};
}

constexpr double kStageT0 = 100.0;     ///< the stage's device clock at its first sample
constexpr double kAnalyzerT0 = 5000.0; ///< the analyzer's clock: unrelated to the stage's
constexpr int kSamples = 10000;        ///< 10 s at 1 kHz
constexpr double kPeriod = 0.001;

float stageValue(int k) { return static_cast<float>(3.0 * k * kPeriod); }  ///< a ramp: 3 mm/s
float analyzerValue(int k) { return static_cast<float>(k % 7); }

class PlotCursorsTest : public ::testing::Test {
protected:
    void SetUp() override
    {
        std::vector<float> v(kSamples);
        for (int k = 0; k < kSamples; ++k)
            v[std::size_t(k)] = stageValue(k);
        stageStore.appendRun(kStageT0, kPeriod, v.data(), v.size());
        for (int k = 0; k < kSamples; ++k)
            v[std::size_t(k)] = analyzerValue(k);
        analyzerStore.appendRun(kAnalyzerT0, kPeriod, v.data(), v.size());
        source.add(stageX, &stageStore, QStringLiteral("Stage X measured"), QStringLiteral("mm"));
        source.add(analyzerZ, &analyzerStore, QStringLiteral("Analyzer Z measured"), QStringLiteral("mm"));

        stack = std::make_unique<ui::PlotStack>(&source);
        stack->addPanel();
        ASSERT_TRUE(stack->addChannel(0, stageX));
        ASSERT_TRUE(stack->addChannel(1, analyzerZ));
        stack->resize(1000, 600);
        stack->show();
        guitest::pump(20);
        stack->setAnchors(analyzerStore.lastTime(), stageStore.lastTime());
        stack->setTimeRange(-10, 0);
        stack->redraw();
        cursors = new ui::PlotCursors(stack.get());
    }

    /// Index of the stored sample nearest device time t of a 1 kHz run starting at t0.
    static int sampleAt(double t0, double t) { return static_cast<int>(std::lround((t - t0) / kPeriod)); }

    dev::tele::ChannelStore stageStore{kSamples};
    dev::tele::ChannelStore analyzerStore{kSamples};
    ui::StorePlotSource source;
    dev::tele::ChannelKey stageX = key(1, 0, ChannelKind::Measured);
    dev::tele::ChannelKey analyzerZ = key(0, 2, ChannelKind::Measured);
    std::unique_ptr<ui::PlotStack> stack;
    ui::PlotCursors* cursors = nullptr;  // owned by the stack
};

TEST_F(PlotCursorsTest, ReadTheStoredSampleAtEachCursorOnEachInstrumentsClock)
{
    cursors->setVisible(true);
    cursors->setPositions(-5.0, -2.5);
    EXPECT_DOUBLE_EQ(cursors->deltaT(), 2.5);

    const auto readings = cursors->readings();
    ASSERT_EQ(readings.size(), 2);
    const ui::CursorReading& stage = readings[0];
    EXPECT_EQ(stage.panel, 0);
    EXPECT_EQ(stage.name, QStringLiteral("Stage X measured"));
    EXPECT_EQ(stage.unit, QStringLiteral("mm"));
    ASSERT_TRUE(stage.a && stage.b);
    const int ka = sampleAt(kStageT0, stageStore.lastTime() - 5.0);
    const int kb = sampleAt(kStageT0, stageStore.lastTime() - 2.5);
    EXPECT_EQ(ka, 4999);
    EXPECT_EQ(kb, 7499);
    EXPECT_FLOAT_EQ(stage.a->value, stageValue(ka));
    EXPECT_FLOAT_EQ(stage.b->value, stageValue(kb));
    ASSERT_TRUE(stage.deltaY());
    EXPECT_NEAR(*stage.deltaY(), 7.5, 1e-4) << "3 mm/s over 2.5 s";

    // The analyzer's channel is read on the analyzer's clock, not the stage's.
    const ui::CursorReading& analyzer = readings[1];
    EXPECT_EQ(analyzer.panel, 1);
    ASSERT_TRUE(analyzer.a && analyzer.b);
    EXPECT_NEAR(analyzer.a->tS, analyzerStore.lastTime() - 5.0, kPeriod / 2);
    EXPECT_FLOAT_EQ(analyzer.a->value, analyzerValue(sampleAt(kAnalyzerT0, analyzerStore.lastTime() - 5.0)));
    EXPECT_FLOAT_EQ(analyzer.b->value, analyzerValue(sampleAt(kAnalyzerT0, analyzerStore.lastTime() - 2.5)));
}

TEST_F(PlotCursorsTest, ReadoutTableShowsTimesValuesAndDeltas)
{
    ui::CursorReadout readout(cursors);
    readout.show();
    cursors->setVisible(true);
    cursors->setPositions(-5.0, -2.5);
    ASSERT_EQ(readout.rowCount(), 3);  // time + two channels
    EXPECT_EQ(readout.item(0, 3)->text(), QStringLiteral("2.5000"));
    EXPECT_EQ(readout.item(1, 0)->text(), QStringLiteral("Stage X measured (mm)"));
    EXPECT_NEAR(readout.item(1, 1)->text().toDouble(), 14.997, 1e-4);
    EXPECT_NEAR(readout.item(1, 3)->text().toDouble(), 7.5, 1e-4);
    cursors->setVisible(false);
    EXPECT_FALSE(readout.isVisible());
}

TEST_F(PlotCursorsTest, DraggingACursorMovesItAndNotTheView)
{
    cursors->setVisible(true);
    cursors->setPositions(-6.0, -3.0);
    stack->replot();
    const QCPRange before = stack->timeRange();
    ui::PlotPanel* top = stack->panel(0);
    const int y = top->rect()->center().y();
    const QPoint from(int(std::lround(top->timeAxis()->coordToPixel(-6.0))), y);
    const QPoint to = from + QPoint(120, 0);
    auto send = [&](QEvent::Type type, const QPoint& at, Qt::MouseButton button, Qt::MouseButtons held) {
        QMouseEvent e(type, QPointF(at), QPointF(stack->mapToGlobal(at)), button, held, Qt::NoModifier);
        QApplication::sendEvent(stack.get(), &e);
    };
    send(QEvent::MouseButtonPress, from, Qt::LeftButton, Qt::LeftButton);
    send(QEvent::MouseMove, from + QPoint(60, 0), Qt::NoButton, Qt::LeftButton);
    send(QEvent::MouseMove, to, Qt::NoButton, Qt::LeftButton);
    send(QEvent::MouseButtonRelease, to, Qt::LeftButton, Qt::NoButton);

    EXPECT_NEAR(cursors->position(0), top->timeAxis()->pixelToCoord(to.x()), 1e-9);
    EXPECT_DOUBLE_EQ(cursors->position(1), -3.0) << "only the grabbed cursor moves";
    EXPECT_DOUBLE_EQ(stack->timeRange().lower, before.lower) << "a cursor drag must not pan the plot";
    EXPECT_DOUBLE_EQ(stack->timeRange().upper, before.upper);
}

TEST_F(PlotCursorsTest, CursorsFollowPlotsAddedAndRemoved)
{
    cursors->setVisible(true);
    stack->addPanel();
    EXPECT_EQ(stack->itemCount(), 2 * 3 + 2) << "a line per plot per cursor, and two labels";
    stack->removePanel(2);
    EXPECT_EQ(stack->itemCount(), 2 * 2 + 2);
    cursors->setVisible(false);
    EXPECT_EQ(stack->itemCount(), 0);
}

TEST(PlotReduction, ASingleSampleSpikeSurvivesAndPointsFollowTheScreen)
{
    constexpr int n = 200000;
    dev::tele::ChannelStore store(n);
    std::vector<float> v(n, 0.f);
    v[54321] = 100.f;
    v[177777] = -50.f;
    store.appendRun(0.0, 1e-4, v.data(), v.size());
    ui::StorePlotSource source;
    const auto k = key(1, 0, ChannelKind::FollowingError);
    source.add(k, &store, QStringLiteral("Stage X following error"), QStringLiteral("µm"));
    ui::PlotStack stack(&source);
    ASSERT_TRUE(stack.addChannel(0, k));
    stack.resize(800, 300);
    stack.show();
    guitest::pump(20);
    stack.setAnchors(std::nan(""), store.lastTime());
    stack.setTimeRange(-20, 0);
    stack.redraw();

    QCPGraph* g = stack.panel(0)->graph(k);
    ASSERT_NE(g, nullptr);
    double lo = 0, hi = 0;
    for (auto it = g->data()->constBegin(); it != g->data()->constEnd(); ++it) {
        lo = std::min(lo, it->value);
        hi = std::max(hi, it->value);
    }
    EXPECT_EQ(hi, 100.0) << "the one-sample spike is on screen";
    EXPECT_EQ(lo, -50.0);
    EXPECT_GT(stack.columns(), 100);
    EXPECT_LE(g->dataCount(), 2 * stack.columns() + 2) << n << " samples reduced to the screen's columns";
    // Auto-scale shows the spike too.
    EXPECT_GE(stack.panel(0)->leftAxis()->range().upper, 100.0);
    EXPECT_LE(stack.panel(0)->leftAxis()->range().lower, -50.0);
    EXPECT_EQ(stack.panel(0)->leftAxis()->label(), QStringLiteral("µm"));
}

TEST(PlotReduction, FewSamplesAreHandedOverRaw)
{
    dev::tele::ChannelStore store(1000);
    std::vector<float> v(100);
    for (int i = 0; i < 100; ++i)
        v[std::size_t(i)] = float(i * i);
    store.appendRun(10.0, 0.01, v.data(), v.size());
    ui::StorePlotSource source;
    const auto k = key(1, 1, ChannelKind::Measured);
    source.add(k, &store, QStringLiteral("Stage Y measured"), QStringLiteral("mm"));
    ui::PlotStack stack(&source);
    stack.addChannel(0, k);
    stack.resize(800, 300);
    stack.show();
    guitest::pump(20);
    stack.setAnchors(std::nan(""), store.lastTime());
    stack.setTimeRange(-10, 0);
    stack.redraw();
    QCPGraph* g = stack.panel(0)->graph(k);
    ASSERT_EQ(g->dataCount(), 100);
    auto it = g->data()->constBegin();
    for (int i = 0; i < 100; ++i, ++it) {
        EXPECT_NEAR(it->key, store.at(std::size_t(i)).tS - store.lastTime(), 1e-9);
        EXPECT_EQ(it->value, double(i * i));
    }
}

} // namespace
