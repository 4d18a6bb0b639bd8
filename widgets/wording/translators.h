#pragma once
// The translations a program shows: BenchPilot's own catalogue (resources/
// translations, compiled into the program) and Qt's (dialog buttons, file
// dialogs: qtbase_*.qm from the system), installed into QCoreApplication
// together. Installing or removing a translator makes Qt send LanguageChange to
// every widget, which is how an open screen rewords itself (retranslateUi).
//
// A translator installed here can step aside without being removed: while an
// EnglishScope lives on the calling thread it answers nothing, so tr() falls
// back to the English source. ui::words::englishText uses that to put English in
// JSON while the screens show Chinese; removing the translators instead would
// send LanguageChange to every widget each time a message is logged.
#include <QLocale>
#include <QObject>
#include <QString>
#include <QStringList>
#include <QTranslator>

#include <memory>
#include <vector>

namespace ui::words {

/// While one lives, the translators of this thread's Translators answer nothing.
class EnglishScope {
public:
    EnglishScope();
    ~EnglishScope();
    EnglishScope(const EnglishScope&) = delete;
    EnglishScope& operator=(const EnglishScope&) = delete;
};
/// True inside an EnglishScope (ui::words::number then writes C-locale digits too).
bool englishOnly();

/// A QTranslator that answers nothing inside an EnglishScope.
class StepAsideTranslator final : public QTranslator {
public:
    using QTranslator::QTranslator;
    QString translate(const char* context, const char* sourceText, const char* disambiguation, int n) const override;
};

class Translators final : public QObject {
    Q_OBJECT
public:
    explicit Translators(QObject* parent = nullptr);
    ~Translators() override;

    /// The languages BenchPilot has a catalogue for: "en" (the source) and "zh_CN".
    static QStringList languages();
    /// What "system" resolves to here: the first of the system's UI languages we
    /// have, else "en".
    static QString systemLanguage();

    /// Installs the catalogues of `language` ("en", "zh_CN", or "system") and sets
    /// the default QLocale to match, so numbers and dates follow it. "en" removes
    /// every translator. False (and English) for a language without a catalogue.
    bool setLanguage(const QString& language);
    /// The language in force ("en" or "zh_CN"), after "system" was resolved.
    QString language() const { return m_language; }

private:
    void removeAll();
    std::vector<std::unique_ptr<StepAsideTranslator>> m_installed;
    QString m_language = QStringLiteral("en");
};

} // namespace ui::words
