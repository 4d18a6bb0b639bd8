#include "openrpc.h"

#include "control_lease.h"

#include <QCoreApplication>
#include <QJsonArray>

namespace app::api {

namespace {
[[maybe_unused]] QString tr(const char* text) { return QCoreApplication::translate("app::api", text); }

QJsonObject typed(const char* type) { return QJsonObject{{QStringLiteral("type"), QString::fromLatin1(type)}}; }
QJsonObject numberOrNumbers()
{
    return QJsonObject{{QStringLiteral("oneOf"),
                        QJsonArray{typed("number"), QJsonObject{{QStringLiteral("type"), QStringLiteral("array")},
                                                                {QStringLiteral("items"), typed("number")}}}}};
}

QJsonObject param(const QString& name, const QJsonObject& schema, const QString& description, bool required = false)
{
    return QJsonObject{{QStringLiteral("name"), name},
                       {QStringLiteral("schema"), schema},
                       {QStringLiteral("description"), description},
                       {QStringLiteral("required"), required}};
}

QJsonObject method(const QString& name, const QString& summary, const QJsonArray& params, const QString& access,
                   const QString& description = {})
{
    QJsonObject m{{QStringLiteral("name"), name},
                  {QStringLiteral("summary"), summary},
                  {QStringLiteral("paramStructure"), QStringLiteral("by-name")},
                  {QStringLiteral("params"), params},
                  {QStringLiteral("result"), QJsonObject{{QStringLiteral("name"), QStringLiteral("result")}, {QStringLiteral("schema"), typed("object")}}},
                  {QStringLiteral("x-access"), access}};
    if (!description.isEmpty())
        m.insert(QStringLiteral("description"), description);
    return m;
}

/// The API's own methods (not commands of the CLI).
QJsonArray builtinMethods()
{
    const QJsonObject leaseSchema = typed("string");
    return {
        method(QStringLiteral("rpc.discover"), tr("this document"), {}, QStringLiteral("read")),
        method(QStringLiteral("client.hello"), tr("say who is calling (shown in the GUI) and where relative paths start"),
               {param(QStringLiteral("name"), typed("string"), tr("a name for the GUI and the event log")),
                param(QStringLiteral("cwd"), typed("string"), tr("the client's working directory: relative paths in calls start here"))},
               QStringLiteral("read")),
        method(QStringLiteral("control.acquire"), tr("take the control lease (one holder at a time)"),
               {param(QStringLiteral("client"), typed("string"), tr("a name for the GUI and the event log"))}, QStringLiteral("read"),
               tr("Returns {\"lease\": TOKEN}. Send control.heartbeat with it at least every %1 ms (100 ms is a good pace); "
                  "the operator can take control back at any time.")
                   .arg(ControlLease::kHeartbeatTimeoutMs)),
        method(QStringLiteral("control.release"), tr("give the control lease back"),
               {param(QStringLiteral("lease"), leaseSchema, tr("the lease from control.acquire"), true)}, QStringLiteral("read")),
        method(QStringLiteral("control.heartbeat"), tr("keep the control lease (send as a notification, no id, every 100 ms)"),
               {param(QStringLiteral("lease"), leaseSchema, tr("the lease from control.acquire"), true)}, QStringLiteral("read")),
        method(QStringLiteral("control.status"), tr("who holds control, since when"), {}, QStringLiteral("read")),
        method(QStringLiteral("subscribe"), tr("live data: positions, state, jobs, log, telemetry"),
               {param(QStringLiteral("topics"), typed("object"),
                      tr("topic → options: {\"positions\": {\"instrument\": \"stage\", \"max_hz\": 50}, \"state\": {}, \"jobs\": {}, "
                         "\"log\": {}, \"telemetry\": {\"instrument\": \"stage\", \"channels\": [\"X.measured\"], \"rate_hz\": 1000}}"),
                      true)},
               QStringLiteral("read")),
        method(QStringLiteral("unsubscribe"), tr("end a subscription"),
               {param(QStringLiteral("subscription"), typed("integer"), tr("the number subscribe answered"), true)}, QStringLiteral("read")),
        method(QStringLiteral("call.cancel"), tr("interrupt a running call of this client, as Ctrl+C interrupts the CLI"),
               {param(QStringLiteral("call"), QJsonObject{{QStringLiteral("type"), QJsonArray{QStringLiteral("integer"), QStringLiteral("string")}}},
                      tr("the id of the call"), true)},
               QStringLiteral("read")),
        method(QStringLiteral("cli.run"), tr("run benchpilot-cli's words as benchpilot-cli --attach does: output as cli.output, then the exit code"),
               {param(QStringLiteral("argv"), QJsonObject{{QStringLiteral("type"), QStringLiteral("array")}, {QStringLiteral("items"), typed("string")}},
                      tr("the words after benchpilot-cli"), true),
                param(QStringLiteral("cwd"), typed("string"), tr("where relative paths start")),
                param(QStringLiteral("client"), typed("string"), tr("a name for the GUI and the event log"))},
               QStringLiteral("control")),
    };
}
} // namespace

QString accessName(app::cli::Access access, bool readsWithoutArguments)
{
    switch (access) {
    case app::cli::Access::Compute: return QStringLiteral("compute");
    case app::cli::Access::Read: return QStringLiteral("read");
    case app::cli::Access::Safety: return QStringLiteral("safety");
    case app::cli::Access::Control: return readsWithoutArguments ? QStringLiteral("control when setting") : QStringLiteral("control");
    }
    return QStringLiteral("control");
}

QJsonObject paramSchema(app::cli::ParamType type, const QStringList& choices)
{
    using T = app::cli::ParamType;
    switch (type) {
    case T::Text:
        if (!choices.isEmpty())
            return QJsonObject{{QStringLiteral("type"), QStringLiteral("string")}, {QStringLiteral("enum"), QJsonArray::fromStringList(choices)}};
        return QJsonObject{{QStringLiteral("type"), QJsonArray{QStringLiteral("string"), QStringLiteral("number")}}};
    case T::Number: return typed("number");
    case T::Integer: return typed("integer");
    case T::Boolean: return typed("boolean");
    case T::Numbers: return numberOrNumbers();
    case T::Axis: return QJsonObject{{QStringLiteral("type"), QStringLiteral("string")}, {QStringLiteral("pattern"), QStringLiteral("^[A-Za-z]$")}};
    case T::Axes:
        return QJsonObject{{QStringLiteral("oneOf"),
                            QJsonArray{QJsonObject{{QStringLiteral("type"), QStringLiteral("string")}, {QStringLiteral("pattern"), QStringLiteral("^[A-Za-z]+$")}},
                                       QJsonObject{{QStringLiteral("type"), QStringLiteral("array")}, {QStringLiteral("items"), typed("string")}}}}};
    case T::AxisValues:
        return QJsonObject{{QStringLiteral("type"), QStringLiteral("object")}, {QStringLiteral("additionalProperties"), numberOrNumbers()}};
    case T::AxisRanges:
        return QJsonObject{{QStringLiteral("type"), QStringLiteral("object")},
                           {QStringLiteral("additionalProperties"),
                            QJsonObject{{QStringLiteral("type"), QStringLiteral("array")}, {QStringLiteral("items"), typed("number")},
                                        {QStringLiteral("minItems"), 2}, {QStringLiteral("maxItems"), 2}}}};
    case T::File:
        return QJsonObject{{QStringLiteral("type"), QStringLiteral("string")}, {QStringLiteral("x-path"), true}};
    }
    return typed("string");
}

QJsonObject openRpcDocument(const QVector<CommandMethod>& methods)
{
    QJsonArray list = builtinMethods();
    for (const CommandMethod& m : methods) {
        QJsonArray params;
        for (const MethodParam& p : methodParams(m)) {
            QJsonObject o = param(p.name, paramSchema(p.type, p.choices), apiWording(m, p.description), p.required);
            if (!p.defaultValue.isEmpty())
                o.insert(QStringLiteral("x-default"), p.defaultValue);
            if (!p.option.isEmpty() && !p.common)
                o.insert(QStringLiteral("x-cli"), QStringLiteral("--") + p.option);
            params.append(o);
        }
        const app::cli::ApiSpec& spec = m.command->api;
        QJsonObject o = method(m.method, m.command->summary, params, accessName(spec.access, spec.readsWithoutArguments),
                               apiWording(m, m.command->description));
        o.insert(QStringLiteral("x-cli"), QStringLiteral("benchpilot-cli %1").arg(m.path));
        if (!spec.example.isEmpty()) {
            QJsonArray exampleParams;
            for (auto it = spec.example.begin(); it != spec.example.end(); ++it)
                exampleParams.append(QJsonObject{{QStringLiteral("name"), it.key()}, {QStringLiteral("value"), it.value()}});
            o.insert(QStringLiteral("examples"), QJsonArray{QJsonObject{{QStringLiteral("name"), m.method}, {QStringLiteral("params"), exampleParams}}});
        }
        list.append(o);
    }
    return QJsonObject{{QStringLiteral("openrpc"), QStringLiteral("1.2.6")},
                       {QStringLiteral("info"),
                        QJsonObject{{QStringLiteral("title"), QStringLiteral("BenchPilot scripting API")},
                                    {QStringLiteral("version"), QStringLiteral(BP_VERSION)},
                                    {QStringLiteral("description"), tr("JSON-RPC 2.0, one object per line; see docs/api.md")}}},
                       {QStringLiteral("methods"), list}};
}

} // namespace app::api
