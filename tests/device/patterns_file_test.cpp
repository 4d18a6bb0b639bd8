// Pattern files (device/files/pattern_file.h): the examples load and plan, files round-trip,
// every problem is reported at once with its place, writes are atomic.
#include "device/english_words.h"
#include "device/files/pattern_file.h"

#include <QDir>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

using motion::plans::Pattern;
using motion::plans::PatternShape;

namespace {

/// resources/examples/ of the source tree, as the build knows it (a compiler cache
/// may make __FILE__ relative to another directory than the one the test runs in).
std::string examplesDir() { return std::string(BP_SOURCE_DIR) + "/resources/examples/"; }

std::string slurp(const std::string& path)
{
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

std::string problemsOf(std::string_view text)
{
    return i18ntest::englishFormat(dev::files::parsePattern(text).problems, "p.pattern.json");
}

}  // namespace

TEST(PatternsFile, EveryExampleLoadsPlansAndIsWrittenExactlyAsStored)
{
    QDir dir(QString::fromStdString(examplesDir()));
    const auto names = dir.entryList({QStringLiteral("*.pattern.json")}, QDir::Files);
    ASSERT_GE(names.size(), 6);
    for (const QString& n : names) {
        const std::string text = slurp(examplesDir() + n.toStdString());
        const auto r = dev::files::parsePattern(text);
        ASSERT_TRUE(r.pattern) << n.toStdString() << "\n" << i18ntest::englishFormat(r.problems, n.toStdString());
        EXPECT_FALSE(motion::plans::plan(*r.pattern).empty()) << n.toStdString();
        EXPECT_EQ(dev::files::writePattern(*r.pattern), text) << n.toStdString() << " is not in the writer's form";
    }
}

TEST(PatternsFile, EveryShapeRoundTrips)
{
    for (PatternShape s : motion::plans::kAllShapes) {
        Pattern p;
        p.name = "shape ü";
        p.shape = s;
        p.feedMmS = 3.25;
        p.zMm = -0.5;
        p.rectangle.clockwise = true;
        p.raster.alongY = true;
        p.wave.angleDeg = 12.5;
        const std::string text = dev::files::writePattern(p);
        const auto r = dev::files::parsePattern(text);
        ASSERT_TRUE(r.pattern) << text << i18ntest::englishFormat(r.problems, "x");
        EXPECT_EQ(dev::files::writePattern(*r.pattern), text);
        EXPECT_EQ(motion::plans::plan(*r.pattern).size(), motion::plans::plan(p).size());
    }
}

TEST(PatternsFile, AllProblemsAtOnceWithLineColumnAndField)
{
    const std::string text = "{\n"
                             "  \"schema\": \"benchpilot.pattern\",\n"
                             "  \"version\": 1,\n"
                             "  \"shape\": \"circle\",\n"
                             "  \"feed_mm_s\": \"fast\",\n"
                             "  \"center_mm\": [50],\n"
                             "  \"radius\": 5,\n"
                             "  \"direction\": \"left\"\n"
                             "}\n";
    EXPECT_EQ(problemsOf(text),
              "p.pattern.json:5:16: feed_mm_s: must be a number, not a string\n"
              "p.pattern.json:6:16: center_mm: must be an array of 2 numbers\n"
              "p.pattern.json:1:1: radius_mm: is missing\n"
              "p.pattern.json:8:16: direction: \"left\" is not one of \"ccw\", \"cw\"\n"
              "p.pattern.json:7:3: radius: unknown field; did you mean \"radius_mm\"?\n");
}

TEST(PatternsFile, ThePatternsOwnRulesArePlacedAtTheirField)
{
    const std::string text = "{\"schema\": \"benchpilot.pattern\", \"version\": 1, \"shape\": \"spiral\", \"feed_mm_s\": 4,\n"
                             " \"center_mm\": [50, 50], \"start_radius_mm\": 1, \"pitch_mm\": 0, \"turns\": 2.2}\n";
    EXPECT_EQ(problemsOf(text), "p.pattern.json:2:59: pitch_mm: must be above 0.000 mm (got 0.000 mm)\n"
                                "p.pattern.json:2:71: turns: must be a whole or half number of turns (got 2.2)\n");
}

TEST(PatternsFile, ANewerVersionOrAnotherKindIsRefused)
{
    EXPECT_NE(problemsOf(R"({"schema": "benchpilot.pattern", "version": 2, "shape": "line"})").find("written by a newer BenchPilot"),
              std::string::npos);
    EXPECT_NE(problemsOf(R"({"schema": "benchpilot.recipe", "version": 1})").find("expected \"benchpilot.pattern\""),
              std::string::npos);
    EXPECT_NE(problemsOf("{\"schema\": ").find("p.pattern.json:1:12"), std::string::npos);
    // Fields of another shape are not silently ignored.
    EXPECT_NE(problemsOf(R"({"schema": "benchpilot.pattern", "version": 1, "shape": "line", "feed_mm_s": 1,
        "start_mm": [0, 0], "end_mm": [1, 1], "radius_mm": 3})").find("radius_mm: unknown field"),
              std::string::npos);
}

TEST(PatternsFile, SaveIsAtomicAndLoadNamesTheFile)
{
    QTemporaryDir tmp;
    const QString path = tmp.filePath(QStringLiteral("c.pattern.json"));
    Pattern p;
    p.name = "c";
    motion::msg::Message error;
    ASSERT_TRUE(dev::files::savePatternFile(path, p, &error)) << error;
    Pattern back;
    dev::files::json::Problems problems;
    ASSERT_TRUE(dev::files::loadPatternFile(path, &back, &problems)) << i18ntest::englishFormat(problems, "c.pattern.json");
    EXPECT_EQ(back.name, "c");
    EXPECT_EQ(back.circle.radiusMm, p.circle.radiusMm);
    std::ofstream(tmp.filePath(QStringLiteral("bad.pattern.json")).toStdString()) << "{\"schema\": \"benchpilot.pattern\"}";
    EXPECT_FALSE(dev::files::loadPatternFile(tmp.filePath(QStringLiteral("bad.pattern.json")), &back, &problems));
    EXPECT_EQ(i18ntest::englishFormat(problems, "bad.pattern.json").rfind("bad.pattern.json:1:", 0), 0u) << i18ntest::englishFormat(problems, "bad.pattern.json");
    dev::files::json::Problems none;
    EXPECT_FALSE(dev::files::loadPatternFile(tmp.filePath(QStringLiteral("none.pattern.json")), &back, &none));
    EXPECT_NE(i18ntest::englishFormat(none, "x").find("none.pattern.json"), std::string::npos);
}
