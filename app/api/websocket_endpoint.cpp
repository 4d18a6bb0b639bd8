#include "websocket_endpoint.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QRandomGenerator>
#include <QSaveFile>
#include <QUrlQuery>

#ifdef BP_WITH_WEBSOCKETS
#include <QWebSocket>
#include <QWebSocketServer>
#endif

#include <sys/stat.h>

namespace app::api {

namespace {
[[maybe_unused]] QString tr(const char* text) { return QCoreApplication::translate("app::api", text); }

#ifdef BP_WITH_WEBSOCKETS
/// Compares without an early exit, so the time taken says nothing about the token.
bool sameSecret(const QByteArray& a, const QByteArray& b)
{
    if (a.size() != b.size())
        return false;
    unsigned char diff = 0;
    for (int i = 0; i < a.size(); ++i)
        diff |= static_cast<unsigned char>(a[i] ^ b[i]);
    return diff == 0;
}

class WebSocketChannel final : public Channel {
public:
    explicit WebSocketChannel(QWebSocket* socket) : m_socket(socket)
    {
        m_socket->setParent(this);
        connect(m_socket, &QWebSocket::textMessageReceived, this, [this](const QString& m) { emit received(m.toUtf8(), true); });
        connect(m_socket, &QWebSocket::binaryMessageReceived, this, [this](const QByteArray& m) { emit received(m, true); });
        connect(m_socket, &QWebSocket::bytesWritten, this, [this](qint64 n) { m_pending = std::max<qint64>(0, m_pending - n); });
        connect(m_socket, &QWebSocket::disconnected, this, &Channel::closed);
    }
    void write(const QByteArray& line) override
    {
        const QByteArray body = line.endsWith('\n') ? line.left(line.size() - 1) : line;
        m_pending += m_socket->sendTextMessage(QString::fromUtf8(body));
    }
    qint64 pendingBytes() const override { return m_pending; }
    void close() override { m_socket->abort(); }
    QString transport() const override { return QStringLiteral("websocket"); }

private:
    QWebSocket* m_socket;
    qint64 m_pending = 0;
};
#endif
} // namespace

WebSocketEndpoint::WebSocketEndpoint(QObject* parent) : QObject(parent) {}
WebSocketEndpoint::~WebSocketEndpoint() = default;

QString WebSocketEndpoint::loadOrCreateToken(const QString& file, QString* error)
{
    QFile f(file);
    if (f.exists()) {
        struct stat st {};
        if (::stat(QFile::encodeName(file).constData(), &st) == 0 && (st.st_mode & 077) != 0) {
            *error = tr("the token file %1 can be read by others (chmod 600 it)").arg(file);
            return {};
        }
        if (!f.open(QIODevice::ReadOnly)) {
            *error = tr("cannot read the token file %1: %2").arg(file, f.errorString());
            return {};
        }
        const QString token = QString::fromUtf8(f.readAll()).trimmed();
        if (token.size() < 16) {
            *error = tr("the token in %1 is too short (at least 16 characters)").arg(file);
            return {};
        }
        return token;
    }
    QDir().mkpath(QFileInfo(file).absolutePath());
    QByteArray raw(32, '\0');
    for (char& c : raw)
        c = static_cast<char>(QRandomGenerator::system()->bounded(256));
    const QByteArray token = raw.toHex();
    QSaveFile out(file);
    if (!out.open(QIODevice::WriteOnly) || !out.setPermissions(QFileDevice::ReadOwner | QFileDevice::WriteOwner)
        || out.write(token + '\n') < 0 || !out.commit()) {
        *error = tr("cannot write the token file %1: %2").arg(file, out.errorString());
        return {};
    }
    ::chmod(QFile::encodeName(file).constData(), 0600);
    return QString::fromLatin1(token);
}

bool WebSocketEndpoint::originAllowed(const QString& origin, const QStringList& allowed)
{
    // Programs (Python, websocat) send no Origin; a browser always does, and a page
    // may only come in from an origin the operator named.
    if (origin.isEmpty())
        return true;
    return allowed.contains(origin);
}

bool WebSocketEndpoint::listen(quint16 port, const QString& tokenFile, const QStringList& allowedOrigins, QString* error)
{
#ifdef BP_WITH_WEBSOCKETS
    m_token = loadOrCreateToken(tokenFile, error);
    if (m_token.isEmpty())
        return false;
    m_tokenFile = tokenFile;
    m_allowedOrigins = allowedOrigins;
    m_server = new QWebSocketServer(QStringLiteral("BenchPilot"), QWebSocketServer::NonSecureMode, this);
    if (!m_server->listen(QHostAddress::LocalHost, port)) {
        *error = tr("cannot listen on 127.0.0.1:%1: %2").arg(port).arg(m_server->errorString());
        return false;
    }
    connect(m_server, &QWebSocketServer::newConnection, this, [this] {
        while (QWebSocket* s = m_server->nextPendingConnection()) {
            const QString token = QUrlQuery(s->requestUrl()).queryItemValue(QStringLiteral("token"));
            if (!originAllowed(s->origin(), m_allowedOrigins)) {
                s->close(QWebSocketProtocol::CloseCodePolicyViolated, tr("origin not allowed"));
                s->deleteLater();
                continue;
            }
            if (!sameSecret(token.toUtf8(), m_token.toUtf8())) {
                s->close(QWebSocketProtocol::CloseCodePolicyViolated, tr("a token is required (?token=… from the token file)"));
                s->deleteLater();
                continue;
            }
            emit newChannel(new WebSocketChannel(s));
        }
    });
    return true;
#else
    (void)port, (void)tokenFile, (void)allowedOrigins;
    *error = tr("this BenchPilot was built without Qt WebSockets (install qt6-websockets-dev: ./scripts/setup)");
    return false;
#endif
}

QString WebSocketEndpoint::url() const
{
#ifdef BP_WITH_WEBSOCKETS
    if (m_server && m_server->isListening())
        return QStringLiteral("ws://127.0.0.1:%1/").arg(m_server->serverPort());
#endif
    return {};
}

} // namespace app::api
