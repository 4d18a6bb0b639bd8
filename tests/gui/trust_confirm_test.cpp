// One rule for what asks first (widgets/common/confirmation.h). Plate Abort, Disconnect during
// a run and quitting with unsaved edits or a running job ask; "no" leaves
// everything as it was.
#include "app/gui/instrument_session.h"
#include "app/gui/main_window.h"
#include "device/link/simulated_link.h"
#include "gui_wait.h"
#include "gui_window.h"
#include "widgets/connection_bar.h"
#include "widgets/jog_screen.h"
#include "widgets/message_banner.h"
#include "widgets/wording/wording.h"
#include "widgets/plates/plate_map.h"
#include "widgets/plates/plates_screen.h"
#include "widgets/plates/recipe_editor.h"
#include "widgets/plates/run_panel.h"

#include <QPushButton>
#include <QTemporaryDir>
#include <QTest>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using guitest::pump;
using guitest::waitFor;

using guitest::button;

namespace {

class TrustConfirmTest : public ::testing::Test {
protected:
    void SetUp() override
    {
        auto o = guitest::testWindowOptions();
        o.answer = [this](const QString& q) {
            questions << q;
            return answer;
        };
        w = std::make_unique<app::MainWindow>(o);
        w->resize(1500, 950);
        w->show();
        ASSERT_TRUE(waitFor([&] { return analyzer()->isReady() && w->stage()->instrument()->isReady(); }, 5000));
        ASSERT_TRUE(w->showScreen(QStringLiteral("plates")));
        screen = w->platesScreen();
        screen->setRunLogDirectory(dir.path());
        screen->setConfirm([this](const QString& q) {
            questions << q;
            return answer;
        });
        ui::ConnectionChoice c;
        c.baud = 0;
        w->analyzer()->connectTo(c);
        ASSERT_TRUE(waitFor([&] { return analyzer()->isReady(); }, 5000));
        qobject_cast<dev::SimulatedLink*>(w->analyzer()->link())->host().setTimeScale(5);
        analyzer()->home(0);
        ASSERT_TRUE(waitFor(
            [&] {
                const auto& a = analyzer()->status().axes;
                return a.size() == 4 && std::all_of(a.begin(), a.end(), [](const auto& x) { return x.homed && !x.moving; });
            },
            60000));
        screen->plateMap()->setSelection({{0, 0}, {0, 1}, {0, 2}, {1, 0}, {1, 1}, {1, 2}, {2, 0}, {2, 1}});
        QTest::mouseClick(button(screen, QObject::tr("Aspirate from these")), Qt::LeftButton);
    }
    void run()
    {
        answer = true;
        QTest::mouseClick(button(screen->runPanel(), QObject::tr("Run")), Qt::LeftButton);
        ASSERT_TRUE(waitFor([&] { return screen->runner()->state() == dev::jobs::RunState::Running; }, 5000));
        questions.clear();
        answer = false;
    }
    dev::Instrument* analyzer() { return w->analyzer()->instrument(); }
    QTemporaryDir dir;
    std::unique_ptr<app::MainWindow> w;
    ui::PlatesScreen* screen = nullptr;
    QStringList questions;
    bool answer = false;
};

} // namespace

TEST_F(TrustConfirmTest, PlateAbortAsksFirst)
{
    run();
    QTest::mouseClick(button(screen->runPanel(), QObject::tr("Abort")), Qt::LeftButton);
    ASSERT_EQ(questions.size(), 1);
    EXPECT_TRUE(questions[0].startsWith(QStringLiteral("Abort"))) << questions[0].toStdString();
    pump(100);
    EXPECT_EQ(screen->runner()->state(), dev::jobs::RunState::Running) << "aborted although the operator said no";
    answer = true;
    QTest::mouseClick(button(screen->runPanel(), QObject::tr("Abort")), Qt::LeftButton);
    ASSERT_TRUE(waitFor([&] { return screen->runner()->state() == dev::jobs::RunState::Stopped; }, 10000));
}

TEST_F(TrustConfirmTest, DisconnectDuringARunAsksFirst)
{
    run();
    auto bars = w->findChildren<ui::ConnectionBar*>();
    ASSERT_GE(bars.size(), 1);
    emit bars[0]->disconnectRequested();
    ASSERT_EQ(questions.size(), 1);
    EXPECT_TRUE(questions[0].contains(QStringLiteral("plate run"))) << questions[0].toStdString();
    pump(100);
    EXPECT_TRUE(analyzer()->isReady()) << "disconnected although the operator said no";
    answer = true;
    emit bars[0]->disconnectRequested();
    ASSERT_TRUE(waitFor([&] { return !analyzer()->isReady(); }, 3000));
}

