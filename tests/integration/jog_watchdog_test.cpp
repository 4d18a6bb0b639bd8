// A jog lasts only while the host refreshes it. When the refreshes stop reaching
// the device (frozen GUI, pulled cable) the device must bring the axis to rest
// within 250 ms of the last refresh it received. Measured on the simulator's
// virtual clock, so a slow test machine cannot make it pass or fail.
#include "sim_session.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>

using namespace itest;
using K = dev::proto::EventKind;
using dev::LinkFaults;
using dev::LoopbackPair;

namespace {

constexpr double kWatchdogBudgetUs = 250'000;

struct Sample {
    std::uint64_t timeUs;
    double commanded, measured;  ///< axis units
};

struct WatchdogCase {
    dev::proto::DeviceKind kind;
    const char* name;
    double jogSpeed;  ///< axis units per second
};

class JogWatchdog : public ::testing::TestWithParam<WatchdogCase> {};

} // namespace

TEST_P(JogWatchdog, JogWhoseRefreshesStopIsAtRestWithin250msOfTheLastRefresh)
{
    const WatchdogCase c = GetParam();
    SimSession s(c.kind);
    ASSERT_TRUE(s.connect()) << s.linkErrors.join(QStringLiteral(" | ")).toStdString();
    const int x = s.axis('X');

    // Fine-grained position telemetry of X, with the device's own timestamps.
    const QVector<dev::proto::ChannelRef> channels{{static_cast<std::uint8_t>(x), dev::proto::ChannelKind::Commanded},
                                              {static_cast<std::uint8_t>(x), dev::proto::ChannelKind::Measured}};
    bool subscribed = false;
    s.client.subscribe(channels, 1000, [&](const auto& e, const auto&) {
        EXPECT_FALSE(e) << motion::msg::debugString(e->message);
        subscribed = true;
    });
    ASSERT_TRUE(waitFor([&] { return subscribed; }, 3000));
    std::vector<Sample> samples;
    QObject::connect(&s.client, &dev::BenchPilotClient::telemetryReceived, &s.client, [&](const dev::proto::TelemetryBatch& b) {
        const std::size_t n = b.channels.size();
        if (n != 2)
            return;
        for (std::size_t k = 0; k < b.sampleCount; ++k)
            samples.push_back({b.firstSampleTimeUs + k * b.periodUs, s.client.toAxisUnits(b.channels[0], b.values[k * n]),
                               s.client.toAxisUnits(b.channels[1], b.values[k * n + 1])});
    });

    // The device clock at the last jog refresh the device received. This slot runs
    // after the simulator has taken the bytes in, so the clock is the receive time.
    std::uint64_t lastRefreshUs = 0;
    int refreshes = 0;
    dev::proto::FrameDecoder deviceSide;
    QObject::connect(s.link.pair().end(LoopbackPair::B), &dev::Transport::bytesReceived, &s.client,
                     [&](const QByteArray& bytes) {
                         std::vector<dev::proto::Frame> frames;
                         deviceSide.feed(reinterpret_cast<const std::uint8_t*>(bytes.constData()),
                                         static_cast<std::size_t>(bytes.size()), frames);
                         for (const auto& f : frames) {
                             if (f.type != static_cast<std::uint8_t>(dev::proto::MsgType::JogVelocity))
                                 continue;
                             const auto r = dev::proto::decodeJogVelocityRequest(f.payload);
                             if (r && !r->velocities.empty() && r->velocities[0] != 0) {
                                 lastRefreshUs = s.link.machine().timeUs();
                                 ++refreshes;
                             }
                         }
                     });

    s.client.startJog(x, c.jogSpeed);
    ASSERT_TRUE(waitFor([&] { return s.readout('X').jogging; }, 3000));
    spin(400);
    ASSERT_TRUE(s.readout('X').jogging) << "the jog must be running before its refreshes are cut";
    ASSERT_GE(refreshes, 4);

    // Cut host → device: the client keeps refreshing, nothing arrives.
    const std::size_t mark = s.events.size();
    LinkFaults cut;
    cut.dropChunkProbability = 1.0;
    cut.seed = 3;
    s.link.pair().setFaults(LoopbackPair::A, cut);

    ASSERT_TRUE(s.waitEvent(K::JogExpired, x, mark, 5000)) << "the device never noticed the refreshes stopped";
    const auto restKinds = {K::MotionDone, K::Stopped};
    int restIndex = -1;
    ASSERT_TRUE(waitFor(
        [&] {
            for (K k : restKinds) {
                const int i = s.findEvent(k, x, mark);
                if (i >= 0 && (restIndex < 0 || i < restIndex))
                    restIndex = i;
            }
            return restIndex >= 0;
        },
        5000))
        << "no event said the axis came to rest";
    // Telemetry for a while beyond the budget, so "still" is seen, not assumed.
    ASSERT_TRUE(waitFor([&] { return !samples.empty() && samples.back().timeUs > lastRefreshUs + 450'000; }, 5000));

    const auto& expired = s.events[std::size_t(s.findEvent(K::JogExpired, x, mark))];
    const auto& rest = s.events[std::size_t(restIndex)];
    const double tripMs = (double(expired.deviceTimeUs) - double(lastRefreshUs)) / 1000.0;
    const double restEventMs = (double(rest.deviceTimeUs) - double(lastRefreshUs)) / 1000.0;

    // From telemetry: when the commanded and the measured position stopped changing.
    // The measured one is at rest once it stays within 2 µm of where it ends: the
    // stage's in-position window, one count of the analyzer's encoder.
    constexpr double kAtRestMm = 0.002;
    const Sample final = samples.back();
    // Time of the first sample after the last one that differs from the final; 0 if none differs.
    auto stillFrom = [&](const std::function<bool(const Sample&)>& differs) -> std::uint64_t {
        for (std::size_t i = samples.size(); i-- > 0;)
            if (differs(samples[i]))
                return samples[i + 1].timeUs;  // the last sample equals the final one, so i + 1 exists
        return 0;
    };
    const std::uint64_t commandedStillUs = stillFrom([&](const Sample& v) { return std::abs(v.commanded - final.commanded) > 1e-6; });
    const std::uint64_t measuredStillUs = stillFrom([&](const Sample& v) { return std::abs(v.measured - final.measured) > kAtRestMm + 1e-9; });
    const double commandedStillMs = (double(commandedStillUs) - double(lastRefreshUs)) / 1000.0;
    const double measuredStillMs = (double(measuredStillUs) - double(lastRefreshUs)) / 1000.0;
    std::printf("[ info ] %s jog at %.1f mm/s, refreshes cut: watchdog tripped %.1f ms after the last refresh; "
                "commanded still at %.1f ms, %s still at %.1f ms, rest event at %.1f ms (device clock)\n",
                c.name, c.jogSpeed, tripMs, commandedStillMs,
                c.kind == dev::proto::DeviceKind::Stage ? "grating" : "encoder", measuredStillMs, restEventMs);
    std::fflush(stdout);

    ASSERT_GT(commandedStillUs, 0u) << "the axis never moved in the recorded window";
    ASSERT_GT(measuredStillUs, 0u);
    EXPECT_GE(tripMs, 150.0) << "tripped before the watchdog period";
    EXPECT_LE(commandedStillMs, kWatchdogBudgetUs / 1000.0);
    EXPECT_LE(measuredStillMs, kWatchdogBudgetUs / 1000.0);
    EXPECT_LE(restEventMs, kWatchdogBudgetUs / 1000.0) << "the device reported rest late";

    // And it stays there: the machine itself, not a stale reading.
    const double parked = s.link.machine().commandedLogical(x);
    spin(300);
    EXPECT_DOUBLE_EQ(s.link.machine().commandedLogical(x), parked);
}

INSTANTIATE_TEST_SUITE_P(BothInstruments, JogWatchdog,
                         ::testing::Values(WatchdogCase{dev::proto::DeviceKind::Analyzer, "analyzer", 50.0},
                                           WatchdogCase{dev::proto::DeviceKind::Stage, "stage", 20.0}),
                         [](const auto& p) { return std::string(p.param.name); });
