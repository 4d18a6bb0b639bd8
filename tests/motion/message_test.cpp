#include "motion/message.h"

#include <gtest/gtest.h>

namespace {

TEST(Message, ArgumentsAreFoundByNameWithTheirTypes)
{
    const motion::msg::Message m = motion::msg::make("pattern.value_above",
                                     {motion::msg::real("min", 0, motion::msg::Unit::Mm), motion::msg::real("value", -2.5, motion::msg::Unit::Mm),
                                      motion::msg::verbatim("field", "radius_mm"), motion::msg::integer("segment", 3)});
    EXPECT_EQ(m.number("value"), -2.5);
    EXPECT_EQ(m.integer("segment"), 3);
    EXPECT_EQ(m.number("segment"), 3.0);  // a whole number reads as a number too
    EXPECT_EQ(m.text("field"), "radius_mm");
    EXPECT_EQ(m.arg("missing"), nullptr);
    EXPECT_EQ(m.number("missing", 7), 7);
    EXPECT_EQ(m.integer("value", -1), -1);  // a real is not silently truncated to an integer
}

TEST(Message, DebugStringNamesTheIdAndEveryArgumentWithItsUnit)
{
    const motion::msg::Message inner = motion::msg::make("device.not_homed", {motion::msg::verbatim("axis", "X")});
    const motion::msg::Message m = motion::msg::make("request.refused", {motion::msg::term("what", "request.move"), motion::msg::nested("reason", inner),
                                                         motion::msg::real("value", 12.5, motion::msg::Unit::Um)});
    EXPECT_EQ(motion::msg::debugString(m),
              "request.refused{what=term:request.move, reason=device.not_homed{axis=\"X\"}, value=12.5 µm}");
}

TEST(Message, EqualityComparesIdsArgumentsUnitsAndNestedMessages)
{
    const auto a = motion::msg::make("x", {motion::msg::real("v", 1, motion::msg::Unit::Mm), motion::msg::nested("why", motion::msg::make("y"))});
    EXPECT_EQ(a, motion::msg::make("x", {motion::msg::real("v", 1, motion::msg::Unit::Mm), motion::msg::nested("why", motion::msg::make("y"))}));
    EXPECT_NE(a, motion::msg::make("x", {motion::msg::real("v", 1, motion::msg::Unit::Um), motion::msg::nested("why", motion::msg::make("y"))}));
    EXPECT_NE(a, motion::msg::make("x", {motion::msg::real("v", 1, motion::msg::Unit::Mm), motion::msg::nested("why", motion::msg::make("z"))}));
    EXPECT_NE(a, motion::msg::make("x", {motion::msg::integer("v", 1, motion::msg::Unit::Mm), motion::msg::nested("why", motion::msg::make("y"))}));
}

} // namespace
