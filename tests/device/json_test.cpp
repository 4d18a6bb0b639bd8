// The JSON reader and writer under every file format: positions for messages,
// strictness, round trips, and the field reader that collects every problem.
#include "device/english_words.h"
#include "device/files/json.h"
#include "device/files/json_fields.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace dev::files::json;

namespace {
ParseError errorOf(std::string_view text)
{
    const ParseResult r = parse(text);
    EXPECT_FALSE(r) << text;
    return r.error;
}
} // namespace

TEST(Json, ValuesKeepTheirLineAndColumn)
{
    const ParseResult r = parse("{\n  \"a\": 1,\n  \"b\": [true, \"x\"],\n  \"ü\": null\n}");
    ASSERT_TRUE(r) << r.error.message;
    const Value& v = *r.value;
    EXPECT_EQ(v.position().line, 1);
    ASSERT_TRUE(v.find("a"));
    EXPECT_EQ(v.find("a")->position().line, 2);
    EXPECT_EQ(v.find("a")->position().column, 8);
    const Value* b = v.find("b");
    ASSERT_TRUE(b && b->isArray());
    EXPECT_EQ(b->items()[1].position().line, 3);
    EXPECT_EQ(b->items()[1].position().column, 15);
    // Columns count characters: "ü" is two bytes but one column.
    EXPECT_EQ(v.members()[2].keyPosition.column, 3);
    EXPECT_EQ(v.find("ü")->position().column, 8);
    EXPECT_EQ(v.members()[0].key, "a");  // file order is kept
    EXPECT_EQ(v.members()[2].key, "ü");
}

TEST(Json, ErrorsSayWhatAndWhere)
{
    auto e = errorOf("{\"a\": 1,\n}");
    EXPECT_NE(i18ntest::english(e.message).find("trailing comma"), std::string::npos) << e.message;
    EXPECT_EQ(e.position.line, 2);
    EXPECT_EQ(e.position.column, 1);

    e = errorOf("[1, 2,]");
    EXPECT_NE(i18ntest::english(e.message).find("trailing comma"), std::string::npos);

    e = errorOf("{\"a\": 1, \"b\": 2, \"a\": 3}");
    EXPECT_NE(i18ntest::english(e.message).find("\"a\" appears twice"), std::string::npos) << e.message;
    EXPECT_EQ(e.position.column, 18);

    e = errorOf("// note\n{}");
    EXPECT_NE(i18ntest::english(e.message).find("comments"), std::string::npos);

    e = errorOf("{\"name\": \"abc\n\"}");
    EXPECT_NE(i18ntest::english(e.message).find("unterminated string"), std::string::npos);

    e = errorOf("{\"a\": 01}");
    EXPECT_NE(i18ntest::english(e.message).find("leading zeros"), std::string::npos);

    e = errorOf("{\"a\": NaN}");
    EXPECT_NE(i18ntest::english(e.message).find("expected a value"), std::string::npos);

    e = errorOf("{\"a\": 1e999}");
    EXPECT_NE(i18ntest::english(e.message).find("too large"), std::string::npos);

    e = errorOf("{} {}");
    EXPECT_NE(i18ntest::english(e.message).find("after the end"), std::string::npos);

    e = errorOf("\"\xC3\x28\"");
    EXPECT_NE(i18ntest::english(e.message).find("UTF-8"), std::string::npos);
    e = errorOf("\"\xED\xA0\x80\"");  // an encoded surrogate
    EXPECT_NE(i18ntest::english(e.message).find("UTF-8"), std::string::npos);
    e = errorOf("\"\\uD800x\"");
    EXPECT_NE(i18ntest::english(e.message).find("surrogate"), std::string::npos);
    e = errorOf("");
    EXPECT_NE(i18ntest::english(e.message).find("end of the text"), std::string::npos);
}

TEST(Json, DeepNestingIsRefusedNotACrash)
{
    std::string deep(kMaxDepth + 10, '[');
    deep += std::string(kMaxDepth + 10, ']');
    const auto e = errorOf(deep);
    EXPECT_NE(i18ntest::english(e.message).find("nested deeper"), std::string::npos);
    std::string ok(kMaxDepth, '[');
    ok += std::string(kMaxDepth, ']');
    EXPECT_TRUE(parse(ok));
}

TEST(Json, EscapesAndUnicodeRoundTrip)
{
    const ParseResult r = parse(R"(["a\"b\\c\/d\b\f\n\r\t", "\u00e9\u4e2d\ud83d\ude00", "\u0001"])");
    ASSERT_TRUE(r) << r.error.message;
    EXPECT_EQ(r.value->items()[0].asString(), "a\"b\\c/d\b\f\n\r\t");
    EXPECT_EQ(r.value->items()[1].asString(), "\xC3\xA9\xE4\xB8\xAD\xF0\x9F\x98\x80");
    const std::string text = write(*r.value);
    const ParseResult back = parse(text);
    ASSERT_TRUE(back) << text;
    for (std::size_t k = 0; k < 3; ++k)
        EXPECT_EQ(back.value->items()[k].asString(), r.value->items()[k].asString());
    EXPECT_NE(text.find("\\u0001"), std::string::npos);
}

