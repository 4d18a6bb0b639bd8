#include "cli_session.h"
#include "command.h"

#include <QCoreApplication>
#include <QJsonDocument>

#include <cmath>

namespace app::cli {

namespace {
/// Marks a word the parser must not take for an option; see unmarkNegative().
const QChar kNegativeMark(0x1F);
} // namespace

QString unmarkNegative(const QString& word)
{
    return word.startsWith(kNegativeMark) ? word.mid(1) : word;
}

QString markNegative(const QString& word)
{
    // "-5", "-0.5", "-.5", "-1e3": a number, never an option name.
    if (word.size() >= 2 && word[0] == QLatin1Char('-') && (word[1].isDigit() || (word[1] == QLatin1Char('.') && word.size() > 2)))
        return kNegativeMark + word;
    return word;
}

Invocation::Invocation(QString path, QCommandLineParser& parser, LinkOptions link, QTextStream& out, QTextStream& err,
                       InvocationHost& host)
    : m_path(std::move(path)), m_parser(parser), m_link(std::move(link)), m_out(out), m_err(err), m_host(host)
{
}

Invocation::~Invocation() = default;

bool Invocation::isSet(const QString& option) const { return m_parser.isSet(option); }
bool Invocation::given(const QString& option) const { return m_parser.optionNames().contains(option); }
QString Invocation::value(const QString& option) const { return unmarkNegative(m_parser.value(option)); }

QStringList Invocation::values(const QString& option) const
{
    QStringList v = m_parser.values(option);
    for (QString& s : v)
        s = unmarkNegative(s);
    return v;
}

QStringList Invocation::arguments() const
{
    QStringList words = m_parser.positionalArguments();
    for (QString& s : words)
        s = unmarkNegative(s);
    return words;
}

void Invocation::report(const QString& message)
{
    m_reports << message;
    m_host.reported(message);
    m_err << "benchpilot-cli " << m_path << ": " << message << "\n";
    m_err.flush();
}

void Invocation::printJson(const QJsonObject& object)
{
    m_out << QJsonDocument(object).toJson(QJsonDocument::Compact) << "\n";
    m_out.flush();
    m_host.printedJson(object);
}

int Invocation::usage(const QString& message)
{
    report(message);
    return Usage;
}

int Invocation::refused(const QString& message)
{
    report(message);
    return Refused;
}

int Invocation::linkTrouble(const QString& message)
{
    report(message);
    return LinkTrouble;
}

bool Invocation::number(const QString& option, double& value, std::optional<double> fallback)
{
    if (!isSet(option)) {
        if (!fallback) {
            report(QCoreApplication::translate("app::cli", "--%1 is required").arg(option));
            return false;
        }
        value = *fallback;
        return true;
    }
    bool ok = false;
    value = this->value(option).toDouble(&ok);
    if (!ok || !std::isfinite(value)) {
        report(QCoreApplication::translate("app::cli", "--%1 '%2' is not a number").arg(option, this->value(option)));
        return false;
    }
    return true;
}

bool Invocation::numbers(const QString& option, QVector<double>& values, int count)
{
    if (!isSet(option)) {
        report(QCoreApplication::translate("app::cli", "--%1 is required").arg(option));
        return false;
    }
    values.clear();
    const QString text = value(option);
    for (const QString& part : text.split(QLatin1Char(','))) {
        bool ok = false;
        const double v = part.trimmed().toDouble(&ok);
        if (!ok || !std::isfinite(v)) {
            report(QCoreApplication::translate("app::cli", "--%1 '%2': '%3' is not a number").arg(option, text, part));
            return false;
        }
        values << v;
    }
    if (count > 0 && values.size() != count) {
        report(QCoreApplication::translate("app::cli", "--%1 '%2' needs %3 comma-separated numbers").arg(option, text).arg(count));
        return false;
    }
    return true;
}

CliSession* Invocation::session()
{
    if (!m_session)
        m_session = m_host.openSession(*this);
    return m_session.get();
}

QVector<CliSession*> Invocation::haltSessions()
{
    if (!m_session && m_moreSessions.empty()) {
        std::vector<std::unique_ptr<CliSession>> opened = m_host.openHaltSessions(*this);
        for (auto& s : opened) {
            if (!m_session)
                m_session = std::move(s);
            else
                m_moreSessions.push_back(std::move(s));
        }
    }
    QVector<CliSession*> all;
    if (m_session)
        all << m_session.get();
    for (const auto& s : m_moreSessions)
        all << s.get();
    return all;
}

std::vector<std::unique_ptr<CliSession>> InvocationHost::openHaltSessions(Invocation& inv)
{
    std::vector<std::unique_ptr<CliSession>> sessions;
    if (auto s = openSession(inv))
        sessions.push_back(std::move(s));
    return sessions;
}

ApiParam optionParam(const char* option, ParamType type, bool required)
{
    QString name = QString::fromLatin1(option);
    name.replace(QLatin1Char('-'), QLatin1Char('_'));
    return ApiParam{name, type, {}, required, QString::fromLatin1(option), {}};
}

QCommandLineOption option(const char* name, const char* description, const char* valueName, const char* fallback)
{
    QCommandLineOption o(QString::fromLatin1(name), QCoreApplication::translate("app::cli", description),
                         valueName ? QString::fromUtf8(valueName) : QString());  // "x,y;x,y;…" is UTF-8, as the source is
    if (fallback)
        o.setDefaultValue(QString::fromUtf8(fallback));
    return o;
}

} // namespace app::cli
