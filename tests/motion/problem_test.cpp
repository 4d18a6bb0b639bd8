// The one problem type and the one result shape every validator, planner and reader
// uses: a refusal always carries an error, a value may carry warnings, and the
// debugging form names the place as far as it is known.
#include "motion/checked.h"
#include "motion/problem.h"

#include <gtest/gtest.h>

namespace {

TEST(Problem, AWarningDoesNotRefuse)
{
    motion::msg::Problems ps{motion::msg::warning("cycles", motion::msg::make("accuracy.few_cycles"))};
    EXPECT_FALSE(motion::msg::hasErrors(ps));
    EXPECT_EQ(motion::msg::errorCount(ps), 0);
    ps.push_back(motion::msg::error("targets_mm[3]", motion::msg::make("accuracy.value_above")));
    EXPECT_TRUE(motion::msg::hasErrors(ps));
    EXPECT_EQ(motion::msg::errorCount(ps), 1);
}

TEST(Problem, PathsJoinAsTheFilesWriteThem)
{
    EXPECT_EQ(motion::msg::fieldPath("", "cycles"), "cycles");
    EXPECT_EQ(motion::msg::fieldPath("settle", "timeout_s"), "settle.timeout_s");
    EXPECT_EQ(motion::msg::indexPath("steps", 3), "steps[3]");
    EXPECT_EQ(motion::msg::fieldPath(motion::msg::indexPath("steps", 3), "wells"), "steps[3].wells");
}

TEST(Problem, TheDebugFormNamesThePlaceAsFarAsItIsKnown)
{
    motion::msg::Problem p = motion::msg::warning("steps[3].volume_ul", motion::msg::make("recipe.volume_low"));
    EXPECT_EQ(motion::msg::debugString(p), "steps[3].volume_ul: warning: recipe.volume_low{}");
    p.file = "a.recipe.json";
    p.line = 12;
    p.column = 7;
    p.severity = motion::msg::Severity::Error;
    EXPECT_EQ(motion::msg::debugString(p), "a.recipe.json:12:7: steps[3].volume_ul: recipe.volume_low{}");
}

TEST(Checked, AValueMayCarryWarningsARefusalAlwaysAnError)
{
    const auto fine = motion::msg::Checked<int>::ok(3);
    ASSERT_TRUE(fine);
    EXPECT_EQ(*fine, 3);
    EXPECT_TRUE(fine.problems().empty());
    EXPECT_TRUE(fine.error().empty());

    const auto warned = motion::msg::Checked<int>::from(4, {motion::msg::warning("x", motion::msg::make("w"))});
    ASSERT_TRUE(warned);
    EXPECT_EQ(warned.problems().size(), 1u);

    const auto refused = motion::msg::Checked<int>::from(5, {motion::msg::warning("x", motion::msg::make("w")), motion::msg::error("y", motion::msg::make("e"))});
    EXPECT_FALSE(refused);
    EXPECT_EQ(refused.problems().size(), 2u) << "the warnings stay beside the errors";
    EXPECT_EQ(refused.error().id, "e") << "the first error, not the first problem";

    const auto failed = motion::msg::Checked<std::string>::fail(motion::msg::make("profile.not_positive"));
    EXPECT_FALSE(failed);
    EXPECT_EQ(failed.error().id, "profile.not_positive");
}

} // namespace