TEST(Json, NumbersAreWrittenShortestAndReadBackExactly)
{
    Value a = Value::array();
    a.push(0.1).push(14.38).push(-3).push(1e-7).push(123456789012.0).push(0.30000000000000004).push(-0.0);
    const std::string text = write(a, false);
    EXPECT_EQ(text, "[0.1,14.38,-3,1e-07,123456789012,0.30000000000000004,0]");
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> d(-1e6, 1e6);
    for (int k = 0; k < 2000; ++k) {
        const double x = d(rng) * std::pow(10.0, static_cast<int>(rng() % 20) - 10);
        const ParseResult r = parse(write(Value(x), false));
        ASSERT_TRUE(r);
        EXPECT_EQ(r.value->asNumber(), x);
    }
}

TEST(Json, WriterKeepsOrderAndIndents)
{
    Value v = schemaObject("benchpilot.test", 1);
    v.set("name", "plate A");
    v.set("xy_mm", Value::array().push(14.38).push(11.24));
    v.set("steps", Value::array().push(Value::object().set("type", "wait")));
    v.set("name", "plate B");  // replaced in place, order kept
    EXPECT_EQ(write(v),
              "{\n"
              "  \"schema\": \"benchpilot.test\",\n"
              "  \"version\": 1,\n"
              "  \"name\": \"plate B\",\n"
              "  \"xy_mm\": [14.38, 11.24],\n"
              "  \"steps\": [\n"
              "    {\n"
              "      \"type\": \"wait\"\n"
              "    }\n"
              "  ]\n"
              "}\n");
}

TEST(JsonFields, EveryProblemIsCollectedWithItsPlace)
{
    const ParseResult r = parse("{\n"
                                "  \"schema\": \"benchpilot.test\", \"version\": 1,\n"
                                "  \"volume_ul\": -5,\n"
                                "  \"cycles\": 2.5,\n"
                                "  \"mode\": \"fast\",\n"
                                "  \"volum\": 3,\n"
                                "  \"name\": 7\n"
                                "}");
    ASSERT_TRUE(r);
    Problems problems;
    EXPECT_EQ(checkSchema(*r.value, "benchpilot.test", 1, problems), 1);
    ObjectReader o(*r.value, "", problems);
    EXPECT_FALSE(o.number("volume_ul", true, 0, 1000));
    EXPECT_FALSE(o.integer("cycles", true, 1, 100));
    EXPECT_FALSE(o.oneOf("mode", true, {"slow", "normal"}));
    EXPECT_FALSE(o.string("name", true));
    EXPECT_FALSE(o.number("speed", true, 0, 10));
    EXPECT_EQ(o.number("speed_opt", false, 0, 10), std::nullopt);
    o.refuseUnknown({"schema", "version", "volume_ul", "cycles", "mode", "name", "speed"});
    const std::string text = i18ntest::englishFormat(problems, "r.json");
    EXPECT_NE(text.find("r.json:3:16: volume_ul: must be from 0 to 1000 (got -5)"), std::string::npos) << text;
    EXPECT_NE(text.find("r.json:4:13: cycles: must be a whole number (got 2.5)"), std::string::npos) << text;
    EXPECT_NE(text.find("mode: \"fast\" is not one of \"slow\", \"normal\""), std::string::npos) << text;
    EXPECT_NE(text.find("r.json:7:11: name: must be a string, not a number"), std::string::npos) << text;
    EXPECT_NE(text.find("r.json:1:1: speed: is missing"), std::string::npos) << text;
    EXPECT_NE(text.find("r.json:6:3: volum: unknown field; did you mean \"volume_ul\"?"), std::string::npos) << text;
    EXPECT_EQ(problems.size(), 6u) << text;
}

TEST(JsonFields, SchemaHeaderIsChecked)
{
    Problems p;
    EXPECT_FALSE(checkSchema(*parse("[1]").value, "benchpilot.x", 1, p));
    EXPECT_FALSE(checkSchema(*parse("{\"version\": 1}").value, "benchpilot.x", 1, p));
    EXPECT_FALSE(checkSchema(*parse("{\"schema\": \"benchpilot.y\", \"version\": 1}").value, "benchpilot.x", 1, p));
    EXPECT_FALSE(checkSchema(*parse("{\"schema\": \"benchpilot.x\", \"version\": 2}").value, "benchpilot.x", 1, p));
    EXPECT_FALSE(checkSchema(*parse("{\"schema\": \"benchpilot.x\", \"version\": 0.5}").value, "benchpilot.x", 1, p));
    EXPECT_EQ(checkSchema(*parse("{\"schema\": \"benchpilot.x\", \"version\": 2}").value, "benchpilot.x", 3, p), 2);
    ASSERT_EQ(p.size(), 5u);
    EXPECT_NE(i18ntest::english(p.list()[3].message).find("newer BenchPilot"), std::string::npos);
    EXPECT_NE(i18ntest::english(p.list()[2].message).find("expected \"benchpilot.x\""), std::string::npos);
}

TEST(Json, RandomBytesNeverCrashAndValidTextRoundTrips)
{
    std::mt19937_64 rng(11);
    const std::string alphabet = "{}[]:,\" \n\\tfnrule0123456789.-+eE\xC3\xA9\x80";
    for (int k = 0; k < 20000; ++k) {
        std::string s;
        const int n = static_cast<int>(rng() % 40);
        for (int i = 0; i < n; ++i)
            s += alphabet[rng() % alphabet.size()];
        const ParseResult r = parse(s);
        if (r) {
            const ParseResult again = parse(write(*r.value));
            ASSERT_TRUE(again) << s;
            EXPECT_EQ(write(*again.value), write(*r.value));
        } else {
            EXPECT_GE(r.error.position.line, 1);
            EXPECT_GE(r.error.position.column, 1);
            EXPECT_FALSE(r.error.message.empty());
        }
    }
}
