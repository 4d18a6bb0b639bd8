// benchpilot-cli scan run with a camera stitches as the tiles come: after the last tile
// the four files the Mosaic tab writes are in the folder, placed as a later `stitch` of the
// folder places them; a scan killed part-way leaves no mosaic, and the same command again
// continues it and stitches it whole; a plan with a mirrored, turned camera is told which
// setting to change when the scan ends.
#include "device/files/text_file.h"

#include "integration/programs.h"
#include "integration/wait.h"

#include <QDir>
#include <QFile>
#include <QImage>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <Eigen/Core>

#include <map>

using namespace itest;

namespace {

const char* const kMosaicFiles[] = {"mosaic.ome.tif", "TileConfiguration.registered.txt", "mosaic.stitch.json", "quality-map.png"};

/// 4 × 3 tiles of 256 × 256 px at 1 µm, 15 % overlap, quick moves: a textured part of the
/// simulated slide with the camera's seed 11 (every pair trusted).
QString liveStitchPlan(const QTemporaryDir& dir)
{
    const auto made = runProgram(binary("benchpilot-cli"),
                                 {QStringLiteral("scan"), QStringLiteral("plan"), QStringLiteral("--roi"), QStringLiteral("20,20,20.7,20.5"),
                                  QStringLiteral("--sensor"), QStringLiteral("256,256"), QStringLiteral("--sensor-um"), QStringLiteral("10"),
                                  QStringLiteral("--mag"), QStringLiteral("10"), QStringLiteral("--overlap"), QStringLiteral("0.15"),
                                  QStringLiteral("--speed"), QStringLiteral("10"), QStringLiteral("--settle"), QStringLiteral("0.02"),
                                  QStringLiteral("--exposure"), QStringLiteral("0.01")});
    EXPECT_EQ(made.exitCode, 0) << made.describe();
    const QString plan = dir.filePath(QStringLiteral("p.scan.json"));
    motion::msg::Message error;
    EXPECT_TRUE(dev::files::writeAtomically(plan, made.out.toStdString(), &error));
    return plan;
}

/// The --json lines that hold `key`.
std::vector<QJsonObject> linesWith(const QString& out, const char* key)
{
    std::vector<QJsonObject> found;
    for (const QString& line : out.split(QLatin1Char('\n'), Qt::SkipEmptyParts)) {
        const QJsonObject o = QJsonDocument::fromJson(line.toUtf8()).object();
        if (o.contains(QLatin1String(key)))
            found.push_back(o);
    }
    return found;
}

/// Each tile's registered top-left from a stitch report (JSON text).
std::map<QString, Eigen::Vector2d> registeredPx(const QByteArray& report)
{
    std::map<QString, Eigen::Vector2d> out;
    const QJsonObject o = QJsonDocument::fromJson(report.mid(report.indexOf('{'))).object();
    for (const QJsonValue& t : o.value(QStringLiteral("tiles")).toArray()) {
        const QJsonArray p = t.toObject().value(QStringLiteral("registered_px")).toArray();
        out[t.toObject().value(QStringLiteral("file")).toString()] = Eigen::Vector2d(p.at(0).toDouble(), p.at(1).toDouble());
    }
    return out;
}

QByteArray readAll(const QString& path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

} // namespace

TEST(ScanLiveStitchCli, AKillMidScanLeavesNoMosaicAndTheRunAgainStitchesItAsAStitchOfTheFolderDoes)
{
    QTemporaryDir dir;
    const QString plan = liveStitchPlan(dir);
    const QString out = dir.filePath(QStringLiteral("run"));
    const QStringList runArgs = {QStringLiteral("--sim"), QStringLiteral("stage"), QStringLiteral("--json"), QStringLiteral("scan"),
                                 QStringLiteral("run"), plan, QStringLiteral("--out"), out, QStringLiteral("--home"),
                                 QStringLiteral("--camera"), QStringLiteral("sim"), QStringLiteral("--camera-seed"), QStringLiteral("11")};
    {
        QProcess p;
        p.start(binary("benchpilot-cli"), runArgs);
        ASSERT_TRUE(p.waitForStarted());
        QByteArray seen;
        ASSERT_TRUE(waitFor(
            [&] {
                seen += p.readAllStandardOutput();
                return seen.count("\"pair\"") >= 3 && seen.count("\"image\"") >= 6;
            },
            90000))
            << seen.toStdString();
        p.kill();  // SIGKILL mid-scan, pairs already registered
        p.waitForFinished();
    }
    for (const char* name : kMosaicFiles)
        EXPECT_FALSE(QFile::exists(QDir(out).filePath(QLatin1String(name)))) << name << " after a kill";
    EXPECT_TRUE(QDir(out).entryList({QStringLiteral("mosaic*")}, QDir::Files).isEmpty()) << "not even a partial mosaic";

    const auto again = runProgram(binary("benchpilot-cli"), runArgs, 120000);
    ASSERT_EQ(again.exitCode, 0) << again.describe();
    EXPECT_LE(again.out.count(QStringLiteral("\"image\"")), 12 - 6) << "the scan continued: " << again.out.toStdString();
    // Every pair is registered in this run: the earlier tiles are read back from the folder.
    EXPECT_EQ(linesWith(again.out, "pair").size(), 17u) << again.out.toStdString();
    const auto stitched = linesWith(again.out, "stitched");
    ASSERT_EQ(stitched.size(), 1u) << again.out.toStdString();
    const QJsonObject s = stitched.front().value(QStringLiteral("stitched")).toObject();
    EXPECT_EQ(s.value(QStringLiteral("tiles")).toInt(), 12);
    EXPECT_TRUE(s.value(QStringLiteral("live")).toBool());
    EXPECT_EQ(s.value(QStringLiteral("pairs_trusted")).toInt(), 17) << again.out.toStdString();
    EXPECT_TRUE(s.value(QStringLiteral("camera_check")).toArray().isEmpty()) << "the plan's camera is the simulated one";
    const QJsonArray files = s.value(QStringLiteral("files")).toArray();
    ASSERT_EQ(files.size(), 4) << again.out.toStdString();
    for (int i = 0; i < 4; ++i) {
        EXPECT_EQ(QFileInfo(files.at(i).toString()).fileName(), QLatin1String(kMosaicFiles[i]));
        EXPECT_TRUE(QFile::exists(QDir(out).filePath(QLatin1String(kMosaicFiles[i])))) << kMosaicFiles[i];
    }
    EXPECT_FALSE(QImage(QDir(out).filePath(QStringLiteral("quality-map.png"))).isNull());

    // The same positions as a stitch of the folder afterwards.
    const auto later = runProgram(binary("benchpilot-cli"), {QStringLiteral("--json"), QStringLiteral("stitch"), out, QStringLiteral("--plan"), plan,
                                                             QStringLiteral("--out"), QDir(out).filePath(QStringLiteral("later.ome.tif"))},
                                  120000);
    ASSERT_EQ(later.exitCode, 0) << later.describe();
    const auto live = registeredPx(readAll(QDir(out).filePath(QStringLiteral("mosaic.stitch.json"))));
    const auto batch = registeredPx(later.out.toUtf8());
    ASSERT_EQ(live.size(), 12u);
    ASSERT_EQ(batch.size(), 12u);
    for (const auto& [file, p] : batch) {
        ASSERT_TRUE(live.count(file)) << file.toStdString();
        EXPECT_LT((live.at(file) - p).norm(), 0.05) << file.toStdString();
    }
}

TEST(ScanLiveStitchCli, APlanWithAMirroredTurnedCameraIsToldAfterTheScanAndNoStitchStitchesNothing)
{
    QTemporaryDir dir;
    const QString plan = liveStitchPlan(dir);
    const QString out = dir.filePath(QStringLiteral("run"));
    // The simulated camera truly mirrored and turned 1°; the plan says neither.
    const QStringList scanArgs = {QStringLiteral("--sim"),   QStringLiteral("stage"), QStringLiteral("scan"),         QStringLiteral("run"),
                                  plan,                      QStringLiteral("--out"), out,                            QStringLiteral("--camera"),
                                  QStringLiteral("sim"),     QStringLiteral("--camera-seed"), QStringLiteral("11"), QStringLiteral("--camera-true"),
                                  QStringLiteral("mirror,rotation-deg=1")};
    const auto run = runProgram(binary("benchpilot-cli"), QStringList{QStringLiteral("--json")} + scanArgs + QStringList{QStringLiteral("--home")}, 180000);
    ASSERT_EQ(run.exitCode, 0) << run.describe();
    const auto stitched = linesWith(run.out, "stitched");
    ASSERT_EQ(stitched.size(), 1u) << run.out.toStdString();
    const QJsonObject s = stitched.front().value(QStringLiteral("stitched")).toObject();
    const QJsonArray check = s.value(QStringLiteral("camera_check")).toArray();
    EXPECT_TRUE(check.contains(QStringLiteral("imaging.camera_check.mirrored"))) << run.out.toStdString();
    EXPECT_TRUE(check.contains(QStringLiteral("imaging.camera_check.rotated"))) << run.out.toStdString();
    EXPECT_EQ(s.value(QStringLiteral("camera_advice")).toArray().size(), check.size());
    // The report says which plan settings to change, as Stitch's does.
    const QJsonObject report = QJsonDocument::fromJson(readAll(QDir(out).filePath(QStringLiteral("mosaic.stitch.json")))).object();
    const QJsonArray change = report.value(QStringLiteral("camera_check")).toObject().value(QStringLiteral("change")).toArray();
    EXPECT_TRUE(change.contains(QStringLiteral("camera.image_y")));
    EXPECT_TRUE(change.contains(QStringLiteral("camera.rotation_deg")));

    // Every tile taken and the mosaic gone (a kill between the last tile and the files):
    // --no-stitch leaves it so; the command without it stitches the folder, in words.
    for (const char* name : kMosaicFiles)
        ASSERT_TRUE(QFile::remove(QDir(out).filePath(QLatin1String(name)))) << name;
    const auto none = runProgram(binary("benchpilot-cli"), scanArgs + QStringList{QStringLiteral("--no-stitch")});
    ASSERT_EQ(none.exitCode, 0) << none.describe();
    for (const char* name : kMosaicFiles)
        EXPECT_FALSE(QFile::exists(QDir(out).filePath(QLatin1String(name)))) << name << " with --no-stitch";
    const auto folder = runProgram(binary("benchpilot-cli"), scanArgs, 120000);
    ASSERT_EQ(folder.exitCode, 0) << folder.describe();
    for (const char* name : kMosaicFiles)
        EXPECT_TRUE(QFile::exists(QDir(out).filePath(QLatin1String(name)))) << name;
    EXPECT_TRUE(folder.out.contains(QStringLiteral("12 tiles, 17 pairs"))) << folder.out.toStdString();
    EXPECT_TRUE(folder.out.contains(QStringLiteral("image y to stage-plus-y"))) << "the camera check in words: " << folder.out.toStdString();
}
