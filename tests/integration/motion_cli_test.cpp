// benchpilot-cli's motion commands, called in-process with string buffers.
#include "app/cli/command.h"

#include <gtest/gtest.h>

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <cmath>

namespace {

struct Run {
    std::optional<int> code;
    QString out, err;
    QJsonObject json() const { return QJsonDocument::fromJson(out.toUtf8()).object(); }
};

Run run(const QString& command, const QStringList& args)
{
    Run r;
    QTextStream out(&r.out), err(&r.err);
    r.code = app::cli::runCli(QStringList{command} + args, out, err);
    out.flush();
    err.flush();
    return r;
}

QStringList words(const char* text) { return QString::fromLatin1(text).split(QLatin1Char(' '), Qt::SkipEmptyParts); }

}  // namespace

TEST(MotionCli, JerkLimitedProfileSamples)
{
    const auto r = run(QStringLiteral("profile"), words("--kind jerk-limited --distance 120 --vmax 100 --amax 1000 --jmax 10000 --dt 0.1"));
    ASSERT_EQ(r.code, 0) << r.err.toStdString();
    const auto json = r.json();
    EXPECT_NEAR(json["duration"].toDouble(), 1.4, 1e-12);
    const auto samples = json["samples"].toArray();
    ASSERT_EQ(samples.size(), 15);  // 0, 0.1, …, 1.4
    EXPECT_EQ(samples.last().toObject()["s"].toDouble(), 120);
    EXPECT_NEAR(samples[7].toObject()["v"].toDouble(), 100, 1e-9);
    for (const char* key : {"t", "s", "v", "a", "j"})
        EXPECT_TRUE(samples[3].toObject().contains(QLatin1String(key))) << key;
}

TEST(MotionCli, SeedXyMoveIsSynchronizedPerAxis)
{
    // Seed 000 §4.1: (30, 40) along tan θ = 4/3.
    const auto r = run(QStringLiteral("profile"), words("--kind seed-scurve --distance 30,40 --vmax 50 --accel-time 0.1 --dt 0.05"));
    ASSERT_EQ(r.code, 0) << r.err.toStdString();
    const auto axes = r.json()["axes"].toArray();
    ASSERT_EQ(axes.size(), 2);
    const auto x = axes[0].toObject()["samples"].toArray(), y = axes[1].toObject()["samples"].toArray();
    ASSERT_EQ(x.size(), y.size());
    for (int i = 0; i < x.size(); ++i)
        EXPECT_NEAR(3 * y[i].toObject()["s"].toDouble(), 4 * x[i].toObject()["s"].toDouble(), 1e-9);
    EXPECT_EQ(x.last().toObject()["s"].toDouble(), 30);
    EXPECT_EQ(y.last().toObject()["s"].toDouble(), 40);
}

TEST(MotionCli, BadOptionsAreNamedWithTheirValue)
{
    auto r = run(QStringLiteral("profile"), words("--kind jerk-limited --distance 10 --vmax abc"));
    EXPECT_EQ(r.code, 1);
    EXPECT_TRUE(r.err.contains(QLatin1String("--vmax 'abc' is not a number"))) << r.err.toStdString();
    EXPECT_TRUE(r.out.isEmpty());
    r = run(QStringLiteral("profile"), words("--kind jerk-limited --distance 10 --vmax 10 --amax 100"));
    EXPECT_EQ(r.code, 1);
    EXPECT_TRUE(r.err.contains(QLatin1String("--jmax: jMaxMmS3 = 0"))) << r.err.toStdString();
    r = run(QStringLiteral("profile"), words("--kind s-curve --distance 10 --vmax 10"));
    EXPECT_TRUE(r.err.contains(QLatin1String("--kind 's-curve'"))) << r.err.toStdString();
    r = run(QStringLiteral("profile"), words("--distance 10 --vmax 10 --speed 3"));
    EXPECT_TRUE(r.err.contains(QLatin1String("unknown option '--speed'"))) << r.err.toStdString();
    r = run(QStringLiteral("interpolate"), words("--shape line --to 1,2,3 --step 0.1"));
    EXPECT_EQ(r.code, 1);
    EXPECT_TRUE(r.err.contains(QLatin1String("--to '1,2,3' needs 2"))) << r.err.toStdString();
}

