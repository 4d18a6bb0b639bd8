#include "widgets/wording/wording.h"

#include "widgets/wording/translators.h"
#include "device/files/json_fields.h"

#include <QJsonObject>
#include <QJsonValue>

namespace ui::words {

QString unitKey(motion::msg::Unit unit) { return unitSymbol(unit).trimmed(); }

QString englishText(const motion::msg::Message& m)
{
    // The translators step aside (translators.h) rather than being removed, so
    // the screens showing Chinese get no LanguageChange for every JSON line.
    const EnglishScope english;
    return text(m);
}

QString englishTerm(const std::string& id)
{
    const EnglishScope english;
    return term(id);
}

QJsonObject toJson(const motion::msg::Message& m)
{
    QJsonObject args, units;
    for (const motion::msg::Arg& a : m.args) {
        const QString name = QString::fromStdString(a.name);
        QJsonValue v;
        if (auto* i = std::get_if<long long>(&a.value))
            v = static_cast<qint64>(*i);
        else if (auto* d = std::get_if<double>(&a.value))
            v = *d;
        else if (auto* s = std::get_if<motion::msg::Verbatim>(&a.value))
            v = QString::fromStdString(s->text);
        else if (auto* t = std::get_if<motion::msg::Term>(&a.value))
            v = QString::fromStdString(t->id);
        else if (auto* n = std::get_if<std::shared_ptr<const motion::msg::Message>>(&a.value); n && *n)
            v = toJson(**n);
        args.insert(name, v);
        if (!unitKey(a.unit).isEmpty())
            units.insert(name, unitKey(a.unit));
    }
    QJsonObject o{{QStringLiteral("id"), QString::fromStdString(m.id)}, {QStringLiteral("args"), args}};
    if (!units.isEmpty())
        o.insert(QStringLiteral("units"), units);
    o.insert(QStringLiteral("message"), englishText(m));
    return o;
}

QJsonObject toJson(const motion::msg::Problem& p)
{
    QJsonObject o = toJson(p.message);
    if (!p.file.empty())
        o.insert(QStringLiteral("file"), QString::fromStdString(p.file));
    if (p.line > 0) {
        o.insert(QStringLiteral("line"), p.line);
        o.insert(QStringLiteral("column"), p.column);
    }
    if (!p.path.empty())
        o.insert(QStringLiteral("field"), QString::fromStdString(p.path));
    if (p.isWarning())
        o.insert(QStringLiteral("warning"), true);
    return o;
}

} // namespace ui::words
