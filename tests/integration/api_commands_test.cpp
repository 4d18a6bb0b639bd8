// The API's methods are benchpilot-cli's commands: the same parameters and exactly the
// same JSON results (one schema for both), run inside the server without nesting an
// event loop.
#include "api_support.h"
#include "cli_in_process.h"

#include "app/api/command_methods.h"
#include "app/api/json_rpc.h"

using itest::ApiFixture;
using itest::ApiTestClient;

namespace {

QJsonObject withoutDeviceTime(QJsonObject o) { return o; }

TEST(ApiCommands, EveryOfferedCommandIsAMethodAndDiscoverListsItWithItsParameters)
{
    ApiFixture f(false);
    ApiTestClient c(f.path);
    const QJsonObject doc = ApiTestClient::result(c.call(QStringLiteral("rpc.discover")));
    QStringList listed;
    for (const QJsonValue& m : doc.value(QStringLiteral("methods")).toArray())
        listed << m.toObject().value(QStringLiteral("name")).toString();
    for (const auto& m : app::api::commandMethods())
        EXPECT_TRUE(listed.contains(m.method)) << m.method.toStdString();
    for (const char* builtin : {"rpc.discover", "control.acquire", "control.release", "control.heartbeat", "subscribe", "cli.run"})
        EXPECT_TRUE(listed.contains(QString::fromLatin1(builtin))) << builtin;
    EXPECT_FALSE(listed.contains(QStringLiteral("completion"))) << "a shell's business";
    for (const char* m : {"device.info", "device.status", "device.home", "device.move", "device.jog", "device.stop", "device.estop",
                          "device.reset", "recipe.validate", "recipe.plan", "recipe.run", "pattern.plan", "pattern.run", "scan.plan",
                          "scan.run", "tuning.step_test", "tuning.tune"})
        EXPECT_TRUE(listed.contains(QString::fromLatin1(m))) << m;
    // device.move: its targets, typed, and the lease it needs.
    for (const QJsonValue& m : doc.value(QStringLiteral("methods")).toArray())
        if (m.toObject().value(QStringLiteral("name")).toString() == QLatin1String("device.move")) {
            QStringList params;
            for (const QJsonValue& p : m.toObject().value(QStringLiteral("params")).toArray())
                params << p.toObject().value(QStringLiteral("name")).toString();
            EXPECT_EQ(params, (QStringList{QStringLiteral("targets"), QStringLiteral("relative"), QStringLiteral("speed"),
                                           QStringLiteral("instrument"), QStringLiteral("timeout"), QStringLiteral("lease")}));
            EXPECT_EQ(m.toObject().value(QStringLiteral("x-access")).toString(), QStringLiteral("control"));
        }
}

TEST(ApiCommands, DeviceStatusIsTheClisJsonObject)
{
    ApiFixture f(false);
    ApiTestClient c(f.path);
    const QJsonObject api = ApiTestClient::result(c.call(QStringLiteral("device.status")));
    const itest::CliResult cli = itest::runCliInProcess(itest::splitWords("--sim stage --json status"));
    ASSERT_EQ(cli.code, 0);
    EXPECT_EQ(api.keys(), cli.json().keys());
    EXPECT_EQ(api.value(QStringLiteral("axes")).toObject().keys(), cli.json().value(QStringLiteral("axes")).toObject().keys());
    EXPECT_EQ(api.value(QStringLiteral("axes")).toObject().value(QStringLiteral("X")).toObject().keys(),
              cli.json().value(QStringLiteral("axes")).toObject().value(QStringLiteral("X")).toObject().keys());
    EXPECT_EQ(withoutDeviceTime(api), withoutDeviceTime(cli.json())) << "a fresh simulated stage reads the same";
}

TEST(ApiCommands, AComputingCommandGivesExactlyTheClisResult)
{
    ApiFixture f(false);
    ApiTestClient c(f.path);
    const QJsonObject api = ApiTestClient::result(
        c.call(QStringLiteral("motion.profile"), QJsonObject{{QStringLiteral("kind"), QStringLiteral("trapezoid")},
                                                             {QStringLiteral("distance"), QJsonArray{2}},
                                                             {QStringLiteral("vmax"), 10},
                                                             {QStringLiteral("amax"), 100},
                                                             {QStringLiteral("dt"), 0.1}}));
    const itest::CliResult cli =
        itest::runCliInProcess(itest::splitWords("profile --kind trapezoid --distance 2 --vmax 10 --amax 100 --dt 0.1"));
    ASSERT_EQ(cli.code, 0) << cli.err.toStdString();
    EXPECT_FALSE(api.isEmpty());
    EXPECT_EQ(api, cli.json());
}

TEST(ApiCommands, RelativePathsStartWhereTheClientSaysItIs)
{
    ApiFixture f(false);
    ApiTestClient c(f.path);
    c.call(QStringLiteral("client.hello"), QJsonObject{{QStringLiteral("name"), QStringLiteral("paths")},
                                                       {QStringLiteral("cwd"), QStringLiteral(BP_SOURCE_DIR)}});
    const QJsonObject a = c.call(QStringLiteral("recipe.validate"),
                                 QJsonObject{{QStringLiteral("file"), QStringLiteral("resources/examples/reagent-transfer.recipe.json")},
                                             {QStringLiteral("calibration"), QStringLiteral("none")}});
    const QJsonObject r = ApiTestClient::result(a);
    EXPECT_TRUE(r.value(QStringLiteral("ok")).toBool()) << QJsonDocument(a).toJson().toStdString();
    EXPECT_GT(r.value(QStringLiteral("ops")).toInt(), 0);
}

TEST(ApiCommands, ARecipeThatDoesNotValidateIsInvalidParamsWithEveryProblem)
{
    ApiFixture f(false);
    ApiTestClient c(f.path);
    QTemporaryDir dir;
    QFile bad(dir.filePath(QStringLiteral("bad.recipe.json")));
    ASSERT_TRUE(bad.open(QIODevice::WriteOnly));
    bad.write("{\"schema\": \"benchpilot.recipe\", \"version\": 1, \"steps\": 3}\n");
    bad.close();
    const QJsonObject a = c.call(QStringLiteral("recipe.plan"), QJsonObject{{QStringLiteral("file"), bad.fileName()},
                                                                           {QStringLiteral("calibration"), QStringLiteral("none")}});
    EXPECT_EQ(ApiTestClient::errorCode(a), app::api::code::kInvalidParams);
    EXPECT_FALSE(ApiTestClient::errorMessage(a).isEmpty());
}

TEST(ApiCommands, WithBothInstrumentsConnectedTheCallMustSayWhich)
{
    ApiFixture f(true);
    ApiTestClient c(f.path);
    QJsonObject a = c.call(QStringLiteral("device.status"));
    EXPECT_EQ(ApiTestClient::errorCode(a), app::api::code::kInvalidParams);
    EXPECT_TRUE(ApiTestClient::errorMessage(a).contains(QStringLiteral("instrument analyzer|stage"))) << ApiTestClient::errorMessage(a).toStdString();
    a = c.call(QStringLiteral("device.status"), QJsonObject{{QStringLiteral("instrument"), QStringLiteral("analyzer")}});
    EXPECT_EQ(ApiTestClient::result(a).value(QStringLiteral("instrument")).toString(), QStringLiteral("analyzer"));
    a = c.call(QStringLiteral("device.status"), QJsonObject{{QStringLiteral("instrument"), QStringLiteral("laser")}});
    EXPECT_EQ(ApiTestClient::errorCode(a), app::api::code::kInvalidParams);
}

TEST(ApiCommands, AWaitingCallLetsTheServerAnswerOthersMeanwhile)
{
    // A timed jog waits for seconds inside the command; the event loop (and another
    // client's status call) goes on: the call runs on a fiber, not a nested loop.
    ApiFixture f(false);
    ApiTestClient script(f.path);
    ApiTestClient watcher(f.path);
    const QString lease = ApiTestClient::result(script.call(QStringLiteral("control.acquire"), QJsonObject{{QStringLiteral("client"), QStringLiteral("jogger")}}))
                              .value(QStringLiteral("lease")).toString();
    ASSERT_FALSE(lease.isEmpty());
    script.send(QStringLiteral("device.jog"),
                QJsonObject{{QStringLiteral("axis"), QStringLiteral("X")}, {QStringLiteral("velocity"), 1}, {QStringLiteral("seconds"), 1.5},
                            {QStringLiteral("lease"), lease}},
                77);
    // Keep the lease alive while it runs, as a client's heartbeat thread does.
    QTimer beat;
    QObject::connect(&beat, &QTimer::timeout, [&] { script.send(QStringLiteral("control.heartbeat"), QJsonObject{{QStringLiteral("lease"), lease}}); });
    beat.start(100);
    ASSERT_TRUE(itest::waitFor([&] { return f.stage.proxy.status().anyMoving(); }, 5000));
    const QJsonObject during = watcher.call(QStringLiteral("device.status"));
    EXPECT_TRUE(ApiTestClient::result(during).value(QStringLiteral("axes")).toObject().value(QStringLiteral("X")).toObject().value(QStringLiteral("moving")).toBool())
        << "answered while the jog runs";
    const QJsonObject done = script.waitAnswer(77);
    EXPECT_TRUE(done.contains(QStringLiteral("result"))) << QJsonDocument(done).toJson().toStdString();
    EXPECT_GT(ApiTestClient::result(done).value(QStringLiteral("axes")).toObject().value(QStringLiteral("X")).toObject().value(QStringLiteral("position")).toDouble(), 0.5);
}

} // namespace
