#include "motion/message.h"

#include <gtest/gtest.h>

namespace {

TEST(Message, ArgumentsAreFoundByNameWithTheirTypes)
{
    const msg::Message m = msg::make("pattern.value_above",
                                     {msg::real("min", 0, msg::Unit::Mm), msg::real("value", -2.5, msg::Unit::Mm),
                                      msg::verbatim("field", "radius_mm"), msg::integer("segment", 3)});
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
    const msg::Message inner = msg::make("device.not_homed", {msg::verbatim("axis", "X")});
    const msg::Message m = msg::make("request.refused", {msg::term("what", "request.move"), msg::nested("reason", inner),
                                                         msg::real("value", 12.5, msg::Unit::Um)});
    EXPECT_EQ(msg::debugString(m),
              "request.refused{what=term:request.move, reason=device.not_homed{axis=\"X\"}, value=12.5 µm}");
}

TEST(Message, EqualityComparesIdsArgumentsUnitsAndNestedMessages)
{
    const auto a = msg::make("x", {msg::real("v", 1, msg::Unit::Mm), msg::nested("why", msg::make("y"))});
    EXPECT_EQ(a, msg::make("x", {msg::real("v", 1, msg::Unit::Mm), msg::nested("why", msg::make("y"))}));
    EXPECT_NE(a, msg::make("x", {msg::real("v", 1, msg::Unit::Um), msg::nested("why", msg::make("y"))}));
    EXPECT_NE(a, msg::make("x", {msg::real("v", 1, msg::Unit::Mm), msg::nested("why", msg::make("z"))}));
    EXPECT_NE(a, msg::make("x", {msg::integer("v", 1, msg::Unit::Mm), msg::nested("why", msg::make("y"))}));
}

} // namespace
