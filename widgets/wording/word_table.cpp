#include "widgets/wording/word_table.h"

#include "widgets/wording/wording.h"

#include <QCoreApplication>
#include <QStringList>

namespace ui::words {

QString fill(const QString& pattern, const QStringList& values)
{
    QString out;
    out.reserve(pattern.size() + 32);
    for (qsizetype i = 0; i < pattern.size(); ++i) {
        const QChar c = pattern[i];
        if (c != QLatin1Char('%') || i + 1 >= pattern.size() || !pattern[i + 1].isDigit() || pattern[i + 1] == QLatin1Char('0')) {
            out += c;
            continue;
        }
        qsizetype j = i + 1;
        int k = 0;
        while (j < pattern.size() && pattern[j].isDigit() && k < 10)
            k = k * 10 + pattern[j++].digitValue();
        if (k >= 1 && k <= values.size()) {
            out += values[k - 1];
            i = j - 1;
        } else {
            out += c;  // a placeholder without a value stays visible rather than vanishing
        }
    }
    return out;
}

QString fromRows(const char* context, const Row* rows, std::size_t count, const motion::msg::Message& m)
{
    for (std::size_t r = 0; r < count; ++r) {
        const Row& row = rows[r];
        if (m.id != row.id)
            continue;
        const int n = *row.numerus ? static_cast<int>(m.integer(row.numerus, static_cast<long long>(m.number(row.numerus, 0)))) : -1;
        const QString pattern = QCoreApplication::translate(context, row.source.text, row.source.disambiguation, n);
        QStringList values;
        const QString names = QString::fromLatin1(row.args);
        if (!names.isEmpty())
            for (const QString& name : names.split(QLatin1Char(',')))
                values << ui::words::arg(m, name.trimmed().toStdString());
        return fill(pattern, values);
    }
    return {};
}

QString fromTerms(const char* context, const TermRow* rows, std::size_t count, const std::string& id)
{
    for (std::size_t r = 0; r < count; ++r)
        if (id == rows[r].id)
            return QCoreApplication::translate(context, rows[r].source.text, rows[r].source.disambiguation);
    return {};
}

} // namespace ui::words
