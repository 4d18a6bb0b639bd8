// Export of the stacked plots, read back: the CSV holds the raw stored samples of the
// visible range of both instruments (or, above the limit, the min/max per pixel
// column, and says so); the PNG loads as a picture of the plots; the PDF is a PDF.
#include "gui_wait.h"
#include "widgets/plot_export.h"
#include "widgets/plot_panel.h"
#include "widgets/plot_stack.h"

#include <QFile>
#include <QImage>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

namespace {

using dev::proto::ChannelKind;

struct Csv {
    QList<QByteArray> comments;
    QList<QByteArray> header;
    QList<QList<QByteArray>> rows;
};

Csv readCsv(const QString& path)
{
    Csv csv;
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return csv;
    while (!f.atEnd()) {
        const QByteArray line = f.readLine().trimmed();
        if (line.startsWith('#'))
            csv.comments << line;
        else if (csv.header.isEmpty())
            csv.header = line.split(',');
        else if (!line.isEmpty())
            csv.rows << line.split(',');
    }
    return csv;
}

class PlotExportTest : public ::testing::Test {
protected:
    void SetUp() override
    {
        // The stage at 1 kHz from device time 100 s, the analyzer at 500 Hz from 7 s:
        // two clocks that have nothing to do with each other.
        std::vector<float> v(10000);
        for (std::size_t k = 0; k < v.size(); ++k)
            v[k] = float(std::sin(double(k) * 0.01) * 12.5);
        stage.appendRun(100.0, 0.001, v.data(), v.size());
        for (std::size_t k = 0; k < 5000; ++k)
            v[k] = float(k) * 0.25f;
        analyzer.appendRun(7.0, 0.002, v.data(), 5000);
        source.setInstrumentName(0, QStringLiteral("Analyzer"));
        source.setInstrumentName(1, QStringLiteral("Stage"));
        source.add(stageKey, &stage, QStringLiteral("Stage X measured"), QStringLiteral("mm"));
        source.add(analyzerKey, &analyzer, QStringLiteral("Analyzer P measured"), QStringLiteral("µL"));
        plots = std::make_unique<ui::PlotStack>(&source);
        plots->addPanel();
        plots->addChannel(0, stageKey);
        plots->addChannel(1, analyzerKey);
        plots->resize(900, 500);
        plots->show();
        guitest::pump(20);
        plots->setAnchors(analyzer.lastTime(), stage.lastTime());
        plots->setTimeRange(-2, 0);
        plots->redraw();
    }

