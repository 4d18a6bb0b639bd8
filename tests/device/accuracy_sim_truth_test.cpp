// The simulator keeps the work point's true position apart from what the encoder or
// grating reads, as on a real machine: the stage's grating loop reads near zero error
// while a gauge at the work point sees the grating's scale error and the Abbe error;
// the analyzer's open-loop carriage carries the screw's lead error and lost steps, which
// its encoder (on the carriage) sees as the gauge does. And the simulated gauge speaks
// its dialect (docs/accuracy.md, "Gauge dialect").
#include "device/sim/machine_config.h"
#include "device/sim/sim_gauge.h"
#include "sim_test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace {

using namespace simtest;

constexpr int kX = 0;

double seedXErrorUm(double x) { return 1.563 + 0.9473 * x - 0.0006 * x * x; }

using StageHomed = HomedMachine<dev::sim::stageConfig>;
using AnalyzerHomed = HomedMachine<dev::sim::analyzerConfig>;

TEST_F(StageHomed, TheGratingReadsNoErrorWhileTheWorkPointCarriesTheSystematicOne)
{
    // Approach each target from below and from above: the loop puts the grating on it
    // within a count either way, the work point lands off by the same curve both ways.
    for (double target : {10.0, 50.0, 90.0}) {
        for (double from : {target - 2, target + 2}) {
            ASSERT_FALSE(m.move(absMove(bit(kX), {from})));
            ASSERT_TRUE(r.runUntilIdle(30));
            ASSERT_FALSE(m.move(absMove(bit(kX), {target})));
            ASSERT_TRUE(r.runUntilIdle(30));
            r.run(0.05);
            const double readbackErrUm = (measuredMm(m, kX) - target) * 1e3;
            const double gaugeErrUm = (m.workPointLogical(kX) - target) * 1e3;
            EXPECT_LE(std::fabs(readbackErrUm), 0.5 + 1e-6) << "one count at most: the grating is the loop's own reference, at " << target;
            // Seed 002's curve at the carriage, plus the grating's +5 µm/m that the loop passes
            // on to the carriage (−0.5 µm at 100 mm from the machine's zero).
            const double zero = m.logicalOffset(kX);  // the machine position the readback reads 0 at
            const double expectUm = seedXErrorUm(m.axis(kX).carriage()) - 5e-3 * (target + zero);
            EXPECT_NEAR(gaugeErrUm, expectUm, 0.6) << "at " << target << " from " << from;
            EXPECT_GT(gaugeErrUm, 0.9 * target - 1) << "tens of µm the grating never shows";
        }
    }
}

TEST_F(StageHomed, TheGratingsScaleErrorMovesTheCarriageNotTheReading)
{
    ASSERT_FALSE(m.move(absMove(bit(kX), {80})));
    ASSERT_TRUE(r.runUntilIdle(30));
    r.run(0.05);
    EXPECT_NEAR(measuredMm(m, kX), 80, 0.0005 + 1e-9);
    // 5 µm per metre of a grating read as right: the carriage is 0.4 µm short at 80 mm.
    EXPECT_NEAR((m.axis(kX).carriage() - m.axis(kX).measured()) * 1e3, -0.4, 0.3);
}

TEST_F(AnalyzerHomed, TheEncoderOnTheCarriageSeesLeadErrorAsTheGaugeDoes)
{
    // Open loop: the steps put the carriage off by the screw's lead error; the encoder
    // reads the carriage, so readback and work point agree to a count.
    double worstReadbackUm = 0;
    for (double target : {20.0, 21.0, 22.0, 23.0, 100.0, 150.0}) {
        ASSERT_FALSE(m.move(absMove(bit(kX), {target})));
        ASSERT_TRUE(r.runUntilIdle(30));
        const double readbackErrUm = (measuredMm(m, kX) - target) * 1e3;
        const double gaugeErrUm = (m.workPointLogical(kX) - target) * 1e3;
        EXPECT_NEAR(readbackErrUm, gaugeErrUm, 2.0) << "one encoder count at " << target;
        worstReadbackUm = std::max(worstReadbackUm, std::fabs(readbackErrUm));
    }
    EXPECT_GT(worstReadbackUm, 10) << "150 µm/m of lead error shows at 150 mm";
}

