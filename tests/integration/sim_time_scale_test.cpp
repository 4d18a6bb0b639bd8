// A simulator whose clock is sped up over a baud-paced loopback: its wire runs at
// the same scale, so the telemetry the firmware budgets per second of its link
// still fits and replies do not queue behind samples (SimulatorHost::setTimeScale).
#include "device/telemetry/telemetry_hub.h"
#include "sim_session.h"

namespace {

TEST(SimTimeScale, ASpedUpSimulatorOnAPacedLinkAnswersWhileItStreamsEveryHistoryChannel)
{
    itest::SimSession s(dev::proto::DeviceKind::Analyzer, itest::kLinkBaud);
    dev::tele::TelemetryHub hub;
    hub.enableHistory();  // what the application does: every axis's history channels from connection on
    hub.addInstrument(0, QStringLiteral("Analyzer"), &s.client);
    ASSERT_TRUE(s.connect());
    const int axes = s.client.identity().axes.size();
    ASSERT_TRUE(itest::waitFor([&] { return s.client.subscribedChannels().size() == axes * 3; }, 5000));
    s.link.host().setTimeScale(10);
    EXPECT_EQ(s.link.pair().timeScale(), 10.0);
    // Ten round trips, each while 10 device seconds of samples a wall second cross the wire.
    for (int k = 0; k < 10; ++k) {
        const auto err = s.call([&](auto cb) { s.client.stop(0, cb); }, 3000);
        ASSERT_FALSE(err) << k << ": " << motion::msg::debugString(err->message);
    }
    EXPECT_EQ(s.client.stats().retransmits, 0u) << "a reply queued behind samples is retried";
    EXPECT_EQ(hub.lostSamples(0), 0u);
    s.link.host().setTimeScale(1);
    EXPECT_EQ(s.link.pair().timeScale(), 1.0);
}

} // namespace
