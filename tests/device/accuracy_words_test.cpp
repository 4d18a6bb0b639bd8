// Every message id the accuracy bench emits (motion/metrology, its files, runners,
// sources, the gauge and the CLI) is in docs/accuracy.md's appendix and is worded as
// a sentence, with each of its arguments in it: a new id cannot ship as
// "accuracy.run.link_lost{…}" on a screen.
#include "widgets/wording/wording.h"

#include <QRegularExpression>
#include <QString>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

std::string readAll(const fs::path& p)
{
    std::ifstream in(p);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

/// Ids emitted by motion::msg::make("…") in the accuracy bench's sources.
std::set<std::string> emittedIds()
{
    const fs::path root(BP_SOURCE_DIR);
    std::set<std::string> out;
    // Qt's expressions, not std::regex: GCC 12 warns falsely inside libstdc++'s regex
    // compiler in the sanitizer build.
    static const QRegularExpression make(QStringLiteral(R"re(motion::msg::make\("((accuracy|compensation|file|gauge)\.[a-z_.0-9]+)")re"));
    for (const char* dir : {"motion/metrology", "device/files/accuracy", "device/jobs/accuracy", "device/link", "app/cli"})
        for (const auto& e : fs::recursive_directory_iterator(root / dir)) {
            if (!e.is_regular_file() || (e.path().extension() != ".cpp" && e.path().extension() != ".h"))
                continue;
            const std::string text = readAll(e.path());
            for (auto it = make.globalMatch(QString::fromStdString(text)); it.hasNext();)
                out.insert(it.next().captured(1).toStdString());
        }
    return out;
}

/// Ids of the appendix table with their argument names: "| `id` | a, b, [c] | …".
std::map<std::string, std::vector<std::string>> appendix()
{
    const std::string doc = readAll(fs::path(BP_SOURCE_DIR) / "docs" / "accuracy.md");
    std::map<std::string, std::vector<std::string>> out;
    const auto at = doc.find("## Appendix: message ids");
    std::istringstream lines(doc.substr(at == std::string::npos ? 0 : at));
    std::string line;
    static const QRegularExpression row(QStringLiteral(R"re(^\| `([a-z_.0-9]+)` \| ([^|]*) \|)re"));
    while (std::getline(lines, line))
        if (const QRegularExpressionMatch m = row.match(QString::fromStdString(line)); m.hasMatch()) {
            std::vector<std::string> args;
            std::string list = m.captured(2).toStdString();
            for (char& c : list)
                if (c == '[' || c == ']' || c == ',')
                    c = ' ';
            std::istringstream words(list);
            std::string w;
            while (words >> w)
                if (w != "—")
                    args.push_back(w);
            out[m.captured(1).toStdString()] = args;
        }
    return out;
}

TEST(AccuracyWords, EveryIdEmittedIsInTheAppendixAndWorded)
{
    const auto ids = emittedIds();
    const auto table = appendix();
    ASSERT_GT(ids.size(), 80u) << "the scan found the sources";
    for (const std::string& id : ids) {
        const auto row = table.find(id);
        EXPECT_NE(row, table.end()) << id << " is not in docs/accuracy.md's appendix";
        if (row == table.end())
            continue;
        std::vector<motion::msg::Arg> args;
        for (const std::string& a : row->second)
            args.push_back(motion::msg::verbatim(a, "<" + a + ">"));
        const motion::msg::Message m = motion::msg::make(id, args);
        const QString text = ui::words::text(m);
        EXPECT_NE(text.toStdString(), motion::msg::debugString(m)) << id << " has no words";
        EXPECT_FALSE(text.isEmpty()) << id;
        // Every argument the id documents appears in its sentence (file.json_field is its detail).
        for (const std::string& a : row->second)
            EXPECT_TRUE(text.contains(QString::fromStdString("<" + a + ">"))) << id << " leaves out " << a << ": " << text.toStdString();
    }
}

TEST(AccuracyWords, TermsAreWorded)
{
    EXPECT_EQ(ui::words::term("direction.up"), QStringLiteral("up"));
    EXPECT_EQ(ui::words::term("rotation.ccw"), QStringLiteral("counter-clockwise"));
}

} // namespace
