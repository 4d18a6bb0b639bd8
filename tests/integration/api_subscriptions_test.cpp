// Live data (docs/api.md, "Subscriptions"): a full snapshot first, then only what
// changed, each message with a sequence number, the device time and what it folded in;
// a slow client gets the latest values, never a queue.
#include "api_support.h"

#include "app/api/subscriptions.h"

using itest::ApiFixture;
using itest::ApiTestClient;

namespace {

QJsonObject topic(const char* name, const QJsonObject& options = {}) { return QJsonObject{{QString::fromLatin1(name), options}}; }

bool isTopic(const QJsonObject& p, const char* name) { return p.value(QStringLiteral("topic")).toString() == QLatin1String(name); }

QString acquire(ApiTestClient& c)
{
    return ApiTestClient::result(c.call(QStringLiteral("control.acquire"), QJsonObject{{QStringLiteral("client"), QStringLiteral("mover")}}))
        .value(QStringLiteral("lease"))
        .toString();
}

TEST(ApiSubscriptions, PositionsStartWithASnapshotThenCarryOnlyWhatChangedWithSequenceNumbers)
{
    ApiFixture f(false);
    ApiTestClient listener(f.path), mover(f.path);
    const QJsonObject sub = ApiTestClient::result(listener.call(QStringLiteral("subscribe"),
                                                                QJsonObject{{QStringLiteral("topics"), topic("positions", {{QStringLiteral("max_hz"), 50}})}}));
    ASSERT_TRUE(sub.contains(QStringLiteral("subscription")));
    const QJsonObject first = listener.waitNotification(QStringLiteral("subscription"));
    EXPECT_TRUE(first.value(QStringLiteral("snapshot")).toBool());
    EXPECT_EQ(first.value(QStringLiteral("instrument")).toString(), QStringLiteral("stage"));
    EXPECT_EQ(first.value(QStringLiteral("data")).toObject().keys(), (QStringList{QStringLiteral("X"), QStringLiteral("Y")}));
    EXPECT_TRUE(first.value(QStringLiteral("device_time_us")).toDouble() > 0);
    const QString lease = acquire(mover);
    mover.send(QStringLiteral("device.jog"), QJsonObject{{QStringLiteral("axis"), QStringLiteral("Y")}, {QStringLiteral("velocity"), 1},
                                                         {QStringLiteral("seconds"), 0.5}, {QStringLiteral("lease"), lease}}, 5);
    qint64 seq = first.value(QStringLiteral("seq")).toInteger();
    qint64 deviceTime = first.value(QStringLiteral("device_time_us")).toInteger();
    for (int n = 0; n < 4; ++n) {
        const QJsonObject m = listener.waitNotification(QStringLiteral("subscription"));
        ASSERT_FALSE(m.isEmpty());
        EXPECT_FALSE(m.value(QStringLiteral("snapshot")).toBool());
        EXPECT_GT(m.value(QStringLiteral("seq")).toInteger(), seq);
        EXPECT_EQ(m.value(QStringLiteral("coalesced")).toInteger(), m.value(QStringLiteral("seq")).toInteger() - seq - 1);
        EXPECT_GE(m.value(QStringLiteral("device_time_us")).toInteger(), deviceTime);
        EXPECT_EQ(m.value(QStringLiteral("data")).toObject().keys(), QStringList{QStringLiteral("Y")}) << "X did not move";
        seq = m.value(QStringLiteral("seq")).toInteger();
        deviceTime = m.value(QStringLiteral("device_time_us")).toInteger();
    }
    mover.waitAnswer(5);
}

TEST(ApiSubscriptions, StateJobsAndTheLogFollowWhatHappens)
{
    ApiFixture f(false);
    ApiTestClient listener(f.path), other(f.path);
    listener.call(QStringLiteral("subscribe"),
                  QJsonObject{{QStringLiteral("topics"), QJsonObject{{QStringLiteral("state"), QJsonObject{}}, {QStringLiteral("jobs"), QJsonObject{}},
                                                                     {QStringLiteral("log"), QJsonObject{}}}}});
    const QJsonObject state = listener.waitNotification(QStringLiteral("subscription"), [](const QJsonObject& p) { return isTopic(p, "state"); });
    EXPECT_EQ(state.value(QStringLiteral("data")).toObject().value(QStringLiteral("link")).toString(), QStringLiteral("ready"));
    EXPECT_FALSE(state.value(QStringLiteral("data")).toObject().value(QStringLiteral("estop")).toBool());
    listener.waitNotification(QStringLiteral("subscription"), [](const QJsonObject& p) { return isTopic(p, "log"); });

    // A changing call is a job on the board and an entry in the log, with its client's name.
    const QString lease = acquire(other);
    other.call(QStringLiteral("device.zero"), QJsonObject{{QStringLiteral("axes"), QStringLiteral("X")}, {QStringLiteral("lease"), lease}});
    const QJsonObject job = listener.waitNotification(QStringLiteral("subscription"), [](const QJsonObject& p) {
        if (!isTopic(p, "jobs"))
            return false;
        for (const QJsonValue& j : p.value(QStringLiteral("data")).toObject())
            if (j.toObject().value(QStringLiteral("kind")).toString() == QLatin1String("device.zero"))
                return true;
        return false;
    });
    EXPECT_FALSE(job.isEmpty());
    const QJsonObject log = listener.waitNotification(QStringLiteral("subscription"), [](const QJsonObject& p) {
        if (!isTopic(p, "log"))
            return false;
        for (const QJsonValue& e : p.value(QStringLiteral("data")).toObject().value(QStringLiteral("entries")).toArray())
            if (e.toObject().value(QStringLiteral("client")).toString().startsWith(QStringLiteral("mover"))
                && e.toObject().value(QStringLiteral("text")).toString().contains(QStringLiteral("device.zero")))
                return true;
        return false;
    });
    EXPECT_FALSE(log.isEmpty());

    // E-stop: only what changed.
    other.call(QStringLiteral("device.estop"));
    const QJsonObject latched = listener.waitNotification(QStringLiteral("subscription"), [](const QJsonObject& p) {
        return isTopic(p, "state") && p.value(QStringLiteral("data")).toObject().value(QStringLiteral("estop")).toBool();
    });
    ASSERT_FALSE(latched.isEmpty());
    EXPECT_FALSE(latched.value(QStringLiteral("data")).toObject().contains(QStringLiteral("link"))) << "the link did not change";
}

TEST(ApiSubscriptions, TelemetryComesInBatchesWithChannelsUnitsAndTheDevicesSampleIndex)
{
    ApiFixture f(false);
    ApiTestClient c(f.path);
    const QJsonObject a = c.call(QStringLiteral("subscribe"),
                                 QJsonObject{{QStringLiteral("topics"),
                                              topic("telemetry", {{QStringLiteral("channels"), QJsonArray{QStringLiteral("X.measured"), QStringLiteral("X.following_error")}},
                                                                  {QStringLiteral("rate_hz"), 200}})}});
    ASSERT_TRUE(a.contains(QStringLiteral("result"))) << QJsonDocument(a).toJson().toStdString();
    QJsonObject batch = c.waitNotification(QStringLiteral("subscription"), [](const QJsonObject& p) { return isTopic(p, "telemetry"); });
    ASSERT_FALSE(batch.isEmpty());
    const QJsonObject data = batch.value(QStringLiteral("data")).toObject();
    EXPECT_EQ(data.value(QStringLiteral("channels")).toArray().size(), 2);
    EXPECT_EQ(data.value(QStringLiteral("units")).toArray().at(0).toString(), QStringLiteral("mm"));
    EXPECT_GT(data.value(QStringLiteral("samples")).toArray().size(), 0);
    EXPECT_EQ(data.value(QStringLiteral("samples")).toArray().at(0).toArray().size(), 2);
    EXPECT_EQ(batch.value(QStringLiteral("seq")).toInteger(), data.value(QStringLiteral("first_sample")).toInteger());
    const QJsonObject bad = c.call(QStringLiteral("subscribe"), QJsonObject{{QStringLiteral("topics"), topic("telemetry", {{QStringLiteral("channels"), QJsonArray{QStringLiteral("Q.measured")}}})}});
    EXPECT_EQ(ApiTestClient::errorCode(bad), app::api::code::kInvalidParams);
    EXPECT_TRUE(ApiTestClient::errorMessage(bad).startsWith(QStringLiteral("topics.telemetry.channels"))) << ApiTestClient::errorMessage(bad).toStdString();
}

/// A channel whose reader is as far behind as the test says.
class SlowChannel final : public app::api::Channel {
public:
    void write(const QByteArray& line) override { lines << line; }
    qint64 pendingBytes() const override { return behindBytes; }
    void close() override {}
    QString transport() const override { return QStringLiteral("test"); }
    qint64 behindBytes = 0;
    QList<QByteArray> lines;
};

TEST(ApiSubscriptions, ASlowClientGetsTheLatestValuesNeverAQueue)
{
    ApiFixture f(false);
    auto* channel = new SlowChannel;
    app::api::ApiClient slow(999, channel);
    app::api::ParamProblem problem;
    const QJsonObject r = f.server->subscriptions().subscribe(&slow, QJsonObject{{QStringLiteral("topics"), topic("positions", {{QStringLiteral("max_hz"), 1000}})}}, &problem);
    ASSERT_FALSE(r.isEmpty()) << problem.message.toStdString();
    ASSERT_TRUE(itest::waitFor([&] { return channel->lines.size() == 1; }, 5000)) << "the snapshot";
    // Behind: nothing more is written however much changes.
    channel->behindBytes = 10 * app::api::ApiClient::kUpdateBackpressureBytes;
    ApiTestClient mover(f.path);
    const QString lease = acquire(mover);
    mover.call(QStringLiteral("device.jog"), QJsonObject{{QStringLiteral("axis"), QStringLiteral("X")}, {QStringLiteral("velocity"), 2},
                                                         {QStringLiteral("seconds"), 0.6}, {QStringLiteral("lease"), lease}});
    EXPECT_EQ(channel->lines.size(), 1);
    // Caught up: one message with the newest positions, saying how many it folded in.
    channel->behindBytes = 0;
    ASSERT_TRUE(itest::waitFor([&] { return channel->lines.size() >= 2; }, 5000));
    const QJsonObject m = QJsonDocument::fromJson(channel->lines[1]).object().value(QStringLiteral("params")).toObject();
    EXPECT_GT(m.value(QStringLiteral("coalesced")).toInteger(), 3) << "the updates it could not take, folded";
    const double x = m.value(QStringLiteral("data")).toObject().value(QStringLiteral("X")).toObject().value(QStringLiteral("measured")).toDouble();
    EXPECT_NEAR(x, f.stage.proxy.status().axes[0].measured, 0.05) << "the latest value";
    EXPECT_EQ(f.server->subscriptions().counts(999).coalesced, static_cast<quint64>(m.value(QStringLiteral("coalesced_total")).toInteger()));
    f.server->subscriptions().clientGone(999);
}

} // namespace