TEST_F(TrustConfirmTest, QuittingWithUnsavedEditsOrARunningJobAsksFirst)
{
    ASSERT_TRUE(screen->recipeEditor()->isModified());
    EXPECT_FALSE(w->close());
    ASSERT_EQ(questions.size(), 1);
    EXPECT_TRUE(questions[0].contains(QStringLiteral("not saved"))) << questions[0].toStdString();
    EXPECT_TRUE(w->isVisible());
    run();
    EXPECT_FALSE(w->close());
    ASSERT_EQ(questions.size(), 1);
    EXPECT_TRUE(questions[0].contains(QStringLiteral("plate run"))) << questions[0].toStdString();
    answer = true;
    EXPECT_TRUE(w->close());
}

// Ctrl+Q (File > Quit) quits as closing the window does: it asks first when work would be lost.
TEST_F(TrustConfirmTest, CtrlQQuitsAndAsksFirstWhenWorkWouldBeLost)
{
    ASSERT_TRUE(screen->recipeEditor()->isModified());
    w->activateWindow();
    QTest::keyClick(w.get(), Qt::Key_Q, Qt::ControlModifier);
    pump(20);
    ASSERT_EQ(questions.size(), 1) << "Ctrl+Q did not reach Quit";
    EXPECT_TRUE(questions[0].contains(QStringLiteral("not saved"))) << questions[0].toStdString();
    EXPECT_TRUE(w->isVisible());
    answer = true;
    QTest::keyClick(w.get(), Qt::Key_Q, Qt::ControlModifier);
    pump(20);
    EXPECT_FALSE(w->isVisible());
}

TEST_F(TrustConfirmTest, HomingAPlungerThatHoldsLiquidSaysHowMuchWouldBePushedOut)
{
    // The failure this catches: the operator was led to home the plunger with 220 µL in the syringe.
    dev::Instrument* a = analyzer();
    // Statuses counted from the home request on, so "homed and still" is news, not the last reading.
    int fresh = 0;
    QObject::connect(a, &dev::Instrument::statusChanged, w.get(), [&fresh] { ++fresh; });
    a->home(0);
    ASSERT_TRUE(waitFor([&] {
        if (fresh < 3 || a->status().anyMoving())
            return false;
        for (const auto& axis : a->status().axes)
            if (!axis.homed)
                return false;
        return true;
    }, 20000));
    int p = -1;
    for (int i = 0; i < a->identity().axes.size(); ++i)
        if (a->identity().axes[i].letter == QLatin1Char('P'))
            p = i;
    ASSERT_GE(p, 0);
    QString refused;
    a->move({{p, 220}}, false, 0, [&](const std::optional<dev::RequestError>& e) {
        if (e)
            refused = ui::words::text(e->message);
    });
    ASSERT_TRUE(waitFor([&] { return std::abs(a->status().axes[p].commanded - 220) < 0.01 && !a->status().anyMoving(); }, 20000))
        << "P at " << a->status().axes[p].commanded << " homed " << a->status().axes[p].homed << " " << refused.toStdString();
    ASSERT_TRUE(w->showScreen(QStringLiteral("jog")));
    w->showInstrument(0);
    w->jogScreen(0)->setConfirm([this](const QString& q) {
        questions << q;
        return false;
    });
    QTest::mouseClick(button(w->jogScreen(0), QObject::tr("Home all")), Qt::LeftButton);
    ASSERT_EQ(questions.size(), 1);
    EXPECT_TRUE(questions[0].contains(QStringLiteral("220.0 µL"))) << questions[0].toStdString();
    pump(200);
    EXPECT_NEAR(a->status().axes[p].commanded, 220, 0.01) << "homed although the operator said no";
}

TEST_F(TrustConfirmTest, RequestsCutShortByTheOperatorsDisconnectRaiseNoAlarm)
{
    // The screenshot of a plate run showed "Analyzer: 0x12 abandoned: disconnected" in red
    // after a deliberate reconnect: the request was cut short because the operator asked.
    ASSERT_FALSE(w->banner()->hasMessage()) << w->banner()->text().toStdString();
    analyzer()->home(0);  // queued, not yet sent: the disconnect below abandons it
    w->analyzer()->disconnectLink();
    pump(100);
    EXPECT_FALSE(w->banner()->hasMessage()) << w->banner()->text().toStdString();
}
