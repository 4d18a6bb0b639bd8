// The Plates screen driven as a person would: drag across wells, make a step of
// them, run it on the simulated analyzer; hover, edit with undo, save and open,
// and teach a slot.
#include "app/gui/instrument_session.h"
#include "app/gui/main_window.h"
#include "device/files/recipes/recipe_file.h"
#include "device/files/text_file.h"
#include "device/link/simulated_link.h"
#include "gui_wait.h"
#include "gui_window.h"
#include "widgets/common/button_key.h"
#include "widgets/common/number_field.h"
#include "widgets/plates/calibration_panel.h"
#include "widgets/plates/plate_map.h"
#include "widgets/plates/plates_screen.h"
#include "widgets/plates/recipe_editor.h"
#include "widgets/plates/run_panel.h"
#include "widgets/plates/step_form.h"

#include <QComboBox>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMouseEvent>
#include <QProgressBar>
#include <QPushButton>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QToolButton>
#include <QUndoStack>

#include <gtest/gtest.h>

using guitest::pump;
using guitest::waitFor;

using guitest::button;

namespace {

void mouse(QWidget* w, QEvent::Type type, const QPointF& at, Qt::MouseButtons held)
{
    const Qt::MouseButton b = type == QEvent::MouseMove ? Qt::NoButton : Qt::LeftButton;
    QMouseEvent e(type, at, w->mapToGlobal(at), b, held, Qt::NoModifier);
    QApplication::sendEvent(w, &e);
}

/// Presses beside the first well, drags past the last and lets go.
void dragAcross(ui::PlateMap* map, const motion::plates::WellId& from, const motion::plates::WellId& to)
{
    const QPointF a = map->wellCenter(from) - QPointF(4, 4), b = map->wellCenter(to) + QPointF(4, 4);
    mouse(map, QEvent::MouseButtonPress, a, Qt::LeftButton);
    for (int k = 1; k <= 10; ++k)
        mouse(map, QEvent::MouseMove, a + (b - a) * k / 10.0, Qt::LeftButton);
    mouse(map, QEvent::MouseButtonRelease, b, Qt::NoButton);
}

class PlatesScreenTest : public ::testing::Test {
protected:
    void SetUp() override
    {
        w = guitest::openReadyWindow({1500, 950});
        ASSERT_TRUE(w) << "the simulated instruments did not become ready";
        ASSERT_TRUE(w->showScreen(QStringLiteral("plates")));
        screen = w->platesScreen();
        ASSERT_NE(screen, nullptr);
        screen->setRunLogDirectory(dir.path());
        pump(50);
    }
    dev::Instrument* analyzer() { return w->analyzer()->instrument(); }
    /// An unpaced simulator with a fast clock, homed: runs take seconds, not minutes.
    void fastHomedAnalyzer()
    {
        ui::ConnectionChoice c;
        c.baud = 0;
        w->analyzer()->connectTo(c);
        ASSERT_TRUE(waitFor([&] { return analyzer()->isReady(); }, 5000));
        auto* link = qobject_cast<dev::SimulatedLink*>(w->analyzer()->link());
        ASSERT_NE(link, nullptr);
        link->host().setTimeScale(20);
        analyzer()->home(0);
        ASSERT_TRUE(waitFor(
            [&] {
                const auto& a = analyzer()->status().axes;
                return a.size() == 4 && std::all_of(a.begin(), a.end(), [](const auto& x) { return x.homed && !x.moving; });
            },
            30000));
    }

    /// The operator's jogging, done as a move: the tip over `m` and still.
    bool moveTo(const motion::plates::PointMm& m)
    {
        analyzer()->move({{0, m.x}, {1, m.y}}, false);
        return waitFor(
            [&] {
                const auto& a = analyzer()->status().axes;
                return std::abs(a[0].commanded - m.x) < 1e-6 && std::abs(a[1].commanded - m.y) < 1e-6 && !a[0].moving && !a[1].moving;
            },
            10000);
    }

    QTemporaryDir dir;
    std::unique_ptr<app::MainWindow> w;
    ui::PlatesScreen* screen = nullptr;
};

} // namespace

