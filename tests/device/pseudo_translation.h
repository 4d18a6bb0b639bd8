#pragma once
// A stand-in for the coming translation: while one of these lives, every message
// of the named tr() contexts comes out with its vowels accented ("%1" and the
// layout stay, the English words do not). A test that passes with it installed
// shows that a decision does not hang on the English wording of a message.
#include <QCoreApplication>
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
        if (!m_contexts.contains(QLatin1String(context)))
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

} // namespace i18ntest
