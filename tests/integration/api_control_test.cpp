// Who is in control (docs/api.md, "Control"): one holder of the lease; the operator's
// Take back ends it at once; it dies with its connection or its heartbeats, and then
// velocity motion stops as when a jog key is released; E-stop is never gated; every
// changing call is in the event log with the client's name.
#include "api_support.h"

#include "app/api/json_rpc.h"

#include <optional>

using itest::ApiFixture;
using itest::ApiTestClient;

namespace {

QString acquire(ApiTestClient& c, const char* name)
{
    return ApiTestClient::result(c.call(QStringLiteral("control.acquire"), QJsonObject{{QStringLiteral("client"), QString::fromLatin1(name)}}))
        .value(QStringLiteral("lease"))
        .toString();
}

QJsonObject jogParams(const QString& lease, double velocity)
{
    return QJsonObject{{QStringLiteral("axis"), QStringLiteral("X")}, {QStringLiteral("velocity"), velocity}, {QStringLiteral("lease"), lease}};
}

/// Device time (µs) when the stage's X is at rest again after `from` (0 if it never is).
quint64 restTimeUs(ApiFixture& f, int timeoutMs)
{
    quint64 at = 0;
    itest::waitFor([&] {
        const auto& st = f.stage.proxy.status();
        if (!st.axes.isEmpty() && !st.axes[0].moving && !f.stage.proxy.isJogging(0))
            at = st.deviceTimeUs;
        return at != 0;
    }, timeoutMs);
    return at;
}

TEST(ApiControl, ChangingNeedsTheLeaseReadingDoesNot)
{
    ApiFixture f(false);
    ApiTestClient c(f.path);
    QJsonObject a = c.call(QStringLiteral("device.jog"), QJsonObject{{QStringLiteral("axis"), QStringLiteral("X")}, {QStringLiteral("velocity"), 1}});
    EXPECT_EQ(ApiTestClient::errorCode(a), app::api::code::kNotInControl);
    EXPECT_TRUE(ApiTestClient::errorMessage(a).contains(QStringLiteral("control.acquire")));
    EXPECT_FALSE(f.stage.proxy.isJogging(0));
    EXPECT_TRUE(c.call(QStringLiteral("device.status")).contains(QStringLiteral("result")));
    EXPECT_TRUE(c.call(QStringLiteral("device.limits")).contains(QStringLiteral("result"))) << "showing the limits reads";
    a = c.call(QStringLiteral("device.limits"), QJsonObject{{QStringLiteral("limits"), QJsonObject{{QStringLiteral("X"), QJsonArray{5, 95}}}}});
    EXPECT_EQ(ApiTestClient::errorCode(a), app::api::code::kNotInControl) << "setting them changes";
}

TEST(ApiControl, OneHolderAtATimeAndAStaleLeaseIsRefused)
{
    ApiFixture f(false);
    ApiTestClient first(f.path), second(f.path);
    const QString lease = acquire(first, "first");
    ASSERT_FALSE(lease.isEmpty());
    const QJsonObject refused = second.call(QStringLiteral("control.acquire"), QJsonObject{{QStringLiteral("client"), QStringLiteral("second")}});
    EXPECT_EQ(ApiTestClient::errorCode(refused), app::api::code::kNotInControl);
    EXPECT_TRUE(ApiTestClient::errorMessage(refused).contains(QStringLiteral("first"))) << "names who has it";
    // The lease is the first client's: the second cannot use it.
    const QJsonObject stolen = second.call(QStringLiteral("device.jog"), jogParams(lease, 1));
    EXPECT_EQ(ApiTestClient::errorCode(stolen), app::api::code::kNotInControl);
    EXPECT_TRUE(first.call(QStringLiteral("control.release"), QJsonObject{{QStringLiteral("lease"), lease}}).contains(QStringLiteral("result")));
    EXPECT_FALSE(acquire(second, "second").isEmpty());
    const QJsonObject old = first.call(QStringLiteral("device.jog"), jogParams(lease, 1));
    EXPECT_EQ(ApiTestClient::errorCode(old), app::api::code::kNotInControl) << "a released lease is dead";
}

TEST(ApiControl, TakeBackStopsTheScriptsJogAtOnceAndItsNextCallIsRefused)
{
    ApiFixture f(false);
    ApiTestClient script(f.path);
    const QString lease = acquire(script, "sweeper");
    QTimer beat;
    QObject::connect(&beat, &QTimer::timeout, [&] { script.send(QStringLiteral("control.heartbeat"), QJsonObject{{QStringLiteral("lease"), lease}}); });
    beat.start(100);
    const QJsonObject jog = script.call(QStringLiteral("device.jog"), jogParams(lease, 2));
    ASSERT_TRUE(jog.contains(QStringLiteral("result"))) << QJsonDocument(jog).toJson().toStdString();
    ASSERT_TRUE(itest::waitFor([&] { return f.stage.proxy.status().axes.value(0).moving; }, 5000));
    f.server->takeBack();  // the operator's button
    EXPECT_FALSE(f.stage.proxy.isJogging(0)) << "the held jog is released at once";
    const QJsonObject lost = script.waitNotification(QStringLiteral("control.lost"));
    EXPECT_EQ(lost.value(QStringLiteral("reason")).toString(), QStringLiteral("taken_back"));
    const QJsonObject next = script.call(QStringLiteral("device.jog"), jogParams(lease, 2));
    EXPECT_EQ(ApiTestClient::errorCode(next), app::api::code::kNotInControl);
    EXPECT_NE(restTimeUs(f, 5000), 0u);
    bool logged = false;
    for (const auto& e : f.server->journal().entries())
        logged = logged || (e.client.startsWith(QStringLiteral("sweeper")) && e.text.contains(QStringLiteral("took it back")));
    EXPECT_TRUE(logged);
}

TEST(ApiControl, AClosedConnectionEndsTheLeaseAndTheJogWithinHalfASecondOfDeviceTime)
{
    ApiFixture f(false);
    auto script = std::make_unique<ApiTestClient>(f.path);
    const QString lease = acquire(*script, "doomed");
    ASSERT_TRUE(script->call(QStringLiteral("device.jog"), jogParams(lease, 2)).contains(QStringLiteral("result")));
    ASSERT_TRUE(itest::waitFor([&] { return f.stage.proxy.status().axes.value(0).moving; }, 5000));
    const quint64 lastSeenMoving = f.stage.proxy.status().deviceTimeUs;
    script->socket.abort();  // what the kernel does for a process killed with SIGKILL
    const quint64 rest = restTimeUs(f, 5000);
    ASSERT_NE(rest, 0u);
    EXPECT_LE(rest - lastSeenMoving, 500000u) << "device time from the last status seen moving to rest";
    EXPECT_FALSE(f.server->lease().holder().has_value());
}

TEST(ApiControl, HeartbeatSilenceEndsTheLease)
{
    ApiFixture f(false);
    ApiTestClient script(f.path);
    const QString lease = acquire(script, "sleepy");
    ASSERT_TRUE(script.call(QStringLiteral("device.jog"), jogParams(lease, 2)).contains(QStringLiteral("result")));
    // No heartbeats: the lease ends by itself and the jog with it.
    const QJsonObject lost = script.waitNotification(QStringLiteral("control.lost"), {}, 10000);
    EXPECT_EQ(lost.value(QStringLiteral("reason")).toString(), QStringLiteral("heartbeat_lost"));
    EXPECT_FALSE(f.stage.proxy.isJogging(0));
    EXPECT_NE(restTimeUs(f, 5000), 0u);
}

TEST(ApiControl, AHoldersLongCallIsProofOfLifeAndItsSilenceCountsFromTheAnswer)
{
    ApiFixture f(false);
    ApiTestClient script(f.path);
    const QString lease = acquire(script, "no heartbeat thread");
    ASSERT_FALSE(lease.isEmpty());
    // A call that lasts three times the heartbeat timeout, and not one heartbeat: a raw
    // script that acquires and then homes or moves, waiting for the answer.
    const QJsonObject jog = script.call(QStringLiteral("device.jog"),
                                        QJsonObject{{QStringLiteral("axis"), QStringLiteral("X")}, {QStringLiteral("velocity"), 2},
                                                    {QStringLiteral("seconds"), 1.5}, {QStringLiteral("lease"), lease}});
    ASSERT_TRUE(jog.contains(QStringLiteral("result"))) << QJsonDocument(jog).toJson().toStdString();
    for (const QJsonObject& n : script.notifications)
        EXPECT_NE(n.value(QStringLiteral("method")).toString(), QStringLiteral("control.lost")) << "not while it waited for its own call";
    EXPECT_TRUE(f.server->lease().holder().has_value()) << "still held when its call answers";
    // From the answer on, silence counts again: without heartbeats the lease ends.
    const QJsonObject lost = script.waitNotification(QStringLiteral("control.lost"), {}, 10000);
    EXPECT_EQ(lost.value(QStringLiteral("reason")).toString(), QStringLiteral("heartbeat_lost"));
}

TEST(ApiControl, AClosedConnectionEndsTheLeaseAtOnceEvenDuringItsCall)
{
    ApiFixture f(false);
    auto script = std::make_unique<ApiTestClient>(f.path);
    const QString lease = acquire(*script, "doomed mid-call");
    std::optional<app::api::ControlLease::EndReason> why;
    QObject::connect(&f.server->lease(), &app::api::ControlLease::ended, &f.server->lease(),
                     [&why](const app::api::ControlLease::Holder&, app::api::ControlLease::EndReason r) { why = r; });
    script->send(QStringLiteral("device.jog"),
                 QJsonObject{{QStringLiteral("axis"), QStringLiteral("X")}, {QStringLiteral("velocity"), 2},
                             {QStringLiteral("seconds"), 60}, {QStringLiteral("lease"), lease}},
                 1);
    ASSERT_TRUE(itest::waitFor([&] { return f.stage.proxy.status().axes.value(0).moving; }, 5000));
    script->socket.abort();
    ASSERT_TRUE(itest::waitFor([&] { return why.has_value(); }, 5000));
    EXPECT_EQ(*why, app::api::ControlLease::EndReason::ConnectionClosed) << "not left to a heartbeat timeout";
    EXPECT_NE(restTimeUs(f, 5000), 0u) << "its jog stops with the lease, long before its 60 s";
}

TEST(ApiControl, EStopFromAnotherClientLatchesAtOnceWhileTheFirstHoldsTheLease)
{
    ApiFixture f(false);
    ApiTestClient holder(f.path), other(f.path);
    const QString lease = acquire(holder, "holder");
    QTimer beat;
    QObject::connect(&beat, &QTimer::timeout, [&] { holder.send(QStringLiteral("control.heartbeat"), QJsonObject{{QStringLiteral("lease"), lease}}); });
    beat.start(100);
    ASSERT_TRUE(holder.call(QStringLiteral("device.jog"), jogParams(lease, 2)).contains(QStringLiteral("result")));
    const QJsonObject a = other.call(QStringLiteral("device.estop"));
    ASSERT_TRUE(a.contains(QStringLiteral("result"))) << QJsonDocument(a).toJson().toStdString();
    EXPECT_TRUE(ApiTestClient::result(a).value(QStringLiteral("estop")).toBool()) << "latched by the time the call answers";
    EXPECT_TRUE(f.stage.proxy.status().estop);
    // The holder's motion calls are now refused by the device, with the E-stop's code.
    const QJsonObject refused = holder.call(QStringLiteral("device.jog"),
                                            QJsonObject{{QStringLiteral("axis"), QStringLiteral("X")}, {QStringLiteral("velocity"), 1},
                                                        {QStringLiteral("seconds"), 0.2}, {QStringLiteral("lease"), lease}});
    EXPECT_EQ(ApiTestClient::errorCode(refused), app::api::code::kEStopLatched) << QJsonDocument(refused).toJson().toStdString();
}

TEST(ApiControl, AttachedCliRunTakesAFreeLeaseForOneCallAndIsRefusedWhileAScriptHoldsIt)
{
    ApiFixture f(false);
    ApiTestClient script(f.path), shell(f.path);
    auto run = [&](const QStringList& argv) {
        const int id = shell.nextId++;
        shell.send(QStringLiteral("cli.run"), QJsonObject{{QStringLiteral("argv"), QJsonArray::fromStringList(argv)}}, id);
        return ApiTestClient::result(shell.waitAnswer(id)).value(QStringLiteral("exit_code")).toInt(-1);
    };
    EXPECT_EQ(run({QStringLiteral("zero"), QStringLiteral("X")}), 0);
    EXPECT_FALSE(f.server->lease().holder().has_value()) << "given back when the call ends";
    const QString lease = acquire(script, "owner");
    ASSERT_FALSE(lease.isEmpty());
    EXPECT_EQ(run({QStringLiteral("zero"), QStringLiteral("X")}), 2) << "refused: exit code 2";
    const QJsonObject err = shell.waitNotification(QStringLiteral("cli.output"), [](const QJsonObject& p) {
        return p.value(QStringLiteral("stream")).toString() == QLatin1String("stderr");
    });
    EXPECT_TRUE(err.value(QStringLiteral("text")).toString().contains(QStringLiteral("owner"))) << err.value(QStringLiteral("text")).toString().toStdString();
    EXPECT_EQ(run({QStringLiteral("status")}), 0) << "reading needs no lease";
}

} // namespace
