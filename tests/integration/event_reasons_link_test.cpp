// Event reasons over the loopback: the BenchPilot client asks for them in HELLO and
// hands each event on worded, so the log, a banner or a job's stop message says it in
// the operator's language; against firmware that sends no reasons (protocol 1.0 here)
// the device's own text is what is shown, as before.
#include "device/backends/benchpilot/benchpilot_client.h"
#include "device/link/simulated_link.h"
#include "device/protocol/event_reasons.h"
#include "device/sim/machine_config.h"
#include "widgets/wording/translators.h"
#include "widgets/wording/wording.h"
#include "wait.h"

#include <gtest/gtest.h>

#include <vector>

using itest::waitFor;

namespace {

struct Rig {
    explicit Rig(bool reasonsKnown) : link(dev::sim::stageConfig(), 0)
    {
        link.host().firmware().setHelloExtensions(reasonsKnown);  // off: a protocol 1.0 device
        QObject::connect(&client, &dev::BenchPilotClient::eventReceived, &client,
                         [this](const dev::DeviceEvent& e) { events.push_back(e); });
        client.setTransport(link.hostEnd());
    }
    ~Rig() { client.setTransport(nullptr); }
    /// Connects, then E-stop and reset: two events every device raises.
    void estopAndReset()
    {
        client.connectLink();
        ASSERT_TRUE(waitFor([&] { return client.isReady(); }, 5000));
        client.estop();
        ASSERT_TRUE(waitFor([&] { return events.size() >= 1; }, 3000));
        client.reset();
        ASSERT_TRUE(waitFor([&] { return events.size() >= 2; }, 3000));
    }
    dev::SimulatedLink link;
    dev::BenchPilotClient client;
    std::vector<dev::DeviceEvent> events;
};

} // namespace

TEST(EventReasonsLink, EventsArriveWordedInTheOperatorsLanguage)
{
    Rig r(true);
    r.estopAndReset();
    ASSERT_EQ(r.events[0].kind, dev::proto::EventKind::EStop);
    EXPECT_TRUE(r.events[0].worded);
    EXPECT_EQ(r.events[0].detail.id, "device.why.all_halted");
    EXPECT_EQ(r.events[1].detail.id, "device.why.cleared");
    ui::words::Translators translators;
    ASSERT_TRUE(translators.setLanguage(QStringLiteral("zh_CN")));
    const QString zh = ui::words::text(r.events[0].detail);
    EXPECT_FALSE(zh.contains(QLatin1String("halted"))) << zh.toStdString();
    EXPECT_FALSE(zh.isEmpty());
    translators.setLanguage(QStringLiteral("en"));
    EXPECT_EQ(r.events[0].text, QStringLiteral("emergency stop: all motion halted")) << "the device's text stays beside it";
}

TEST(EventReasonsLink, ADeviceThatSendsNoReasonsIsShownInItsOwnWords)
{
    Rig r(false);
    r.estopAndReset();
    ASSERT_EQ(r.events[0].kind, dev::proto::EventKind::EStop);
    EXPECT_FALSE(r.events[0].worded);
    EXPECT_TRUE(r.events[0].detail.empty());
    EXPECT_EQ(r.events[0].text, QStringLiteral("emergency stop: all motion halted"));
    const motion::msg::Arg shown = dev::eventDetail(r.events[0]);
    EXPECT_EQ(std::get<motion::msg::Verbatim>(shown.value).text, "emergency stop: all motion halted");
}
