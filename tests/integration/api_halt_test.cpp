// A halt is never refused for want of saying which instrument (docs/api.md, "Control"):
// with the analyzer and the stage both connected, device.estop and device.stop naming
// none halt every connected instrument, as the GUI's E-stop button and Esc do, and
// their answer says which. The same through benchpilot-cli --attach, where
// --instrument (or the older --sim) names one of the GUI's instruments.
#include "api_support.h"
#include "cli_in_process.h"
#include "programs.h"

#include "app/api/json_rpc.h"

#include <QProcess>

using itest::ApiFixture;
using itest::ApiTestClient;

namespace {

/// Runs benchpilot-cli while this process's event loop serves the API.
itest::ProgramRun runCliBeside(const QStringList& args)
{
    QProcess p;
    p.start(itest::binary("benchpilot-cli"), args);
    itest::ProgramRun r;
    if (!p.waitForStarted(10000))
        return r;
    return itest::collectRun(p, itest::waitFor([&] { return p.state() == QProcess::NotRunning; }, 60000));
}

QStringList names(const QJsonValue& array)
{
    QStringList out;
    for (const QJsonValue& v : array.toArray())
        out << v.toString();
    return out;
}

/// Starts a held jog of X on `sim` for a client that holds the lease (a machine in motion to halt).
void startJog(ApiTestClient& c, const QString& lease, const char* instrument)
{
    const QJsonObject a = c.call(QStringLiteral("device.jog"), QJsonObject{{QStringLiteral("instrument"), QString::fromLatin1(instrument)},
                                                                           {QStringLiteral("axis"), QStringLiteral("X")},
                                                                           {QStringLiteral("velocity"), 2},
                                                                           {QStringLiteral("lease"), lease}});
    ASSERT_TRUE(a.contains(QStringLiteral("result"))) << QJsonDocument(a).toJson().toStdString();
}

TEST(ApiHalt, AnEStopNamingNoInstrumentLatchesEveryConnectedOneAndSaysWhich)
{
    ApiFixture f;
    ASSERT_TRUE(f.analyzer && f.analyzer->proxy.isReady() && f.stage.proxy.isReady());
    ApiTestClient script(f.path), other(f.path);
    const QString lease = ApiTestClient::result(script.call(QStringLiteral("control.acquire"))).value(QStringLiteral("lease")).toString();
    QTimer beat;
    QObject::connect(&beat, &QTimer::timeout, [&] { script.send(QStringLiteral("control.heartbeat"), QJsonObject{{QStringLiteral("lease"), lease}}); });
    beat.start(100);
    startJog(script, lease, "stage");
    startJog(script, lease, "analyzer");
    ASSERT_TRUE(itest::waitFor([&] { return f.stage.proxy.status().axes.value(0).moving && f.analyzer->proxy.status().axes.value(0).moving; }, 5000));

    // From a client without the lease, naming nothing: both machines latch.
    const QJsonObject a = other.call(QStringLiteral("device.estop"));
    ASSERT_TRUE(a.contains(QStringLiteral("result"))) << "never refused: " << QJsonDocument(a).toJson().toStdString();
    const QJsonObject r = ApiTestClient::result(a);
    EXPECT_EQ(names(r.value(QStringLiteral("halted"))), (QStringList{QStringLiteral("analyzer"), QStringLiteral("stage")}));
    const QJsonArray statuses = r.value(QStringLiteral("instruments")).toArray();
    ASSERT_EQ(statuses.size(), 2);
    for (const QJsonValue& s : statuses)
        EXPECT_TRUE(s.toObject().value(QStringLiteral("estop")).toBool()) << s.toObject().value(QStringLiteral("instrument")).toString().toStdString();
    EXPECT_TRUE(f.stage.proxy.status().estop);
    EXPECT_TRUE(f.analyzer->proxy.status().estop);
    EXPECT_TRUE(itest::waitFor([&] { return !f.stage.proxy.status().anyMoving() && !f.analyzer->proxy.status().anyMoving(); }, 5000));
    bool logged = false;
    for (const auto& e : f.server->journal().entries())
        logged = logged || (e.text.contains(QStringLiteral("device.estop")) && e.text.contains(QStringLiteral("analyzer, stage")));
    EXPECT_TRUE(logged) << "the event log names both";
}

TEST(ApiHalt, AStopNamingNoInstrumentStopsEveryConnectedOneAndSaysWhich)
{
    ApiFixture f;
    ApiTestClient script(f.path), other(f.path);
    const QString lease = ApiTestClient::result(script.call(QStringLiteral("control.acquire"))).value(QStringLiteral("lease")).toString();
    QTimer beat;
    QObject::connect(&beat, &QTimer::timeout, [&] { script.send(QStringLiteral("control.heartbeat"), QJsonObject{{QStringLiteral("lease"), lease}}); });
    beat.start(100);
    startJog(script, lease, "stage");
    startJog(script, lease, "analyzer");
    ASSERT_TRUE(itest::waitFor([&] { return f.stage.proxy.status().axes.value(0).moving && f.analyzer->proxy.status().axes.value(0).moving; }, 5000));

    const QJsonObject a = other.call(QStringLiteral("device.stop"));
    ASSERT_TRUE(a.contains(QStringLiteral("result"))) << "never refused: " << QJsonDocument(a).toJson().toStdString();
    const QJsonObject r = ApiTestClient::result(a);
    EXPECT_EQ(names(r.value(QStringLiteral("halted"))), (QStringList{QStringLiteral("analyzer"), QStringLiteral("stage")}));
    for (const QJsonValue& s : r.value(QStringLiteral("instruments")).toArray())
        for (const QJsonValue& axis : s.toObject().value(QStringLiteral("axes")).toObject())
            EXPECT_FALSE(axis.toObject().value(QStringLiteral("moving")).toBool()) << "answered when both are still";
    EXPECT_FALSE(f.stage.proxy.status().anyMoving());
    EXPECT_FALSE(f.analyzer->proxy.status().anyMoving());
}

TEST(ApiHalt, NamingOneInstrumentHaltsThatOneAlone)
{
    ApiFixture f;
    ApiTestClient c(f.path);
    const QJsonObject r = ApiTestClient::result(c.call(QStringLiteral("device.estop"), QJsonObject{{QStringLiteral("instrument"), QStringLiteral("stage")}}));
    EXPECT_EQ(names(r.value(QStringLiteral("halted"))), QStringList{QStringLiteral("stage")});
    EXPECT_EQ(r.value(QStringLiteral("instrument")).toString(), QStringLiteral("stage")) << "one instrument's status, as before";
    EXPECT_TRUE(f.stage.proxy.status().estop);
    EXPECT_FALSE(f.analyzer->proxy.status().estop);
}

TEST(ApiHalt, AReadNamingNoInstrumentIsStillAskedWhichAndSaysHow)
{
    ApiFixture f;
    ApiTestClient c(f.path);
    const QJsonObject a = c.call(QStringLiteral("device.status"));
    EXPECT_EQ(ApiTestClient::errorCode(a), app::api::code::kInvalidParams);
    EXPECT_TRUE(ApiTestClient::errorMessage(a).contains(QStringLiteral("instrument analyzer|stage"))) << ApiTestClient::errorMessage(a).toStdString();
    EXPECT_FALSE(ApiTestClient::errorMessage(a).contains(QStringLiteral("--sim"))) << "the API's own word for it";
}

TEST(ApiHalt, AttachedEStopNamingNoInstrumentHaltsBothAndTheInstrumentOptionNamesOne)
{
    ApiFixture f;
    const QStringList attach{QStringLiteral("--attach"), QStringLiteral("--api-socket"), f.path};

    // --instrument names one of the GUI's instruments; --sim, the older spelling, still does.
    itest::ProgramRun r = runCliBeside(attach + itest::splitWords("--instrument analyzer status"));
    ASSERT_TRUE(r.finished);
    EXPECT_EQ(r.exitCode, 0) << r.describe();
    EXPECT_TRUE(r.out.startsWith(QStringLiteral("analyzer"))) << r.describe();
    r = runCliBeside(attach + itest::splitWords("--sim stage status"));
    EXPECT_EQ(r.exitCode, 0) << r.describe();
    EXPECT_TRUE(r.out.startsWith(QStringLiteral("stage"))) << r.describe();
    r = runCliBeside(attach + itest::splitWords("--instrument stage --sim analyzer status"));
    EXPECT_EQ(r.exitCode, 1) << "two different names is a usage error: " << r.describe();

    r = runCliBeside(attach + itest::splitWords("--json stop"));
    EXPECT_EQ(r.exitCode, 0) << r.describe();
    const QJsonObject stopped = QJsonDocument::fromJson(r.out.toUtf8()).object();
    EXPECT_EQ(names(stopped.value(QStringLiteral("halted"))), (QStringList{QStringLiteral("analyzer"), QStringLiteral("stage")})) << r.describe();

    r = runCliBeside(attach + itest::splitWords("--instrument stage estop"));
    EXPECT_EQ(r.exitCode, 0) << r.describe();
    EXPECT_TRUE(f.stage.proxy.status().estop);
    EXPECT_FALSE(f.analyzer->proxy.status().estop) << "the one named, alone";

    r = runCliBeside(attach + itest::splitWords("estop"));
    ASSERT_TRUE(r.finished);
    EXPECT_EQ(r.exitCode, 0) << "never refused: " << r.describe();
    EXPECT_TRUE(f.analyzer->proxy.status().estop);
    EXPECT_TRUE(f.stage.proxy.status().estop);
    EXPECT_TRUE(r.out.contains(QStringLiteral("analyzer  [E-STOP]")) && r.out.contains(QStringLiteral("stage  [E-STOP]"))) << r.describe();

}

TEST(ApiHalt, TheHelpSaysWhatInstrumentAndSimDoWithAttach)
{
    const itest::CliResult r = itest::runCliInProcess({QStringLiteral("--help")});
    ASSERT_EQ(r.code, 0);
    EXPECT_TRUE(r.out.contains(QStringLiteral("with --attach: which of the GUI's"))) << r.out.toStdString();
    EXPECT_TRUE(r.out.contains(QStringLiteral("older spelling of --instrument"))) << r.out.toStdString();
}

} // namespace