TEST_F(AnalyzerHomed, LostStepsPutTheWorkPointShortAndTheEncoderSaysSo)
{
    m.axis(kX).setLoadFactor(1.2);
    ASSERT_FALSE(m.move(absMove(bit(kX), {120})));
    ASSERT_TRUE(r.runUntilIdle(30));
    EXPECT_GT(m.axis(kX).lostSteps(), 100);
    EXPECT_LT(m.workPointLogical(kX), 119) << "steps lost, the carriage stopped short";
    EXPECT_NEAR(measuredMm(m, kX), m.workPointLogical(kX), 0.002);
    EXPECT_NEAR(commandedMm(m, kX), 120, 1e-6) << "the step counter still says 120";
    EXPECT_NE(r.find(dev::proto::EventKind::LostSteps, kX), nullptr);
}

// ---- the simulated gauge ---------------------------------------------------------------

std::string ask(dev::sim::SimGauge& g, const std::string& bytes)
{
    g.receive(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
    std::vector<std::uint8_t> out;
    g.drainOutput(out);
    return std::string(out.begin(), out.end());
}

TEST(SimGauge, AnswersAQuestionMarkWithASignedReadingAndItsUnit)
{
    double position = 12.34561;
    dev::sim::GaugeConfig c;
    c.noiseMm = 0;
    dev::sim::SimGauge g([&] { return position; }, c);
    EXPECT_EQ(ask(g, "?\r"), "+012.3456 mm\r\n");
    position = -3.2;
    EXPECT_EQ(ask(g, "?"), "") << "nothing until the CR";
    EXPECT_EQ(ask(g, "\r"), "-003.2000 mm\r\n");
    position = -0.00001;
    EXPECT_EQ(ask(g, "?\r\n"), "+000.0000 mm\r\n") << "a reading that rounds to zero has no minus; the LF ends an empty line";
    EXPECT_EQ(dev::sim::SimGauge::format(1.23456, 0.001), "+001.235 mm");
    EXPECT_EQ(dev::sim::SimGauge::format(123.5, 0.0001), "+123.5000 mm");
}

TEST(SimGauge, IgnoresWhatIsNotARequest)
{
    dev::sim::GaugeConfig c;
    c.noiseMm = 0;
    dev::sim::SimGauge g([] { return 1.0; }, c);
    EXPECT_EQ(ask(g, "hello\r"), "");
    EXPECT_EQ(ask(g, std::string(200, '?') + "\r"), "") << "an overlong line is dropped whole";
    EXPECT_EQ(ask(g, " ? \r"), "+001.0000 mm\r\n");
    EXPECT_EQ(g.requests(), 1u);
}

TEST(SimGauge, NoiseHasTheGivenSpreadAndReadingsTheGivenResolution)
{
    dev::sim::GaugeConfig c;
    c.noiseMm = 0.0005;
    c.resolutionMm = 0.0001;
    dev::sim::SimGauge g([] { return 50.0; }, c);
    double sum = 0, sum2 = 0;
    const int n = 400;
    for (int i = 0; i < n; ++i) {
        const std::string a = ask(g, "?\r");
        ASSERT_EQ(a.size(), std::string("+050.0000 mm\r\n").size()) << a;
        const double v = std::stod(a.substr(0, 9));
        sum += v;
        sum2 += v * v;
    }
    const double mean = sum / n, sd = std::sqrt(sum2 / n - mean * mean);
    EXPECT_NEAR(mean, 50.0, 0.0001);
    EXPECT_NEAR(sd, 0.0005, 0.0001);
}

TEST(SimGauge, FaultsAnswerGarbageOrNothing)
{
    dev::sim::SimGauge g([] { return 1.0; }, {});
    g.setFault(dev::sim::SimGauge::Fault::Garbage);
    EXPECT_EQ(ask(g, "?\r"), "Err 7\r\n");
    g.setFault(dev::sim::SimGauge::Fault::Silent);
    EXPECT_EQ(ask(g, "?\r"), "");
}

} // namespace
