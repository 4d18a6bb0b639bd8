// benchpilot-cli with a camera: a scan killed with SIGKILL mid-run and started again ends
// with every tile's image present and whole, none logged twice; camera list and snap; bad
// sources named.
#include "device/camera/tile_tiff.h"
#include "device/files/scan_run_log.h"
#include "device/files/text_file.h"

#include "integration/programs.h"
#include "integration/wait.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <set>

using namespace itest;

namespace {

QStringList planArgs()
{
    // 4 × 3 tiles of 256 × 256 px at 1 µm.
    return {QStringLiteral("scan"), QStringLiteral("plan"), QStringLiteral("--roi"), QStringLiteral("20,20,20.7,20.5"),
            QStringLiteral("--sensor"), QStringLiteral("256,256"), QStringLiteral("--sensor-um"), QStringLiteral("10"),
            QStringLiteral("--mag"), QStringLiteral("10"), QStringLiteral("--overlap"), QStringLiteral("0.15")};
}

} // namespace

TEST(CameraCli, AScanKilledMidRunEndsWithEveryImageWholeAndNoneTwice)
{
    QTemporaryDir dir;
    const QString plan = dir.filePath(QStringLiteral("p.scan.json"));
    const QString out = dir.filePath(QStringLiteral("run"));
    const auto made = runProgram(binary("benchpilot-cli"), planArgs());
    ASSERT_EQ(made.exitCode, 0) << made.describe();
    motion::msg::Message error;
    ASSERT_TRUE(dev::files::writeAtomically(plan, made.out.toStdString(), &error));
    const QStringList runArgs = {QStringLiteral("--sim"), QStringLiteral("stage"), QStringLiteral("--json"), QStringLiteral("scan"),
                                 QStringLiteral("run"), plan, QStringLiteral("--out"), out, QStringLiteral("--home"),
                                 QStringLiteral("--camera"), QStringLiteral("sim")};
    {
        QProcess p;
        p.start(binary("benchpilot-cli"), runArgs);
        ASSERT_TRUE(p.waitForStarted());
        QByteArray seen;
        ASSERT_TRUE(waitFor(
            [&] {
                seen += p.readAllStandardOutput();
                return seen.count("\"image\"") >= 5;
            },
            90000))
            << seen.toStdString();
        p.kill();  // SIGKILL: no goodbye
        p.waitForFinished();
    }
    const auto again = runProgram(binary("benchpilot-cli"), runArgs, 120000);
    ASSERT_EQ(again.exitCode, 0) << again.describe();
    EXPECT_TRUE(again.out.contains(QStringLiteral("\"tile\":12"))) << again.out.toStdString();
    EXPECT_LE(again.out.count(QStringLiteral("\"image\"")), 12 - 5) << "the run continued: " << again.out.toStdString();

    std::string text;
    ASSERT_TRUE(dev::files::readText(QDir(out).filePath(QLatin1String(dev::files::scan::kRunLogFile)), &text, &error));
    const auto log = dev::files::scan::parseRunLog(text);
    ASSERT_TRUE(log.log);
    ASSERT_EQ(log.log->records.size(), 12u) << text;
    std::set<int> tiles;
    for (std::size_t i = 0; i < log.log->records.size(); ++i) {
        tiles.insert(log.log->records[i].target);
        const auto& image = log.log->images[i];
        EXPECT_EQ(dev::camera::fileSha256(QDir(out).filePath(QString::fromStdString(image.file)).toStdString()).value_or(""), image.sha256)
            << image.file;
    }
    EXPECT_EQ(tiles.size(), 12u) << "each tile once";
    EXPECT_EQ(QDir(out).entryList({QStringLiteral("*.part")}, QDir::Files).size(), 0) << "no temporary file left";
    QStringList images = QDir(out).entryList({QStringLiteral("*.tif")}, QDir::Files);
    EXPECT_TRUE(images.removeOne(QStringLiteral("mosaic.ome.tif"))) << "the scan stitches as it goes: " << images.join(QLatin1Char(' ')).toStdString();
    EXPECT_EQ(images.size(), 12) << images.join(QLatin1Char(' ')).toStdString();
}

TEST(CameraCli, SnapWritesATileAndBadSourcesAreNamed)
{
    QTemporaryDir dir;
    const QString file = dir.filePath(QStringLiteral("plate.tif"));
    const auto snap = runProgram(binary("benchpilot-cli"), {QStringLiteral("--sim"), QStringLiteral("stage"), QStringLiteral("--json"),
                                                            QStringLiteral("camera"), QStringLiteral("snap"), QStringLiteral("--camera"),
                                                            QStringLiteral("sim"), QStringLiteral("--specimen"), QStringLiteral("grid-plate"),
                                                            QStringLiteral("--out"), file, QStringLiteral("--exposure-ms"), QStringLiteral("5")});
    ASSERT_EQ(snap.exitCode, 0) << snap.describe();
    EXPECT_TRUE(snap.out.contains(QStringLiteral("\"width\":2048"))) << snap.out.toStdString();
    dev::camera::Frame f;
    std::string description;
    motion::msg::Message error;
    ASSERT_TRUE(dev::camera::readTiff(file.toStdString(), &f, &description, &error));
    EXPECT_EQ(f.width, 2048);
    EXPECT_NE(description.find("\"exposure_ms\":5"), std::string::npos) << description;

    for (const char* bad : {"bogus", "folder:"}) {
        const auto r = runProgram(binary("benchpilot-cli"), {QStringLiteral("--sim"), QStringLiteral("stage"), QStringLiteral("camera"),
                                                             QStringLiteral("snap"), QStringLiteral("--camera"), QLatin1String(bad),
                                                             QStringLiteral("--out"), dir.filePath(QStringLiteral("x.tif"))});
        EXPECT_EQ(r.exitCode, 1) << bad << ": " << r.describe();
        EXPECT_TRUE(r.err.contains(QLatin1String(bad))) << "the message names what was typed: " << r.describe();
        EXPECT_FALSE(QFile::exists(dir.filePath(QStringLiteral("x.tif"))));
    }
    const auto list = runProgram(binary("benchpilot-cli"), {QStringLiteral("--json"), QStringLiteral("camera"), QStringLiteral("list")});
    ASSERT_EQ(list.exitCode, 0) << list.describe();
    EXPECT_TRUE(list.out.contains(QStringLiteral("\"grid-plate\""))) << list.out.toStdString();
}
