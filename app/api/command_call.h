#pragma once
// One call of a benchpilot-cli command made through the API: the command's words run
// through the CLI's own parser and code (app::cli::runCommandLine) on a Fiber, so its
// waits suspend it and the GUI's event loop goes on; the host side of it (where its
// instrument comes from, where its output goes, what interrupts it) is this class.
//
// The call outlives its client: a job a script started keeps running when the script
// goes (its output is then dropped, and the server hands the job to the operator).
#include "app/cli/command.h"
#include "app/cli/fiber.h"
#include "device/client/request_error.h"

#include <QJsonArray>
#include <QJsonObject>
#include <QJsonValue>
#include <QPointer>
#include <QString>
#include <QStringList>
#include <QTextStream>

#include <functional>
#include <map>
#include <memory>

namespace app::api {

class ApiClient;
class ApiServer;
struct CommandMethod;
struct ServedInstrument;

class CommandCall final : public app::cli::InvocationHost {
public:
    enum class Style {
        Method,  ///< a typed method ("device.move"): the result is the JSON the command printed
        CliRun,  ///< cli.run (benchpilot-cli --attach): the output streams back as text, then the exit code
    };

    CommandCall(ApiServer& server, ApiClient* client, const QJsonValue& id, Style style, const CommandMethod* method,
                QStringList args, QString leaseToken);
    ~CommandCall() override;

    /// Runs the call until it finishes or waits; true once it has finished (and answered).
    bool resume();
    bool finished() const { return m_fiber.finished(); }
    bool ready() const { return m_fiber.ready(); }
    /// call.cancel: interrupts it as Ctrl+C interrupts the CLI (a recipe run aborts).
    void interrupt();
    /// The server shuts down: every wait returns at once.
    void cancel() { m_fiber.cancel(); }
    /// Its client lost control: velocity motion it keeps going stops.
    void lostControl();
    /// Its client went away: nothing more is written, the call (a job) goes on.
    void detachClient();

    quint64 clientId() const { return m_clientId; }
    const QJsonValue& id() const { return m_id; }
    QString jobId() const { return m_jobId; }
    QString methodName() const;
    QString instrumentKey() const { return m_instrumentKey; }
    bool tookControl() const { return m_tookControl; }
    /// How the event log shows the call: "device.move {"targets":{"X":10}}".
    void setDescription(const QString& text) { m_description = text; }

    // app::cli::InvocationHost
    std::unique_ptr<app::cli::CliSession> openSession(app::cli::Invocation& inv) override;
    void printedJson(const QJsonObject& object) override;
    void progressed(const QJsonObject& progress) override;
    void reported(const QString& message) override { m_reports << message; }
    std::shared_ptr<void> onInterrupt(std::function<void()> interrupt) override;
    std::shared_ptr<void> onLostControl(std::function<void()> lost) override;
    std::shared_ptr<void> onAbort(std::function<void()> abort) override { return onInterrupt(std::move(abort)); }
    QString resolvePath(const QString& path) const override;
    bool canHoldJog() const override { return m_style == Style::Method; }
    void holdJog(app::cli::CliSession& session, int axis, double velocity) override;
    bool insideGui() const override { return true; }
    /// Naming no instrument while several are connected, stop and estop halt every one.
    std::vector<std::unique_ptr<app::cli::CliSession>> openHaltSessions(app::cli::Invocation& inv) override;

private:
    /// A session on `served` for this call, its refusals and the E-stop latch watched.
    std::unique_ptr<app::cli::CliSession> sessionOn(app::cli::Invocation& inv, const ServedInstrument& served);
    void body();
    void flushOutput();
    void answer();
    QString reword(const QString& message) const;

    ApiServer& m_server;
    QPointer<ApiClient> m_client;
    quint64 m_clientId;
    QString m_clientName;
    QString m_cwd;
    QJsonValue m_id;
    Style m_style;
    const CommandMethod* m_method;
    QStringList m_args;
    QString m_leaseToken;
    QString m_description;
    app::cli::Fiber m_fiber;

    // What the command did.
    int m_exit = -1;
    const app::cli::Command* m_ran = nullptr;
    QString m_outText, m_errText;
    int m_outSent = 0, m_errSent = 0;
    QStringList m_reports;
    QJsonArray m_objects;             ///< every object it printed
    int m_progressSent = 0;           ///< of those, sent as call.progress
    int m_outAtLastObject = 0;        ///< where stdout stood when the last object was printed
    QString m_instrumentKey;
    bool m_tookControl = false;       ///< it needed the lease and had it
    bool m_notInControl = false;
    bool m_badInstrument = false;     ///< the words named no instrument the GUI has (or none when two are connected)
    QString m_notInControlWhy;
    bool m_interrupted = false;
    QString m_jobId;
    std::optional<dev::RequestError> m_refusal;
    bool m_estopLatched = false;

    std::map<int, std::function<void()>> m_interruptHooks, m_lostHooks;
    int m_nextHook = 0;
};

} // namespace app::api
