// The accuracy bench through the scripting API: its commands are methods with the CLI's
// results, files go where the client is, and what only benchpilot-cli's own process can
// do (a person typing readings, its own simulator's gauge and clock) is refused with why.
#include "api_support.h"

#include "app/api/json_rpc.h"

#include <QDir>
#include <QFile>
#include <QTimer>

using itest::ApiFixture;
using itest::ApiTestClient;

namespace {

QString lease(ApiTestClient& c)
{
    return ApiTestClient::result(c.call(QStringLiteral("control.acquire"))).value(QStringLiteral("lease")).toString();
}

TEST(ApiAccuracy, AnalyzeReadsAndWritesWhereTheClientIs)
{
    ApiFixture f(false);
    ApiTestClient c(f.path);
    QTemporaryDir work;
    ASSERT_TRUE(QFile::copy(QStringLiteral(BP_SOURCE_DIR "/resources/examples/stage-x-interferometer.readings.csv"),
                            work.filePath(QStringLiteral("x.readings.csv"))));
    c.call(QStringLiteral("client.hello"), QJsonObject{{QStringLiteral("name"), QStringLiteral("bench")}, {QStringLiteral("cwd"), work.path()}});
    const QJsonObject a = c.call(QStringLiteral("accuracy.analyze"), QJsonObject{{QStringLiteral("readings"), QStringLiteral("x.readings.csv")},
                                                                                 {QStringLiteral("out"), QStringLiteral("x.result.json")}});
    const QJsonObject r = ApiTestClient::result(a);
    EXPECT_EQ(r.value(QStringLiteral("standard")).toString(), QStringLiteral("ISO 230-2:2014")) << QJsonDocument(a).toJson().toStdString();
    EXPECT_GT(r.value(QStringLiteral("figures")).toObject().value(QStringLiteral("A")).toDouble(), 0);
    EXPECT_TRUE(QFile::exists(work.filePath(QStringLiteral("x.result.json")))) << "out is taken from the client's folder, not the GUI's";
}

TEST(ApiAccuracy, ManualReadingsAndTheClisOwnSimulatorAreRefusedWithTheReason)
{
    ApiFixture f(false, 0);
    ApiTestClient c(f.path);
    const QString token = lease(c);
    const QJsonObject base{{QStringLiteral("axis"), QStringLiteral("X")}, {QStringLiteral("targets"), QStringLiteral("20:60:5")},
                           {QStringLiteral("lease"), token}};

    QJsonObject p = base;
    p.insert(QStringLiteral("source"), QStringLiteral("manual"));
    QJsonObject a = c.call(QStringLiteral("accuracy.run"), p);
    EXPECT_EQ(ApiTestClient::errorCode(a), app::api::code::kInvalidParams);
    EXPECT_TRUE(ApiTestClient::errorMessage(a).contains(QStringLiteral("Calibration screen"))) << ApiTestClient::errorMessage(a).toStdString();

    p = base;
    p.insert(QStringLiteral("source"), QStringLiteral("gauge:sim"));
    a = c.call(QStringLiteral("accuracy.run"), p);
    EXPECT_EQ(ApiTestClient::errorCode(a), app::api::code::kInvalidParams);
    EXPECT_TRUE(ApiTestClient::errorMessage(a).contains(QStringLiteral("Calibration screen"))) << ApiTestClient::errorMessage(a).toStdString();

    for (const char* method : {"accuracy.run", "accuracy.circle"}) {
        p = QString::fromLatin1(method) == QLatin1String("accuracy.run") ? base
                                                                        : QJsonObject{{QStringLiteral("radius"), 2}, {QStringLiteral("lease"), token}};
        p.insert(QStringLiteral("time_scale"), 20);
        a = c.call(QString::fromLatin1(method), p);
        EXPECT_EQ(ApiTestClient::errorCode(a), app::api::code::kInvalidParams) << method;
        EXPECT_EQ(a.value(QStringLiteral("error")).toObject().value(QStringLiteral("data")).toObject().value(QStringLiteral("field")).toString(),
                  QStringLiteral("time_scale"))
            << method << ": the GUI's simulator keeps its pace";
    }
    // Nothing moved: the refusals came before any motion.
    EXPECT_FALSE(f.stage.proxy.status().anyMoving());
}

TEST(ApiAccuracy, ARunOnAnAxisHomedBeforeWaitsForItsNewHomingToEnd)
{
    // home: true on an axis that is already homed used to take the last status (homed,
    // still) for the end of the new homing and send the first move into it: refused busy.
    ApiFixture f(false, 0);
    f.stage.link.host().setTimeScale(20);
    ApiTestClient c(f.path);
    QTemporaryDir work;
    c.call(QStringLiteral("client.hello"), QJsonObject{{QStringLiteral("name"), QStringLiteral("bench")}, {QStringLiteral("cwd"), work.path()}});
    const QString token = lease(c);
    QTimer beat;  // the lease lives on heartbeats
    QObject::connect(&beat, &QTimer::timeout, [&] { c.send(QStringLiteral("control.heartbeat"), QJsonObject{{QStringLiteral("lease"), token}}); });
    beat.start(100);
    const QJsonObject home =
        c.call(QStringLiteral("device.home"), QJsonObject{{QStringLiteral("lease"), token}}, 60000);
    ASSERT_FALSE(home.contains(QStringLiteral("error"))) << QJsonDocument(home).toJson().toStdString();
    const QJsonObject a = c.call(QStringLiteral("accuracy.run"),
                                 QJsonObject{{QStringLiteral("axis"), QStringLiteral("X")}, {QStringLiteral("targets"), QStringLiteral("20:60:5")},
                                             {QStringLiteral("cycles"), 2}, {QStringLiteral("dwell"), 0.1}, {QStringLiteral("home"), true},
                                             {QStringLiteral("out"), QStringLiteral("run")}, {QStringLiteral("lease"), token}},
                                 120000);
    ASSERT_FALSE(a.contains(QStringLiteral("error"))) << QJsonDocument(a).toJson().toStdString();
    EXPECT_EQ(ApiTestClient::result(a).value(QStringLiteral("cycles")).toInt(), 2);
    EXPECT_TRUE(QDir(work.filePath(QStringLiteral("run"))).exists());
    // Its progress came apart from its one result object: a call.progress per reading,
    // the last one all 20 (5 targets × 2 cycles × 2 directions).
    int last = -1, count = 0;
    for (const auto& n : c.notifications)
        if (n.value(QStringLiteral("method")).toString() == QLatin1String("call.progress")) {
            const QJsonObject data = n.value(QStringLiteral("params")).toObject().value(QStringLiteral("data")).toObject();
            if (!data.contains(QStringLiteral("readings_taken")))
                continue;
            EXPECT_EQ(data.value(QStringLiteral("readings")).toInt(), 20);
            EXPECT_GE(data.value(QStringLiteral("readings_taken")).toInt(), last) << "in order";
            last = data.value(QStringLiteral("readings_taken")).toInt();
            ++count;
        }
    EXPECT_GE(count, 10);
    EXPECT_EQ(last, 20);
}

} // namespace
