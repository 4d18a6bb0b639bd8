// benchpilot-cli pattern plan|run, called in-process with string buffers.
#include "app/cli/command.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <cmath>

namespace {

struct CliResult {
    int code = -1;
    QString out, err;
    QJsonObject json() const { return QJsonDocument::fromJson(out.toUtf8()).object(); }
};

CliResult cliRun(const QString& words)
{
    CliResult r;
    QTextStream out(&r.out), err(&r.err);
    r.code = app::cli::runCli(words.split(QLatin1Char(' '), Qt::SkipEmptyParts), out, err);
    out.flush();
    err.flush();
    return r;
}

}  // namespace

TEST(PatternsCli, PlanPrintsTheSegmentsAndTheirTiming)
{
    const CliResult r = cliRun(QStringLiteral("pattern plan --shape circle --radius 5 --feed 2 --json"));
    ASSERT_EQ(r.code, 0) << r.err.toStdString();
    const QJsonObject j = r.json();
    EXPECT_EQ(j["shape"].toString(), QStringLiteral("circle"));
    EXPECT_EQ(j["segment_count"].toInt(), 4);
    EXPECT_NEAR(j["length_mm"].toDouble(), 2 * M_PI * 5, 1e-9);
    EXPECT_NEAR(j["estimated_s"].toDouble(), 2 * M_PI * 5 / 2 + 0.02, 1e-3);
    const QJsonArray segs = j["segments"].toArray();
    ASSERT_EQ(segs.size(), 4);
    EXPECT_EQ(segs[0].toObject()["kind"].toString(), QStringLiteral("ARC CCW"));
    EXPECT_EQ(segs[0].toObject()["center_mm"].toArray()[0].toDouble(), 50.0);
    EXPECT_EQ(segs[1].toObject()["entry_mm_s"].toDouble(), 2.0);  // tangent quarters: no slowing down
}

TEST(PatternsCli, EveryShapePlansWithItsOptions)
{
    for (const char* line : {"--shape line --from 0,0 --to 30,40", "--shape rectangle --corner 10,10 --width 5 --height 3 --dir cw",
                             "--shape arc --center 20,20 --radius 3 --sweep-deg 270", "--shape sine --amplitude 2 --wavelength 8 --length 16",
                             "--shape cosine --origin 5,5 --angle-deg 90", "--shape spiral --turns 2.5 --pitch 1",
                             "--shape raster --spacing 5 --along y", "--shape circle --start-deg 45 --dir cw --feed 3"}) {
        const CliResult r = cliRun(QStringLiteral("pattern plan --json ") + QString::fromLatin1(line));
        EXPECT_EQ(r.code, 0) << line << ": " << r.err.toStdString();
        EXPECT_GT(r.json()["segment_count"].toInt(), 0) << line;
    }
    const CliResult text = cliRun(QStringLiteral("pattern plan --shape line --from 20,30 --to 50,70"));
    ASSERT_EQ(text.code, 0);
    EXPECT_TRUE(text.out.contains(QStringLiteral("line: 1 segments, 50.000 mm"))) << text.out.toStdString();
}

TEST(PatternsCli, BadOptionsAreUsageErrorsThatNameTheField)
{
    CliResult r = cliRun(QStringLiteral("pattern plan --shape hexagon"));
    EXPECT_EQ(r.code, 1);
    EXPECT_TRUE(r.err.contains(QStringLiteral("--shape 'hexagon'"))) << r.err.toStdString();
    r = cliRun(QStringLiteral("pattern plan --shape spiral --turns 2.3 --pitch 0"));
    EXPECT_EQ(r.code, 1);
    EXPECT_TRUE(r.err.contains(QStringLiteral("pitch_mm: must be above 0"))) << r.err.toStdString();
    EXPECT_TRUE(r.err.contains(QStringLiteral("turns: must be a whole or half number"))) << r.err.toStdString();
    r = cliRun(QStringLiteral("pattern plan --shape arc --dir left"));
    EXPECT_EQ(r.code, 1);
    r = cliRun(QStringLiteral("pattern plan"));
    EXPECT_EQ(r.code, 1);
    EXPECT_TRUE(r.err.contains(QStringLiteral("--file"))) << r.err.toStdString();
}

TEST(PatternsCli, PlanReadsAPatternFile)
{
    QTemporaryDir tmp;
    const QString f = tmp.filePath(QStringLiteral("r.pattern.json"));
    QFile out(f);
    ASSERT_TRUE(out.open(QIODevice::WriteOnly));
    out.write(R"({"schema": "benchpilot.pattern", "version": 1, "shape": "raster", "feed_mm_s": 4,
                  "corner_mm": [10, 10], "width_mm": 20, "height_mm": 4, "spacing_mm": 1})");
    out.close();
    const CliResult r = cliRun(QStringLiteral("pattern plan --json --file ") + f);
    ASSERT_EQ(r.code, 0) << r.err.toStdString();
    EXPECT_EQ(r.json()["segment_count"].toInt(), 9);
    const CliResult bad = cliRun(QStringLiteral("pattern plan --file ") + tmp.filePath(QStringLiteral("none.pattern.json")));
    EXPECT_EQ(bad.code, 1);
}

TEST(PatternsCli, RunRefusesAPatternOutsideTheSoftLimitsByItsSegment)
{
    const CliResult r = cliRun(QStringLiteral("--sim stage pattern run --shape rectangle --corner 80,10 --width 30 --height 10 --json"));
    EXPECT_EQ(r.code, 2);
    EXPECT_TRUE(r.err.contains(QStringLiteral("segment 0 (LINE) reaches X = 110.000 mm"))) << r.err.toStdString();
    EXPECT_TRUE(r.err.contains(QStringLiteral("--home-first"))) << r.err.toStdString();
}

TEST(PatternsCli, RunMeasuresTheContourOnTheSimulatedStage)
{
    const CliResult r = cliRun(QStringLiteral("--sim stage pattern run --shape line --from 1,1 --to 3,2 --feed 2 --home-first --json"));
    ASSERT_EQ(r.code, 0) << r.err.toStdString();
    const QStringList lines = r.out.trimmed().split(QLatin1Char('\n'));
    ASSERT_EQ(lines.size(), 1) << "one JSON line: " << r.out.toStdString();
    const QJsonObject j = r.json();
    EXPECT_TRUE(j["complete"].toBool());
    EXPECT_EQ(j["segments_done"].toInt(), 1);
    EXPECT_LT(j["max_contour_um"].toDouble(), 2.0);
    EXPECT_GT(j["rms_contour_um"].toDouble(), 0.0);
    EXPECT_NEAR(j["duration_s"].toDouble(), std::sqrt(5.0) / 2, 0.1);
    EXPECT_GT(j["samples"].toInt(), 100);
}
