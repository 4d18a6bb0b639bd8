#pragma once
// The API over a WebSocket, for tools that cannot open a Unix socket (a browser page,
// a notebook on a Windows host reaching a VM). Off unless `benchpilot --api-websocket
// PORT` asks for it, and then (docs/api.md, "Security"):
//  - bound to 127.0.0.1 only: nothing on the network can connect;
//  - a token is required (ws://127.0.0.1:PORT/?token=…), kept in a 0600 file the
//    operator's own programs can read (made with a fresh random token when missing);
//  - a browser's Origin header must be one the operator allowed (--api-allow-origin):
//    a web page the operator happens to visit cannot drive the bench;
//  - each text message is one JSON-RPC request; each answer is one text message.
#include "api_client.h"

#include <QObject>
#include <QStringList>

#include <memory>

class QWebSocket;
class QWebSocketServer;

namespace app::api {

class WebSocketEndpoint : public QObject {
    Q_OBJECT
public:
    explicit WebSocketEndpoint(QObject* parent = nullptr);
    ~WebSocketEndpoint() override;

    bool listen(quint16 port, const QString& tokenFile, const QStringList& allowedOrigins, QString* error);
    QString url() const;  ///< "ws://127.0.0.1:PORT/" (without the token)
    QString tokenFile() const { return m_tokenFile; }
    /// Reads the token from `file`, or writes a new random one there (0600); "" with why.
    static QString loadOrCreateToken(const QString& file, QString* error);
    /// Whether a connection with this Origin header ("" when none was sent) may proceed.
    static bool originAllowed(const QString& origin, const QStringList& allowed);

signals:
    void newChannel(app::api::Channel* channel);

private:
    QWebSocketServer* m_server = nullptr;
    QString m_token;
    QString m_tokenFile;
    QStringList m_allowedOrigins;
};

} // namespace app::api
