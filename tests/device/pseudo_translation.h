#pragma once
// A stand-in for a translation: while one of these lives, every message of the
// named tr() contexts (every context, for an empty list) comes out with its vowels
// accented ("%1" and the layout stay, the English words do not). A test that
// passes with it installed shows that a decision does not hang on the English
// wording of a message; untranslated() finds text on screen that never went
// through tr() (its vowels are still plain).
#include <QCoreApplication>
#include <QRegularExpression>
#include <QStringList>
#include <QTranslator>

#include <utility>

namespace i18ntest {

class PseudoTranslation final : public QTranslator {
public:
    explicit PseudoTranslation(QStringList contexts) : m_contexts(std::move(contexts)) { QCoreApplication::installTranslator(this); }
    ~PseudoTranslation() override { QCoreApplication::removeTranslator(this); }
    PseudoTranslation(const PseudoTranslation&) = delete;
    PseudoTranslation& operator=(const PseudoTranslation&) = delete;

    bool isEmpty() const override { return false; }
    QString translate(const char* context, const char* sourceText, const char* /*disambiguation*/, int /*n*/) const override
    {
        if (!m_contexts.isEmpty() && !m_contexts.contains(QLatin1String(context)))
            return {};  // null: the next translator, or the source text
        static const QString plain = QStringLiteral("aeiouAEIOU");
        static const QString accented = QStringLiteral("áéíóúÁÉÍÓÚ");
        QString s = QString::fromUtf8(sourceText);
        for (QChar& c : s) {
            const auto k = plain.indexOf(c);
            if (k >= 0)
                c = accented[k];
        }
        return s;
    }

private:
    QStringList m_contexts;
};

/// The words of `text` that still read as English under a PseudoTranslation: three
/// or more ASCII letters with a plain vowel, outside the names that stay as they are
/// (products, formats, abbreviations, units) and outside markup.
inline QStringList untranslated(QString text)
{
    static const QStringList kKept = {
        QStringLiteral("BenchPilot"), QStringLiteral("GRBL"),  QStringLiteral("Grbl"), QStringLiteral("Fiji"),
        QStringLiteral("Micro"),      QStringLiteral("Manager"), QStringLiteral("Opentrons"), QStringLiteral("LinuxCNC"),
        QStringLiteral("Ziegler"),    QStringLiteral("Nichols"), QStringLiteral("Tyreus"), QStringLiteral("Luyben"),
        QStringLiteral("Pessen"),     QStringLiteral("loopback"), QStringLiteral("analyzer"), QStringLiteral("stage"),
        QStringLiteral("simulated"),  QStringLiteral("Esc"), QStringLiteral("Ctrl"), QStringLiteral("Shift"),
    };
    static const QRegularExpression markup(QStringLiteral("<[^>]*>|&[a-z]+;"));
    static const QRegularExpression word(QStringLiteral("[A-Za-z]{3,}"));
    text.remove(markup);
    QStringList out;
    for (auto m = word.globalMatch(text); m.hasNext();) {
        const QString w = m.next().captured(0);
        const bool plainVowel = w.contains(QRegularExpression(QStringLiteral("[aeiouAEIOU]")));
        const bool abbreviation = w == w.toUpper() && w.size() <= 5;  // PID, CSV, RMS, IAE
        if (plainVowel && !abbreviation && !kKept.contains(w))
            out << w;
    }
    return out;
}

} // namespace i18ntest
