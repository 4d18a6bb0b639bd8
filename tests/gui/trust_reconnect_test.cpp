// Disconnect → Connect on the in-process simulator finds the
// same instrument (a powered machine whose cable was out), and a plate run
// interrupted by Disconnect resumes after Connect with every well done exactly
// once and the plunger's contents right.
#include "app/gui/instrument_session.h"
#include "app/gui/main_window.h"
#include "device/link/simulated_link.h"
#include "gui_wait.h"
#include "gui_window.h"
#include "widgets/common/number_field.h"
#include "widgets/plates/plate_map.h"
#include "widgets/plates/plates_screen.h"
#include "widgets/plates/recipe_editor.h"
#include "widgets/plates/run_panel.h"

#include <QPushButton>
#include <QTemporaryDir>
#include <QComboBox>
#include <QFile>
#include <QTest>
#include <QToolButton>

#include <gtest/gtest.h>

#include <algorithm>

using guitest::pump;
using guitest::waitFor;

using guitest::button;

namespace {

class TrustReconnectTest : public ::testing::Test {
protected:
    void SetUp() override
    {
        w = guitest::openReadyWindow({1500, 950});
        ASSERT_TRUE(w) << "the simulated instruments did not become ready";
        ASSERT_TRUE(w->showScreen(QStringLiteral("plates")));
        screen = w->platesScreen();
        screen->setRunLogDirectory(dir.path());
        choice.baud = 0;  // unpaced, with a fast clock: runs take seconds
        w->analyzer()->connectTo(choice);
        ASSERT_TRUE(waitFor([&] { return analyzer()->isReady(); }, 5000));
        auto* link = qobject_cast<dev::SimulatedLink*>(w->analyzer()->link());
        ASSERT_NE(link, nullptr);
        link->host().setTimeScale(20);
        analyzer()->home(0);
        ASSERT_TRUE(waitFor([&] { return allHomedAndStill(); }, 30000));
    }
    dev::Instrument* analyzer() { return w->analyzer()->instrument(); }
    bool allHomedAndStill()
    {
        const auto& a = analyzer()->status().axes;
        return a.size() == 4 && std::all_of(a.begin(), a.end(), [](const auto& x) { return x.homed && !x.moving; });
    }
    void reconnect()
    {
        w->analyzer()->disconnectLink();
        pump(300);
        ASSERT_FALSE(analyzer()->isReady());
        w->analyzer()->connectTo(choice);
        ASSERT_TRUE(waitFor([&] { return analyzer()->isReady() && analyzer()->status().axes.size() == 4; }, 5000));
        pump(200);
    }
    QTemporaryDir dir;
    ui::ConnectionChoice choice;
    std::unique_ptr<app::MainWindow> w;
    ui::PlatesScreen* screen = nullptr;
};

} // namespace

TEST_F(TrustReconnectTest, DisconnectThenConnectFindsTheSameSimulatedInstrument)
{
    analyzer()->move({{0, 30}, {1, 20}, {3, 120}}, false);
    ASSERT_TRUE(waitFor([&] { return allHomedAndStill() && std::abs(analyzer()->status().axes[3].commanded - 120) < 1e-6; }, 10000));
    reconnect();
    const auto& a = analyzer()->status().axes;
    for (int i = 0; i < 4; ++i)
        EXPECT_TRUE(a[static_cast<std::size_t>(i)].homed) << "axis " << i << " lost its homing over a reconnect";
    EXPECT_NEAR(a[0].commanded, 30, 1e-6);
    EXPECT_NEAR(a[1].commanded, 20, 1e-6);
    EXPECT_NEAR(a[3].commanded, 120, 1e-6) << "the plunger's 120 µL are gone";
}

