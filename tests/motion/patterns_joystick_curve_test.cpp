// Joystick deflection → velocity: dead-band, expo, round two-axis shaping.
#include "motion/jog/joystick_curve.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace motion::jog;

TEST(PatternsJoystickCurve, DeadbandGivesNothingAndTheRimGivesFullSpeed)
{
    const StickShaping s{0.1, 0.5};
    EXPECT_EQ(shapeAxis(0.0, s), 0.0);
    EXPECT_EQ(shapeAxis(0.09, s), 0.0);
    EXPECT_EQ(shapeAxis(-0.1, s), 0.0);
    EXPECT_DOUBLE_EQ(shapeAxis(1.0, s), 1.0);
    EXPECT_DOUBLE_EQ(shapeAxis(-1.0, s), -1.0);
    EXPECT_DOUBLE_EQ(shapeAxis(3.0, s), 1.0);  // beyond the rim: cut
    EXPECT_EQ(shapeAxis(std::nan(""), s), 0.0);
    // Past the dead-band the output starts from 0 (no jump) and rises monotonically.
    EXPECT_LT(shapeAxis(0.1001, s), 1e-3);
    double last = 0;
    for (int k = 11; k <= 100; ++k) {
        const double v = shapeAxis(k / 100.0, s);
        EXPECT_GT(v, last);
        last = v;
    }
}

TEST(PatternsJoystickCurve, ExpoGivesFinerControlNearTheCentre)
{
    const StickShaping linear{0, 0}, cubic{0, 1}, mixed{0, 0.5};
    EXPECT_DOUBLE_EQ(shapeAxis(0.5, linear), 0.5);
    EXPECT_DOUBLE_EQ(shapeAxis(0.5, cubic), 0.125);
    EXPECT_DOUBLE_EQ(shapeAxis(0.5, mixed), 0.5 * 0.5 + 0.5 * 0.125);
}

TEST(PatternsJoystickCurve, TwoAxesKeepTheDirectionAndARoundDeadband)
{
    const StickShaping s{0.1, 0.3};
    const auto v = shapeStick({0.6, 0.8}, s);  // length 1 along (3,4)/5
    EXPECT_NEAR(v.x, 0.6, 1e-12);
    EXPECT_NEAR(v.y, 0.8, 1e-12);
    const auto small = shapeStick({0.07, 0.07}, s);  // |d| = 0.099: inside the round dead-band
    EXPECT_EQ(small.x, 0.0);
    EXPECT_EQ(small.y, 0.0);
    const auto diag = shapeStick({0.5, 0.5}, s), axis = shapeStick({std::sqrt(0.5), 0}, s);
    EXPECT_NEAR(std::hypot(diag.x, diag.y), axis.x, 1e-12);  // same push, same speed
    const auto far = shapeStick({3, 4}, s);
    EXPECT_NEAR(std::hypot(far.x, far.y), 1.0, 1e-12);
}
