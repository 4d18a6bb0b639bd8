// The hostile campaign (CTest label hostile, not in ./scripts/test): every job over
// many seeds at 0.1 %, 0.3 % and 1 % of bytes damaged (dropped, corrupted, doubled,
// jittered), judged on the simulator's own record. One "[ hostile ]" line per run;
// docs/testing.md ("Hostile link") has the table made from them.
//   BP_HOSTILE_SEEDS   seeds per rate (default 3)
//   BP_HOSTILE_RATES   comma-separated byte fault rates (default 0.001,0.003,0.01)
//   BP_HOSTILE_FIRST   first seed number (default 1), to add seeds to an earlier campaign
#include "integration/hostile_support.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <functional>
#include <vector>

namespace {

std::vector<double> rates()
{
    std::vector<double> out;
    const QByteArray env = qgetenv("BP_HOSTILE_RATES");
    for (const QByteArray& r : (env.isEmpty() ? QByteArray("0.001,0.003,0.01") : env).split(','))
        out.push_back(r.toDouble());
    return out;
}

int seeds()
{
    const int n = qEnvironmentVariableIntValue("BP_HOSTILE_SEEDS");
    return n > 0 ? n : 3;
}

int first()
{
    const int n = qEnvironmentVariableIntValue("BP_HOSTILE_FIRST");
    return n > 0 ? n : 1;
}

void campaign(const std::function<hostile::Outcome(double, std::uint64_t)>& run)
{
    for (double rate : rates())
        for (int seed = first(); seed < first() + seeds(); ++seed) {
            const hostile::Outcome o = run(rate, static_cast<std::uint64_t>(seed) * 7919);
            std::printf("%s\n", o.line().c_str());
            std::fflush(stdout);
            EXPECT_TRUE(o.held) << o.line();
        }
}

} // namespace

TEST(Hostile, Recipe96Wells)
{
    campaign([](double r, std::uint64_t s) { return hostile::recipe(r, s, "A1:H12", 96); });
}

TEST(Hostile, ScanWithAnUnplug)
{
    campaign([](double r, std::uint64_t s) { return hostile::scan(r, s, 3.6, true); });
}

TEST(Hostile, Pattern)
{
    campaign([](double r, std::uint64_t s) { return hostile::pattern(r, s); });
}

TEST(Hostile, TuningCut)
{
    campaign([](double r, std::uint64_t s) { return hostile::tuningCut(r, s); });
}

TEST(Hostile, Joystick)
{
    campaign([](double r, std::uint64_t s) { return hostile::joystick(r, s, 800); });
}
