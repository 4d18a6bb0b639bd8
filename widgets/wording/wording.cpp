#include "widgets/wording/wording.h"

#include "device/client/instrument_types.h"

#include "widgets/wording/areas.h"
#include "widgets/wording/translators.h"

#include <QCoreApplication>
#include <QLocale>

#include <cmath>
#include <utility>

namespace ui::words {
namespace {

using SentenceFn = QString (*)(const motion::msg::Message&);
using TermFn = QString (*)(const std::string&);

/// Which area words which ids. Longest prefix first where prefixes nest.
const std::pair<const char*, SentenceFn> kSentences[] = {
    {"capability.", &areas::capability},
    {"accuracy.", &areas::accuracy},
    {"compensation.", &areas::accuracy},
    {"device.why.", &areas::deviceEvent},
    {"device.refused", &areas::refusal},
    {"request.", &areas::device},
    {"link.", &areas::device},
    {"device.", &areas::device},
    {"telemetry.", &areas::device},
    {"file.", &areas::file},
    {"grbl.", &areas::grbl},
    {"pattern.", &areas::pattern},
    {"plate.", &areas::plate},
    {"profile.", &areas::profile},
    {"recipe.", &areas::recipe},
    {"scan.", &areas::scan},
    {"camera.", &areas::camera},
    {"tuning.", &areas::tuning},
    {"gauge.", &areas::gauge},
};

const TermFn kTerms[] = {
    &areas::capabilityTerm,
    &areas::accuracyTerm,
    &areas::deviceTerm,
    &areas::fileTerm,
    &areas::grblTerm,
    &areas::patternTerm,
    &areas::recipeTerm,
    &areas::scanTerm,
    &areas::tuningTerm,
};

bool startsWith(const std::string& s, const char* prefix)
{
    return s.rfind(prefix, 0) == 0;
}

/// Digits after the decimal point that suit a unit: what an operator reads on the
/// instrument (µm on a stage, 0.001 mm on the analyzer), not what a double holds.
int decimalsOf(motion::msg::Unit u)
{
    using U = motion::msg::Unit;
    switch (u) {
    case U::Count: return 0;
    case U::Mm: return 3;
    case U::Um: return 1;
    case U::Nm: return 0;
    case U::MmPerS: return 2;
    case U::MmPerS2: return 0;
    case U::MmPerS3: return 0;
    case U::MmPerMin: return 0;
    case U::Ul: return 1;
    case U::UlPerS: return 1;
    case U::S: return 2;
    case U::Ms: return 1;
    case U::Us: return 0;
    case U::Hz: return 1;
    case U::Percent: return 1;
    case U::Deg: return 1;
    case U::Rad: return 3;
    case U::PerS: return 1;
    case U::Baud: return 0;
    case U::Byte: return 0;
    case U::None: break;
    }
    // No unit: as many digits as make the value readable, up to six significant.
    return -1;
}

} // namespace

QString unitSymbol(motion::msg::Unit unit)
{
    using U = motion::msg::Unit;
    switch (unit) {
    case U::None:
    case U::Count: return {};
    case U::Mm: return QStringLiteral(" mm");
    case U::Um: return QStringLiteral(" µm");
    case U::Nm: return QStringLiteral(" nm");
    case U::MmPerS: return QStringLiteral(" mm/s");
    case U::MmPerS2: return QStringLiteral(" mm/s²");
    case U::MmPerS3: return QStringLiteral(" mm/s³");
    case U::MmPerMin: return QStringLiteral(" mm/min");
    case U::Ul: return QStringLiteral(" µL");
    case U::UlPerS: return QStringLiteral(" µL/s");
    case U::S: return QStringLiteral(" s");
    case U::Ms: return QStringLiteral(" ms");
    case U::Us: return QStringLiteral(" µs");
    case U::Hz: return QStringLiteral(" Hz");
    case U::Percent: return QStringLiteral(" %");
    case U::Deg: return QStringLiteral("°");
    case U::Rad: return QStringLiteral(" rad");
    case U::PerS: return QStringLiteral(" 1/s");
    case U::Baud: return QStringLiteral(" Bd");
    case U::Byte: return QStringLiteral(" B");
    }
    return {};
}

QString duration(double seconds)
{
    if (!(seconds >= 0) || !std::isfinite(seconds))
        return QStringLiteral("—");
    const QLocale locale = englishOnly() ? QLocale::c() : QLocale();
    const long long s = std::llround(seconds);
    if (seconds < 10)
        return QCoreApplication::translate("ui::words::Durations", "%1 s").arg(locale.toString(seconds, 'f', 1));
    if (s < 60)
        return QCoreApplication::translate("ui::words::Durations", "%1 s").arg(locale.toString(s));
    if (s < 3600)
        return QCoreApplication::translate("ui::words::Durations", "%1 min %2 s").arg(locale.toString(s / 60)).arg(s % 60, 2, 10, QLatin1Char('0'));
    return QCoreApplication::translate("ui::words::Durations", "%1 h %2 min").arg(locale.toString(s / 3600)).arg((s % 3600) / 60, 2, 10, QLatin1Char('0'));
}

QString number(double v, motion::msg::Unit unit)
{
    if (!std::isfinite(v))
        return QString::number(v) + unitSymbol(unit);
    if (unit == motion::msg::Unit::S && v >= 60)
        return duration(v);
    const QLocale locale = englishOnly() ? QLocale::c() : QLocale();
    const int decimals = decimalsOf(unit);
    QString digits;
    if (decimals < 0) {
        digits = locale.toString(v, 'g', 6);
    } else {
        // A value too small for the unit's precision keeps its significant digits,
        // so "0.0004 mm" never reads as "0.000 mm".
        const double smallest = std::pow(10.0, -decimals);
        digits = (v != 0 && std::fabs(v) < smallest) ? locale.toString(v, 'g', 3) : locale.toString(v, 'f', decimals);
    }
    return digits + unitSymbol(unit);
}

QString value(const motion::msg::Arg& a)
{
    struct Visit {
        const motion::msg::Arg& arg;
        QString operator()(std::monostate) const { return {}; }
        QString operator()(long long v) const { return (englishOnly() ? QLocale::c() : QLocale()).toString(v) + unitSymbol(arg.unit); }
        QString operator()(double v) const { return number(v, arg.unit); }
        QString operator()(const motion::msg::Verbatim& v) const { return QString::fromStdString(v.text); }
        QString operator()(const motion::msg::Term& t) const { return term(t.id); }
        QString operator()(const std::shared_ptr<const motion::msg::Message>& m) const { return m ? text(*m) : QString(); }
    };
    return std::visit(Visit{a}, a.value);
}

QString arg(const motion::msg::Message& m, const std::string& name)
{
    const motion::msg::Arg* a = m.arg(name);
    return a ? value(*a) : QString();
}

QString term(const std::string& id)
{
    for (TermFn fn : kTerms) {
        const QString t = fn(id);
        if (!t.isNull())
            return t;
    }
    return QString::fromStdString(id);
}

QString sentence(const QString& text)
{
    // Latin letters only: "µL" starts with the micro sign, which upper-cases to a Greek Mu.
    if (text.isEmpty() || !text.front().isLower() || text.front().script() != QChar::Script_Latin)
        return text;
    // A file's name or a path keeps its case: "sampling-96.recipe.json was not opened"
    // names a file that "Sampling-96.recipe.json" is not. Its first word holds a
    // separator or an extension (a dot with more after it).
    qsizetype end = 0;
    while (end < text.size() && !text.at(end).isSpace() && text.at(end) != QLatin1Char(':'))
        ++end;
    const QStringView first = QStringView(text).left(end);
    const qsizetype dot = first.indexOf(QLatin1Char('.'));
    if (first.contains(QLatin1Char('/')) || first.contains(QLatin1Char('\\')) || (dot >= 0 && dot + 1 < first.size()))
        return text;
    return text.front().toUpper() + text.mid(1);
}

QString eventDetail(const dev::DeviceEvent& e)
{
    return value(dev::eventDetail(e));  // one rule for which to show: dev::eventDetail's
}

QString text(const motion::msg::Message& m)
{
    if (m.empty())
        return {};
    for (const auto& [prefix, fn] : kSentences) {
        if (!startsWith(m.id, prefix))
            continue;
        const QString t = fn(m);
        if (!t.isNull())
            return t;
    }
    return QString::fromStdString(motion::msg::debugString(m));
}

} // namespace ui::words
