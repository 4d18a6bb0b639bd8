#include "command_call.h"

#include "api_client.h"
#include "api_server.h"
#include "command_methods.h"
#include "json_rpc.h"

#include "app/cli/cli_session.h"

#include <QCoreApplication>
#include <QDir>
#include <QJsonDocument>

namespace app::api {

namespace {
[[maybe_unused]] QString tr(const char* text) { return QCoreApplication::translate("app::api::CommandCall", text); }

/// A guard that removes a hook from its map when the command lets go of it.
std::shared_ptr<void> hookGuard(std::map<int, std::function<void()>>& hooks, int key)
{
    return std::shared_ptr<void>(nullptr, [&hooks, key](void*) { hooks.erase(key); });
}

} // namespace

CommandCall::CommandCall(ApiServer& server, ApiClient* client, const QJsonValue& id, Style style, const CommandMethod* method,
                         QStringList args, QString leaseToken)
    : m_server(server), m_client(client), m_clientId(client->id()), m_clientName(client->name()), m_cwd(client->cwd()), m_id(id),
      m_style(style), m_method(method), m_args(std::move(args)), m_leaseToken(std::move(leaseToken)), m_fiber([this] { body(); })
{
    client->callStarted();
}

CommandCall::~CommandCall()
{
    if (m_client)
        m_client->callEnded();
}

QString CommandCall::methodName() const
{
    if (m_method)
        return m_method->method;
    QString path;
    if (app::cli::findCommand(m_args, &path))
        return QStringLiteral("cli.run %1").arg(path);
    return QStringLiteral("cli.run");
}

void CommandCall::body()
{
    QTextStream out(&m_outText), err(&m_errText);
    m_exit = app::cli::runCommandLine(m_args, out, err, *this, &m_ran);
    out.flush();
    err.flush();
}

bool CommandCall::resume()
{
    const bool done = m_fiber.resume();
    flushOutput();
    if (done)
        answer();
    return done;
}

void CommandCall::flushOutput()
{
    if (!m_client || m_id.isUndefined())  // a notification is never answered, nor its output sent
        return;
    if (m_style == Style::CliRun) {
        // The text as it comes, so an attached `recipe run` prints each well as it is done.
        auto send = [this](const QString& text, int& sent, const char* stream) {
            if (text.size() > sent) {
                m_client->send(notificationLine(QStringLiteral("cli.output"),
                                                QJsonObject{{QStringLiteral("call"), m_id},
                                                            {QStringLiteral("stream"), QString::fromLatin1(stream)},
                                                            {QStringLiteral("text"), text.mid(sent)}}));
                sent = static_cast<int>(text.size());
            }
        };
        send(m_outText, m_outSent, "stdout");
        send(m_errText, m_errSent, "stderr");
        return;
    }
    // Every object but the newest went out as progress (the newest may be the result).
    while (m_progressSent + 1 < m_objects.size()) {
        m_client->send(notificationLine(QStringLiteral("call.progress"),
                                        QJsonObject{{QStringLiteral("call"), m_id}, {QStringLiteral("data"), m_objects[m_progressSent]}}),
                       ApiClient::Priority::Update);
        ++m_progressSent;
    }
}

QString CommandCall::reword(const QString& message) const { return m_method ? apiWording(*m_method, message) : message; }

void CommandCall::answer()
{
    if (!m_jobId.isEmpty()) {
        m_server.jobs().finish(m_jobId, m_exit == app::cli::Ok ? QStringLiteral("finished") : QStringLiteral("stopped"));
        if (!m_objects.isEmpty())
            m_server.jobs().setProgress(m_jobId, m_objects.last().toObject());
    }
    if (m_tookControl)
        m_server.logActivity(m_clientName, QStringLiteral("call"),
                             m_exit == app::cli::Ok ? tr("%1: done").arg(methodName())
                                               : tr("%1: %2").arg(methodName(), reword(m_reports.value(m_reports.size() - 1, tr("failed")))),
                             m_exit != app::cli::Ok);
    if (!m_client || m_id.isUndefined())
        return;
    if (m_style == Style::CliRun) {
        // Not in control is a refusal for a shell script (the CLI's exit code 2); an
        // instrument the words must name is a usage error (1).
        const int code = m_notInControl ? int(app::cli::Refused) : m_badInstrument ? int(app::cli::Usage) : m_exit;
        m_client->send(resultLine(m_id, QJsonObject{{QStringLiteral("exit_code"), code}}));
        return;
    }
    if (m_exit == app::cli::Ok) {
        // The last object printed, unless the command ended with a sentence after it
        // (scan run's "144 tiles taken; wrote …"): then that text, the objects having
        // gone out as progress.
        const QString trailing = m_outText.mid(m_outAtLastObject).trimmed();
        QJsonValue result;
        if (!m_objects.isEmpty() && trailing.isEmpty()) {
            result = m_objects.last();
        } else {
            if (m_progressSent < m_objects.size())
                m_client->send(notificationLine(QStringLiteral("call.progress"),
                                                QJsonObject{{QStringLiteral("call"), m_id}, {QStringLiteral("data"), m_objects.last()}}),
                               ApiClient::Priority::Update);
            result = QJsonObject{{QStringLiteral("text"), m_objects.isEmpty() ? m_outText : trailing}};
        }
        m_client->send(resultLine(m_id, result));
        return;
    }
    int code = code::kInternalError;
    if (m_notInControl) {
        code = code::kNotInControl;
    } else if (m_interrupted) {
        code = code::kCancelled;
    } else if (m_exit == app::cli::Usage || m_badInstrument) {
        code = code::kInvalidParams;
    } else if (m_exit == app::cli::LinkTrouble) {
        code = code::kLinkTrouble;
    } else if (m_exit == app::cli::Refused) {
        code = code::kRefused;
        if (m_refusal) {
            switch (m_refusal->code) {
            case dev::proto::ErrorCode::NotHomed: code = code::kNotHomed; break;
            case dev::proto::ErrorCode::SoftLimit: code = code::kSoftLimit; break;
            case dev::proto::ErrorCode::EStopActive: code = code::kEStopLatched; break;
            default: break;
            }
        } else if (m_estopLatched) {
            code = code::kEStopLatched;
        }
    }
    QStringList messages;
    for (const QString& m : m_reports)
        messages << reword(m);
    if (messages.isEmpty())  // the parser's own complaints ("benchpilot-cli move: unknown option …")
        for (const QString& line : m_errText.split(QLatin1Char('\n'), Qt::SkipEmptyParts))
            if (line.startsWith(QLatin1String("benchpilot-cli")) && line.contains(QLatin1String(": ")))
                messages << reword(line.section(QStringLiteral(": "), 1));
    if (m_notInControl && (messages.isEmpty() || messages.last() != reword(m_notInControlWhy)))
        messages << reword(m_notInControlWhy);
    QString message = messages.isEmpty() ? QString() : messages.last();
    if (message.isEmpty()) {
        // Text the command wrote on stderr (recipe validate lists problems there).
        message = reword(m_errText.trimmed().section(QLatin1Char('\n'), -1));
        if (message.isEmpty())
            message = tr("failed with exit code %1").arg(m_exit);
    }
    // Not in control is a refusal (the CLI's exit code 2), whatever the command made of it.
    QJsonObject data{{QStringLiteral("exit_code"), m_notInControl ? int(app::cli::Refused) : m_exit}};
    if (messages.size() > 1)
        data.insert(QStringLiteral("messages"), QJsonArray::fromStringList(messages));
    if (!m_objects.isEmpty())
        data.insert(QStringLiteral("result"), m_objects.last());
    if (m_refusal)
        data.insert(QStringLiteral("device_error"), QString::fromLatin1(dev::proto::errorCodeName(m_refusal->code)));
    if (code == code::kInvalidParams && m_method) {
        // The field, when the message starts with one ("speed needs a positive number").
        for (const MethodParam& p : methodParams(*m_method))
            if (message.startsWith(p.name + QLatin1Char(' ')) || message.startsWith(p.name + QLatin1Char(':'))) {
                data.insert(QStringLiteral("field"), p.name);
                break;
            }
    }
    m_client->send(errorLine(m_id, code, message, data));
}

void CommandCall::interrupt()
{
    m_interrupted = true;
    const auto hooks = m_interruptHooks;  // a hook may let go of itself
    for (const auto& [key, hook] : hooks)
        hook();
}

void CommandCall::lostControl()
{
    const auto hooks = m_lostHooks;
    for (const auto& [key, hook] : hooks)
        hook();
    if (!m_jobId.isEmpty())
        m_server.jobs().handOver(m_jobId);
}

void CommandCall::detachClient()
{
    if (m_client)
        m_client->callEnded();
    m_client = nullptr;
}

std::unique_ptr<app::cli::CliSession> CommandCall::openSession(app::cli::Invocation& inv)
{
    const app::cli::LinkOptions& link = inv.link();
    if (!link.port.isEmpty()) {
        inv.report(tr("inside the GUI its own connections are used: --port does not apply (name the instrument with --instrument analyzer|stage)"));
        return nullptr;
    }
    QString why;
    const ServedInstrument* served = m_server.resolveInstrument(link.sim, &why, &m_badInstrument);
    if (!served) {
        inv.report(why);
        return nullptr;
    }
    m_instrumentKey = served->key;
    const app::cli::Command* cmd = app::cli::findCommand(m_args);
    const app::cli::ApiSpec spec = cmd ? cmd->api : app::cli::ApiSpec{};
    const bool control = spec.access == app::cli::Access::Control && !(spec.readsWithoutArguments && inv.arguments().isEmpty());
    if (control) {
        if (!m_server.mayControl(m_clientId, m_clientName, m_leaseToken, m_style == Style::CliRun, &why)) {
            m_notInControl = true;
            m_notInControlWhy = why;
            inv.report(why);
            return nullptr;
        }
        m_tookControl = true;
        m_server.logActivity(m_clientName, QStringLiteral("call"),
                             tr("%1 on the %2").arg(m_description.isEmpty() ? methodName() : m_description, served->key), false);
        m_jobId = m_server.jobs().add(m_method ? m_method->method : methodName(), served->key, m_clientName, true);
    }
    if (spec.access == app::cli::Access::Safety)  // stop and E-stop change things too: in the log, never gated
        m_server.logActivity(m_clientName, QStringLiteral("call"),
                             tr("%1 on the %2").arg(m_description.isEmpty() ? methodName() : m_description, served->key), false);
    return sessionOn(inv, *served);
}

std::unique_ptr<app::cli::CliSession> CommandCall::sessionOn(app::cli::Invocation& inv, const ServedInstrument& served)
{
    auto session = std::make_unique<app::cli::CliSession>(inv, served.instrument.data());
    const QString consumer = QStringLiteral("api call %1 of client %2 on %3").arg(reinterpret_cast<quintptr>(this)).arg(m_clientId).arg(served.key);
    const ServedInstrument copy = served;
    if (served.simulator)
        session->setSimulatorLookup(served.simulator);
    session->setTelemetryWish([this, consumer, copy](const QVector<dev::proto::ChannelRef>& channels, int rateHz) {
        m_server.wantTelemetry(consumer, copy, channels, rateHz);
    });
    // A refusal the command reports comes through the instrument's signal or request():
    // remember the device's code for the error the client gets.
    QObject::connect(served.instrument.data(), &dev::Instrument::statusChanged, session.get(),
                     [this](const dev::InstrumentStatus& st) { m_estopLatched = st.estop; });
    QObject::connect(served.instrument.data(), &dev::Instrument::requestFailed, session.get(), [this](const dev::RequestError& e) {
        if (e.kind == dev::RequestError::Kind::Device)
            m_refusal = e;
    });
    m_estopLatched = served.instrument->status().estop;
    return session;
}

std::vector<std::unique_ptr<app::cli::CliSession>> CommandCall::openHaltSessions(app::cli::Invocation& inv)
{
    // An instrument named, or at most one connected: as any command (a named one that is
    // not connected is said so; none connected is link trouble).
    const QVector<const ServedInstrument*> ready = m_server.connectedInstruments();
    if (!inv.link().sim.isEmpty() || !inv.link().port.isEmpty() || ready.size() < 2)
        return app::cli::InvocationHost::openHaltSessions(inv);
    // None named with several connected: every one, as the GUI's E-stop button and Esc do.
    // A halt is never refused for want of saying which.
    QStringList keys;
    std::vector<std::unique_ptr<app::cli::CliSession>> sessions;
    for (const ServedInstrument* served : ready) {
        keys << served->key;
        sessions.push_back(sessionOn(inv, *served));
    }
    m_instrumentKey = keys.join(QStringLiteral(", "));
    m_server.logActivity(m_clientName, QStringLiteral("call"),
                         tr("%1 on every connected instrument (%2)").arg(m_description.isEmpty() ? methodName() : m_description, m_instrumentKey),
                         false);
    return sessions;
}

void CommandCall::printedJson(const QJsonObject& object)
{
    m_objects.append(object);
    m_outAtLastObject = static_cast<int>(m_outText.size());
    if (!m_jobId.isEmpty())
        m_server.jobs().setProgress(m_jobId, object);
}

void CommandCall::progressed(const QJsonObject& progress)
{
    if (!m_jobId.isEmpty())
        m_server.jobs().setProgress(m_jobId, progress);
    // A method's caller gets it as call.progress (cli.run's gets the CLI's text instead).
    if (m_client && !m_id.isUndefined() && m_style != Style::CliRun)
        m_client->send(notificationLine(QStringLiteral("call.progress"), QJsonObject{{QStringLiteral("call"), m_id}, {QStringLiteral("data"), progress}}),
                       ApiClient::Priority::Update);
}

std::shared_ptr<void> CommandCall::onInterrupt(std::function<void()> interrupt)
{
    const int key = m_nextHook++;
    m_interruptHooks[key] = std::move(interrupt);
    return hookGuard(m_interruptHooks, key);
}

std::shared_ptr<void> CommandCall::onLostControl(std::function<void()> lost)
{
    const int key = m_nextHook++;
    m_lostHooks[key] = std::move(lost);
    return hookGuard(m_lostHooks, key);
}

QString CommandCall::resolvePath(const QString& path) const
{
    if (path.isEmpty() || QDir::isAbsolutePath(path) || m_cwd.isEmpty())
        return path;
    return QDir(m_cwd).absoluteFilePath(path);
}

void CommandCall::holdJog(app::cli::CliSession& session, int axis, double velocity)
{
    m_server.holdJog(m_clientId, session.instrument(), axis, velocity);
}

} // namespace app::api
