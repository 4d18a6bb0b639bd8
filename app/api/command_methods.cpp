#include "command_methods.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <QLocale>

#include <algorithm>
#include <cmath>

namespace app::api {
namespace {

[[maybe_unused]] QString tr(const char* text) { return QCoreApplication::translate("app::api", text); }

void collect(const std::vector<app::cli::Command>& list, const QString& prefix, QVector<CommandMethod>& out)
{
    for (const auto& c : list) {
        const QString path = prefix.isEmpty() ? c.name : prefix + QLatin1Char(' ') + c.name;
        if (!c.subcommands.empty()) {
            collect(c.subcommands, path, out);
            continue;
        }
        if (!c.api.offered || !c.run)
            continue;
        out.push_back({app::cli::methodName(path, c), path, &c});
    }
}

QString jsonName(const QString& option)
{
    QString n = option;
    n.replace(QLatin1Char('-'), QLatin1Char('_'));
    return n;
}

QString typeName(const QJsonValue& v)
{
    switch (v.type()) {
    case QJsonValue::Null: return QStringLiteral("null");
    case QJsonValue::Bool: return QStringLiteral("a boolean");
    case QJsonValue::Double: return QStringLiteral("a number");
    case QJsonValue::String: return QStringLiteral("a string");
    case QJsonValue::Array: return QStringLiteral("an array");
    case QJsonValue::Object: return QStringLiteral("an object");
    case QJsonValue::Undefined: break;
    }
    return QStringLiteral("nothing");
}

/// A number as the command line would be given it: shortest exact text.
QString numberText(double v) { return QString::number(v, 'g', QLocale::FloatingPointShortest); }

bool finiteNumber(const QJsonValue& v) { return v.isDouble() && std::isfinite(v.toDouble()); }

/// The value of a Numbers parameter as "a,b,c".
bool numbersText(const QJsonValue& v, QString* text, QString* why)
{
    if (finiteNumber(v)) {
        *text = numberText(v.toDouble());
        return true;
    }
    if (!v.isArray() || v.toArray().isEmpty()) {
        *why = tr("expected an array of numbers, got %1").arg(typeName(v));
        return false;
    }
    QStringList parts;
    for (const QJsonValue& e : v.toArray()) {
        if (!finiteNumber(e)) {
            *why = tr("expected an array of numbers, found %1 in it").arg(typeName(e));
            return false;
        }
        parts << numberText(e.toDouble());
    }
    *text = parts.join(QLatin1Char(','));
    return true;
}

bool isAxisLetter(const QString& s) { return s.size() == 1 && s[0].isLetter(); }

} // namespace

QVector<CommandMethod> commandMethods()
{
    QVector<CommandMethod> out;
    collect(app::cli::commands(), QString(), out);
    return out;
}

const CommandMethod* findMethod(const QVector<CommandMethod>& methods, const QString& method)
{
    for (const auto& m : methods)
        if (m.method == method)
            return &m;
    return nullptr;
}

QVector<MethodParam> methodParams(const CommandMethod& m)
{
    QVector<MethodParam> out;
    const app::cli::ApiSpec& spec = m.command->api;
    for (const app::cli::ApiParam& p : spec.params)
        if (p.option.isEmpty())
            out.push_back({p.name, p.type, p.description, p.required, {}, p.choices, {}, false});
    for (const QCommandLineOption& o : m.command->options) {
        const QString option = o.names().constLast();
        if (spec.cliOnly.contains(option))
            continue;
        MethodParam mp;
        mp.option = option;
        mp.name = jsonName(option);
        mp.type = o.valueName().isEmpty() ? app::cli::ParamType::Boolean : app::cli::ParamType::Text;
        mp.description = o.description();
        mp.defaultValue = o.defaultValues().join(QLatin1Char(','));
        for (const app::cli::ApiParam& p : spec.params)
            if (p.option == option) {
                mp.name = p.name;
                mp.type = p.type;
                mp.required = p.required;
                mp.choices = p.choices;
                if (!p.description.isEmpty())
                    mp.description = p.description;
            }
        out.push_back(mp);
    }
    if (spec.access != app::cli::Access::Compute || spec.instrumentParam)
        out.push_back({QStringLiteral("instrument"), app::cli::ParamType::Text,
                       spec.access == app::cli::Access::Safety
                           ? tr("analyzer or stage; left out, every connected instrument (never refused for not saying which)")
                           : tr("analyzer or stage; may be left out when only one is connected"),
                       false, QStringLiteral("instrument"), {QStringLiteral("analyzer"), QStringLiteral("stage")}, {}, true});
    if (spec.access == app::cli::Access::Control || spec.access == app::cli::Access::Safety)
        out.push_back({QStringLiteral("timeout"), app::cli::ParamType::Number, tr("longest wait for motion to finish, s (default: 120)"), false,
                       QStringLiteral("timeout"), {}, {}, true});
    if (spec.access == app::cli::Access::Control)
        out.push_back({QStringLiteral("lease"), app::cli::ParamType::Text,
                       spec.readsWithoutArguments ? tr("the lease from control.acquire (needed only when setting)")
                                                  : tr("the lease from control.acquire"),
                       false, {}, {}, {}, true});
    return out;
}

bool needsLease(const CommandMethod& m, bool hasPositionalWords)
{
    const app::cli::ApiSpec& spec = m.command->api;
    if (spec.access != app::cli::Access::Control)
        return false;
    return !spec.readsWithoutArguments || hasPositionalWords;
}

bool toWords(const CommandMethod& m, const QJsonObject& params, QStringList* words, bool* positional, ParamProblem* problem)
{
    const QVector<MethodParam> known = methodParams(m);
    auto fail = [problem](const QString& field, const QString& message) {
        *problem = {field, message};
        return false;
    };
    for (auto it = params.begin(); it != params.end(); ++it) {
        if (it.key() == QLatin1String("lease"))
            continue;
        const bool isKnown = std::any_of(known.begin(), known.end(), [&](const MethodParam& p) { return p.name == it.key(); });
        if (!isKnown) {
            QStringList names;
            for (const auto& p : known)
                if (p.name != QLatin1String("lease"))
                    names << p.name;
            // An empty name still needs a field the client can read.
            return fail(it.key().isEmpty() ? QStringLiteral("\"\"") : it.key(),
                        names.isEmpty() ? tr("unknown parameter (this method takes none)")
                                                  : tr("unknown parameter (parameters: %1)").arg(names.join(QStringLiteral(", "))));
        }
    }
    QStringList optionWords, positionalWords;
    bool missingPositional = false;
    QString missingName;
    for (const MethodParam& p : known) {
        if (p.name == QLatin1String("lease"))
            continue;
        const QJsonValue v = params.value(p.name);
        if (v.isUndefined() || v.isNull()) {
            if (p.required)
                return fail(p.name, tr("required"));
            if (p.option.isEmpty() && !missingPositional) {
                missingPositional = true;
                missingName = p.name;
            }
            continue;
        }
        if (p.option.isEmpty() && missingPositional)
            return fail(p.name, tr("given without %1, which comes before it").arg(missingName));
        QStringList texts;  // one word each (positional) or one option each
        QString why;
        switch (p.type) {
        case app::cli::ParamType::Boolean:
            if (!v.isBool())
                return fail(p.name, tr("expected true or false, got %1").arg(typeName(v)));
            if (v.toBool())
                optionWords << QStringLiteral("--") + p.option;
            continue;
        case app::cli::ParamType::Number:
            if (!finiteNumber(v))
                return fail(p.name, tr("expected a number, got %1").arg(typeName(v)));
            texts << numberText(v.toDouble());
            break;
        case app::cli::ParamType::Integer:
            if (!finiteNumber(v) || v.toDouble() != std::floor(v.toDouble()) || std::abs(v.toDouble()) > 1e15)
                return fail(p.name, tr("expected a whole number, got %1").arg(v.isDouble() ? numberText(v.toDouble()) : typeName(v)));
            texts << numberText(v.toDouble());
            break;
        case app::cli::ParamType::Numbers: {
            QString t;
            if (!numbersText(v, &t, &why))
                return fail(p.name, why);
            texts << t;
            break;
        }
        case app::cli::ParamType::Axis:
            if (!v.isString() || !isAxisLetter(v.toString()))
                return fail(p.name, tr("expected one axis letter such as \"X\", got %1").arg(v.isString() ? QLatin1Char('"') + v.toString() + QLatin1Char('"') : typeName(v)));
            texts << v.toString();
            break;
        case app::cli::ParamType::Axes: {
            QString letters;
            if (v.isString()) {
                letters = v.toString();
            } else if (v.isArray()) {
                for (const QJsonValue& e : v.toArray()) {
                    if (!e.isString() || !isAxisLetter(e.toString()))
                        return fail(p.name, tr("expected axis letters such as \"XY\" or [\"X\", \"Y\"]"));
                    letters += e.toString();
                }
            }
            if (letters.isEmpty() || !std::all_of(letters.begin(), letters.end(), [](QChar c) { return c.isLetter(); }))
                return fail(p.name, tr("expected axis letters such as \"XY\" or [\"X\", \"Y\"], got %1").arg(typeName(v)));
            texts << letters;
            break;
        }
        case app::cli::ParamType::AxisValues:
        case app::cli::ParamType::AxisRanges: {
            if (!v.isObject() || v.toObject().isEmpty())
                return fail(p.name, tr("expected an object of axis letters, such as %1, got %2")
                                        .arg(p.type == app::cli::ParamType::AxisRanges ? QStringLiteral("{\"X\": [0, 50]}") : QStringLiteral("{\"X\": 10}"),
                                             typeName(v)));
            const QJsonObject axes = v.toObject();
            for (auto a = axes.begin(); a != axes.end(); ++a) {
                const QString field = p.name + QLatin1Char('.') + a.key();
                if (!isAxisLetter(a.key()))
                    return fail(field, tr("not an axis letter"));
                if (p.type == app::cli::ParamType::AxisRanges) {
                    const QJsonArray r = a.value().toArray();
                    if (!a.value().isArray() || r.size() != 2 || !finiteNumber(r[0]) || !finiteNumber(r[1]))
                        return fail(field, tr("expected [min, max], got %1").arg(typeName(a.value())));
                    texts << QStringLiteral("%1=%2:%3").arg(a.key(), numberText(r[0].toDouble()), numberText(r[1].toDouble()));
                } else {
                    QString t;
                    if (!numbersText(a.value(), &t, &why))
                        return fail(field, why);
                    texts << a.key() + QLatin1Char('=') + t;
                }
            }
            break;
        }
        case app::cli::ParamType::Text:
        case app::cli::ParamType::File:
            if (v.isString()) {
                texts << v.toString();
            } else if (finiteNumber(v)) {
                texts << numberText(v.toDouble());
            } else if (v.isArray() && !v.toArray().isEmpty()) {
                const QJsonArray a = v.toArray();
                if (std::all_of(a.begin(), a.end(), [](const QJsonValue& e) { return e.isString(); })) {
                    for (const QJsonValue& e : a)
                        texts << e.toString();  // a repeated option, or several words
                } else {
                    QString t;
                    if (!numbersText(v, &t, &why))
                        return fail(p.name, tr("expected a string, a number or an array of either"));
                    texts << t;
                }
            } else {
                return fail(p.name, tr("expected a string, got %1").arg(typeName(v)));
            }
            if (!p.choices.isEmpty())
                for (const QString& t : texts)
                    if (!p.choices.contains(t))
                        return fail(p.name, tr("'%1' is not one of %2").arg(t, p.choices.join(QStringLiteral(", "))));
            break;
        }
        for (const QString& t : texts) {
            if (p.option.isEmpty())
                positionalWords << t;
            else
                optionWords << QStringLiteral("--%1=%2").arg(p.option, t);
        }
    }
    *words = optionWords;
    *positional = !positionalWords.isEmpty();
    if (!positionalWords.isEmpty())
        *words << QStringLiteral("--") << positionalWords;
    return true;
}

QString apiWording(const CommandMethod& m, const QString& message)
{
    // Longest option names first, so "--start-deg" is not taken for "--start".
    QVector<QPair<QString, QString>> names;
    for (const MethodParam& p : methodParams(m)) {
        if (!p.option.isEmpty())
            names.push_back({QStringLiteral("--") + p.option, p.name});
        // A command's own words may name the instrument by --sim, its older spelling.
        if (p.common && p.option == QLatin1String("instrument"))
            names.push_back({QStringLiteral("--sim"), p.name});
    }
    std::sort(names.begin(), names.end(), [](const auto& a, const auto& b) { return a.first.size() > b.first.size(); });
    QString out;
    for (int i = 0; i < message.size();) {
        bool replaced = false;
        if (message[i] == QLatin1Char('-'))
            for (const auto& [option, name] : names) {
                const int end = i + option.size();
                if (message.mid(i, option.size()) == option
                    && (end >= message.size() || !(message[end].isLetterOrNumber() || message[end] == QLatin1Char('-')))) {
                    out += name;
                    i = end;
                    replaced = true;
                    break;
                }
            }
        if (!replaced)
            out += message[i++];
    }
    return out;
}

} // namespace app::api
