#pragma once
// The scripting API served in-process (as the GUI serves it) on both simulated
// instruments, and a test client on its Unix socket that waits on the event loop
// for answers and keeps every notification it gets.
#include "app/api/api_server.h"
#include "device/backends/benchpilot/benchpilot_client.h"
#include "device/client/instrument_proxy.h"
#include "device/link/simulated_link.h"
#include "device/telemetry/telemetry_hub.h"
#include "wait.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLocalSocket>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <deque>
#include <memory>

namespace itest {

/// One simulated instrument behind a proxy, as app/gui/instrument_session holds it.
struct ServedSim {
    explicit ServedSim(dev::proto::DeviceKind kind, qint32 baud = 115200) : link(kind, baud)
    {
        backend = new dev::BenchPilotClient;
        proxy.setBackend(backend);
        backend->setTransport(link.hostEnd());
        proxy.connectLink();
    }
    ~ServedSim()
    {
        backend->setTransport(nullptr);
    }
    dev::SimulatedLink link;
    dev::InstrumentProxy proxy;
    dev::BenchPilotClient* backend;
};

class ApiFixture {
public:
    /// `baud` 0: links without pacing, for a simulator whose clock is sped up.
    explicit ApiFixture(bool withAnalyzer = true, qint32 baud = 115200)
        : stage(dev::proto::DeviceKind::Stage, baud)
    {
        if (withAnalyzer)
            analyzer = std::make_unique<ServedSim>(dev::proto::DeviceKind::Analyzer, baud);
        QVector<app::api::ServedInstrument> served;
        if (analyzer) {
            hub.addInstrument(0, QStringLiteral("Analyzer"), &analyzer->proxy);
            served.push_back({QStringLiteral("analyzer"), &analyzer->proxy, 0, [this] { return &analyzer->link; }});
        }
        hub.addInstrument(1, QStringLiteral("Stage"), &stage.proxy);
        served.push_back({QStringLiteral("stage"), &stage.proxy, 1, [this] { return &stage.link; }});
        server = std::make_unique<app::api::ApiServer>(served, &hub);
        path = dir.filePath(QStringLiteral("api.sock"));
        QString error;
        listening = server->listen(path, &error);
        EXPECT_TRUE(listening) << error.toStdString();
        waitFor([this] { return stage.proxy.isReady() && (!analyzer || analyzer->proxy.isReady()); }, 10000);
    }
    ~ApiFixture() { server.reset(); }

    QTemporaryDir dir;
    dev::tele::TelemetryHub hub;
    std::unique_ptr<ServedSim> analyzer;
    ServedSim stage;
    std::unique_ptr<app::api::ApiServer> server;
    QString path;
    bool listening = false;
};

/// A client of the API on its socket.
class ApiTestClient {
public:
    explicit ApiTestClient(const QString& path)
    {
        socket.connectToServer(path);
        QObject::connect(&socket, &QLocalSocket::readyRead, &socket, [this] { readLines(); });
        waitFor([this] { return socket.state() == QLocalSocket::ConnectedState; }, 5000);
    }

    bool connected() const { return socket.state() == QLocalSocket::ConnectedState; }

    void sendRaw(const QByteArray& bytes)
    {
        socket.write(bytes);
        socket.flush();
    }

    /// Sends a call and waits for its answer (the whole response object; {} on timeout).
    QJsonObject call(const QString& method, const QJsonObject& params = {}, int timeoutMs = 20000)
    {
        const int id = nextId++;
        send(method, params, id);
        return waitAnswer(id, timeoutMs);
    }

    void send(const QString& method, const QJsonObject& params, QJsonValue id = QJsonValue::Undefined)
    {
        QJsonObject o{{QStringLiteral("jsonrpc"), QStringLiteral("2.0")}, {QStringLiteral("method"), method},
                      {QStringLiteral("params"), params}};
        if (!id.isUndefined())
            o.insert(QStringLiteral("id"), id);
        sendRaw(QJsonDocument(o).toJson(QJsonDocument::Compact) + '\n');
    }

    QJsonObject waitAnswer(const QJsonValue& id, int timeoutMs = 20000)
    {
        QJsonObject found;
        waitFor([&] {
            for (auto it = answers.begin(); it != answers.end(); ++it)
                if (it->value(QStringLiteral("id")) == id) {
                    found = *it;
                    answers.erase(it);
                    return true;
                }
            return !connected() && socket.bytesAvailable() == 0;
        }, timeoutMs);
        return found;
    }

    /// The next answer of any id (for raw lines whose id the test cannot set).
    QJsonObject nextAnswer(int timeoutMs = 5000)
    {
        waitFor([&] { return !answers.empty(); }, timeoutMs);
        if (answers.empty())
            return {};
        const QJsonObject o = answers.front();
        answers.pop_front();
        return o;
    }

    /// Waits for a notification of `method` matching `accept`; removes and returns it.
    QJsonObject waitNotification(const QString& method, const std::function<bool(const QJsonObject& params)>& accept = {},
                                 int timeoutMs = 10000)
    {
        QJsonObject found;
        waitFor([&] {
            for (auto it = notifications.begin(); it != notifications.end(); ++it)
                if (it->value(QStringLiteral("method")).toString() == method
                    && (!accept || accept(it->value(QStringLiteral("params")).toObject()))) {
                    found = it->value(QStringLiteral("params")).toObject();
                    notifications.erase(it);
                    return true;
                }
            return false;
        }, timeoutMs);
        return found;
    }

    static int errorCode(const QJsonObject& answer) { return answer.value(QStringLiteral("error")).toObject().value(QStringLiteral("code")).toInt(); }
    static QString errorMessage(const QJsonObject& answer)
    {
        return answer.value(QStringLiteral("error")).toObject().value(QStringLiteral("message")).toString();
    }
    static QJsonObject result(const QJsonObject& answer) { return answer.value(QStringLiteral("result")).toObject(); }

    QLocalSocket socket;
    std::deque<QJsonObject> answers;
    std::deque<QJsonObject> notifications;
    int nextId = 1;
    QByteArray buffer;

private:
    void readLines()
    {
        buffer += socket.readAll();
        for (int nl = buffer.indexOf('\n'); nl >= 0; nl = buffer.indexOf('\n')) {
            const QJsonObject o = QJsonDocument::fromJson(buffer.left(nl)).object();
            buffer.remove(0, nl + 1);
            (o.contains(QStringLiteral("method")) ? notifications : answers).push_back(o);
        }
    }
};

} // namespace itest
