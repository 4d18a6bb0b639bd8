// The hostile line on real ptys, quick (default run): benchpilot-sim ← bp-faultline ←
// benchpilot-cli at 1 % of bytes damaged, the cable pulled part-way, the run resumed by a
// new CLI from its log; judged on the simulator's journal. The campaign over seeds, rates
// and killed CLIs is tests/hostile/hostile_pty_campaign_test.cpp (label hostile).
#include "hostile_pty_support.h"

#include <gtest/gtest.h>

namespace {
void report(const hostile::Outcome& o)
{
    std::printf("%s\n", o.line().c_str());
    std::fflush(stdout);
    EXPECT_TRUE(o.held) << o.line();
}
} // namespace

TEST(HostilePtyQuick, RecipeThroughAPulledCableEveryWellOnceAndThePlungerAccountedFor)
{
    report(hostile::ptyRecipe(0.01, 1, "A1:A3", 3, {hostile::Cut::Unplug, 1}));
}

TEST(HostilePtyQuick, ScanThroughAPulledCableEveryTileOnceWithAMeasuredPosition)
{
    report(hostile::ptyScan(0.01, 1, 1.8, {hostile::Cut::Unplug, 2}));
}