TEST_F(TrustReconnectTest, APlateRunInterruptedByDisconnectResumesWithEveryWellDoneOnce)
{
    ui::PlateMap* map = screen->plateMap();
    map->setSelection({{0, 0}, {0, 1}, {0, 2}, {1, 0}, {1, 1}, {1, 2}});
    QPushButton* aspirate = button(screen, QObject::tr("Aspirate from these"));
    ASSERT_NE(aspirate, nullptr);
    QTest::mouseClick(aspirate, Qt::LeftButton);
    ASSERT_EQ(screen->plan().ops.size(), 6u);
    int decisions = 0;
    screen->setInterruptedDecider([&](const dev::jobs::InterruptedOp&) {
        ++decisions;
        return dev::jobs::InterruptedChoice::Redo;
    });
    std::vector<int> finished;
    QObject::connect(screen->runner(), &dev::jobs::RecipeRunner::opFinished, screen, [&](int op) { finished.push_back(op); });
    QTest::mouseClick(button(screen->runPanel(), QObject::tr("Run")), Qt::LeftButton);
    ASSERT_TRUE(waitFor([&] { return finished.size() >= 2; }, 30000)) << dev::jobs::runStateTerm(screen->runner()->state());
    reconnect();
    ASSERT_TRUE(waitFor([&] { return screen->runner()->state() == dev::jobs::RunState::Stopped; }, 5000))
        << dev::jobs::runStateTerm(screen->runner()->state());
    EXPECT_TRUE(allHomedAndStill());
    QPushButton* resume = button(screen->runPanel(), QObject::tr("Resume"));
    ASSERT_NE(resume, nullptr);
    ASSERT_TRUE(resume->isEnabled());
    QStringList notes;
    QObject::connect(screen, &ui::PlatesScreen::note, screen, [&](const QString& m) { notes << m; });
    QTest::mouseClick(resume, Qt::LeftButton);
    EXPECT_TRUE(notes.join(QLatin1Char('\n')).contains(QStringLiteral("found the same instrument")))
        << "the resume does not say what it found: " << notes.join(QLatin1Char('\n')).toStdString();
    ASSERT_TRUE(waitFor([&] { return screen->runner()->state() == dev::jobs::RunState::Finished; }, 30000))
        << dev::jobs::runStateTerm(screen->runner()->state()) << " after " << decisions << " decisions";
    ASSERT_TRUE(waitFor([&] { return !analyzer()->status().anyMoving(); }, 5000));
    std::vector<int> sorted = finished;
    std::sort(sorted.begin(), sorted.end());
    EXPECT_EQ(sorted, (std::vector<int>{0, 1, 2, 3, 4, 5})) << "a well was done twice or not at all";
    EXPECT_NEAR(analyzer()->status().axes[3].commanded, 60, 1e-6) << "six wells of 10 µL";
}

// The failure this catches: Open… during a plate run replaced the plate map with "No
// plate" while the old run went on. A run holds the recipe that runs on screen.
TEST_F(TrustReconnectTest, OpenDuringAPlateRunKeepsTheRecipeThatRuns)
{
    const QString other = dir.filePath(QStringLiteral("empty.recipe.json"));
    ASSERT_TRUE(screen->saveRecipe(other));  // the recipe before any step: opening it would empty the run's plan
    screen->plateMap()->setSelection({{0, 0}, {0, 1}, {0, 2}, {1, 0}, {1, 1}, {1, 2}});
    QTest::mouseClick(button(screen, QObject::tr("Aspirate from these")), Qt::LeftButton);
    ASSERT_EQ(screen->plan().ops.size(), 6u);
    QString said;
    QObject::connect(screen, &ui::PlatesScreen::problem, screen, [&](const QString& m) { said = m; });
    QTest::mouseClick(button(screen->runPanel(), QObject::tr("Run")), Qt::LeftButton);
    ASSERT_TRUE(waitFor([&] { return screen->runner()->state() == dev::jobs::RunState::Running; }, 5000));
    QToolButton* open = nullptr;
    for (auto* b : screen->recipeEditor()->findChildren<QToolButton*>())
        if (b->text() == QObject::tr("Open…"))
            open = b;
    ASSERT_NE(open, nullptr);
    EXPECT_FALSE(open->isEnabled()) << "Open… offered while a run is under way";
    EXPECT_FALSE(screen->openRecipe(other));
    EXPECT_FALSE(said.isEmpty()) << "refused without a word";
    EXPECT_EQ(screen->plan().ops.size(), 6u) << "the plan on screen is no longer the one that runs";
    EXPECT_EQ(screen->recipeEditor()->recipe().steps.size(), 1u);
    ASSERT_TRUE(waitFor([&] { return screen->runner()->state() == dev::jobs::RunState::Finished; }, 30000));
    EXPECT_TRUE(open->isEnabled());
    EXPECT_TRUE(screen->openRecipe(other));
}

