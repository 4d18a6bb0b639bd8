// The hostile campaign on real ptys (label hostile): benchpilot-sim ← bp-faultline ←
// benchpilot-cli, per seed and rate, each job once with the cable pulled part-way and once
// with the CLI killed (SIGKILL) part-way and a new CLI resuming from the run log. Seeds and
// rates from the same variables as the loopback campaign (hostile_campaign_test.cpp).
#include "integration/hostile_pty_support.h"

#include <gtest/gtest.h>

#include <functional>
#include <vector>

namespace {

std::vector<double> ptyRates()
{
    std::vector<double> out;
    const QByteArray env = qgetenv("BP_HOSTILE_RATES");
    for (const QByteArray& r : (env.isEmpty() ? QByteArray("0.003,0.01") : env).split(','))
        out.push_back(r.toDouble());
    return out;
}

void ptyCampaign(const std::function<hostile::Outcome(double, std::uint64_t)>& run)
{
    const int seeds = qEnvironmentVariableIntValue("BP_HOSTILE_SEEDS") > 0 ? qEnvironmentVariableIntValue("BP_HOSTILE_SEEDS") : 3;
    const int first = qEnvironmentVariableIntValue("BP_HOSTILE_FIRST") > 0 ? qEnvironmentVariableIntValue("BP_HOSTILE_FIRST") : 1;
    for (double rate : ptyRates())
        for (int seed = first; seed < first + seeds; ++seed) {
            const hostile::Outcome o = run(rate, static_cast<std::uint64_t>(seed) * 7919);
            std::printf("%s\n", o.line().c_str());
            std::fflush(stdout);
            EXPECT_TRUE(o.held) << o.line();
        }
}

} // namespace

TEST(HostilePty, Recipe24WellsWithAnUnplug)
{
    ptyCampaign([](double r, std::uint64_t s) { return hostile::ptyRecipe(r, s, "A1:B12", 24, {hostile::Cut::Unplug, 8}); });
}

TEST(HostilePty, Recipe24WellsWithAKilledCli)
{
    ptyCampaign([](double r, std::uint64_t s) { return hostile::ptyRecipe(r, s, "A1:B12", 24, {hostile::Cut::Kill, 8}); });
}

// The case a lab fears most: sampling-96, the CLI killed a third of the way through.
TEST(HostilePty, Recipe96WellsWithAKilledCli)
{
    ptyCampaign([](double r, std::uint64_t s) { return hostile::ptyRecipe(r, s, "A1:H12", 96, {hostile::Cut::Kill, 30}); });
}

TEST(HostilePty, ScanWithAnUnplug)
{
    ptyCampaign([](double r, std::uint64_t s) { return hostile::ptyScan(r, s, 3.6, {hostile::Cut::Unplug, 5}); });
}

TEST(HostilePty, ScanWithAKilledCli)
{
    ptyCampaign([](double r, std::uint64_t s) { return hostile::ptyScan(r, s, 3.6, {hostile::Cut::Kill, 5}); });
}

// A circle (each job goes through the bad line, pattern included): whole through
// damaged bytes; cut by an unplug, the CLI ends with how long it ran, the stage on the path.
TEST(HostilePty, PatternThroughDamagedBytes)
{
    ptyCampaign([](double r, std::uint64_t s) { return hostile::ptyPattern(r, s, false); });
}

TEST(HostilePty, PatternWithAnUnplug)
{
    ptyCampaign([](double r, std::uint64_t s) { return hostile::ptyPattern(r, s, true); });
}

// Gains: a Ziegler–Nichols run cut by an unplug leaves the axis under the gains it had, at rest.
TEST(HostilePty, TuningWithAnUnplug)
{
    ptyCampaign([](double r, std::uint64_t s) { return hostile::ptyTuningCut(r, s); });
}

// A held jog: after the line is pulled or hangs, X rests within the device's watchdog of
// its last renewal (the loopback's joystick case, on real ptys; odd seeds pull, even hang).
TEST(HostilePty, HeldJogWhenTheLineDies)
{
    ptyCampaign([](double r, std::uint64_t s) { return hostile::ptyJog(r, s); });
}
