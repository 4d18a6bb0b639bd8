// InstrumentProxy, the one object screens keep while backends come and go: calls reach
// the current backend, its signals come out of the proxy and an old backend's do not, a
// switch tells holders of paths()/tuning() to fetch them again, and without a backend
// every request is refused at once. Capability reasons pass through unchanged.
#include "device/backends/benchpilot/benchpilot_client.h"
#include "device/client/instrument_proxy.h"
#include "device/client/tuning_client.h"
#include "device/link/simulated_link.h"
#include "iface_fake_instrument.h"
#include "wait.h"

#include <QPointer>
#include <QSignalSpy>

#include <gtest/gtest.h>

using itest::FakeInstrument;
using itest::waitFor;

TEST(IfaceProxy, WithoutABackendItIsDisconnectedAndRefusesAtOnce)
{
    dev::InstrumentProxy proxy;
    EXPECT_EQ(proxy.state(), dev::LinkState::Disconnected);
    EXPECT_TRUE(proxy.identity().axes.isEmpty());
    EXPECT_EQ(proxy.paths(), nullptr);
    EXPECT_EQ(proxy.tuning(), nullptr);
    QSignalSpy failed(&proxy, &dev::Instrument::requestFailed);
    std::optional<dev::RequestError> answer;
    bool called = false;
    proxy.move({{0, 1.0}}, false, 0, [&](const auto& e) {
        called = true;
        answer = e;
    });
    ASSERT_TRUE(called);  // no event loop needed: nothing was sent
    ASSERT_TRUE(answer);
    EXPECT_EQ(answer->kind, dev::RequestError::Kind::LinkDown);
    EXPECT_EQ(failed.count(), 1);
    EXPECT_EQ(proxy.whyNot(dev::Capability::Homing).id, dev::kNotConnectedId);
}

TEST(IfaceProxy, CallsAndSignalsGoThroughToTheCurrentBackend)
{
    dev::InstrumentProxy proxy;
    auto* fake = new FakeInstrument;
    proxy.setBackend(fake);
    EXPECT_EQ(fake->parent(), &proxy);
    QSignalSpy identified(&proxy, &dev::Instrument::identified);
    QSignalSpy states(&proxy, &dev::Instrument::stateChanged);
    QSignalSpy events(&proxy, &dev::Instrument::eventReceived);
    proxy.connectLink();
    EXPECT_TRUE(proxy.isReady());
    EXPECT_EQ(identified.count(), 1);
    EXPECT_GE(states.count(), 2);
    EXPECT_EQ(proxy.identity().family, QStringLiteral("Fake 0.1"));
    bool accepted = false;
    proxy.move({{0, 12.5}}, false, 0, [&](const auto& e) { accepted = !e; });
    ASSERT_TRUE(waitFor([&] { return accepted && events.count() >= 1; }, 2000));
    ASSERT_EQ(fake->moves.size(), 1u);
    EXPECT_DOUBLE_EQ(proxy.status().axes[0].commanded, 12.5);
    EXPECT_TRUE(proxy.can(dev::Capability::TriggerOutput));
}

TEST(IfaceProxy, ASwitchOfBackendIsAnnouncedAndTheOldOneFallsSilent)
{
    dev::InstrumentProxy proxy;
    auto* first = new FakeInstrument;
    proxy.setBackend(first);
    proxy.connectLink();
    QSignalSpy replaced(&proxy, &dev::Instrument::partsReplaced);
    QSignalSpy identified(&proxy, &dev::Instrument::identified);
    QSignalSpy statuses(&proxy, &dev::Instrument::statusChanged);

    auto* second = new FakeInstrument(50, 1000);
    second->identityToReport().model = QStringLiteral("second stage");
    second->connectLink();  // already identified when it is handed over
    proxy.setBackend(second);
    EXPECT_EQ(replaced.count(), 1);
    EXPECT_EQ(identified.count(), 1);  // the new identity, announced as if it had just connected
    EXPECT_EQ(proxy.identity().model, QStringLiteral("second stage"));
    EXPECT_DOUBLE_EQ(proxy.identity().axes[0].maxAccel, 50);

    // The old backend is deleted later; until then nothing it says reaches the proxy.
    const QPointer<FakeInstrument> old(first);
    const int before = statuses.count();
    emit first->statusChanged(first->status());
    EXPECT_EQ(statuses.count(), before);
    EXPECT_TRUE(waitFor([&] { return old.isNull(); }, 2000));
}

TEST(IfaceProxy, ReasonsAreTheBackendsOwn)
{
    dev::InstrumentProxy proxy;
    proxy.setBackend(new FakeInstrument(200, 4000, dev::Capability::Homing));
    proxy.connectLink();
    const motion::msg::Message why = proxy.whyNot(dev::Capability::PidGains);
    EXPECT_EQ(why.id, "capability.no_pid_gains");
    EXPECT_EQ(why.text("instrument"), "instrument.stage");
    EXPECT_EQ(why.text("family"), "Fake 0.1");
    EXPECT_EQ(why.text("because"), "capability.because.fake");
    EXPECT_TRUE(proxy.whyNot(dev::Capability::Homing).empty());
}

// An instrument that claims the arched move but does not take it (a decorator that
// forgot to pass it on did this to the GUI's plate runs) refused it with no reason at all.
TEST(IfaceProxy, AnArchedMoveNotTakenIsRefusedWithAReasonEvenWhenTheCapabilityIsClaimed)
{
    dev::InstrumentProxy proxy;
    proxy.setBackend(new FakeInstrument(200, 4000, dev::Capability::Homing | dev::Capability::ArchedMove));
    proxy.connectLink();
    ASSERT_TRUE(proxy.can(dev::Capability::ArchedMove));
    std::optional<dev::RequestError> answer;
    proxy.archMove({10, 10, 5, 20, 1, 1, 50, 30}, [&](const auto& e) { answer = e; });
    ASSERT_TRUE(answer);
    EXPECT_EQ(answer->kind, dev::RequestError::Kind::Invalid);
    EXPECT_FALSE(answer->message.empty());
    EXPECT_EQ(answer->message.text("family"), "Fake 0.1");
}

TEST(IfaceProxy, TheBenchPilotBackendBehindAProxyRunsTheSimulator)
{
    dev::SimulatedLink link(dev::proto::DeviceKind::Stage, 0);
    dev::InstrumentProxy proxy;
    auto* client = new dev::BenchPilotClient;
    proxy.setBackend(client);
    client->setTransport(link.hostEnd());
    proxy.connectLink();
    ASSERT_TRUE(waitFor([&] { return proxy.isReady(); }, 5000));
    EXPECT_EQ(proxy.identity().family, QStringLiteral("BenchPilot protocol 1"));
    ASSERT_NE(proxy.paths(), nullptr);
    ASSERT_NE(proxy.tuning(), nullptr);
    EXPECT_TRUE(proxy.tuning()->hasGains());
    EXPECT_TRUE(proxy.can(dev::Capability::PathQueue));
    EXPECT_TRUE(proxy.can(dev::Capability::StopsOnHostLoss));
    // The protocol has no trigger output; the reason says so.
    const motion::msg::Message why = proxy.whyNot(dev::Capability::TriggerOutput);
    EXPECT_EQ(why.id, "capability.no_trigger_output");
    EXPECT_EQ(why.text("because"), "capability.because.not_in_protocol");
    bool refused = false;
    proxy.pulseTrigger(0.01, [&](const auto& e) { refused = e.has_value(); });
    EXPECT_TRUE(refused);
    client->setTransport(nullptr);
}