// Found driving the screen under Xvfb: a drag from A1's centre to H3's centre took A1:G2.
// Only wells whose centres lay inside the rectangle counted, and the release point, where
// no move had been reported, was not the drag's end.
TEST_F(PlatesScreenTest, ADragFromInsideOneWellToInsideAnotherTakesBothAndTheBlockBetween)
{
    ui::PlateMap* map = screen->plateMap();
    const QPointF a = map->wellCenter({0, 0}) + QPointF(1, 1);
    const QPointF b = map->wellCenter({7, 2}) - QPointF(1, 1);
    mouse(map, QEvent::MouseButtonPress, a, Qt::LeftButton);
    mouse(map, QEvent::MouseMove, (a + b) / 2, Qt::LeftButton);  // the last move reported: about D2
    mouse(map, QEvent::MouseButtonRelease, b, Qt::NoButton);
    std::set<motion::plates::WellId> want;
    for (int row = 0; row < 8; ++row)
        for (int col = 0; col < 3; ++col)
            want.insert({row, col});
    EXPECT_EQ(map->selection(), want) << map->selection().size() << " wells";
}

TEST_F(PlatesScreenTest, DragSelectsWellsAndTheirStepRunsOnTheSimulator)
{
    fastHomedAnalyzer();
    ui::PlateMap* map = screen->plateMap();
    dragAcross(map, {0, 0}, {1, 2});  // A1 … B3
    std::set<motion::plates::WellId> want = {{0, 0}, {0, 1}, {0, 2}, {1, 0}, {1, 1}, {1, 2}};
    EXPECT_EQ(map->selection(), want);
    QPushButton* aspirate = button(screen, QObject::tr("Aspirate from these"));
    ASSERT_NE(aspirate, nullptr);
    ASSERT_TRUE(aspirate->isEnabled());
    QTest::mouseClick(aspirate, Qt::LeftButton);
    const motion::plates::Recipe& r = screen->recipeEditor()->recipe();
    ASSERT_EQ(r.steps.size(), 1u);
    EXPECT_EQ(r.steps[0].type, motion::plates::StepType::Aspirate);
    EXPECT_EQ(r.steps[0].wells, (std::vector<std::string>{"A1:B3"}));
    EXPECT_TRUE(screen->plan().ok());
    EXPECT_EQ(screen->plan().ops.size(), 6u);

    QPushButton* run = button(screen->runPanel(), QObject::tr("Run"));
    ASSERT_NE(run, nullptr);
    ASSERT_TRUE(run->isEnabled());
    QTest::mouseClick(run, Qt::LeftButton);
    ASSERT_TRUE(waitFor([&] { return screen->runner()->state() == dev::jobs::RunState::Finished; }, 30000))
        << dev::jobs::runStateTerm(screen->runner()->state());
    ASSERT_TRUE(waitFor([&] { return !analyzer()->status().anyMoving(); }, 5000));
    pump(200);
    EXPECT_NEAR(analyzer()->status().axes[3].commanded, 60, 1e-6) << "six wells of 10 µL";
    // The map shows every selected well done, and the rest unused.
    map->clearSelection();
    const QImage img = map->grab().toImage();
    auto colorAt = [&](const motion::plates::WellId& id) { return QColor(img.pixel(map->wellCenter(id).toPoint())); };
    for (const auto& id : want)
        EXPECT_EQ(colorAt(id), ui::PlateMap::colorOf(ui::PlateMap::WellState::Done)) << motion::plates::wellName(id);
    EXPECT_EQ(colorAt({7, 11}), ui::PlateMap::colorOf(ui::PlateMap::WellState::Unused));
    // The run log is where the screen said.
    EXPECT_FALSE(screen->runner()->logPath().isEmpty());
    EXPECT_TRUE(screen->runner()->logPath().startsWith(dir.path()));
    // Its message lines start with a capital and are whole in their tooltips (a long log
    // name was cut with "…" in Chinese).
    auto* messages = screen->runPanel()->findChild<QListWidget*>(QStringLiteral("runMessages"));
    ASSERT_NE(messages, nullptr);
    ASSERT_GT(messages->count(), 0);
    for (int i = 0; i < messages->count(); ++i) {
        const QString line = messages->item(i)->text();
        EXPECT_EQ(messages->item(i)->toolTip(), line);
        const QString sentence = line.section(QStringLiteral("  "), 1);
        EXPECT_TRUE(!sentence.isEmpty() && sentence.front().isUpper()) << line.toStdString();
    }
}