    dev::tele::ChannelStore stage{10000};
    dev::tele::ChannelStore analyzer{5000};
    dev::tele::ChannelKey stageKey{1, dev::proto::ChannelRef{0, ChannelKind::Measured}};
    dev::tele::ChannelKey analyzerKey{0, dev::proto::ChannelRef{3, ChannelKind::Measured}};
    ui::StorePlotSource source;
    std::unique_ptr<ui::PlotStack> plots;
    QTemporaryDir dir;
};

TEST_F(PlotExportTest, CsvHoldsTheRawSamplesOfTheVisibleRangeOfBothInstruments)
{
    const QString path = dir.filePath(QStringLiteral("sub/view.csv"));
    const ui::CsvExportResult r = ui::exportCsv(*plots, path);
    ASSERT_TRUE(r.ok) << r.error.toStdString();
    EXPECT_FALSE(r.decimated);
    const Csv csv = readCsv(path);
    ASSERT_FALSE(csv.comments.isEmpty());
    EXPECT_TRUE(csv.comments.first().contains("raw samples"));
    EXPECT_EQ(csv.header, (QList<QByteArray>{"time_s", "instrument", "Stage X measured [mm]",
                                             QStringLiteral("Analyzer P measured [µL]").toUtf8()}));
    // 2 s at 1 kHz and at 500 Hz, up to and including the newest sample (at x = 0).
    std::size_t nextStage = stage.lowerBound(stage.lastTime() - 2);
    std::size_t nextAnalyzer = analyzer.lowerBound(analyzer.lastTime() - 2);
    EXPECT_NEAR(double(stage.size() - nextStage), 2000, 1);
    EXPECT_NEAR(double(analyzer.size() - nextAnalyzer), 1000, 1);
    ASSERT_EQ(csv.rows.size(), qsizetype(stage.size() - nextStage + analyzer.size() - nextAnalyzer));
    EXPECT_EQ(r.rows, csv.rows.size());

    double lastTime = -1e9;
    for (const auto& row : csv.rows) {
        ASSERT_EQ(row.size(), 4);
        const double t = row[0].toDouble();
        EXPECT_GE(t, lastTime) << "rows in time order";
        lastTime = t;
        if (row[1] == "Stage") {
            const dev::tele::Sample s = stage.at(nextStage++);
            EXPECT_NEAR(t, s.tS - stage.lastTime(), 1e-6);
            EXPECT_EQ(row[2].toFloat(), s.value) << "exact stored value";
            EXPECT_TRUE(row[3].isEmpty());
        } else {
            ASSERT_EQ(row[1], "Analyzer");
            const dev::tele::Sample s = analyzer.at(nextAnalyzer++);
            EXPECT_NEAR(t, s.tS - analyzer.lastTime(), 1e-6);
            EXPECT_TRUE(row[2].isEmpty());
            EXPECT_EQ(row[3].toFloat(), s.value);
        }
    }
    EXPECT_EQ(nextStage, stage.size());
    EXPECT_EQ(nextAnalyzer, analyzer.size());
    EXPECT_DOUBLE_EQ(lastTime, 0.0);
}

TEST_F(PlotExportTest, CsvAboveTheRawLimitHoldsTheDecimatedViewAndSaysSo)
{
    const QString path = dir.filePath(QStringLiteral("dec.csv"));
    const ui::CsvExportResult r = ui::exportCsv(*plots, path, /*rawLimitSamples=*/1000);
    ASSERT_TRUE(r.ok) << r.error.toStdString();
    EXPECT_TRUE(r.decimated);
    const Csv csv = readCsv(path);
    EXPECT_TRUE(csv.comments.first().contains("decimated"));
    ASSERT_EQ(csv.rows.size() % 2, 0);
    EXPECT_LE(csv.rows.size(), 2 * plots->columns());
    EXPECT_GT(csv.rows.size(), plots->columns());
    // Every extreme of the range is in the file.
    float lo = 1e9f, hi = -1e9f, fileLo = 1e9f, fileHi = -1e9f;
    for (std::size_t i = stage.lowerBound(stage.lastTime() - 2); i < stage.size(); ++i) {
        lo = std::min(lo, stage.at(i).value);
        hi = std::max(hi, stage.at(i).value);
    }
    for (const auto& row : csv.rows)
        if (!row[2].isEmpty()) {
            fileLo = std::min(fileLo, row[2].toFloat());
            fileHi = std::max(fileHi, row[2].toFloat());
        }
    EXPECT_EQ(fileLo, lo);
    EXPECT_EQ(fileHi, hi);
}

TEST_F(PlotExportTest, PngLoadsAsAPictureOfThePlots)
{
    const QString path = dir.filePath(QStringLiteral("view.png"));
    QString error;
    ASSERT_TRUE(ui::exportPng(*plots, path, &error)) << error.toStdString();
    QImage img(path);
    ASSERT_FALSE(img.isNull());
    EXPECT_EQ(img.size(), plots->size());
    // Not a blank picture: the stage's blue line is in it.
    bool blue = false;
    for (int y = 0; y < img.height() && !blue; ++y)
        for (int x = 0; x < img.width() && !blue; ++x)
            blue = img.pixelColor(x, y) == ui::PlotPanel::penFor(stageKey).color();
    EXPECT_TRUE(blue);
}

TEST_F(PlotExportTest, PdfIsWritten)
{
    const QString path = dir.filePath(QStringLiteral("view.pdf"));
    QString error;
    ASSERT_TRUE(ui::exportPdf(*plots, path, &error)) << error.toStdString();
    QFile f(path);
    ASSERT_TRUE(f.open(QIODevice::ReadOnly));
    EXPECT_TRUE(f.read(5).startsWith("%PDF"));
    EXPECT_GT(f.size(), 1000);
}

TEST_F(PlotExportTest, UnwritablePlaceIsASentenceNotACrash)
{
    QFile blocker(dir.filePath(QStringLiteral("file")));
    ASSERT_TRUE(blocker.open(QIODevice::WriteOnly));
    blocker.close();
    const ui::CsvExportResult r = ui::exportCsv(*plots, dir.filePath(QStringLiteral("file/below.csv")));
    EXPECT_FALSE(r.ok);
    EXPECT_FALSE(r.error.isEmpty());
}

} // namespace
