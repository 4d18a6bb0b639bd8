// Words that were cut or could not be read, as an afternoon at 1366 × 768 found them: the
// scripting strip cut at "Your m…", the event log two rows high (three now), a plot's ticks labelled
// "10, 10, 10".
#include "api_script.h"
#include "gui_window.h"

#include "app/gui/api_panel.h"
#include "app/gui/api_wiring.h"
#include "widgets/event_log.h"
#include "widgets/plot_ticks.h"
#include "widgets/tuning/response_plot.h"
#include "widgets/wording/translators.h"

#include <QHeaderView>
#include <QLabel>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTimer>

#include <qcustomplot.h>

#include <gtest/gtest.h>

#include <cmath>

namespace {

/// Whether `label` shows all of its text: on its lines when it wraps, on one line when not.
bool wholeIn(QLabel* label)
{
    if (label->wordWrap())
        return label->heightForWidth(label->contentsRect().width()) <= label->contentsRect().height();
    return label->fontMetrics().horizontalAdvance(label->text()) <= label->contentsRect().width();
}

class TrustWords : public ::testing::TestWithParam<const char*> {
protected:
    void SetUp() override { ASSERT_TRUE(translators.setLanguage(QString::fromLatin1(GetParam()))); }
    void TearDown() override { translators.setLanguage(QStringLiteral("en")); }
    ui::words::Translators translators;
};

TEST_P(TrustWords, TheScriptingStripSaysItsWholeSentenceAt1366x768)
{
    QTemporaryDir dir;
    const app::MainWindowOptions options = guitest::apiWindowOptions(dir.filePath(QStringLiteral("api.sock")));
    const auto w = guitest::openReadyWindow(QSize(1366, 768), options);
    ASSERT_TRUE(w);
    ASSERT_NE(w->api()->server(), nullptr) << w->api()->startError().toStdString();
    guitest::Script script(options.api.socketPath);
    const QJsonObject acquired =
        script.call(QStringLiteral("control.acquire"), QJsonObject{{QStringLiteral("client"), QStringLiteral("plate-then-image")}});
    const QString lease = acquired.value(QStringLiteral("result")).toObject().value(QStringLiteral("lease")).toString();
    ASSERT_FALSE(lease.isEmpty());
    QTimer beat;
    QObject::connect(&beat, &QTimer::timeout, [&] { script.heartbeat(lease); });
    beat.start(100);
    app::ApiControlStrip* strip = w->api()->strip();
    ASSERT_TRUE(guitest::waitFor([&] { return strip->isVisible(); }, 2000));
    guitest::pump(50);
    QLabel* label = nullptr;
    for (auto* l : strip->findChildren<QLabel*>())
        if (l->text() == strip->text())
            label = l;
    ASSERT_NE(label, nullptr);
    EXPECT_TRUE(wholeIn(label)) << "cut: \"" << label->text().toStdString() << "\" in " << label->width() << " × " << label->height()
                                << " px";
    EXPECT_TRUE(strip->takeBackButton()->isVisible());
    guitest::keepPicture(w.get(), QStringLiteral("strip-%1.png").arg(QLatin1String(GetParam())));
}

TEST_P(TrustWords, TheEventLogShowsSeveralRowsAt768PixelsHigh)
{
    const auto w = guitest::openReadyWindow(QSize(1366, 768));
    ASSERT_TRUE(w);
    auto* table = w->eventLog()->findChild<QTableWidget*>();
    ASSERT_NE(table, nullptr);
    for (const QString& screen : w->screenNames()) {
        ASSERT_TRUE(w->showScreen(screen));
        guitest::pump(30);
        const int rows = table->viewport()->height() / table->verticalHeader()->defaultSectionSize();
        EXPECT_GE(rows, 3) << screen.toStdString() << ": " << table->viewport()->height() << " px for rows of "
                           << table->verticalHeader()->defaultSectionSize();
    }
}

INSTANTIATE_TEST_SUITE_P(Languages, TrustWords, ::testing::Values("en", "zh_CN"),
                         [](const ::testing::TestParamInfo<const char*>& i) { return std::string(i.param); });

/// The tick labels `axis` shows over [lo, hi].
QStringList ticksOver(QCustomPlot& plot, double lo, double hi)
{
    plot.xAxis->setRange(lo, hi);
    plot.replot();
    const QVector<QString> labels = plot.xAxis->tickVectorLabels();
    return QStringList(labels.begin(), labels.end());
}

TEST(TrustWordsTicks, TickLabelsDifferAndSayTheirValueAtEveryRange)
{
    QCustomPlot plot;
    plot.resize(600, 300);
    ui::useDistinctTickLabels(plot.xAxis);
    const std::pair<double, double> ranges[] = {{100, 100.0004}, {10, 10.00002}, {-1e-5, 1e-5}, {0, 0.001}, {0, 100},
                                                {-250, 250},     {1000, 1000.5}, {99.9998, 100.0002}, {0.123, 0.127}};
    for (const auto& [lo, hi] : ranges) {
        const QStringList labels = ticksOver(plot, lo, hi);
        const QVector<double> ticks = plot.xAxis->tickVector();
        ASSERT_GE(labels.size(), 2) << lo << "…" << hi;
        EXPECT_EQ(QSet<QString>(labels.begin(), labels.end()).size(), labels.size())
            << lo << "…" << hi << ": " << labels.join(QStringLiteral(", ")).toStdString();
        // Each label reads back as its tick, to within a hundredth of the step.
        const double step = ticks.size() > 1 ? ticks[1] - ticks[0] : 1;
        for (int i = 0; i < labels.size() && i < ticks.size(); ++i) {
            bool ok = false;
            const double v = plot.locale().toDouble(labels[i], &ok);
            EXPECT_TRUE(ok) << labels[i].toStdString();
            EXPECT_NEAR(v, ticks[i], std::abs(step) / 100) << lo << "…" << hi << ": " << labels[i].toStdString();
        }
    }
}

// The step test's legend, run beside the Z-N verification at 1366 × 768, was cut at its left:
// "…s PID gains verification (Kp 2.5066 · Ki 962.75 /s · Kd 1.6315 ms)".
TEST(TrustWordsLegend, TheStepTestLegendFitsItsPlot)
{
    ui::ResponsePlot plot(ui::ResponsePlot::Mode::Overlay);
    plot.resize(330, 330);  // the plot's width beside the gains and the results at 1366 px
    plot.show();
    motion::control::Record r;
    r.periodS = 1e-3;
    for (int i = 0; i < 120; ++i)
        r.append(0.02, 0.02 * (1 - std::exp(-i / 10.0)), 0);
    plot.addRun(r, QStringLiteral("Gains in use (Kp 0.25 · Ki 500 /s · Kd 30 µs)"));
    plot.addRun(r, QStringLiteral("Ziegler–Nichols PID gains verification (Kp 2.5066 · Ki 962.75 /s · Kd 1.6315 ms)"));
    plot.plot()->replot();
    const QRect legend = plot.plot()->legend->outerRect();
    const QRect room = plot.plot()->rect();
    EXPECT_GE(legend.left(), room.left()) << "the legend starts " << room.left() - legend.left() << " px left of its plot";
    EXPECT_LE(legend.right(), room.right());
    EXPECT_EQ(ui::ResponsePlot::legendLines(QStringLiteral("PID verification (Kp 2)")), QStringLiteral("PID verification\n(Kp 2)"));
}

} // namespace