// Seen under Xvfb in Chinese: a recipe named 新方案 logged to "--20261127-143319-403.run.jsonl",
// its name dropped and a leading "--" that any command-line tool takes for an option.
TEST(PlatesRunLogName, KeepsTheRecipesNameInAnyScriptAndNeverStartsWithADash)
{
    const QDateTime at(QDate(2026, 11, 27), QTime(14, 33, 19, 403));
    EXPECT_EQ(ui::PlatesScreen::runLogName(QStringLiteral("新方案"), at), QStringLiteral("新方案-20261127-143319-403.run.jsonl"));
    EXPECT_EQ(ui::PlatesScreen::runLogName(QStringLiteral("New recipe"), at), QStringLiteral("New-recipe-20261127-143319-403.run.jsonl"));
    EXPECT_EQ(ui::PlatesScreen::runLogName(QStringLiteral("--all/../wells "), at), QStringLiteral("all-..-wells-20261127-143319-403.run.jsonl"));
    EXPECT_EQ(ui::PlatesScreen::runLogName(QStringLiteral(" / "), at), QStringLiteral("recipe-20261127-143319-403.run.jsonl"));
}

TEST_F(PlatesScreenTest, ClickAndCtrlClickAndHoverShowCoordinatesAndVolume)
{
    ui::PlateMap* map = screen->plateMap();
    const QPointF b3 = map->wellCenter({1, 2});
    mouse(map, QEvent::MouseButtonPress, b3, Qt::LeftButton);
    mouse(map, QEvent::MouseButtonRelease, b3, Qt::NoButton);
    EXPECT_EQ(map->selection(), (std::set<motion::plates::WellId>{{1, 2}}));
    QTest::mouseClick(button(screen, QObject::tr("Dispense into these")), Qt::LeftButton);
    mouse(map, QEvent::MouseMove, b3, Qt::NoButton);
    const QString text = map->hoverText();
    // B3 of an SBS 96 plate: 14.38 + 2·9, 11.24 + 9 mm; slot 1's corner at (8, 8).
    EXPECT_TRUE(text.startsWith(QStringLiteral("B3 · plate (32.38, 20.24) mm · machine (40.38, 28.24) mm"))) << text.toStdString();
    EXPECT_TRUE(text.contains(QStringLiteral("10 µL dispensed"))) << text.toStdString();
    EXPECT_TRUE(text.contains(QStringLiteral("not calibrated"))) << text.toStdString();
    // A dispense with nothing in the syringe does not validate: Run is off, the problem says why.
    EXPECT_FALSE(screen->plan().ok());
    EXPECT_FALSE(button(screen->runPanel(), QObject::tr("Run"))->isEnabled());
}

