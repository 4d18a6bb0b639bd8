#pragma once
// The scripting API in the GUI's process (docs/api.md): JSON-RPC 2.0 over a Unix
// socket (and, when asked, a WebSocket on 127.0.0.1), one more user of the same
// instrument proxies and job runners as the screens. device/ knows nothing of it.
//
// Methods are benchpilot-cli's commands (command_methods.h), run on fibers on the
// GUI's event loop (command_call.h), plus the API's own: rpc.discover, client.hello,
// control.acquire|release|heartbeat|status, subscribe, unsubscribe, call.cancel, cli.run.
// Who may change what is the ControlLease; live data goes out through Subscriptions.
#include "api_client.h"
#include "command_methods.h"
#include "control_lease.h"
#include "event_journal.h"
#include "job_board.h"

#include "device/client/instrument.h"

#include <QObject>
#include <QPointer>
#include <QTimer>
#include <QVector>

#include <functional>
#include <map>
#include <memory>
#include <vector>

class QLocalServer;

namespace dev::tele {
class TelemetryHub;
}

namespace app::api {

class CommandCall;
class Subscriptions;
class WebSocketEndpoint;

/// An instrument the server offers, as the application holds it.
struct ServedInstrument {
    QString key;                            ///< "analyzer", "stage": what `instrument` names
    QPointer<dev::Instrument> instrument;   ///< the GUI's proxy (not owned)
    int hubIndex = -1;                      ///< its index in the telemetry hub, −1 if not there
    /// The in-process simulator's link behind the instrument now (it changes on a
    /// reconnect), or nullptr: a simulated camera looks at its true work point.
    std::function<QObject*()> simulator;
};

class ApiServer : public QObject {
    Q_OBJECT
public:
    static constexpr int kMaxCallsPerClient = 8;
    static constexpr int kMaxClients = 32;
    static constexpr int kFiberTickMs = 5;   ///< how often waiting calls look at their condition

    ApiServer(QVector<ServedInstrument> instruments, dev::tele::TelemetryHub* hub, QObject* parent = nullptr);
    ~ApiServer() override;

    /// Listens on the Unix socket at `path` (its folder made 0700, the socket 0600); a
    /// stale socket file from a dead GUI is replaced, a live one is not. False with why.
    bool listen(const QString& path, QString* error);
    QString socketPath() const { return m_socketPath; }
    /// The WebSocket (off unless asked): 127.0.0.1:port, a token from a 0600 file, and
    /// browser Origins refused unless listed. False with why.
    bool listenWebSocket(quint16 port, const QString& tokenFile, const QStringList& allowedOrigins, QString* error);
    QString webSocketUrl() const;

    /// Why a job the operator started keeps scripts from taking control; "" when none
    /// runs. The GUI says which screen runs what.
    void setOperatorBusy(std::function<QString()> why) { m_operatorBusy = std::move(why); }

    ControlLease& lease() { return m_lease; }
    EventJournal& journal() { return m_journal; }
    JobBoard& jobs() { return m_jobs; }
    const QVector<ServedInstrument>& instruments() const { return m_instruments; }
    dev::tele::TelemetryHub* hub() const { return m_hub; }
    Subscriptions& subscriptions() { return *m_subscriptions; }

    struct ClientInfo {
        quint64 id = 0;
        QString name;
        QString transport;
        QDateTime since;
        int calls = 0;
        bool holdsLease = false;
    };
    QVector<ClientInfo> clients() const;

    /// The operator's Take back: the holder's next call is refused; its velocity motion stops.
    void takeBack();
    /// Interrupts the call running job `jobId` (the GUI's Abort for a script's job).
    bool interruptJob(const QString& jobId);
    /// Every call (and job) of the API still running.
    int callsRunning() const { return static_cast<int>(m_calls.size()); }

    // ---- for CommandCall -------------------------------------------------------------
    /// The served instrument `kind` names ("" = the only one connected); nullptr with why,
    /// and `callersFault` set when the caller must name another (or any) instrument.
    const ServedInstrument* resolveInstrument(const QString& kind, QString* why, bool* callersFault = nullptr) const;
    /// Every served instrument that is connected and ready, in the order served.
    QVector<const ServedInstrument*> connectedInstruments() const;
    /// May the client change things? With `oneCall` (cli.run) a free lease is taken for the call.
    bool mayControl(quint64 clientId, const QString& clientName, const QString& token, bool oneCall, QString* why);
    void holdJog(quint64 clientId, dev::Instrument* instrument, int axis, double velocity);
    /// Routes a call's telemetry wish through the hub (nothing without one).
    void wantTelemetry(const QString& consumer, const ServedInstrument& instrument, const QVector<dev::proto::ChannelRef>& channels,
                       int rateHz);
    /// An entry in the event log (and the GUI's, through activity()).
    void logActivity(const QString& client, const QString& kind, const QString& text, bool problem);
    void callFinished(CommandCall* call);

signals:
    void clientsChanged();
    /// Something a client did (a changing call, taking or losing control), for the GUI's event log.
    void activity(const QString& client, const QString& text, bool problem);
    /// A job a script started is now the operator's (its script lost control).
    void jobHandedOver(const QString& jobId, const QString& text);

private:
    void addClient(Channel* channel);
    void onLine(ApiClient* client, const QByteArray& line);
    void handle(ApiClient* client, const Request& r);
    void handleBuiltin(ApiClient* client, const Request& r, bool* handled);
    void startCall(ApiClient* client, const Request& r, std::unique_ptr<CommandCall> call);
    void onClientClosed(ApiClient* client, const QString& why);
    void onLeaseEnded(const ControlLease::Holder& holder, ControlLease::EndReason reason);
    void tick();
    void answerError(ApiClient* client, const Request& r, int code, const QString& message, const QJsonValue& data = {});
    ApiClient* clientById(quint64 id) const;
    /// A call of the lease holder's still running, on its open connection, that it will be
    /// answered: proof of life that stands in for heartbeats (ControlLease::setCallInProgress).
    bool holderWaitsForACall(quint64 clientId) const;

    QVector<ServedInstrument> m_instruments;
    dev::tele::TelemetryHub* m_hub;
    QVector<CommandMethod> m_methods;
    QLocalServer* m_local = nullptr;
    QString m_socketPath;
    std::unique_ptr<WebSocketEndpoint> m_webSocket;
    ControlLease m_lease;
    EventJournal m_journal;
    JobBoard m_jobs;
    std::unique_ptr<Subscriptions> m_subscriptions;
    std::map<quint64, ApiClient*> m_clients;
    quint64 m_nextClientId = 1;
    std::vector<std::unique_ptr<CommandCall>> m_calls;
    /// Velocity jogs a client holds open (device.jog without seconds): stopped when it loses control.
    struct HeldJog {
        quint64 clientId;
        QPointer<dev::Instrument> instrument;
        int axis;
    };
    std::vector<HeldJog> m_heldJogs;
    QTimer m_tick;
    std::function<QString()> m_operatorBusy;
    bool m_shuttingDown = false;
};

} // namespace app::api
