// The main window on a GRBL controller (benchpilot-sim --protocol grbl on a pty): the stage's bar
// detects the protocol and connects the GRBL backend, the Jog screen offers Unlock while the
// controller does not trust its position and Set home here where it cannot home, and the E-stop
// says that a moving GRBL controller loses its position. Set BP_SHOT_DIR to keep a picture.
#include "../integration/pty_simulator.h"
#include "gui_window.h"
#include "widgets/jog_screen.h"
#include "widgets/message_banner.h"

#include <QLabel>
#include <QPushButton>

#include <gtest/gtest.h>

namespace {

QPushButton* button(QWidget* w, const QString& text)
{
    for (auto* b : w->findChildren<QPushButton*>())
        if (b->text() == text)
            return b;
    return nullptr;
}

TEST(GrblWindow, TheStageOnAGrblPortDetectsItUnlocksAndSaysWhatAnEStopCosts)
{
    itest::PtySimulator sim;
    ASSERT_TRUE(sim.start(QStringLiteral("stage"), 4, {QStringLiteral("--protocol"), QStringLiteral("grbl")})) << qPrintable(sim.error());
    app::MainWindowOptions o = guitest::testWindowOptions();
    ui::ConnectionChoice port;
    port.simulator = false;
    port.port = sim.link();
    o.connection[1] = port;
    o.showInstrument = 1;
    app::MainWindow w(o);
    w.resize(1366, 768);
    w.show();
    dev::Instrument* stage = w.stage()->instrument();
    ASSERT_TRUE(guitest::waitFor([&] { return stage->isReady(); }, 15000));
    EXPECT_EQ(stage->identity().family, QStringLiteral("Grbl 1.1h"));
    ui::JogScreen* jog = w.jogScreen(1);
    // Power-up with homing enabled: in alarm, so Unlock is offered; homing is possible.
    QPushButton* unlock = button(jog, QStringLiteral("Unlock…"));
    ASSERT_NE(unlock, nullptr);
    ASSERT_TRUE(guitest::waitFor([&] { return unlock->isVisible(); }, 3000));
    EXPECT_FALSE(button(jog, QStringLiteral("Set home here…"))->isVisible());
    // What a lost link costs, said where jogs are started.
    bool said = false;
    for (auto* l : jog->findChildren<QLabel*>())
        said = said || (l->isVisible() && l->text().contains(QStringLiteral("stop budget")));
    EXPECT_TRUE(said);
    if (!qEnvironmentVariableIsEmpty("BP_SHOT_DIR"))
        w.grab().save(qEnvironmentVariable("BP_SHOT_DIR") + QStringLiteral("/grbl-jog-stage-alarm.png"));
    unlock->click();  // no dialogs in tests: the operator's yes
    ASSERT_TRUE(guitest::waitFor([&] { return !stage->status().positionLost && stage->status().axes[0].homed; }, 5000));
    EXPECT_FALSE(unlock->isVisible());
    // An E-stop says what it costs on GRBL.
    w.emergencyStop();
    EXPECT_TRUE(w.banner()->text().contains(QStringLiteral("lost its position"))) << w.banner()->text().toStdString();
    ASSERT_TRUE(guitest::waitFor([&] { return stage->status().estop; }, 3000));
    w.resetEStop();
    if (!qEnvironmentVariableIsEmpty("BP_SHOT_DIR"))
        w.grab().save(qEnvironmentVariable("BP_SHOT_DIR") + QStringLiteral("/grbl-jog-stage.png"));
    w.stage()->disconnectLink();
}

} // namespace