TEST_F(PlatesScreenTest, StepEditsUndoRedoSaveAndOpen)
{
    ui::PlateMap* map = screen->plateMap();
    dragAcross(map, {2, 0}, {2, 11});  // row C
    QTest::mouseClick(button(screen, QObject::tr("Aspirate from these")), Qt::LeftButton);
    ui::RecipeEditor* ed = screen->recipeEditor();
    ASSERT_EQ(ed->recipe().steps.size(), 1u);
    EXPECT_EQ(ed->recipe().steps[0].wells, (std::vector<std::string>{"C1:C12"}));
    // The form's volume field (10 µL as the selection made it): typed twice, one undoable change.
    ui::NumberField* volume = nullptr;
    for (auto* f : ed->findChild<ui::StepForm*>()->findChildren<ui::NumberField*>())
        if (f->isVisible() && f->text() == QStringLiteral("10"))
            volume = f;
    ASSERT_NE(volume, nullptr);
    for (const char* typed : {"25", "30"}) {
        volume->setText(QLatin1String(typed));
        emit volume->editingFinished();
    }
    EXPECT_DOUBLE_EQ(ed->recipe().steps[0].volumeUl, 30);
    ed->undoStack()->undo();
    EXPECT_DOUBLE_EQ(ed->recipe().steps[0].volumeUl, 10) << "both changes of the field were one command";
    EXPECT_EQ(volume->value(), std::optional<double>(10));
    ed->undoStack()->redo();
    EXPECT_DOUBLE_EQ(ed->recipe().steps[0].volumeUl, 30);
    // An unknown well in the wells field: the problem names it and Run is off.
    QLineEdit* wells = nullptr;
    for (auto* l : ed->findChildren<QLineEdit*>())
        if (l->placeholderText().startsWith(QStringLiteral("A1:H1")))
            wells = l;
    ASSERT_NE(wells, nullptr);
    wells->setText(QStringLiteral("C1:C12, I13"));
    emit wells->editingFinished();
    EXPECT_FALSE(screen->plan().ok());
    bool named = false;
    for (auto* list : ed->findChildren<QListWidget*>())
        for (int i = 0; i < list->count(); ++i)
            named = named || list->item(i)->text().contains(QStringLiteral("unknown well \"I13\" on a 96-well plate"));
    EXPECT_TRUE(named);
    EXPECT_FALSE(button(screen->runPanel(), QObject::tr("Run"))->isEnabled());
    ed->undoStack()->undo();
    EXPECT_TRUE(screen->plan().ok());

    // Save (the file chooser is the app's; here it answers with a path) and open again.
    const QString path = dir.filePath(QStringLiteral("row-c.recipe.json"));
    screen->setFileChooser([&](const QString&, const QString&, bool) { return path; });
    QToolButton* save = nullptr;
    for (auto* b : ed->findChildren<QToolButton*>())
        if (b->text() == QObject::tr("Save"))
            save = b;
    ASSERT_NE(save, nullptr);
    EXPECT_EQ(ui::buttonKey(save), QKeySequence(QKeySequence::Save));
    QTest::mouseClick(save, Qt::LeftButton);
    ASSERT_TRUE(QFileInfo::exists(path));
    EXPECT_FALSE(ed->isModified());
    std::string text;
    QString error;
    ASSERT_TRUE(dev::files::readText(path, &text, &error));
    const auto read = dev::files::plates::parseRecipe(text);
    ASSERT_TRUE(read.wellFormed);
    EXPECT_DOUBLE_EQ(read.recipe->steps[0].volumeUl, 30);
    screen->newRecipe();
    EXPECT_TRUE(ed->recipe().steps.empty());
    ASSERT_TRUE(screen->openRecipe(path));
    EXPECT_EQ(ed->recipe().steps.size(), 1u);
    EXPECT_EQ(screen->recipePath(), path);
}

