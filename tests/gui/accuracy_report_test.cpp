// The accuracy report as a person gets it: a PDF a real renderer (poppler's pdftoppm)
// turns into A4 pages with something drawn on them — the figures, the plots — and one
// that cannot be written leaves nothing behind.
#include "device/files/accuracy/accuracy_result_file.h"
#include "device/files/accuracy/error_curve_csv.h"
#include "device/files/accuracy/readings_csv.h"
#include "motion/metrology/contour/circular_test.h"
#include "widgets/report/accuracy_report.h"

#include <QDir>
#include <QFile>
#include <QImage>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <cmath>

namespace {

QString example(const char* name) { return QStringLiteral(BP_SOURCE_DIR "/resources/examples/") + QLatin1String(name); }

/// The pages pdftoppm makes of `pdf` at 40 dpi.
QList<QImage> render(const QString& pdf, const QTemporaryDir& dir)
{
    QList<QImage> pages;
    const QString prefix = dir.filePath(QStringLiteral("page"));
    QProcess p;
    p.start(QStringLiteral("pdftoppm"), {QStringLiteral("-r"), QStringLiteral("40"), QStringLiteral("-png"), pdf, prefix});
    if (!p.waitForFinished(30000) || p.exitCode() != 0) {
        ADD_FAILURE() << "pdftoppm: " << p.readAllStandardError().toStdString();
        return pages;
    }
    for (const QString& f : QDir(dir.path()).entryList({QStringLiteral("page-*.png")}, QDir::Files, QDir::Name))
        pages << QImage(dir.filePath(f));
    return pages;
}

/// Share of pixels that are not white in a band of the page (0 top … 1 bottom).
double inked(const QImage& img, double from, double to)
{
    int dark = 0, all = 0;
    for (int y = static_cast<int>(from * img.height()); y < static_cast<int>(to * img.height()); ++y)
        for (int x = 0; x < img.width(); ++x, ++all)
            if (qGray(img.pixel(x, y)) < 200)
                ++dark;
    return all ? double(dark) / all : 0;
}

TEST(AccuracyReport, APdfOfTwoA4PagesWithTheFiguresAndPlots)
{
    if (QStandardPaths::findExecutable(QStringLiteral("pdftoppm")).isEmpty())
        GTEST_FAIL() << "pdftoppm is missing: ./scripts/setup installs poppler-utils";
    const auto result = dev::files::accuracy::loadAccuracyResultFile(example("stage-x-interferometer.accuracy-result.json"));
    ASSERT_TRUE(result.result) << motion::msg::debugFormat(result.problems);
    const auto readings = dev::files::accuracy::loadReadingsCsv(example("stage-x-interferometer.readings.csv"));
    ASSERT_TRUE(readings.ok());
    ui::report::AxisReportInput in;
    in.title = QStringLiteral("Positioning accuracy of axis X");
    in.instrument = QStringLiteral("BenchPilot microscope stage (simulated)");
    in.source = motion::msg::make("accuracy.source.interferometer");
    in.result = *result.result;
    in.readings = readings.readings;
    in.fit = motion::metrology::fitPolynomials(dev::files::accuracy::fitPointsOf(in.result.evaluation));
    in.before = in.result;  // itself as "before": the comparison is drawn, 1.0× throughout
    in.created = QStringLiteral("2025-01-01T12:00:00");
    QTemporaryDir dir;
    const QString pdf = dir.filePath(QStringLiteral("x.report.pdf"));
    QString error;
    ASSERT_TRUE(ui::report::writeAxisReport(pdf, in, &error)) << error.toStdString();
    EXPECT_FALSE(QFile::exists(pdf + QStringLiteral(".part")));
    const auto pages = render(pdf, dir);
    ASSERT_EQ(pages.size(), 2);
    for (const QImage& page : pages)
        EXPECT_NEAR(double(page.height()) / page.width(), 297.0 / 210.0, 0.02) << "A4 portrait";
    EXPECT_GT(inked(pages[0], 0.05, 0.45), 0.01) << "the set-up and the figures table";
    EXPECT_GT(inked(pages[0], 0.5, 0.9), 0.01) << "the plot";
    EXPECT_GT(inked(pages[1], 0.05, 0.8), 0.01) << "the table, before/after and the fit";
}

TEST(AccuracyReport, ACircleReportAndNothingHalfWritten)
{
    motion::metrology::CircularTest t;
    t.radiusMm = 10;
    t.centreMm = {50, 50};
    std::vector<motion::metrology::CircularRun> runs;
    for (auto r : {motion::metrology::Rotation::Ccw, motion::metrology::Rotation::Cw}) {
        motion::metrology::CircularRun run;
        run.rotation = r;
        for (int k = 0; k < 90; ++k) {
            const double a = k * 2 * 3.141592653589793 / 90, rr = 10 + 0.002 * std::cos(2 * a) + (r == motion::metrology::Rotation::Cw ? 0.001 : 0);
            run.samplesMm.push_back({50 + rr * std::cos(a), 50 + rr * std::sin(a)});
        }
        runs.push_back(run);
    }
    ui::report::CircleReportInput in;
    in.title = QStringLiteral("Circular test");
    in.test = t;
    in.evaluation = motion::metrology::evaluate(t, runs);
    ASSERT_TRUE(in.evaluation.ok());
    QTemporaryDir dir;
    QString error;
    const QString pdf = dir.filePath(QStringLiteral("c.report.pdf"));
    ASSERT_TRUE(ui::report::writeCircleReport(pdf, in, &error)) << error.toStdString();
    const auto pages = render(pdf, dir);
    ASSERT_EQ(pages.size(), 1);
    EXPECT_GT(inked(pages[0], 0.35, 0.9), 0.01) << "the polar plot";
    // A folder that does not exist: refused, nothing left behind.
    const QString nowhere = dir.filePath(QStringLiteral("missing/c.report.pdf"));
    EXPECT_FALSE(ui::report::writeCircleReport(nowhere, in, &error));
    EXPECT_FALSE(error.isEmpty());
    EXPECT_FALSE(QFile::exists(nowhere));
    EXPECT_FALSE(QFile::exists(nowhere + QStringLiteral(".part")));
}

} // namespace