// The failure this catches: the recipe editor clamped a file's safe Z −5 to 0, depth 700
// to 100 and slot 7 to 1 while Problems listed the originals. The editor shows
// the file's values, marked invalid, and the recipe keeps them until fixed.
TEST_F(TrustReconnectTest, TheRecipeEditorShowsAFilesOutOfRangeValuesAsTheyAreMarkedInvalid)
{
    const QString path = dir.filePath(QStringLiteral("odd.recipe.json"));
    QFile f(path);
    ASSERT_TRUE(f.open(QIODevice::WriteOnly));
    f.write(R"({"schema": "benchpilot.recipe", "version": 1, "name": "odd",
  "plates": [{"name": "samples", "slot": "7", "labware": "sbs-96", "safe_z_mm": -5, "depth_z_mm": 700}],
  "steps": [{"type": "aspirate", "plate": "samples", "wells": "A1", "volume_ul": 10, "speed_ul_s": 100}]})");
    f.close();
    screen->openRecipe(path);
    ui::RecipeEditor* ed = screen->recipeEditor();
    ASSERT_EQ(ed->recipe().plates.size(), 1u);
    QStringList shown;
    int invalid = 0;
    for (auto* n : ed->findChildren<ui::NumberField*>()) {
        shown << n->text();
        invalid += n->isValid() ? 0 : 1;
    }
    EXPECT_TRUE(shown.contains(QStringLiteral("-5"))) << shown.join(QLatin1Char(' ')).toStdString();
    EXPECT_TRUE(shown.contains(QStringLiteral("700"))) << shown.join(QLatin1Char(' ')).toStdString();
    EXPECT_EQ(invalid, 2);
    bool slotShown = false;
    for (auto* c : ed->findChildren<QComboBox*>())
        slotShown = slotShown || (c->currentData().toString() == QStringLiteral("7") && !c->toolTip().isEmpty());
    EXPECT_TRUE(slotShown) << "slot 7 is not shown as the file has it";
    EXPECT_EQ(ed->recipe().plates[0].slot, "7");
    EXPECT_EQ(ed->recipe().plates[0].safeZMm, -5);
    EXPECT_EQ(ed->recipe().plates[0].depthZMm, 700);
    EXPECT_FALSE(ed->isModified()) << "opening the file changed it";
}

// A resume after a reconnect checks the instrument against the
// run. One that was switched off (a fresh simulator, homed again) has an empty
// syringe: the resume is refused and says where the plunger is and should be.
TEST_F(TrustReconnectTest, AResumeOnAnInstrumentWhosePlungerDiffersIsRefusedSayingWhy)
{
    screen->plateMap()->setSelection({{0, 0}, {0, 1}, {0, 2}, {1, 0}, {1, 1}, {1, 2}});
    QTest::mouseClick(button(screen, QObject::tr("Aspirate from these")), Qt::LeftButton);
    int finished = 0;
    QObject::connect(screen->runner(), &dev::jobs::RecipeRunner::opFinished, screen, [&] { ++finished; });
    QTest::mouseClick(button(screen->runPanel(), QObject::tr("Run")), Qt::LeftButton);
    ASSERT_TRUE(waitFor([&] { return finished >= 2; }, 30000));
    w->analyzer()->disconnectLink();
    pump(300);
    ui::ConnectionChoice other = choice;
    other.baud = 921600;  // another link speed: a new simulator, as if the analyzer had been switched off
    w->analyzer()->connectTo(other);
    ASSERT_TRUE(waitFor([&] { return analyzer()->isReady() && analyzer()->status().axes.size() == 4; }, 5000));
    analyzer()->home(0);
    ASSERT_TRUE(waitFor([&] { return allHomedAndStill(); }, 60000));
    ASSERT_EQ(screen->runner()->state(), dev::jobs::RunState::Stopped);
    QString said;
    QObject::connect(screen->runPanel(), &ui::RunPanel::problem, screen, [&](const QString& m) { said = m; });
    QTest::mouseClick(button(screen->runPanel(), QObject::tr("Resume")), Qt::LeftButton);
    pump(200);
    EXPECT_EQ(screen->runner()->state(), dev::jobs::RunState::Stopped) << "resumed with an empty syringe";
    EXPECT_TRUE(said.contains(QStringLiteral("plunger"))) << said.toStdString();
}
