// What benchpilot-cli's help and the API's method list say reads as it was written:
// every command's --help (English and Chinese) and every string of rpc.discover's
// OpenRPC document are free of the marks of text decoded with the wrong character set:
// U+FFFD, C1 control characters, and UTF-8 read one byte a character as Latin-1 or
// Windows-1252 ("x,y;â¦" for "x,y;…", "Âµm" for "µm").
#include "api_support.h"
#include "cli_in_process.h"

#include "app/api/command_methods.h"

#include <functional>

using itest::ApiFixture;
using itest::ApiTestClient;

namespace {

/// The byte a character stands for when UTF-8 was read as Latin-1 or Windows-1252; −1 if none.
int byteShown(QChar ch)
{
    const char16_t u = ch.unicode();
    if (u < 0x100)
        return u;
    // Windows-1252's characters for 0x80–0x9F (0x81, 0x8D, 0x8F, 0x90, 0x9D are unassigned).
    static const char16_t cp1252[32] = {0x20AC, 0, 0x201A, 0x0192, 0x201E, 0x2026, 0x2020, 0x2021, 0x02C6, 0x2030, 0x0160,
                                        0x2039, 0x0152, 0,      0x017D, 0,      0,      0x2018, 0x2019, 0x201C, 0x201D, 0x2022,
                                        0x2013, 0x2014, 0x02DC, 0x2122, 0x0161, 0x203A, 0x0153, 0,      0x017E, 0x0178};
    for (int b = 0; b < 32; ++b)
        if (cp1252[b] == u)
            return 0x80 + b;
    return -1;
}

/// What is wrong with `text` as written ("" when nothing): the first mark of mojibake.
QString mojibake(const QString& text)
{
    for (int i = 0; i < text.size(); ++i) {
        const char16_t u = text[i].unicode();
        if (u == 0xFFFD)
            return QStringLiteral("U+FFFD (a character that could not be decoded) at %1").arg(i);
        if (u >= 0x80 && u <= 0x9F)
            return QStringLiteral("a C1 control character U+%1 at %2").arg(u, 4, 16, QLatin1Char('0')).arg(i);
        // A UTF-8 lead byte followed by as many continuation bytes as it announces.
        const int lead = byteShown(text[i]);
        const int more = lead >= 0xC2 && lead <= 0xDF ? 1 : lead >= 0xE0 && lead <= 0xEF ? 2 : lead >= 0xF0 && lead <= 0xF4 ? 3 : 0;
        if (more == 0 || i + more >= text.size())
            continue;
        bool continued = true;
        for (int k = 1; k <= more && continued; ++k) {
            const int b = byteShown(text[i + k]);
            continued = b >= 0x80 && b <= 0xBF;
        }
        if (continued)
            return QStringLiteral("UTF-8 read as Latin-1 or Windows-1252: \"%1\" at %2").arg(text.mid(i, more + 1)).arg(i);
    }
    return {};
}

/// Every command's path ("recipe run"), groups included, as the help walks them.
QStringList commandPaths(const std::vector<app::cli::Command>& list, const QString& above = {})
{
    QStringList out;
    for (const app::cli::Command& c : list) {
        const QString path = above.isEmpty() ? c.name : above + QLatin1Char(' ') + c.name;
        out << path << commandPaths(c.subcommands, path);
    }
    return out;
}

/// Calls `visit` on every string in `v`, keys included, with where it is.
void eachString(const QJsonValue& v, const QString& where, const std::function<void(const QString&, const QString&)>& visit)
{
    if (v.isString()) {
        visit(v.toString(), where);
    } else if (v.isArray()) {
        const QJsonArray a = v.toArray();
        for (int i = 0; i < a.size(); ++i)
            eachString(a[i], QStringLiteral("%1[%2]").arg(where).arg(i), visit);
    } else if (v.isObject()) {
        const QJsonObject o = v.toObject();
        for (auto it = o.begin(); it != o.end(); ++it) {
            visit(it.key(), where + QStringLiteral(" (a key)"));
            eachString(it.value(), where + QLatin1Char('.') + it.key(), visit);
        }
    }
}

TEST(TextAsWritten, TheCheckFindsMojibakeAndPassesTextAsWritten)
{
    // It can fail: the defect as it was shown, and its other common shapes.
    EXPECT_FALSE(mojibake(QString::fromLatin1("--polygon x,y;x,y;\xE2\x80\xA6")).isEmpty()) << "UTF-8 read as Latin-1";
    EXPECT_FALSE(mojibake(QStringLiteral("x,y;â€¦")).isEmpty()) << "UTF-8 read as Windows-1252";
    EXPECT_FALSE(mojibake(QString::fromLatin1("5 \xC2\xB5m")).isEmpty());
    EXPECT_FALSE(mojibake(QStringLiteral("caf\u00C3\u00A9")).isEmpty());
    EXPECT_FALSE(mojibake(QStringLiteral("bad \uFFFD byte")).isEmpty());
    // And it does not cry wolf at what the help really says.
    for (const char* fine : {"x,y;x,y;…", "±5 µm", "mm/s²", "0 … 100 °C", "Ziegler–Nichols", "café", "Größe", "简体中文 µL", "× 4"})
        EXPECT_TRUE(mojibake(QString::fromUtf8(fine)).isEmpty()) << fine << ": " << mojibake(QString::fromUtf8(fine)).toStdString();
}

TEST(TextAsWritten, EveryCommandsHelpInEnglishAndChinese)
{
    const QStringList paths = commandPaths(app::cli::commands());
    ASSERT_GT(paths.size(), 20);
    for (const char* language : {"en", "zh_CN"}) {
        const QStringList lang{QStringLiteral("--lang"), QString::fromLatin1(language)};
        const itest::CliResult top = itest::runCliInProcess(lang + QStringList{QStringLiteral("--help")});
        ASSERT_EQ(top.code, 0) << language;
        EXPECT_EQ(mojibake(top.out).toStdString(), "") << language << " benchpilot-cli --help";
        for (const QString& path : paths) {
            const itest::CliResult r = itest::runCliInProcess(lang + path.split(QLatin1Char(' ')) + QStringList{QStringLiteral("--help")});
            EXPECT_EQ(r.code, 0) << language << " " << path.toStdString() << ": " << r.err.toStdString();
            EXPECT_FALSE(r.out.isEmpty()) << path.toStdString();
            EXPECT_EQ(mojibake(r.out).toStdString(), "") << language << " benchpilot-cli " << path.toStdString() << " --help";
        }
    }
    // The defect as it was found, by name.
    const itest::CliResult scanPlan = itest::runCliInProcess(itest::splitWords("scan plan --help"));
    EXPECT_TRUE(scanPlan.out.contains(QStringLiteral("--polygon x,y;x,y;…"))) << scanPlan.out.toStdString();
}

TEST(TextAsWritten, TheApisMethodListAndOpenRpcDocument)
{
    ApiFixture f(false);
    ApiTestClient c(f.path);
    const QJsonObject doc = ApiTestClient::result(c.call(QStringLiteral("rpc.discover")));
    ASSERT_FALSE(doc.value(QStringLiteral("methods")).toArray().isEmpty());
    int strings = 0;
    eachString(doc, QStringLiteral("rpc.discover"), [&strings](const QString& text, const QString& where) {
        ++strings;
        EXPECT_EQ(mojibake(text).toStdString(), "") << where.toStdString() << ": " << text.toStdString();
    });
    EXPECT_GT(strings, 500) << "every method, parameter and description was read";
    // The methods as the server holds them, option value names included (they are not all in the document).
    for (const app::api::CommandMethod& m : app::api::commandMethods())
        for (const QCommandLineOption& o : m.command->options)
            for (const QString& text : {o.valueName(), o.description(), o.defaultValues().join(QLatin1Char(','))})
                EXPECT_EQ(mojibake(text).toStdString(), "") << m.method.toStdString() << " --" << o.names().constLast().toStdString();
}

} // namespace
