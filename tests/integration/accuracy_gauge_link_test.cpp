// A gauge on a serial line (dev::GaugeLink over a loopback to the simulated gauge):
// one reading per request, a gauge that answers garbage or nothing is reported with
// its port and what it sent, a late answer is never taken for the next reading.
#include "device/link/gauge_link.h"
#include "device/link/loopback.h"
#include "device/link/simulated_link.h"
#include "device/sim/sim_gauge.h"
#include "wait.h"

#include <gtest/gtest.h>

namespace {

struct GaugeBench {
    GaugeBench()
    {
        dev::sim::GaugeConfig c;
        c.noiseMm = 0;
        auto g = std::make_unique<dev::sim::SimGauge>([this] { return position; }, c);
        gauge = g.get();
        host = std::make_unique<dev::SimulatorHost>(std::move(g), pair.end(dev::LoopbackPair::B));
        host->setManualClock(true);
        host->start();
        link.setTimeoutMs(150);
    }
    struct Result {
        bool done = false;
        std::optional<double> value;
        motion::msg::Message problem;
    };
    Result read()
    {
        Result r;
        link.read([&r](std::optional<double> v, const motion::msg::Message& p) {
            r.done = true;
            r.value = v;
            r.problem = p;
        });
        itest::waitFor([&] { return r.done; }, 3000);
        return r;
    }
    double position = 12.3456;
    dev::LoopbackPair pair{0};
    dev::sim::SimGauge* gauge = nullptr;
    std::unique_ptr<dev::SimulatorHost> host;
    dev::GaugeLink link{pair.end(dev::LoopbackPair::A), QStringLiteral("/dev/ttyGAUGE")};
};

bool open(dev::GaugeLink& link)
{
    bool done = false;
    motion::msg::Message problem;
    link.open([&](const motion::msg::Message& p) {
        problem = p;
        done = true;
    });
    itest::waitFor([&] { return done; }, 3000);
    return done && problem.empty();
}

TEST(AccuracyGaugeLink, ReadsOneValueARequest)
{
    GaugeBench b;
    ASSERT_TRUE(open(b.link));
    auto r = b.read();
    ASSERT_TRUE(r.done);
    ASSERT_TRUE(r.value) << motion::msg::debugString(r.problem);
    EXPECT_DOUBLE_EQ(*r.value, 12.3456);
    b.position = -0.25;
    r = b.read();
    EXPECT_DOUBLE_EQ(r.value.value_or(0), -0.25);
    EXPECT_EQ(b.gauge->requests(), 2u);
}

TEST(AccuracyGaugeLink, GarbageIsReportedWithThePortAndWhatWasSent)
{
    GaugeBench b;
    ASSERT_TRUE(open(b.link));
    b.gauge->setFault(dev::sim::SimGauge::Fault::Garbage);
    const auto r = b.read();
    ASSERT_TRUE(r.done);
    EXPECT_FALSE(r.value);
    EXPECT_EQ(r.problem.id, "gauge.not_a_reading");
    EXPECT_EQ(r.problem.text("port"), "/dev/ttyGAUGE");
    EXPECT_EQ(r.problem.text("text"), "Err 7");
}

TEST(AccuracyGaugeLink, ASilentGaugeIsAskedTwiceThenReported)
{
    GaugeBench b;
    ASSERT_TRUE(open(b.link));
    b.gauge->setFault(dev::sim::SimGauge::Fault::Silent);
    const auto r = b.read();
    ASSERT_TRUE(r.done);
    EXPECT_EQ(r.problem.id, "gauge.no_answer");
    EXPECT_NEAR(r.problem.number("timeout"), 0.15, 1e-9);
    EXPECT_EQ(b.gauge->requests(), 2u) << "one retry";
}

TEST(AccuracyGaugeLink, ALineWithoutItsEndAndUnaskedLinesAreNotReadings)
{
    GaugeBench b;
    ASSERT_TRUE(open(b.link));
    // A reading the gauge sent by itself before anything was asked is dropped...
    b.pair.inject(dev::LoopbackPair::B, QByteArray("+099.0000 mm\r\n"));
    itest::waitFor([] { return false; }, 50);
    auto r = b.read();
    EXPECT_DOUBLE_EQ(r.value.value_or(0), 12.3456) << "the answer to the request, not the stale line";
    // ...and bytes that never end their line are what the gauge said when time is up.
    b.gauge->setFault(dev::sim::SimGauge::Fault::Silent);
    bool done = false;
    motion::msg::Message problem;
    b.link.read([&](std::optional<double>, const motion::msg::Message& p) {
        problem = p;
        done = true;
    });
    b.pair.inject(dev::LoopbackPair::B, QByteArray("\x02+01"));
    itest::waitFor([&] { return done; }, 3000);
    EXPECT_EQ(problem.id, "gauge.not_a_reading");
    EXPECT_EQ(problem.text("text"), "\\x02+01");
}

} // namespace
