// The measured path is drawn as what it is: telemetry samples, not a polygon through them
// (a GRBL controller polled at 10 Hz gave 14 samples on a circle, joined into chords 0.12 mm
// inside it beside "max 2.2 µm"). The summary says the sample rate, and when the contour
// figure rests on too few samples to mean much.
#include "gui_wait.h"

#include "motion/numbers.h"

#include "widgets/patterns/contour_plot.h"
#include "widgets/patterns/pattern_preview.h"
#include "widgets/patterns/pattern_screen.h"

#include <qcustomplot.h>

#include <gtest/gtest.h>

#include <cmath>

namespace {

QCPCurve* curveNamed(QCustomPlot* plot, const QString& prefix)
{
    for (int i = 0; i < plot->plottableCount(); ++i)
        if (auto* c = qobject_cast<QCPCurve*>(plot->plottable(i)); c && c->name().startsWith(prefix))
            return c;
    return nullptr;
}

/// A run of 14 samples at 10 Hz around a 3 mm circle, its contour error 2.2 µm at most.
struct SparseCircle {
    std::vector<motion::path::Segment> path;
    std::vector<double> along, times;
    dev::jobs::PatternRunSummary summary;
    SparseCircle()
    {
        motion::path::Segment s;
        s.kind = motion::path::SegmentKind::ArcCcw;
        s.start = s.end = {3, 0};
        s.feedMmS = 1.4;
        path = {s};
        const double length = 2 * motion::kPi * 3;
        for (int k = 0; k < 14; ++k) {
            along.push_back(length * k / 13);
            times.push_back(0.1 * k);
        }
        summary.samples = 14;
        summary.maxContourMm = 0.0022;
        summary.rmsContourMm = 0.0012;
        summary.durationS = 1.3;
        summary.complete = true;
    }
};

} // namespace

TEST(PatternSamples, TheMeasuredPathIsDrawnAsItsSamplesNotJoined)
{
    ui::PatternPreview preview;
    preview.resize(400, 400);
    for (int k = 0; k < 14; ++k) {
        const double a = 2 * motion::kPi * k / 14;
        preview.addRunPoint({3 * std::cos(a), 3 * std::sin(a)}, {3 * std::cos(a), 3 * std::sin(a)});
    }
    QCPCurve* measured = curveNamed(&preview, QStringLiteral("measured"));
    ASSERT_NE(measured, nullptr);
    EXPECT_EQ(measured->lineStyle(), QCPCurve::lsNone) << "the samples are joined into a polygon";
    EXPECT_NE(measured->scatterStyle().shape(), QCPScatterStyle::ssNone) << "the samples are not marked";
    EXPECT_EQ(measured->data()->size(), 14);
}

TEST(PatternSamples, TheSummarySaysTheRateAndWhenTheFigureRestsOnTooFewSamples)
{
    const SparseCircle run;
    const auto sparse = motion::path::judgeSampleDensity(run.path, run.along, run.times, run.summary.maxContourMm);
    const QString text = ui::PatternScreen::runSummaryText(run.summary, sparse);
    EXPECT_TRUE(text.contains(QStringLiteral("14 samples at 10 Hz"))) << text.toStdString();
    EXPECT_TRUE(text.contains(QStringLiteral("Too few samples"))) << text.toStdString();
    EXPECT_TRUE(text.contains(QStringLiteral("87.2 µm"))) << "the chord's sag, said" << text.toStdString();

    // The same circle sampled at 250 Hz: the figure stands, with its rate.
    std::vector<double> along, times;
    for (int k = 0; k < 1000; ++k) {
        along.push_back(2 * motion::kPi * 3 * k / 999);
        times.push_back(k / 250.0);
    }
    dev::jobs::PatternRunSummary dense = run.summary;
    dense.samples = 1000;
    const QString fine = ui::PatternScreen::runSummaryText(dense, motion::path::judgeSampleDensity(run.path, along, times, dense.maxContourMm));
    EXPECT_TRUE(fine.contains(QStringLiteral("1000 samples at 250 Hz"))) << fine.toStdString();
    EXPECT_FALSE(fine.contains(QStringLiteral("Too few"))) << fine.toStdString();
}
