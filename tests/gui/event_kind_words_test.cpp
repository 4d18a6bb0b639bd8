// Every event kind the protocol defines (docs/protocol.md, "Events") has a name a person
// reads in the event log, in English and in Chinese: a compensation event showed as
// "event 40" because its kind was defined beside its feature and never named.
#include "device/protocol/messages.h"
#include "widgets/wording/translators.h"
#include "widgets/wording/wording.h"

#include "../device/pseudo_translation.h"

#include <QFile>
#include <QRegularExpression>

#include <gtest/gtest.h>

namespace {

/// The kinds of docs/protocol.md's Events table, with the name it gives each.
QList<QPair<int, QString>> documentedEventKinds()
{
    QFile f(QStringLiteral(BP_SOURCE_DIR "/docs/protocol.md"));
    if (!f.open(QIODevice::ReadOnly))
        return {};
    const QString text = QString::fromUtf8(f.readAll());
    const int from = text.indexOf(QStringLiteral("\n## Events\n"));
    const int to = text.indexOf(QStringLiteral("\n#"), from + 5);
    if (from < 0)
        return {};
    static const QRegularExpression row(QStringLiteral("^\\| (\\d+) \\| (\\w+) \\|"), QRegularExpression::MultilineOption);
    QList<QPair<int, QString>> out;
    for (auto it = row.globalMatch(text.mid(from, to - from)); it.hasNext();) {
        const auto m = it.next();
        out.append({m.captured(1).toInt(), m.captured(2)});
    }
    return out;
}

} // namespace

TEST(EventKindWords, EveryEventKindTheProtocolDefinesHasANameInEnglishAndInChinese)
{
    const auto kinds = documentedEventKinds();
    ASSERT_GE(kinds.size(), 20) << "the Events table of docs/protocol.md was not found";
    static const QRegularExpression han(QStringLiteral("\\p{Han}"));
    ui::words::Translators translators;
    for (const auto& [code, name] : kinds) {
        const auto kind = static_cast<dev::proto::EventKind>(code);
        const std::string term = dev::proto::eventKindTerm(kind);
        const std::string what = std::to_string(code) + " " + name.toStdString();
        EXPECT_NE(term, "device.event.unknown") << what;
        EXPECT_STRNE(dev::proto::eventKindName(kind), "unknown event") << what << ": the API's journal keys on this name";
        ASSERT_TRUE(translators.setLanguage(QStringLiteral("en")));
        const QString en = ui::words::term(term);
        EXPECT_NE(en.toStdString(), term) << what << ": no English words";
        EXPECT_FALSE(en.contains(han)) << what;
        ASSERT_TRUE(translators.setLanguage(QStringLiteral("zh_CN")));
        const QString zh = ui::words::term(term);
        EXPECT_TRUE(zh.contains(han)) << what << ": " << zh.toStdString();
        EXPECT_TRUE(i18ntest::untranslated(zh).isEmpty()) << what << ": " << zh.toStdString();
    }
    translators.setLanguage(QStringLiteral("en"));
}
