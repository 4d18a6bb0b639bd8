#pragma once
// A script on the window's API socket (docs/api.md): one JSON-RPC call at a time,
// waiting on the real event loop for its answer.
#include "gui_window.h"

#include <QJsonDocument>
#include <QJsonObject>
#include <QLocalSocket>

namespace guitest {

/// The test window's options with the scripting API on a socket of its own.
inline app::MainWindowOptions apiWindowOptions(const QString& socketPath)
{
    app::MainWindowOptions options = testWindowOptions();
    options.api.socketPath = socketPath;
    return options;
}

/// A script on the window's API socket.
class Script {
public:
    explicit Script(const QString& path)
    {
        m_socket.connectToServer(path);
        guitest::waitFor([this] { return m_socket.state() == QLocalSocket::ConnectedState; }, 5000);
    }
    QJsonObject call(const QString& method, const QJsonObject& params = {})
    {
        const int id = m_next++;
        m_socket.write(QJsonDocument(QJsonObject{{QStringLiteral("jsonrpc"), QStringLiteral("2.0")}, {QStringLiteral("id"), id},
                                                 {QStringLiteral("method"), method}, {QStringLiteral("params"), params}})
                           .toJson(QJsonDocument::Compact)
                       + '\n');
        m_socket.flush();
        QJsonObject answer;
        guitest::waitFor([&] {
            m_buffer += m_socket.readAll();
            for (int nl = m_buffer.indexOf('\n'); nl >= 0; nl = m_buffer.indexOf('\n')) {
                const QJsonObject o = QJsonDocument::fromJson(m_buffer.left(nl)).object();
                m_buffer.remove(0, nl + 1);
                if (o.value(QStringLiteral("id")).toInt() == id)
                    answer = o;
            }
            return !answer.isEmpty();
        }, 20000);
        return answer;
    }
    void heartbeat(const QString& lease)
    {
        m_socket.write(QJsonDocument(QJsonObject{{QStringLiteral("jsonrpc"), QStringLiteral("2.0")},
                                                 {QStringLiteral("method"), QStringLiteral("control.heartbeat")},
                                                 {QStringLiteral("params"), QJsonObject{{QStringLiteral("lease"), lease}}}})
                           .toJson(QJsonDocument::Compact)
                       + '\n');
    }

private:
    QLocalSocket m_socket;
    QByteArray m_buffer;
    int m_next = 1;
};

inline int errorCode(const QJsonObject& a) { return a.value(QStringLiteral("error")).toObject().value(QStringLiteral("code")).toInt(); }

} // namespace guitest
