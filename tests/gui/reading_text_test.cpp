// A live reading never shows a sign the machine did not earn: a hair below zero is 0.000.
#include "widgets/common/reading_text.h"

#include <gtest/gtest.h>

TEST(ReadingText, AValueThatRoundsToZeroReadsZeroWithoutASign)
{
    EXPECT_EQ(ui::readingText(-0.0000001, 3), QStringLiteral("0.000"));
    EXPECT_EQ(ui::readingText(-0.0004, 3), QStringLiteral("0.000"));
    EXPECT_EQ(ui::readingText(-0.0006, 3), QStringLiteral("-0.001"));
    EXPECT_EQ(ui::readingText(20.0184, 3), QStringLiteral("20.018"));
    EXPECT_EQ(ui::readingText(-0.004, 2), QStringLiteral("0.00"));
    EXPECT_EQ(ui::readingText(-12.5, 1), QStringLiteral("-12.5"));
}
