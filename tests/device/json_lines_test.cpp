// The line reader under the run logs (scan, accuracy bench, recipe run): line numbers,
// a last line without its newline, and where a line's problems end up in the file.
#include "device/files/json_lines.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

using namespace dev::files::json;

namespace {
std::vector<TextLine> linesOf(std::string_view text)
{
    std::vector<TextLine> out;
    TextLines lines(text);
    while (const auto line = lines.next())
        out.push_back(*line);
    return out;
}
} // namespace

TEST(JsonLines, NumbersEveryLineAndSaysWhetherItEndedWithItsNewline)
{
    const auto lines = linesOf("{\"a\":1}\n\n  \n{\"b\":2");
    ASSERT_EQ(lines.size(), 4u);
    EXPECT_EQ(lines[0].text, "{\"a\":1}");
    EXPECT_EQ(lines[1].text, "");
    EXPECT_EQ(lines[2].text, "  ");
    EXPECT_EQ(lines[3].text, "{\"b\":2");
    for (int k = 0; k < 4; ++k)
        EXPECT_EQ(lines[static_cast<std::size_t>(k)].number, k + 1);
    EXPECT_TRUE(lines[2].complete);
    EXPECT_FALSE(lines[3].complete);
    // A text that ends with its newline has no empty line after it.
    EXPECT_EQ(linesOf("{}\n{}\n").size(), 2u);
    EXPECT_TRUE(linesOf("").empty());
}

TEST(JsonLines, BlankIsSpacesTabsAndACarriageReturnOnly)
{
    EXPECT_TRUE(isBlank(""));
    EXPECT_TRUE(isBlank(" \t\r"));
    EXPECT_FALSE(isBlank(" x "));
}

TEST(JsonLines, ATornLastLineIsDroppedOnlyWhereTheReaderAllowsIt)
{
    const auto lines = linesOf("{\"a\":1}\n{\"b\":");
    ASSERT_EQ(lines.size(), 2u);
    Problems problems;
    ParseResult parsed;
    EXPECT_EQ(parseLine(lines[0], true, parsed, problems), LineOutcome::Value);
    ASSERT_TRUE(parsed);
    EXPECT_TRUE(parsed.value->find("a"));
    EXPECT_EQ(parseLine(lines[1], true, parsed, problems), LineOutcome::Torn);
    EXPECT_TRUE(problems.empty());
    // Not allowed (no header read yet, say): an error at the line and the parser's column.
    EXPECT_EQ(parseLine(lines[1], false, parsed, problems), LineOutcome::Error);
    ASSERT_EQ(problems.size(), 1u);
    EXPECT_EQ(problems.list()[0].line, 2);
    EXPECT_EQ(problems.list()[0].column, 6);  // just past the colon, where a value was due
}

TEST(JsonLines, ALineThatEndsWithItsNewlineIsNeverTakenForTorn)
{
    const auto lines = linesOf("{\"a\":\n");
    ASSERT_EQ(lines.size(), 1u);
    Problems problems;
    ParseResult parsed;
    EXPECT_EQ(parseLine(lines[0], true, parsed, problems), LineOutcome::Error);
    ASSERT_EQ(problems.size(), 1u);
    EXPECT_EQ(problems.list()[0].line, 1);
}

TEST(JsonLines, ALinesProblemsMoveToWhereTheLineStands)
{
    Problems line;
    line.add(Position{1, 9}, "tile", motion::msg::make("file.json.wrong_type"));
    Problems file;
    addAtLine(file, line, 12);
    ASSERT_EQ(file.size(), 1u);
    EXPECT_EQ(file.list()[0].line, 12);
    EXPECT_EQ(file.list()[0].column, 9);
    EXPECT_EQ(file.list()[0].path, "tile");
    EXPECT_EQ(file.list()[0].message.id, "file.json.wrong_type");
}
