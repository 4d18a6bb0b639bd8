#include "json_rpc.h"

#include <QCoreApplication>
#include <QJsonDocument>
#include <QJsonParseError>

namespace app::api {

namespace {
[[maybe_unused]] QString tr(const char* text) { return QCoreApplication::translate("app::api", text); }

Request invalid(const QJsonValue& id, int errorCode, const QString& message)
{
    Request r;
    r.kind = Request::Kind::Invalid;
    r.id = id;
    r.errorCode = errorCode;
    r.errorMessage = message;
    return r;
}
} // namespace

Request readRequest(const QByteArray& line)
{
    QJsonParseError pe;
    const QJsonDocument doc = QJsonDocument::fromJson(line, &pe);
    if (pe.error != QJsonParseError::NoError) {
        // Qt reads only an object or an array at the top: a bare "42" is JSON all the same.
        QJsonParseError wrapped;
        QJsonDocument::fromJson('[' + line + ']', &wrapped);
        if (wrapped.error == QJsonParseError::NoError)
            return invalid(QJsonValue::Null, code::kInvalidRequest, tr("a request is a JSON object"));
        return invalid(QJsonValue::Null, code::kParseError,
                       tr("parse error at byte %1: %2").arg(pe.offset).arg(pe.errorString()));
    }
    if (doc.isArray())
        return invalid(QJsonValue::Null, code::kInvalidRequest, tr("batches are not supported: send one request per line"));
    if (!doc.isObject())
        return invalid(QJsonValue::Null, code::kInvalidRequest, tr("a request is a JSON object"));
    const QJsonObject o = doc.object();
    // The id first, so that every later complaint can be matched to its call.
    QJsonValue id = QJsonValue::Null;
    const bool hasId = o.contains(QStringLiteral("id"));
    if (hasId) {
        const QJsonValue v = o.value(QStringLiteral("id"));
        if (!v.isString() && !v.isDouble() && !v.isNull())
            return invalid(QJsonValue::Null, code::kInvalidRequest, tr("id: must be a number or a string"));
        id = v;
    }
    if (o.value(QStringLiteral("jsonrpc")).toString() != QLatin1String("2.0"))
        return invalid(id, code::kInvalidRequest, tr("jsonrpc: must be \"2.0\""));
    const QJsonValue method = o.value(QStringLiteral("method"));
    if (!method.isString() || method.toString().isEmpty())
        return invalid(id, code::kInvalidRequest, tr("method: must be a non-empty string"));
    Request r;
    r.id = id;
    r.method = method.toString();
    if (o.contains(QStringLiteral("params"))) {
        const QJsonValue p = o.value(QStringLiteral("params"));
        if (p.isArray())
            return invalid(id, code::kInvalidParams, tr("params: give them by name (an object), not by position"));
        if (!p.isObject())
            return invalid(id, code::kInvalidRequest, tr("params: must be an object"));
        r.params = p.toObject();
    }
    r.kind = hasId ? Request::Kind::Call : Request::Kind::Notification;
    return r;
}

QByteArray resultLine(const QJsonValue& id, const QJsonValue& result)
{
    return QJsonDocument(QJsonObject{{QStringLiteral("jsonrpc"), QStringLiteral("2.0")}, {QStringLiteral("id"), id},
                                     {QStringLiteral("result"), result}})
               .toJson(QJsonDocument::Compact)
        + '\n';
}

QByteArray errorLine(const QJsonValue& id, int errorCode, const QString& message, const QJsonValue& data)
{
    QJsonObject e{{QStringLiteral("code"), errorCode}, {QStringLiteral("message"), message}};
    if (!data.isUndefined() && !data.isNull())
        e.insert(QStringLiteral("data"), data);
    return QJsonDocument(QJsonObject{{QStringLiteral("jsonrpc"), QStringLiteral("2.0")}, {QStringLiteral("id"), id},
                                     {QStringLiteral("error"), e}})
               .toJson(QJsonDocument::Compact)
        + '\n';
}

QByteArray notificationLine(const QString& method, const QJsonObject& params)
{
    return QJsonDocument(QJsonObject{{QStringLiteral("jsonrpc"), QStringLiteral("2.0")}, {QStringLiteral("method"), method},
                                     {QStringLiteral("params"), params}})
               .toJson(QJsonDocument::Compact)
        + '\n';
}

void LineSplitter::feed(const QByteArray& bytes, const std::function<void(const QByteArray&)>& line,
                        const std::function<void()>& overlong)
{
    int from = 0;
    while (from < bytes.size()) {
        const int nl = bytes.indexOf('\n', from);
        const int end = nl < 0 ? bytes.size() : nl;
        if (m_skipping) {
            if (nl >= 0)
                m_skipping = false;
        } else if (m_buffer.size() + (end - from) > kMaxLineBytes) {
            m_buffer.clear();
            overlong();
            m_skipping = nl < 0;
        } else {
            m_buffer.append(bytes.constData() + from, end - from);
            if (nl >= 0) {
                QByteArray complete;
                complete.swap(m_buffer);
                if (complete.endsWith('\r'))  // a client that ends lines the Windows way
                    complete.chop(1);
                if (!complete.trimmed().isEmpty())
                    line(complete);
            }
        }
        from = nl < 0 ? bytes.size() : nl + 1;
    }
}

} // namespace app::api
