// The API's WebSocket (docs/api.md, "Security defaults"): 127.0.0.1 only, a token
// from a 0600 file, browser Origins refused unless the operator allowed them.
#include "api_support.h"

#include "app/api/websocket_endpoint.h"

#ifdef BP_WITH_WEBSOCKETS
#include <QFile>
#include <QWebSocket>

#include <sys/stat.h>

using itest::ApiFixture;

namespace {

struct WsClient {
    explicit WsClient(const QString& url, const QString& origin = {}) : socket(origin)
    {
        QObject::connect(&socket, &QWebSocket::textMessageReceived, &socket, [this](const QString& m) { messages << m; });
        socket.open(QUrl(url));
        itest::waitFor([this] { return socket.state() == QAbstractSocket::ConnectedState || socket.state() == QAbstractSocket::UnconnectedState; },
                       5000);
    }
    /// Sends a request and waits for an answer; {} if the connection is refused or closed.
    QJsonObject call(const QString& method)
    {
        socket.sendTextMessage(QStringLiteral("{\"jsonrpc\":\"2.0\",\"id\":1,\"method\":\"%1\"}").arg(method));
        itest::waitFor([this] { return !messages.isEmpty() || socket.state() != QAbstractSocket::ConnectedState; }, 5000);
        return messages.isEmpty() ? QJsonObject{} : QJsonDocument::fromJson(messages.takeFirst().toUtf8()).object();
    }
    QWebSocket socket;
    QStringList messages;
};

TEST(ApiWebSocket, OnlyWithTheTokenAndFromAnAllowedOriginOrNone)
{
    ApiFixture f(false);
    QTemporaryDir dir;
    const QString tokenFile = dir.filePath(QStringLiteral("api.token"));
    QString error;
    ASSERT_TRUE(f.server->listenWebSocket(0, tokenFile, {QStringLiteral("http://localhost:8888")}, &error)) << error.toStdString();
    const QString url = f.server->webSocketUrl();
    EXPECT_TRUE(url.startsWith(QStringLiteral("ws://127.0.0.1:"))) << "bound to the loopback address only";
    struct stat st {};
    ASSERT_EQ(::stat(QFile::encodeName(tokenFile).constData(), &st), 0);
    EXPECT_EQ(st.st_mode & 0777, 0600u) << "a fresh token is for this user alone";
    QFile f2(tokenFile);
    ASSERT_TRUE(f2.open(QIODevice::ReadOnly));
    const QString token = QString::fromUtf8(f2.readAll()).trimmed();
    EXPECT_GE(token.size(), 32);

    EXPECT_TRUE(WsClient(url).call(QStringLiteral("control.status")).isEmpty()) << "no token: refused";
    EXPECT_TRUE(WsClient(url + QStringLiteral("?token=wrong")).call(QStringLiteral("control.status")).isEmpty());
    const QString withToken = url + QStringLiteral("?token=") + token;
    EXPECT_TRUE(WsClient(withToken, QStringLiteral("http://evil.example")).call(QStringLiteral("control.status")).isEmpty())
        << "a web page from elsewhere cannot drive the bench";
    EXPECT_TRUE(WsClient(withToken).call(QStringLiteral("control.status")).contains(QStringLiteral("result"))) << "a program sends no Origin";
    EXPECT_TRUE(WsClient(withToken, QStringLiteral("http://localhost:8888")).call(QStringLiteral("control.status")).contains(QStringLiteral("result")));
}

TEST(ApiWebSocket, ATokenFileOthersCanReadIsRefused)
{
    QTemporaryDir dir;
    const QString tokenFile = dir.filePath(QStringLiteral("api.token"));
    QFile f(tokenFile);
    ASSERT_TRUE(f.open(QIODevice::WriteOnly));
    f.write("0123456789abcdef0123456789abcdef\n");
    f.close();
    ::chmod(QFile::encodeName(tokenFile).constData(), 0644);
    QString error;
    EXPECT_TRUE(app::api::WebSocketEndpoint::loadOrCreateToken(tokenFile, &error).isEmpty());
    EXPECT_TRUE(error.contains(QStringLiteral("chmod 600"))) << error.toStdString();
}

} // namespace
#endif
