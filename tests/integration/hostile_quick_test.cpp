// The hostile line's quick set (default run): each job once at 1 % of bytes damaged,
// kept short. The many-seed campaign is tests/hostile/ (CTest label hostile).
#include "hostile_support.h"

#include <gtest/gtest.h>

namespace {
void report(const hostile::Outcome& o)
{
    std::printf("%s\n", o.line().c_str());
    std::fflush(stdout);
    EXPECT_TRUE(o.held) << o.line();
}
} // namespace

TEST(HostileQuick, RecipeEveryWellOnceAndThePlungerAccountedFor) { report(hostile::recipe(0.01, 1, "A1:A2", 2)); }

TEST(HostileQuick, ScanEveryTileOnceWithAMeasuredPositionThroughAnUnplug) { report(hostile::scan(0.01, 1, 1.8, true)); }

TEST(HostileQuick, PatternRunsThePathOnce) { report(hostile::pattern(0.01, 1)); }

TEST(HostileQuick, TuningCutLeavesTheGains) { report(hostile::tuningCut(0.01, 1)); }

TEST(HostileQuick, JoystickStopsWithinTheWatchdogWhenTheCableIsPulled) { report(hostile::joystick(0.01, 1, 400)); }

TEST(HostileQuick, JoystickStopsWithinTheWatchdogWhenTheLineHangs) { report(hostile::joystick(0.01, 2, 400)); }