TEST_F(PlatesScreenTest, TheCalibrationWizardTeachesASlotAndItIsKept)
{
    fastHomedAnalyzer();
    const QString file = dir.filePath(QStringLiteral("calibration.json"));
    screen->setCalibrationFile(file);
    screen->showTab(QStringLiteral("calibrate"));
    ui::CalibrationPanel* cal = screen->calibrationPanel();
    cal->setSlot(QStringLiteral("1"));
    // The plate sits 0.6 mm right and 0.4 mm back of nominal, turned 0.3°: the
    // operator jogs the tip over each teach well and records it.
    const motion::plates::PlateTransform truth = motion::plates::PlateTransform::make(8.6, 7.6, 0.3);
    const motion::plates::Labware lw = *motion::plates::findBuiltinLabware("sbs-96");
    const auto pts = motion::plates::teachWells(lw);
    for (int i = 0; i < 3; ++i) {
        ASSERT_TRUE(moveTo(truth.apply(pts[static_cast<std::size_t>(i)].plateMm)));
        cal->recordPoint(i);
    }
    ASSERT_TRUE(cal->fit());
    // Editing the recipe meanwhile does not throw the taught points away.
    screen->recipeEditor()->edit(QStringLiteral("rename"), [](motion::plates::Recipe& r) { r.name = "renamed"; });
    ASSERT_TRUE(cal->fit());
    EXPECT_NEAR(cal->fit()->rotationDeg, 0.3, 0.01);
    EXPECT_LT(cal->fit()->maxResidualMm, 0.01);
    ASSERT_TRUE(button(cal, QObject::tr("Save calibration"))->isEnabled());
    QTest::mouseClick(button(cal, QObject::tr("Save calibration")), Qt::LeftButton);
    ASSERT_EQ(cal->calibrations().size(), 1u);
    ASSERT_TRUE(QFileInfo::exists(file)) << "kept between runs";
    // The recipe now goes to the taught wells.
    dragAcross(screen->plateMap(), {0, 0}, {0, 0});
    QTest::mouseClick(button(screen, QObject::tr("Aspirate from these")), Qt::LeftButton);
    ASSERT_FALSE(screen->plan().ops.empty());
    const motion::plates::PointMm a1 = truth.apply(pts[0].plateMm);
    EXPECT_NEAR(screen->plan().ops[0].at.x, a1.x, 0.01);
    EXPECT_NEAR(screen->plan().ops[0].at.y, a1.y, 0.01);
    // A fresh screen (the next session) reads it back.
    ui::PlatesScreen next(analyzer());
    next.setCalibrationFile(file);
    EXPECT_EQ(next.calibrationPanel()->calibrations().size(), 1u);

    // A well taught a millimetre off: the residual shows it and a warning says so.
    cal->setSlot(QStringLiteral("2"));
    for (int i = 0; i < 3; ++i) {
        motion::plates::PointMm m = motion::plates::PlateTransform::make(8, 106, 0).apply(pts[static_cast<std::size_t>(i)].plateMm);
        if (i == 1)
            m.x += 1.0;
        ASSERT_TRUE(moveTo(m));
        cal->recordPoint(i);
    }
    ASSERT_TRUE(cal->fit());
    EXPECT_GT(cal->fit()->maxResidualMm, motion::plates::kResidualWarnMm);
    ASSERT_FALSE(cal->fit()->warnings.empty());
}

TEST_F(PlatesScreenTest, StepTypesAndPlannedOpsShowReadableNamesNotFileIds)
{
    ui::PlateMap* map = screen->plateMap();
    dragAcross(map, {0, 0}, {0, 1});  // A1, A2
    QTest::mouseClick(button(screen, QObject::tr("Aspirate from these")), Qt::LeftButton);
    // The step form's type list: "Air gap", not the file's "air_gap"; the id is the item's data.
    QComboBox* type = nullptr;
    for (auto* c : screen->recipeEditor()->findChildren<QComboBox*>())
        if (c->count() == motion::plates::kStepTypeCount)
            type = c;
    ASSERT_NE(type, nullptr);
    const int airGap = type->findData(static_cast<int>(motion::plates::StepType::AirGap));
    ASSERT_GE(airGap, 0);
    EXPECT_EQ(type->itemText(airGap), QStringLiteral("Air gap"));
    EXPECT_EQ(type->itemText(type->findData(static_cast<int>(motion::plates::StepType::TouchOff))), QStringLiteral("Touch off"));
    EXPECT_EQ(type->currentText(), QStringLiteral("Aspirate"));
    for (int i = 0; i < type->count(); ++i)
        EXPECT_FALSE(type->itemText(i).contains(QLatin1Char('_'))) << type->itemText(i).toStdString();
    // The plan table names each op in words.
    QTableWidget* table = screen->runPanel()->findChild<QTableWidget*>();
    ASSERT_NE(table, nullptr);
    ASSERT_GE(table->rowCount(), 2);
    QStringList cells;
    for (int c = 0; c < table->columnCount(); ++c)
        cells << (table->item(1, c) ? table->item(1, c)->text() : QString());
    EXPECT_TRUE(cells.contains(QStringLiteral("Aspirate 10 µL from samples A2"))) << cells.join(QLatin1String(" | ")).toStdString();
}

