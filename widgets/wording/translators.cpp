#include "widgets/wording/translators.h"

#include <QCoreApplication>
#include <QLibraryInfo>

namespace ui::words {
namespace {
// Per thread: the GUI thread's JSON export must not silence another thread's
// wording, and no lock is needed on the hot path of every tr().
thread_local int t_englishDepth = 0;
} // namespace

EnglishScope::EnglishScope() { ++t_englishDepth; }
EnglishScope::~EnglishScope() { --t_englishDepth; }
bool englishOnly() { return t_englishDepth > 0; }

QString StepAsideTranslator::translate(const char* context, const char* sourceText, const char* disambiguation, int n) const
{
    if (englishOnly())
        return {};
    return QTranslator::translate(context, sourceText, disambiguation, n);
}

Translators::Translators(QObject* parent) : QObject(parent) {}

Translators::~Translators() { removeAll(); }

QStringList Translators::languages() { return {QStringLiteral("en"), QStringLiteral("zh_CN")}; }

QString Translators::systemLanguage()
{
    for (const QString& ui : QLocale::system().uiLanguages()) {
        const QLocale l(ui);
        if (l.language() == QLocale::Chinese && l.script() != QLocale::TraditionalChineseScript)
            return QStringLiteral("zh_CN");
        if (l.language() == QLocale::English)
            return QStringLiteral("en");
    }
    return QStringLiteral("en");
}

void Translators::removeAll()
{
    for (const auto& t : m_installed)
        QCoreApplication::removeTranslator(t.get());
    m_installed.clear();
}

bool Translators::setLanguage(const QString& requested)
{
    const QString language = requested == QLatin1String("system") ? systemLanguage() : requested;
    if (!languages().contains(language)) {
        setLanguage(QStringLiteral("en"));
        return false;
    }
    if (language == m_language && (language == QLatin1String("en") || !m_installed.empty()))
        return true;
    removeAll();
    m_language = QStringLiteral("en");
    if (language == QLatin1String("en")) {
        // English words with the system's numbers and dates (a German bench keeps its
        // decimal comma), unless the system speaks Chinese: then plain English ones.
        const QLocale sys = QLocale::system();
        QLocale::setDefault(sys.language() == QLocale::Chinese ? QLocale(QLocale::English, QLocale::UnitedStates) : sys);
        return true;
    }
    const QLocale locale(language);
    // Ours first in the list Qt searches last-installed-first: Qt's own catalogue
    // is installed before ours so ours wins where both know a context.
    auto qt = std::make_unique<StepAsideTranslator>();
    if (qt->load(locale, QStringLiteral("qtbase"), QStringLiteral("_"), QLibraryInfo::path(QLibraryInfo::TranslationsPath))) {
        QCoreApplication::installTranslator(qt.get());
        m_installed.push_back(std::move(qt));
    }
    auto ours = std::make_unique<StepAsideTranslator>();
    if (!ours->load(QStringLiteral(":/i18n/benchpilot_%1.qm").arg(language))) {
        removeAll();
        return false;
    }
    QCoreApplication::installTranslator(ours.get());
    m_installed.push_back(std::move(ours));
    QLocale::setDefault(locale);
    m_language = language;
    return true;
}

} // namespace ui::words
