// The API's answers to bad input of every kind (docs/api.md, "Bad input and slow
// clients"): each is answered with its JSON-RPC code, or the client is disconnected,
// and another client on the same server never notices.
#include "api_support.h"

#include "app/api/json_rpc.h"

using itest::ApiFixture;
using itest::ApiTestClient;

namespace {

TEST(ApiProtocol, ALineThatIsNotJsonIsAParseError)
{
    ApiFixture f(false);
    ApiTestClient c(f.path);
    c.sendRaw("{\"jsonrpc\": \"2.0\", \"method\": \n");
    const QJsonObject a = c.nextAnswer();
    EXPECT_EQ(ApiTestClient::errorCode(a), app::api::code::kParseError);
    EXPECT_TRUE(a.value(QStringLiteral("id")).isNull());
    // The connection goes on.
    EXPECT_EQ(ApiTestClient::result(c.call(QStringLiteral("control.status"))).value(QStringLiteral("holder")).isNull(), true);
}

TEST(ApiProtocol, JsonThatIsNotARequestIsAnInvalidRequestWithItsIdWhenReadable)
{
    ApiFixture f(false);
    ApiTestClient c(f.path);
    const std::pair<const char*, int> cases[] = {
        {"[1, 2]", app::api::code::kInvalidRequest},                                        // a batch
        {"42", app::api::code::kInvalidRequest},                                            // not an object
        {"{\"id\": 7, \"method\": \"control.status\"}", app::api::code::kInvalidRequest},  // no jsonrpc
        {"{\"jsonrpc\": \"2.0\", \"id\": 8}", app::api::code::kInvalidRequest},            // no method
        {"{\"jsonrpc\": \"2.0\", \"id\": {}, \"method\": \"x\"}", app::api::code::kInvalidRequest},  // an id that is an object
        {"{\"jsonrpc\": \"2.0\", \"id\": 9, \"method\": \"device.status\", \"params\": [1]}", app::api::code::kInvalidParams},
        {"{\"jsonrpc\": \"2.0\", \"id\": 10, \"method\": \"device.status\", \"params\": 3}", app::api::code::kInvalidRequest},
    };
    for (const auto& [line, code] : cases) {
        c.sendRaw(QByteArray(line) + '\n');
        const QJsonObject a = c.nextAnswer();
        EXPECT_EQ(ApiTestClient::errorCode(a), code) << line;
        EXPECT_FALSE(ApiTestClient::errorMessage(a).isEmpty()) << line;
    }
    EXPECT_EQ(c.answers.size(), 0u);
}

TEST(ApiProtocol, AnUnknownMethodAndBadParamsSayWhatIsWrongAndWhere)
{
    ApiFixture f(false);
    ApiTestClient c(f.path);
    QJsonObject a = c.call(QStringLiteral("device.fly"));
    EXPECT_EQ(ApiTestClient::errorCode(a), app::api::code::kMethodNotFound);
    EXPECT_TRUE(ApiTestClient::errorMessage(a).contains(QStringLiteral("device.fly")));

    a = c.call(QStringLiteral("device.move"), QJsonObject{{QStringLiteral("targets"), QJsonObject{{QStringLiteral("X"), QStringLiteral("ten")}}}});
    EXPECT_EQ(ApiTestClient::errorCode(a), app::api::code::kInvalidParams);
    EXPECT_EQ(a.value(QStringLiteral("error")).toObject().value(QStringLiteral("data")).toObject().value(QStringLiteral("field")).toString(),
              QStringLiteral("targets.X"));

    a = c.call(QStringLiteral("device.move"), QJsonObject{{QStringLiteral("speed"), 3}});
    EXPECT_EQ(ApiTestClient::errorCode(a), app::api::code::kInvalidParams);
    EXPECT_TRUE(ApiTestClient::errorMessage(a).startsWith(QStringLiteral("targets: required"))) << ApiTestClient::errorMessage(a).toStdString();

    a = c.call(QStringLiteral("device.status"), QJsonObject{{QStringLiteral("colour"), QStringLiteral("red")}});
    EXPECT_EQ(ApiTestClient::errorCode(a), app::api::code::kInvalidParams);
    EXPECT_TRUE(ApiTestClient::errorMessage(a).contains(QStringLiteral("instrument"))) << "names the parameters it takes";

    // A parameter with an empty name is named all the same (fuzz_api found it unnamed).
    a = c.call(QStringLiteral("device.status"), QJsonObject{{QString(), 1}});
    EXPECT_EQ(ApiTestClient::errorCode(a), app::api::code::kInvalidParams);
    EXPECT_EQ(a.value(QStringLiteral("error")).toObject().value(QStringLiteral("data")).toObject().value(QStringLiteral("field")).toString(),
              QStringLiteral("\"\""));

    // A command's own check, worded with the JSON names, not the CLI's options.
    a = c.call(QStringLiteral("motion.profile"),
               QJsonObject{{QStringLiteral("kind"), QStringLiteral("warp")}, {QStringLiteral("distance"), 10}, {QStringLiteral("vmax"), 5}});
    EXPECT_EQ(ApiTestClient::errorCode(a), app::api::code::kInvalidParams);
    EXPECT_TRUE(ApiTestClient::errorMessage(a).startsWith(QStringLiteral("kind 'warp'"))) << ApiTestClient::errorMessage(a).toStdString();
}

TEST(ApiProtocol, ANotificationIsNeverAnswered)
{
    ApiFixture f(false);
    ApiTestClient c(f.path);
    c.send(QStringLiteral("device.fly"), {});
    c.send(QStringLiteral("device.status"), {});
    const QJsonObject a = c.call(QStringLiteral("control.status"));
    EXPECT_TRUE(a.contains(QStringLiteral("result")));
    itest::spin(100);
    EXPECT_EQ(c.answers.size(), 0u);
}

TEST(ApiProtocol, ALineOverOneMebibyteIsAnsweredAndSkippedAndTheConnectionGoesOn)
{
    ApiFixture f(false);
    ApiTestClient c(f.path);
    QByteArray huge = "{\"jsonrpc\":\"2.0\",\"id\":1,\"method\":\"control.status\",\"params\":{\"pad\":\"";
    huge += QByteArray(app::api::kMaxLineBytes + 10, 'x');
    huge += "\"}}\n";
    c.sendRaw(huge);
    const QJsonObject a = c.nextAnswer(20000);
    EXPECT_EQ(ApiTestClient::errorCode(a), app::api::code::kInvalidRequest);
    EXPECT_TRUE(ApiTestClient::errorMessage(a).contains(QStringLiteral("longer than")));
    EXPECT_TRUE(c.call(QStringLiteral("control.status")).contains(QStringLiteral("result")));
}

TEST(ApiProtocol, AClientThatFloodsIsDisconnectedAndAnotherNeverNotices)
{
    ApiFixture f(false);
    ApiTestClient calm(f.path);
    ApiTestClient flood(f.path);
    QByteArray burst;
    for (int i = 0; i < app::api::ApiClient::kMaxQueuedLines * 4; ++i)
        burst += "{\"jsonrpc\":\"2.0\",\"id\":" + QByteArray::number(i) + ",\"method\":\"control.status\"}\n";
    flood.sendRaw(burst);
    EXPECT_TRUE(itest::waitFor([&] { return !flood.connected(); }, 20000)) << "a client that sends more than it waits for is cut off";
    const QJsonObject a = calm.call(QStringLiteral("device.status"));
    EXPECT_EQ(ApiTestClient::result(a).value(QStringLiteral("instrument")).toString(), QStringLiteral("stage"));
}

TEST(ApiProtocol, AClientThatStopsReadingIsDisconnectedAndAnotherNeverNotices)
{
    ApiFixture f(false);
    ApiTestClient calm(f.path);
    // A raw socket that writes requests with big answers and never reads them.
    QLocalSocket deaf;
    deaf.connectToServer(f.path);
    ASSERT_TRUE(itest::waitFor([&] { return deaf.state() == QLocalSocket::ConnectedState; }, 5000));
    ASSERT_TRUE(itest::waitFor([&] { return f.server->clients().size() == 2; }, 5000));
    QByteArray requests;
    for (int i = 0; i < 100; ++i)
        requests += "{\"jsonrpc\":\"2.0\",\"id\":" + QByteArray::number(i) + ",\"method\":\"rpc.discover\"}\n";
    int rounds = 0;
    const bool cut = itest::waitFor([&] {
        if (f.server->clients().size() < 2)
            return true;
        if (deaf.state() == QLocalSocket::ConnectedState && deaf.bytesToWrite() == 0 && rounds < 20) {
            deaf.write(requests);
            ++rounds;
        }
        return false;
    }, 60000);
    EXPECT_TRUE(cut) << "the server holds at most " << app::api::ApiClient::kMaxPendingBytes << " bytes for a client";
    const QJsonObject a = calm.call(QStringLiteral("device.status"));
    EXPECT_EQ(ApiTestClient::result(a).value(QStringLiteral("instrument")).toString(), QStringLiteral("stage"));
}

TEST(ApiProtocol, LineSplitterKeepsMemoryBoundedWhateverArrives)
{
    app::api::LineSplitter s;
    int lines = 0, overlong = 0;
    const QByteArray chunk(64 * 1024, 'a');
    for (int i = 0; i < 40; ++i)  // 2.5 MiB without a newline
        s.feed(chunk, [&](const QByteArray&) { ++lines; }, [&] { ++overlong; });
    EXPECT_LE(s.pending(), app::api::kMaxLineBytes);
    EXPECT_EQ(overlong, 1) << "one long line, reported once";
    s.feed("tail\n{\"a\":1}\r\n", [&](const QByteArray& l) {
        ++lines;
        EXPECT_EQ(l, QByteArray("{\"a\":1}"));
    }, [&] { ++overlong; });
    EXPECT_EQ(lines, 1) << "the long line's tail is skipped, the next line is whole";
}

} // namespace