// Seen under Xvfb with the reagent-transfer example: the plan said "47 ops over 30 wells",
// the run's question "47 wells", the progress "0 of 0 wells" and then "0 of 47 wells". The
// runner counts operations (a wash, a mix, an aspirate each are one); only sampling-96,
// one op a well, had made the two agree.
TEST_F(PlatesScreenTest, ARunCountsOperationsAndSaysOverHowManyWells)
{
    ASSERT_TRUE(screen->openRecipe(QStringLiteral(BP_SOURCE_DIR "/resources/examples/reagent-transfer.recipe.json")));
    pump(50);
    const motion::plates::RecipePlan& plan = screen->plan();
    ASSERT_TRUE(plan.ok());
    const int ops = static_cast<int>(plan.ops.size()), wells = plan.wellsVisited();
    ASSERT_GT(ops, wells) << "a recipe whose ops are its wells tells nothing";
    auto* progress = screen->runPanel()->findChild<QProgressBar*>();
    ASSERT_NE(progress, nullptr);
    EXPECT_EQ(progress->text().toStdString(), QStringLiteral("0 of %1 operations").arg(ops).toStdString()) << "before the run, the plan's count";
    QString asked;
    screen->setConfirm([&](const QString& q) {
        asked = q;
        return false;
    });
    QPushButton* run = button(screen->runPanel(), QObject::tr("Run"));
    ASSERT_NE(run, nullptr);
    QTest::mouseClick(run, Qt::LeftButton);
    pump(20);
    EXPECT_TRUE(asked.contains(QStringLiteral("%1 operations over %2 wells").arg(ops).arg(wells))) << asked.toStdString();
}

// Paused after a well, the screen showed the next well as "Current" (and the map drew it
// as under way): nothing is under way while paused. The next op is said as next.
TEST_F(PlatesScreenTest, PausedBetweenWellsNothingIsCurrent)
{
    fastHomedAnalyzer();
    ui::PlateMap* map = screen->plateMap();
    dragAcross(map, {0, 0}, {0, 7});  // A1 … A8
    QTest::mouseClick(button(screen, QObject::tr("Aspirate from these")), Qt::LeftButton);
    ASSERT_TRUE(screen->plan().ok());
    QPushButton* run = button(screen->runPanel(), QObject::tr("Run"));
    ASSERT_NE(run, nullptr);
    QTest::mouseClick(run, Qt::LeftButton);
    ASSERT_TRUE(waitFor([&] { return screen->runner()->progress().opsDone >= 2; }, 30000));
    QPushButton* pause = button(screen->runPanel(), QObject::tr("Pause"));
    ASSERT_NE(pause, nullptr);
    QTest::mouseClick(pause, Qt::LeftButton);
    ASSERT_TRUE(waitFor([&] { return screen->runner()->state() == dev::jobs::RunState::Paused; }, 30000))
        << dev::jobs::runStateTerm(screen->runner()->state());
    pump(100);
    const int next = screen->runner()->progress().opsDone;
    const QString nextWell = QString::fromStdString(screen->plan().ops[static_cast<std::size_t>(next)].well);
    QStringList shown;
    for (auto* l : screen->runPanel()->findChildren<QLabel*>())
        shown << l->text();
    const QString all = shown.join(QLatin1Char('|'));
    EXPECT_FALSE(all.contains(QStringLiteral("Current: "))) << "paused, yet something is current: " << all.toStdString();
    EXPECT_TRUE(all.contains(QStringLiteral("Next: "))) << all.toStdString();
    EXPECT_TRUE(all.contains(nextWell)) << nextWell.toStdString() << " in " << all.toStdString();
    // On the map the next well is not drawn as under way.
    const QImage img = map->grab().toImage();
    const motion::plates::WellId id{0, next};
    EXPECT_NE(QColor(img.pixel(map->wellCenter(id).toPoint())), ui::PlateMap::colorOf(ui::PlateMap::WellState::Current))
        << nextWell.toStdString();
    QPushButton* resume = button(screen->runPanel(), QObject::tr("Resume"));
    ASSERT_NE(resume, nullptr);
    QTest::mouseClick(resume, Qt::LeftButton);
    ASSERT_TRUE(waitFor([&] { return screen->runner()->state() == dev::jobs::RunState::Finished; }, 30000));
}

