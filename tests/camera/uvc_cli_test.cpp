// benchpilot-cli with a USB camera on a machine without one: `camera list` says uvc is
// available and lists the cameras found (none here) in the same JSON the API's camera.list
// returns; `camera snap --camera uvc:NAME` fails at once naming the camera, writes nothing
// and does not wait for a frame that will never come.
#if BP_WITH_UVC
#include "integration/programs.h"

#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>

#include <gtest/gtest.h>

using namespace itest;

TEST(UvcCli, ListMarksUsbCamerasAvailableAndListsTheCamerasFound)
{
    const auto list = runProgram(binary("benchpilot-cli"), {QStringLiteral("--json"), QStringLiteral("camera"), QStringLiteral("list")});
    ASSERT_EQ(list.exitCode, 0) << list.describe();
    const QJsonObject o = QJsonDocument::fromJson(list.out.toUtf8()).object();
    bool uvcAvailable = false;
    for (const auto& v : o.value(QStringLiteral("sources")).toArray())
        if (v.toObject().value(QStringLiteral("source")).toString() == QStringLiteral("uvc[:NAME]"))
            uvcAvailable = v.toObject().value(QStringLiteral("available")).toBool();
    EXPECT_TRUE(uvcAvailable) << list.out.toStdString();
    ASSERT_TRUE(o.value(QStringLiteral("cameras")).isArray()) << list.out.toStdString();
    for (const auto& v : o.value(QStringLiteral("cameras")).toArray()) {  // none on a machine without a webcam
        const QJsonObject c = v.toObject();
        EXPECT_TRUE(c.value(QStringLiteral("source")).toString().startsWith(QStringLiteral("uvc:")));
        EXPECT_TRUE(c.value(QStringLiteral("formats")).isArray());
    }
    const auto text = runProgram(binary("benchpilot-cli"), {QStringLiteral("camera"), QStringLiteral("list")});
    ASSERT_EQ(text.exitCode, 0) << text.describe();
    EXPECT_TRUE(text.out.contains(QStringLiteral("USB cameras"))) << text.out.toStdString();
    const QStringList lines = text.out.split(QLatin1Char('\n'));
    const auto uvcLine = std::find_if(lines.begin(), lines.end(), [](const QString& l) { return l.startsWith(QStringLiteral("uvc[:NAME]")); });
    ASSERT_NE(uvcLine, lines.end()) << text.out.toStdString();
    EXPECT_FALSE(uvcLine->contains(QStringLiteral("not in this build"))) << uvcLine->toStdString();
}

TEST(UvcCli, ASnapFromACameraThatIsNotThereFailsAtOnceAndWritesNothing)
{
    QTemporaryDir dir;
    const QString file = dir.filePath(QStringLiteral("x.tif"));
    const QString source = QStringLiteral("uvc:BenchPilot test camera that is not there");
    // Far below the snap's own wait for a frame (tens of seconds): the failure does not wait for one.
    const auto r = runProgram(binary("benchpilot-cli"), {QStringLiteral("--sim"), QStringLiteral("stage"), QStringLiteral("camera"), QStringLiteral("snap"),
                                                         QStringLiteral("--camera"), source, QStringLiteral("--out"), file},
                              15000);
    ASSERT_TRUE(r.finished) << "camera snap waited for a camera that is not there: " << r.describe();
    EXPECT_EQ(r.exitCode, 2) << r.describe();
    EXPECT_TRUE(r.err.contains(source)) << "the message names the camera asked for: " << r.describe();
    EXPECT_TRUE(r.err.contains(QStringLiteral("no USB camera")) || r.err.contains(QStringLiteral("the cameras found are"))) << r.describe();
    EXPECT_FALSE(QFile::exists(file));
}

TEST(UvcCli, AScanWithACameraThatIsNotThereStopsBeforeItStartsAndWritesNothing)
{
    QTemporaryDir dir;
    const auto plan = runProgram(binary("benchpilot-cli"), {QStringLiteral("scan"), QStringLiteral("plan"), QStringLiteral("--roi"),
                                                            QStringLiteral("20,20,20.7,20.5"), QStringLiteral("--sensor"), QStringLiteral("256,256"),
                                                            QStringLiteral("--sensor-um"), QStringLiteral("10"), QStringLiteral("--mag"), QStringLiteral("10")});
    ASSERT_EQ(plan.exitCode, 0) << plan.describe();
    const QString planFile = dir.filePath(QStringLiteral("p.scan.json"));
    {
        QFile f(planFile);
        ASSERT_TRUE(f.open(QIODevice::WriteOnly));
        f.write(plan.out.toUtf8());
    }
    const QString out = dir.filePath(QStringLiteral("run"));
    const QString source = QStringLiteral("uvc:BenchPilot test camera that is not there");
    const auto r = runProgram(binary("benchpilot-cli"), {QStringLiteral("--sim"), QStringLiteral("stage"), QStringLiteral("scan"), QStringLiteral("run"), planFile,
                                                         QStringLiteral("--out"), out, QStringLiteral("--home"), QStringLiteral("--camera"), source},
                              30000);
    ASSERT_TRUE(r.finished) << r.describe();
    EXPECT_EQ(r.exitCode, 2) << r.describe();
    EXPECT_TRUE(r.err.contains(source)) << r.describe();
    EXPECT_FALSE(QFileInfo::exists(out)) << "no run folder, no run log: the run never started";
}

#endif // BP_WITH_UVC