TEST(MotionCli, InterpolateLineArcAndSine)
{
    auto r = run(QStringLiteral("interpolate"), words("--shape line --to 0.5,0.3 --step 0.1"));
    ASSERT_EQ(r.code, 0) << r.err.toStdString();
    auto json = r.json();
    EXPECT_EQ(json["steps"].toInt(), 8);
    EXPECT_LE(json["max_contour_error"].toDouble(), 0.1);
    EXPECT_NEAR(json["points"].toArray().last().toArray()[0].toDouble(), 0.5, 1e-12);

    r = run(QStringLiteral("interpolate"), words("--shape arc --start 11,1 --center 1,1 --to 1,11 --dir ccw --step 0.01"));
    ASSERT_EQ(r.code, 0) << r.err.toStdString();
    json = r.json();
    EXPECT_EQ(json["steps"].toInt(), 2000);
    EXPECT_LE(json["max_contour_error"].toDouble(), 0.01);
    const auto last = json["points"].toArray().last().toArray();
    EXPECT_NEAR(last[0].toDouble(), 1, 1e-9);
    EXPECT_NEAR(last[1].toDouble(), 11, 1e-9);

    r = run(QStringLiteral("interpolate"), words("--shape arc --start 11,1 --center 1,1 --to 1,13 --dir ccw --step 0.01"));
    EXPECT_EQ(r.code, 1);
    EXPECT_TRUE(r.err.contains(QLatin1String("--to '1,13'"))) << r.err.toStdString();

    r = run(QStringLiteral("interpolate"), words("--shape sine --amplitude 2 --wavelength 10 --length 10 --tolerance 0.01 --step 0.001"));
    ASSERT_EQ(r.code, 0) << r.err.toStdString();
    json = r.json();
    EXPECT_GT(json["chords"].toInt(), 10);
    EXPECT_LE(json["max_contour_error"].toDouble(), 0.01 + 0.002);
    EXPECT_GT(json["steps"].toInt(), 10000);
}

TEST(MotionCli, SeedStepTableAt72MHz)
{
    // Seed 001 move in steps, table at the seed's 72 MHz clock and 50 µs interrupt.
    auto r = run(QStringLiteral("steptable"),
                 words("--total-steps 2000 --start-rate 400 --top-rate 8000 --accel 40000 --plateau-steps 10"));
    ASSERT_EQ(r.code, 0) << r.err.toStdString();
    auto json = r.json();
    EXPECT_EQ(json["interrupt_ticks"].toInt(), 3600);
    EXPECT_EQ(json["steps"].toInt(), 2000);
    const auto first = json["entries"].toArray()[0].toObject();
    EXPECT_EQ(first["period_ticks"].toInt(), 180000);  // 400 Hz plateau
    EXPECT_EQ(first["whole_periods"].toInt(), 50);
    EXPECT_EQ(first["match"].toInt(), 1800);
    EXPECT_LE(json["max_whole_periods"].toInt(), 255);
    EXPECT_TRUE(json.contains(QLatin1String("seed_iteration_error")));

    r = run(QStringLiteral("steptable"), words("--kind trapezoid --distance 10 --vmax 20 --amax 200 --start-speed 1 --step 0.01"));
    ASSERT_EQ(r.code, 0) << r.err.toStdString();
    json = r.json();
    EXPECT_EQ(json["steps"].toInt(), 1000);
    EXPECT_LE(std::fabs(json["time_error"].toDouble()), 1e-8);
}

TEST(MotionCli, BlocksPlanSplitAndFrames)
{
    const auto r = run(QStringLiteral("blocks"), words("--joint 1000:1000:1000,75:-500:300 --joint 500:1000:1000"));
    ASSERT_EQ(r.code, 0) << r.err.toStdString();
    const auto json = r.json();
    const auto joint0 = json["joints"].toArray()[0].toObject();
    EXPECT_EQ(joint0["splits"].toInt(), 1);
    EXPECT_EQ(joint0["planned"].toArray().size(), 3);
    const auto frames = json["frames"].toArray();
    ASSERT_EQ(frames.size(), 3);
    EXPECT_EQ(frames[0].toString(), QStringLiteral("0A0#E8030000E803E803"));  // joint 0 block 0
    EXPECT_TRUE(frames[1].toString().startsWith(QLatin1String("0A1#")));     // interleaved: joint 1 next
    EXPECT_TRUE(frames[2].toString().startsWith(QLatin1String("0A0#")));

    const auto bad = run(QStringLiteral("blocks"), words("--joint 100:0:500"));
    EXPECT_EQ(bad.code, 2);
    EXPECT_TRUE(bad.err.contains(QLatin1String("joint 0 block 0: S = 100 microsteps is not reachable"))) << bad.err.toStdString();
    const auto garbled = run(QStringLiteral("blocks"), words("--joint 100:0"));
    EXPECT_EQ(garbled.code, 1);
    EXPECT_TRUE(garbled.err.contains(QLatin1String("block '100:0'"))) << garbled.err.toStdString();
}