// Before Run the screen shows the path the chosen order takes on the plate, the planned
// time beside its time-optimal bound, and how every other order would do.
TEST_F(PlatesScreenTest, ThePathTheBoundAndTheOrdersComparedBeforeRun)
{
    ASSERT_TRUE(screen->openRecipe(QStringLiteral(BP_SOURCE_DIR "/resources/examples/fill-96-arched.recipe.json")));
    pump(50);
    const motion::plates::RecipePlan& plan = screen->plan();
    ASSERT_TRUE(plan.ok());
    screen->showPlate(QStringLiteral("assay"));
    pump(20);
    // Snake rows: A1 … A12, then B12 back to B1.
    const QStringList path = screen->plateMap()->path();
    ASSERT_EQ(path.size(), 96);
    EXPECT_EQ(path.mid(10, 4), (QStringList{QStringLiteral("A11"), QStringLiteral("A12"), QStringLiteral("B12"), QStringLiteral("B11")}));
    auto* speed = screen->runPanel()->findChild<QLabel*>(QStringLiteral("planSpeed"));
    ASSERT_NE(speed, nullptr);
    EXPECT_TRUE(speed->text().contains(QStringLiteral("Time-optimal bound"))) << speed->text().toStdString();
    EXPECT_TRUE(speed->text().contains(QString::number(plan.totalTimeS / plan.boundS, 'f', 2))) << speed->text().toStdString();
    auto* orders = screen->runPanel()->findChild<QTableWidget*>(QStringLiteral("orderComparison"));
    ASSERT_NE(orders, nullptr);
    ASSERT_EQ(orders->rowCount(), 5);
    QStringList names;
    for (int r = 0; r < orders->rowCount(); ++r)
        names << orders->item(r, 0)->text();
    EXPECT_EQ(names, (QStringList{QStringLiteral("As written"), QStringLiteral("Column by column"), QStringLiteral("Snake rows"),
                                  QStringLiteral("Snake columns"), QStringLiteral("Shortest")}));
    EXPECT_EQ(orders->item(2, 0)->toolTip(), QStringLiteral("snake-rows")) << "the file's word";
    EXPECT_FALSE(orders->item(4, 1)->text().isEmpty());
}

// Found driving the screen under Xvfb: the arched example, run from the Run button, stopped
// at its first op with "the analyzer refused a move" and no reason, while the same recipe
// ran from the CLI. The screen's run must do what the CLI's does, and a refusal say why.
TEST_F(PlatesScreenTest, AnArchedRecipeRunsFromTheScreenAsItDoesFromTheCli)
{
    fastHomedAnalyzer();
    ASSERT_TRUE(screen->openRecipe(QStringLiteral(BP_SOURCE_DIR "/resources/examples/fill-96-arched.recipe.json")));
    pump(50);
    ASSERT_TRUE(screen->plan().ok());
    screen->setConfirm([](const QString&) { return true; });
    QStringList problems;
    QObject listening;  // the connection ends with the test, before the window's teardown speaks
    QObject::connect(screen->runner(), &dev::jobs::RecipeRunner::message, &listening, [&](const motion::msg::Message& m, bool isProblem) {
        if (isProblem)
            problems << QString::fromStdString(motion::msg::debugString(m));
    });
    QPushButton* run = button(screen->runPanel(), QObject::tr("Run"));
    ASSERT_NE(run, nullptr);
    QTest::mouseClick(run, Qt::LeftButton);
    ASSERT_TRUE(waitFor([&] { return screen->runner()->progress().opsDone >= 4 || screen->runner()->state() == dev::jobs::RunState::Stopped; }, 60000));
    EXPECT_NE(screen->runner()->state(), dev::jobs::RunState::Stopped) << problems.join(QStringLiteral("; ")).toStdString();
    screen->runner()->abort();
}
