// The screens say why a feature is unavailable, in words, from the instrument's own
// reason (dev::Instrument::whyNot): the Tuning screen names the analyzer, which has no
// gains to tune; the Patterns screen's Run button is disabled with the reason when the
// stage is not connected, and when a backend without a path queue takes over the stage
// (through the session's proxy, as a port speaking another protocol would).
#include "app/gui/instrument_session.h"
#include "app/gui/main_window.h"
#include "app/gui/motion_screens.h"
#include "device/backends/benchpilot/benchpilot_client.h"
#include "device/client/instrument_proxy.h"
#include "device/link/simulated_link.h"
#include "gui_wait.h"
#include "gui_window.h"
#include "widgets/patterns/pattern_screen.h"
#include "widgets/tuning/tuning_screen.h"

#include <QLabel>
#include <QPushButton>

#include <gtest/gtest.h>

using guitest::waitFor;

namespace {

/// The BenchPilot backend on the simulated stage, claiming no path queue: what a device
/// without one (a GRBL board before its streaming lands) looks like to the screens.
class NoPathQueue : public dev::BenchPilotClient {
public:
    dev::Capabilities capabilities() const override
    {
        return BenchPilotClient::capabilities() & ~dev::Capabilities(dev::Capability::PathQueue);
    }
};

QPushButton* runButton(QWidget* screen)
{
    for (QPushButton* b : screen->findChildren<QPushButton*>())
        if (b->text() == QStringLiteral("Run"))
            return b;
    return nullptr;
}

} // namespace

TEST(IfaceCapabilityReasons, TheTuningScreenSaysWhyTheAnalyzerOffersNoTarget)
{
    auto w = guitest::openReadyWindow({1500, 950});
    ASSERT_TRUE(w);
    ASSERT_TRUE(w->showScreen(QStringLiteral("tuning")));
    auto* note = w->tuningScreen()->findChild<QLabel*>(QStringLiteral("tuningUnavailable"));
    ASSERT_NE(note, nullptr);
    EXPECT_TRUE(note->isVisible());
    EXPECT_TRUE(note->text().contains(QStringLiteral("PID gains"))) << note->text().toStdString();
    EXPECT_TRUE(note->text().contains(QStringLiteral("open loop"))) << note->text().toStdString();
    EXPECT_TRUE(note->text().contains(QStringLiteral("BenchPilot protocol 1"))) << note->text().toStdString();
    EXPECT_FALSE(note->text().contains(QStringLiteral("stage")));  // the stage has gains: no note for it
}

TEST(IfaceCapabilityReasons, RunIsDisabledWithTheReasonWhenTheStageIsGone)
{
    auto w = guitest::openReadyWindow({1500, 900});
    ASSERT_TRUE(w);
    ASSERT_TRUE(w->showScreen(QStringLiteral("patterns")));
    ui::PatternScreen* p = w->motionScreens()->patterns();
    p->setInstrument(1);
    QPushButton* run = runButton(p);
    ASSERT_NE(run, nullptr);
    ASSERT_TRUE(waitFor([&] { return run->isEnabled(); }, 2000));
    EXPECT_TRUE(run->toolTip().contains(QStringLiteral("F5")));
    w->stage()->disconnectLink();
    ASSERT_TRUE(waitFor([&] { return !run->isEnabled(); }, 2000));
    EXPECT_EQ(run->toolTip(), QStringLiteral("The stage is not connected."));
}

TEST(IfaceCapabilityReasons, RunIsDisabledWithTheReasonOnABackendWithoutAPathQueue)
{
    auto w = guitest::openReadyWindow({1500, 900});
    ASSERT_TRUE(w);
    ASSERT_TRUE(w->showScreen(QStringLiteral("patterns")));
    ui::PatternScreen* p = w->motionScreens()->patterns();
    p->setInstrument(1);
    QPushButton* run = runButton(p);
    ASSERT_NE(run, nullptr);
    ASSERT_TRUE(waitFor([&] { return run->isEnabled(); }, 2000));

    auto* proxy = dynamic_cast<dev::InstrumentProxy*>(w->stage()->instrument());
    ASSERT_NE(proxy, nullptr) << "the session hands out its proxy";
    w->stage()->disconnectLink();
    auto* link = new dev::SimulatedLink(dev::proto::DeviceKind::Stage, 0, proxy);
    auto* backend = new NoPathQueue;
    proxy->setBackend(backend);
    backend->setTransport(link->hostEnd());
    proxy->connectLink();
    ASSERT_TRUE(waitFor([&] { return proxy->isReady(); }, 5000));
    ASSERT_TRUE(waitFor([&] { return !run->toolTip().contains(QStringLiteral("not connected")); }, 2000));
    EXPECT_FALSE(run->isEnabled());
    EXPECT_TRUE(run->toolTip().contains(QStringLiteral("no path queue"))) << run->toolTip().toStdString();
    EXPECT_TRUE(run->toolTip().startsWith(QStringLiteral("The stage (BenchPilot protocol 1)"))) << run->toolTip().toStdString();
    backend->setTransport(nullptr);
}
