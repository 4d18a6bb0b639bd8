// The one problem type and the one result shape every validator, planner and reader
// uses: a refusal always carries an error, a value may carry warnings, and the
// debugging form names the place as far as it is known.
#include "motion/checked.h"
#include "motion/problem.h"

#include <gtest/gtest.h>

namespace {

TEST(Problem, AWarningDoesNotRefuse)
{
    msg::Problems ps{msg::warning("cycles", msg::make("accuracy.few_cycles"))};
    EXPECT_FALSE(msg::hasErrors(ps));
    EXPECT_EQ(msg::errorCount(ps), 0);
    ps.push_back(msg::error("targets_mm[3]", msg::make("accuracy.value_above")));
    EXPECT_TRUE(msg::hasErrors(ps));
    EXPECT_EQ(msg::errorCount(ps), 1);
}

TEST(Problem, PathsJoinAsTheFilesWriteThem)
{
    EXPECT_EQ(msg::fieldPath("", "cycles"), "cycles");
    EXPECT_EQ(msg::fieldPath("settle", "timeout_s"), "settle.timeout_s");
    EXPECT_EQ(msg::indexPath("steps", 3), "steps[3]");
    EXPECT_EQ(msg::fieldPath(msg::indexPath("steps", 3), "wells"), "steps[3].wells");
}

TEST(Problem, TheDebugFormNamesThePlaceAsFarAsItIsKnown)
{
    msg::Problem p = msg::warning("steps[3].volume_ul", msg::make("recipe.volume_low"));
    EXPECT_EQ(msg::debugString(p), "steps[3].volume_ul: warning: recipe.volume_low{}");
    p.file = "a.recipe.json";
    p.line = 12;
    p.column = 7;
    p.severity = msg::Severity::Error;
    EXPECT_EQ(msg::debugString(p), "a.recipe.json:12:7: steps[3].volume_ul: recipe.volume_low{}");
}

TEST(Checked, AValueMayCarryWarningsARefusalAlwaysAnError)
{
    const auto fine = msg::Checked<int>::ok(3);
    ASSERT_TRUE(fine);
    EXPECT_EQ(*fine, 3);
    EXPECT_TRUE(fine.problems().empty());
    EXPECT_TRUE(fine.error().empty());

    const auto warned = msg::Checked<int>::from(4, {msg::warning("x", msg::make("w"))});
    ASSERT_TRUE(warned);
    EXPECT_EQ(warned.problems().size(), 1u);

    const auto refused = msg::Checked<int>::from(5, {msg::warning("x", msg::make("w")), msg::error("y", msg::make("e"))});
    EXPECT_FALSE(refused);
    EXPECT_EQ(refused.problems().size(), 2u) << "the warnings stay beside the errors";
    EXPECT_EQ(refused.error().id, "e") << "the first error, not the first problem";

    const auto failed = msg::Checked<std::string>::fail(msg::make("profile.not_positive"));
    EXPECT_FALSE(failed);
    EXPECT_EQ(failed.error().id, "profile.not_positive");
}

} // namespace
