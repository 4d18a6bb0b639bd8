// The host's memory of homes set here on GRBL controllers (dev::GrblHomeMemory): one entry per
// controller, replaced when set again, dropped when forgotten; and whatever cannot be read in
// the file — another schema or version, damaged entries, no JSON at all — counts as nothing
// remembered, never as a home.
#include "device/backends/grbl/grbl_home_memory.h"

#include <gtest/gtest.h>

#include <QFile>
#include <QTemporaryDir>

namespace {

dev::GrblHome homeOf(const std::string& controller, double x)
{
    return {controller, "XY", {x, 2, 0}, {x + 1, 3, 0}};
}

} // namespace

TEST(GrblHomeMemory, RemembersReplacesAndForgetsPerController)
{
    QTemporaryDir dir;
    const dev::GrblHomeMemory memory(dir.filePath(QStringLiteral("state/grbl-homes.json")));  // the folder is made
    EXPECT_FALSE(memory.recall("a").has_value());
    ASSERT_TRUE(memory.remember(homeOf("a", 1)));
    ASSERT_TRUE(memory.remember(homeOf("b", 5)));
    ASSERT_TRUE(memory.remember(homeOf("a", 7)));
    const auto a = memory.recall("a");
    ASSERT_TRUE(a.has_value());
    EXPECT_EQ(a->axes, "XY");
    EXPECT_EQ(a->g54Mm, (std::vector<double>{7, 2, 0}));
    EXPECT_EQ(a->machineMm, (std::vector<double>{8, 3, 0}));
    ASSERT_TRUE(memory.forget("a"));
    EXPECT_FALSE(memory.recall("a").has_value());
    EXPECT_TRUE(memory.recall("b").has_value());
}

TEST(GrblHomeMemory, TheFileSaysItsSchemaAndVersionAndKeepsABoundedNumberOfControllers)
{
    std::vector<dev::GrblHome> many;
    for (std::size_t i = 0; i < dev::GrblHomeMemory::kMaxControllers + 5; ++i)
        many.push_back(homeOf("c" + std::to_string(i), static_cast<double>(i)));
    const std::string text = dev::GrblHomeMemory::serialize(many);
    EXPECT_NE(text.find("\"schema\": \"benchpilot.grbl-homes\""), std::string::npos) << text;
    EXPECT_NE(text.find("\"version\": 1"), std::string::npos) << text;
    EXPECT_EQ(dev::GrblHomeMemory::parse(text).size(), dev::GrblHomeMemory::kMaxControllers);

    QTemporaryDir dir;
    const dev::GrblHomeMemory memory(dir.filePath(QStringLiteral("grbl-homes.json")));
    for (const auto& h : many)
        ASSERT_TRUE(memory.remember(h));
    EXPECT_FALSE(memory.recall("c0").has_value());  // the oldest went first
    EXPECT_TRUE(memory.recall("c" + std::to_string(many.size() - 1)).has_value());
}

TEST(GrblHomeMemory, WhatCannotBeReadIsNothingRemembered)
{
    const std::string good = dev::GrblHomeMemory::serialize({homeOf("a", 1)});
    ASSERT_EQ(dev::GrblHomeMemory::parse(good).size(), 1u);
    auto replaced = [&good](const std::string& from, const std::string& to) {
        std::string t = good;
        const auto at = t.find(from);
        EXPECT_NE(at, std::string::npos) << from;
        return at == std::string::npos ? t : t.replace(at, from.size(), to);
    };
    const std::vector<std::string> bad = {
        "",
        "not json",
        "[]",
        good.substr(0, good.size() / 2),                                     // cut off
        replaced("benchpilot.grbl-homes", "benchpilot.recipe"),               // another schema
        replaced("\"version\": 1", "\"version\": 2"),                         // a later version
        replaced("\"axes\": \"XY\"", "\"axes\": \"\""),                       // no axes
        replaced("\"axes\": \"XY\"", "\"axes\": \"XQ\""),                     // not GRBL axes
        replaced("\"controller\": \"a\"", "\"controller\": 5"),               // a number for a name
        replaced("\"g54_mm\": [", "\"g54_mm\": [\"1\", "),                    // a string for a number
        replaced("\"machine_mm\": [", "\"machine_mm\": [1e308, "),            // beyond any machine
        replaced("\"machine_mm\": [", "\"machine_mm\": [1, "),                // sizes differ
        replaced("\"g54_mm\": [", "\"g54_mm\": {\"x\": "),                    // not an array
    };
    for (const auto& text : bad)
        EXPECT_TRUE(dev::GrblHomeMemory::parse(text).empty()) << text;

    // A damaged file on disk: recalled as nothing; remembering writes it afresh.
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("grbl-homes.json"));
    {
        QFile f(path);
        ASSERT_TRUE(f.open(QIODevice::WriteOnly));
        f.write("{\"schema\": \"benchpilot.grbl-homes\", \"version\": 1, \"controllers\": [{\"contr");
    }
    const dev::GrblHomeMemory memory(path);
    EXPECT_FALSE(memory.recall("a").has_value());
    ASSERT_TRUE(memory.remember(homeOf("a", 1)));
    EXPECT_TRUE(memory.recall("a").has_value());
}
