#include "api_server.h"

#include "command_call.h"
#include "openrpc.h"
#include "subscriptions.h"
#include "websocket_endpoint.h"

#include "device/telemetry/telemetry_hub.h"
#include "widgets/wording/wording.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QLocalServer>
#include <QLocalSocket>

#include <sys/stat.h>
#include <unistd.h>

namespace app::api {

namespace {
[[maybe_unused]] QString tr(const char* text) { return QCoreApplication::translate("app::api", text); }

QString clock(const QDateTime& t) { return t.toString(QStringLiteral("HH:mm:ss")); }
} // namespace

ApiServer::ApiServer(QVector<ServedInstrument> instruments, dev::tele::TelemetryHub* hub, QObject* parent)
    : QObject(parent), m_instruments(std::move(instruments)), m_hub(hub), m_methods(commandMethods())
{
    for (const auto& s : m_instruments)
        if (s.instrument)
            m_journal.watch(s.key, s.instrument);
    m_subscriptions = std::make_unique<Subscriptions>(*this);
    m_tick.setInterval(kFiberTickMs);
    connect(&m_tick, &QTimer::timeout, this, &ApiServer::tick);
    connect(&m_lease, &ControlLease::ended, this, &ApiServer::onLeaseEnded);
    connect(&m_lease, &ControlLease::changed, this, &ApiServer::clientsChanged);
    m_lease.setBeforeExpiry([this](quint64 clientId) {
        if (ApiClient* c = clientById(clientId))
            c->drain();
    });
    m_lease.setCallInProgress([this](quint64 clientId) { return holderWaitsForACall(clientId); });
}

ApiServer::~ApiServer()
{
    m_shuttingDown = true;
    // Every wait returns at once; the commands run to their ends (a job stops: its
    // runner goes with it) before anything they use is destroyed.
    for (auto& c : m_calls)
        c->cancel();
    for (int round = 0; round < 1000 && !m_calls.empty(); ++round)
        for (auto it = m_calls.begin(); it != m_calls.end();) {
            (*it)->detachClient();
            if ((*it)->resume()) {
                it = m_calls.erase(it);
            } else {
                ++it;
            }
        }
    for (auto& [id, client] : m_clients) {
        client->disconnect(this);
        delete client;
    }
    m_clients.clear();
    m_subscriptions.reset();
    if (m_local) {
        m_local->close();
        QFile::remove(m_socketPath);
    }
}

bool ApiServer::listen(const QString& path, QString* error)
{
    const QFileInfo info(path);
    const QString dir = info.absolutePath();
    // The folder is the socket's first protection: ours alone (0700).
    if (!QDir().mkpath(dir)) {
        *error = tr("cannot make the folder %1 for the API socket").arg(dir);
        return false;
    }
    struct stat st {};
    if (::stat(QFile::encodeName(dir).constData(), &st) != 0 || st.st_uid != ::getuid()) {
        *error = tr("the folder %1 for the API socket belongs to another user").arg(dir);
        return false;
    }
    if ((st.st_mode & 077) != 0 && dir != QDir::tempPath())
        ::chmod(QFile::encodeName(dir).constData(), 0700);
    if (QFileInfo::exists(path)) {
        QLocalSocket probe;
        probe.connectToServer(path);
        if (probe.waitForConnected(300)) {
            *error = tr("another BenchPilot is already listening at %1").arg(path);
            return false;
        }
        QFile::remove(path);  // left by a GUI that died
    }
    m_local = new QLocalServer(this);
    m_local->setSocketOptions(QLocalServer::UserAccessOption);
    m_local->setMaxPendingConnections(kMaxClients);
    if (!m_local->listen(path)) {
        *error = tr("cannot listen at %1: %2").arg(path, m_local->errorString());
        delete m_local;
        m_local = nullptr;
        return false;
    }
    ::chmod(QFile::encodeName(path).constData(), 0600);
    m_socketPath = path;
    connect(m_local, &QLocalServer::newConnection, this, [this] {
        while (QLocalSocket* s = m_local->nextPendingConnection()) {
            auto* channel = new LocalChannel(s);
            if (channel->peerUid() >= 0 && channel->peerUid() != static_cast<qint64>(::getuid())) {
                channel->close();  // the 0600 socket should make this impossible; be sure anyway
                channel->deleteLater();
                continue;
            }
            addClient(channel);
        }
    });
    logActivity({}, QStringLiteral("server"), tr("API listening at %1").arg(path), false);
    return true;
}

bool ApiServer::listenWebSocket(quint16 port, const QString& tokenFile, const QStringList& allowedOrigins, QString* error)
{
    m_webSocket = std::make_unique<WebSocketEndpoint>();
    if (!m_webSocket->listen(port, tokenFile, allowedOrigins, error)) {
        m_webSocket.reset();
        return false;
    }
    connect(m_webSocket.get(), &WebSocketEndpoint::newChannel, this, [this](Channel* c) { addClient(c); });
    logActivity({}, QStringLiteral("server"), tr("API WebSocket listening at %1").arg(m_webSocket->url()), false);
    return true;
}

QString ApiServer::webSocketUrl() const { return m_webSocket ? m_webSocket->url() : QString(); }

void ApiServer::addClient(Channel* channel)
{
    if (static_cast<int>(m_clients.size()) >= kMaxClients) {
        channel->write(errorLine(QJsonValue::Null, code::kTooManyCalls, tr("too many clients (at most %1)").arg(kMaxClients)));
        channel->close();
        channel->deleteLater();
        return;
    }
    auto* client = new ApiClient(m_nextClientId++, channel, this);
    m_clients[client->id()] = client;
    connect(client, &ApiClient::lineReady, this, [this, client](const QByteArray& line) { onLine(client, line); });
    connect(client, &ApiClient::overlongLine, this, [client] {
        client->send(errorLine(QJsonValue::Null, code::kInvalidRequest,
                               tr("line longer than %1 bytes: skipped to its end").arg(kMaxLineBytes)));
    });
    connect(client, &ApiClient::closed, this, [this, client](const QString& why) { onClientClosed(client, why); });
    connect(client, &ApiClient::nameChanged, this, &ApiServer::clientsChanged);
    emit clientsChanged();
}

ApiClient* ApiServer::clientById(quint64 id) const
{
    const auto it = m_clients.find(id);
    return it == m_clients.end() ? nullptr : it->second;
}

QVector<ApiServer::ClientInfo> ApiServer::clients() const
{
    QVector<ClientInfo> out;
    for (const auto& [id, c] : m_clients)
        if (c->isOpen())
            out.push_back({id, c->name(), c->transport(), c->connectedAt(), c->callsInFlight(), m_lease.isHeldBy(id)});
    return out;
}

void ApiServer::onClientClosed(ApiClient* client, const QString& why)
{
    const quint64 id = client->id();
    if (why != tr("connection closed"))
        logActivity(client->name(), QStringLiteral("client"), tr("disconnected: %1").arg(why), true);
    m_lease.clientGone(id);  // stops its velocity motion (onLeaseEnded)
    m_subscriptions->clientGone(id);
    for (auto& c : m_calls)
        if (c->clientId() == id)
            c->detachClient();
    m_clients.erase(id);
    client->deleteLater();
    emit clientsChanged();
}

void ApiServer::answerError(ApiClient* client, const Request& r, int errorCode, const QString& message, const QJsonValue& data)
{
    if (r.kind == Request::Kind::Notification)
        return;  // JSON-RPC: a notification is never answered
    client->send(errorLine(r.id, errorCode, message, data));
}

void ApiServer::onLine(ApiClient* client, const QByteArray& line)
{
    const Request r = readRequest(line);
    if (r.kind == Request::Kind::Invalid) {
        client->send(errorLine(r.id, r.errorCode, r.errorMessage));
        return;
    }
    handle(client, r);
}

void ApiServer::handle(ApiClient* client, const Request& r)
{
    // Any request that carries the holder's lease keeps the lease alive.
    if (r.params.value(QStringLiteral("lease")).isString())
        if (m_lease.accepts(client->id(), r.params.value(QStringLiteral("lease")).toString()))
            m_lease.touch(client->id());
    bool handled = false;
    handleBuiltin(client, r, &handled);
    if (handled)
        return;
    const CommandMethod* m = findMethod(m_methods, r.method);
    if (!m) {
        answerError(client, r, code::kMethodNotFound, tr("unknown method '%1' (rpc.discover lists them)").arg(r.method));
        return;
    }
    QStringList words;
    bool positional = false;
    ParamProblem problem;
    if (!toWords(*m, r.params, &words, &positional, &problem)) {
        answerError(client, r, code::kInvalidParams, QStringLiteral("%1: %2").arg(problem.field, problem.message),
                    QJsonObject{{QStringLiteral("field"), problem.field}});
        return;
    }
    if (client->callsInFlight() >= kMaxCallsPerClient) {
        answerError(client, r, code::kTooManyCalls, tr("%1 calls are already running for this client; wait for one to end").arg(kMaxCallsPerClient));
        return;
    }
    const QStringList args = m->path.split(QLatin1Char(' ')) + QStringList{QStringLiteral("--json")} + words;
    auto call = std::make_unique<CommandCall>(*this, client, r.kind == Request::Kind::Call ? r.id : QJsonValue(QJsonValue::Undefined),
                                              CommandCall::Style::Method, m, args, r.params.value(QStringLiteral("lease")).toString());
    QJsonObject shown = r.params;
    shown.remove(QStringLiteral("lease"));
    call->setDescription(QStringLiteral("%1 %2").arg(m->method, QString::fromUtf8(QJsonDocument(shown).toJson(QJsonDocument::Compact))));
    startCall(client, r, std::move(call));
}

void ApiServer::startCall(ApiClient* client, const Request& r, std::unique_ptr<CommandCall> call)
{
    (void)client;
    (void)r;
    CommandCall* c = call.get();
    m_calls.push_back(std::move(call));
    if (c->resume()) {
        callFinished(c);
        return;
    }
    if (!m_tick.isActive())
        m_tick.start();
}

void ApiServer::tick()
{
    // Resume every call whose wait is over; a finished one goes (it has answered).
    std::vector<CommandCall*> ready;
    for (auto& c : m_calls)
        if (c->ready())
            ready.push_back(c.get());
    for (CommandCall* c : ready)
        if (c->resume())
            callFinished(c);
    if (m_calls.empty())
        m_tick.stop();
}

bool ApiServer::holderWaitsForACall(quint64 clientId) const
{
    // A velocity jog the client holds open still needs its heartbeats: a call in progress
    // shows that the script waits for it, not that it still watches the jog.
    for (const HeldJog& j : m_heldJogs)
        if (j.clientId == clientId && j.instrument)
            return false;
    const ApiClient* client = clientById(clientId);
    if (!client || !client->isOpen())
        return false;
    for (const auto& c : m_calls)
        if (c->clientId() == clientId && !c->id().isUndefined() && !c->finished())
            return true;
    return false;
}

void ApiServer::callFinished(CommandCall* call)
{
    // The holder's silence is counted from the answer, not from when it asked.
    m_lease.callAnswered(call->clientId());
    m_lease.endOneCallLease(call->clientId());
    for (auto it = m_calls.begin(); it != m_calls.end(); ++it)
        if (it->get() == call) {
            m_calls.erase(it);
            break;
        }
    emit clientsChanged();
}

const ServedInstrument* ApiServer::resolveInstrument(const QString& kind, QString* why, bool* callersFault) const
{
    bool fault = false;
    if (!callersFault)
        callersFault = &fault;
    *callersFault = false;
    if (!kind.isEmpty()) {
        for (const auto& s : m_instruments)
            if (s.key == kind) {
                if (!s.instrument || !s.instrument->isReady()) {
                    *why = tr("the GUI's %1 is not connected (%2)").arg(kind, s.instrument ? ui::words::term(dev::linkStateTerm(s.instrument->state())) : QString());
                    return nullptr;
                }
                return &s;
            }
        *why = tr("the GUI has no instrument '%1'").arg(kind);
        *callersFault = true;
        return nullptr;
    }
    const QVector<const ServedInstrument*> ready = connectedInstruments();
    if (ready.size() == 1)
        return ready.first();
    *why = ready.isEmpty() ? tr("no instrument is connected in the GUI")
                           : tr("the analyzer and the stage are both connected: say which with --instrument analyzer|stage");
    *callersFault = !ready.isEmpty();
    return nullptr;
}

QVector<const ServedInstrument*> ApiServer::connectedInstruments() const
{
    QVector<const ServedInstrument*> ready;
    for (const auto& s : m_instruments)
        if (s.instrument && s.instrument->isReady())
            ready << &s;
    return ready;
}

bool ApiServer::mayControl(quint64 clientId, const QString& clientName, const QString& token, bool oneCall, QString* why)
{
    if (m_lease.accepts(clientId, token)) {
        m_lease.touch(clientId);
        return true;
    }
    const auto& h = m_lease.holder();
    if (oneCall) {
        if (m_lease.isHeldBy(clientId))
            return true;
        if (!h) {
            const QString busy = m_operatorBusy ? m_operatorBusy() : QString();
            if (!busy.isEmpty()) {
                *why = tr("not in control: the operator runs %1").arg(busy);
                return false;
            }
            m_lease.acquire(clientId, clientName, true);
            return true;
        }
    }
    if (h && h->clientId == clientId)
        *why = token.isEmpty() ? tr("not in control: pass the lease from control.acquire as \"lease\"")
                               : tr("not in control: that lease is not the one this client holds");
    else if (h)
        *why = tr("not in control: %1 has had control since %2").arg(h->clientName, clock(h->since));
    else
        *why = tr("not in control: call control.acquire first (the operator can take control back at any time)");
    return false;
}

void ApiServer::holdJog(quint64 clientId, dev::Instrument* instrument, int axis, double velocity)
{
    for (auto it = m_heldJogs.begin(); it != m_heldJogs.end();)
        it = it->instrument == instrument && it->axis == axis ? m_heldJogs.erase(it) : it + 1;
    if (velocity == 0) {
        instrument->stopJog(axis);
        return;
    }
    instrument->startJog(axis, velocity);
    m_heldJogs.push_back({clientId, instrument, axis});
}

void ApiServer::wantTelemetry(const QString& consumer, const ServedInstrument& instrument, const QVector<dev::proto::ChannelRef>& channels,
                              int rateHz)
{
    if (!m_hub || instrument.hubIndex < 0)
        return;  // no hub (tests): the job goes without the samples rather than take the plots' stream
    QVector<dev::tele::ChannelKey> keys;
    for (const auto& ref : channels)
        keys.push_back({instrument.hubIndex, ref});
    m_hub->setWanted(consumer, keys, rateHz);
}

void ApiServer::logActivity(const QString& client, const QString& kind, const QString& text, bool problem)
{
    JournalEntry e;
    e.source = QStringLiteral("api");
    e.kind = kind;
    e.client = client;
    e.text = text;
    e.problem = problem;
    m_journal.add(e);
    emit activity(client, text, problem);
}

void ApiServer::takeBack()
{
    if (!m_lease.holder())
        return;
    m_lease.takeBack();
}

bool ApiServer::interruptJob(const QString& jobId)
{
    for (auto& c : m_calls)
        if (c->jobId() == jobId) {
            c->interrupt();
            return true;
        }
    return false;
}

void ApiServer::onLeaseEnded(const ControlLease::Holder& holder, ControlLease::EndReason reason)
{
    // Velocity motion stops as when a jog key is released (the device decelerates).
    for (auto it = m_heldJogs.begin(); it != m_heldJogs.end();) {
        if (it->clientId == holder.clientId) {
            if (it->instrument)
                it->instrument->stopJog(it->axis);
            it = m_heldJogs.erase(it);
        } else {
            ++it;
        }
    }
    for (auto& c : m_calls) {
        if (c->clientId() != holder.clientId)
            continue;
        c->lostControl();  // timed jogs stop; jobs go on as the operator's
        if (!c->jobId().isEmpty() && !c->finished() && reason != ControlLease::EndReason::CallEnded)
            if (const Job* j = m_jobs.job(c->jobId()); j && j->handedOver)
                emit jobHandedOver(j->id, tr("%1 that %2 started goes on, and is now yours (%3)")
                                              .arg(j->kind, holder.clientName, j->instrument));
    }
    static const QHash<int, const char*> kWhy{
        {static_cast<int>(ControlLease::EndReason::Released), "released control"},
        {static_cast<int>(ControlLease::EndReason::TakenBack), "lost control: the operator took it back"},
        {static_cast<int>(ControlLease::EndReason::ConnectionClosed), "lost control: its connection closed"},
        {static_cast<int>(ControlLease::EndReason::HeartbeatLost), "lost control: no heartbeat for 500 ms"},
        {static_cast<int>(ControlLease::EndReason::CallEnded), "gave back control (its call ended)"}};
    if (reason != ControlLease::EndReason::CallEnded)
        logActivity(holder.clientName, QStringLiteral("control"),
                    QCoreApplication::translate("app::api", kWhy.value(static_cast<int>(reason))),
                    reason == ControlLease::EndReason::TakenBack || reason == ControlLease::EndReason::HeartbeatLost);
    if (ApiClient* c = clientById(holder.clientId); c && reason != ControlLease::EndReason::CallEnded)
        c->send(notificationLine(QStringLiteral("control.lost"), QJsonObject{{QStringLiteral("reason"), ControlLease::reasonKey(reason)}}));
}

void ApiServer::handleBuiltin(ApiClient* client, const Request& r, bool* handled)
{
    *handled = true;
    const QString& m = r.method;
    const QJsonObject& p = r.params;
    auto answer = [&](const QJsonObject& result) {
        if (r.kind == Request::Kind::Call)
            client->send(resultLine(r.id, result));
    };
    auto onlyParams = [&](const QStringList& allowed) {
        for (auto it = p.begin(); it != p.end(); ++it)
            if (!allowed.contains(it.key())) {
                answerError(client, r, code::kInvalidParams,
                            allowed.isEmpty() ? tr("%1: unknown parameter (this method takes none)").arg(it.key())
                                              : tr("%1: unknown parameter (parameters: %2)").arg(it.key(), allowed.join(QStringLiteral(", "))),
                            QJsonObject{{QStringLiteral("field"), it.key()}});
                return false;
            }
        return true;
    };
    auto stringParam = [&](const QString& name, bool required, QString* out) {
        const QJsonValue v = p.value(name);
        if (v.isUndefined() && !required)
            return true;
        if (!v.isString() || (required && v.toString().isEmpty())) {
            answerError(client, r, code::kInvalidParams, tr("%1: expected a string").arg(name), QJsonObject{{QStringLiteral("field"), name}});
            return false;
        }
        *out = v.toString();
        return true;
    };
    if (m == QLatin1String("rpc.discover")) {
        if (onlyParams({}))
            answer(openRpcDocument(m_methods));
    } else if (m == QLatin1String("client.hello")) {
        QString name, cwd;
        if (!onlyParams({QStringLiteral("name"), QStringLiteral("cwd")}) || !stringParam(QStringLiteral("name"), false, &name)
            || !stringParam(QStringLiteral("cwd"), false, &cwd))
            return;
        client->setName(name);
        if (!cwd.isEmpty())
            client->setCwd(cwd);
        QJsonArray instruments;
        for (const auto& s : m_instruments)
            instruments.append(QJsonObject{{QStringLiteral("instrument"), s.key},
                                           {QStringLiteral("link"), s.instrument ? QString::fromLatin1(dev::linkStateKey(s.instrument->state())) : QString()}});
        answer(QJsonObject{{QStringLiteral("client_id"), static_cast<qint64>(client->id())},
                           {QStringLiteral("name"), client->name()},
                           {QStringLiteral("server"), QStringLiteral("BenchPilot %1").arg(QStringLiteral(BP_VERSION))},
                           {QStringLiteral("socket"), m_socketPath},
                           {QStringLiteral("instruments"), instruments},
                           {QStringLiteral("heartbeat_timeout_ms"), ControlLease::kHeartbeatTimeoutMs}});
    } else if (m == QLatin1String("control.acquire")) {
        QString name;
        if (!onlyParams({QStringLiteral("client")}) || !stringParam(QStringLiteral("client"), false, &name))
            return;
        client->setName(name);
        const QString busy = m_lease.holder() ? QString() : (m_operatorBusy ? m_operatorBusy() : QString());
        if (!busy.isEmpty()) {
            answerError(client, r, code::kBusy, tr("the operator runs %1: control stays with the GUI until it ends").arg(busy));
            return;
        }
        const auto token = m_lease.acquire(client->id(), client->name());
        if (!token) {
            const auto& h = *m_lease.holder();
            answerError(client, r, code::kNotInControl, tr("%1 has had control since %2").arg(h.clientName, clock(h.since)),
                        QJsonObject{{QStringLiteral("holder"), h.clientName}, {QStringLiteral("since"), h.since.toString(Qt::ISODate)}});
            return;
        }
        logActivity(client->name(), QStringLiteral("control"), tr("took control"), false);
        answer(QJsonObject{{QStringLiteral("lease"), *token},
                           {QStringLiteral("since"), m_lease.holder()->since.toString(Qt::ISODate)},
                           {QStringLiteral("heartbeat_timeout_ms"), ControlLease::kHeartbeatTimeoutMs}});
    } else if (m == QLatin1String("control.release") || m == QLatin1String("control.heartbeat")) {
        QString token;
        if (!onlyParams({QStringLiteral("lease")}) || !stringParam(QStringLiteral("lease"), true, &token))
            return;
        const bool release = m == QLatin1String("control.release");
        const bool ok = release ? m_lease.release(client->id(), token) : m_lease.accepts(client->id(), token) && m_lease.touch(client->id());
        if (!ok) {
            answerError(client, r, code::kNotInControl,
                        m_lease.holder() && !m_lease.isHeldBy(client->id())
                            ? tr("not in control: %1 has had control since %2").arg(m_lease.holder()->clientName, clock(m_lease.holder()->since))
                            : tr("not in control: this client does not hold that lease (taken back, expired or released)"));
            return;
        }
        answer(QJsonObject{{release ? QStringLiteral("released") : QStringLiteral("ok"), true}});
    } else if (m == QLatin1String("control.status")) {
        if (!onlyParams({}))
            return;
        QJsonValue holder = QJsonValue::Null;
        if (const auto& h = m_lease.holder())
            holder = QJsonObject{{QStringLiteral("client"), h->clientName},
                                 {QStringLiteral("since"), h->since.toString(Qt::ISODate)},
                                 {QStringLiteral("you"), h->clientId == client->id()}};
        answer(QJsonObject{{QStringLiteral("holder"), holder}, {QStringLiteral("heartbeat_timeout_ms"), ControlLease::kHeartbeatTimeoutMs}});
    } else if (m == QLatin1String("subscribe")) {
        ParamProblem problem;
        const QJsonObject result = m_subscriptions->subscribe(client, p, &problem);
        if (result.isEmpty())
            answerError(client, r, code::kInvalidParams, QStringLiteral("%1: %2").arg(problem.field, problem.message),
                        QJsonObject{{QStringLiteral("field"), problem.field}});
        else
            answer(result);
    } else if (m == QLatin1String("unsubscribe")) {
        if (!onlyParams({QStringLiteral("subscription")}))
            return;
        const QJsonValue v = p.value(QStringLiteral("subscription"));
        if (!v.isDouble()) {
            answerError(client, r, code::kInvalidParams, tr("subscription: expected the number subscribe answered"),
                        QJsonObject{{QStringLiteral("field"), QStringLiteral("subscription")}});
            return;
        }
        answer(QJsonObject{{QStringLiteral("unsubscribed"), m_subscriptions->unsubscribe(client->id(), v.toInt())}});
    } else if (m == QLatin1String("call.cancel")) {
        if (!onlyParams({QStringLiteral("call")}))
            return;
        const QJsonValue id = p.value(QStringLiteral("call"));
        bool found = false;
        for (auto& c : m_calls)
            if (c->clientId() == client->id() && c->id() == id && !c->finished()) {
                c->interrupt();
                found = true;
            }
        answer(QJsonObject{{QStringLiteral("cancelled"), found}});
    } else if (m == QLatin1String("cli.run")) {
        if (!onlyParams({QStringLiteral("argv"), QStringLiteral("cwd"), QStringLiteral("client")}))
            return;
        const QJsonValue argv = p.value(QStringLiteral("argv"));
        QStringList args;
        bool ok = argv.isArray();
        for (const QJsonValue& a : argv.toArray()) {
            ok = ok && a.isString();
            args << a.toString();
        }
        if (!ok) {
            answerError(client, r, code::kInvalidParams, tr("argv: expected an array of strings (benchpilot-cli's words)"),
                        QJsonObject{{QStringLiteral("field"), QStringLiteral("argv")}});
            return;
        }
        QString cwd, name;
        if (!stringParam(QStringLiteral("cwd"), false, &cwd) || !stringParam(QStringLiteral("client"), false, &name))
            return;
        if (!name.isEmpty())
            client->setName(name);
        if (!cwd.isEmpty())
            client->setCwd(cwd);
        if (client->callsInFlight() >= kMaxCallsPerClient) {
            answerError(client, r, code::kTooManyCalls, tr("%1 calls are already running for this client").arg(kMaxCallsPerClient));
            return;
        }
        auto call = std::make_unique<CommandCall>(*this, client, r.kind == Request::Kind::Call ? r.id : QJsonValue(QJsonValue::Undefined),
                                                  CommandCall::Style::CliRun, nullptr, args, QString());
        call->setDescription(QStringLiteral("benchpilot-cli %1").arg(args.join(QLatin1Char(' '))));
        startCall(client, r, std::move(call));
    } else {
        *handled = false;
    }
}

} // namespace app::api
