#include "widgets/plates/plates_screen.h"

#include "device/jobs/machine_model.h"

#include "device/files/plates/calibration_file.h"
#include "device/files/plates/deck_file.h"
#include "device/files/plates/labware_file.h"
#include "device/files/recipes/recipe_loader.h"
#include "device/files/text_file.h"
#include "widgets/plates/calibration_panel.h"
#include "widgets/plates/plate_map.h"
#include "widgets/plates/recipe_editor.h"
#include "widgets/plates/run_panel.h"
#include "widgets/retranslator.h"

#include "widgets/wording/wording.h"

#include <QEvent>
#include <QComboBox>
#include <QDateTime>
#include <QDir>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QRegularExpression>
#include <QScrollArea>
#include <QSplitter>
#include <QTabWidget>
#include <QVBoxLayout>

namespace ui {

namespace {
QLabel* legendChip(PlateMap::WellState s, const QString& text, QWidget* parent)
{
    auto* l = new QLabel(QStringLiteral("<span style='background:%1; border:1px solid #777;'>&nbsp;&nbsp;&nbsp;&nbsp;</span> %2")
                             .arg(PlateMap::colorOf(s).name(), text),
                         parent);
    return l;
}
} // namespace

PlatesScreen::PlatesScreen(dev::Instrument* analyzer, QWidget* parent)
    : QWidget(parent), m_client(analyzer), m_runner(new dev::jobs::RecipeRunner(analyzer, this)), m_deck(dev::files::plates::builtinDeck())
{
    auto* split = new QSplitter(Qt::Horizontal, this);
    auto* left = new QWidget(split);
    auto* lv = new QVBoxLayout(left);
    auto* pick = new QHBoxLayout;
    pick->addWidget(new QLabel(tr("Plate"), left));
    m_plate = new QComboBox(left);
    m_plate->setProperty(Retranslator::kItemsAreNames, true);  // the recipe's plate names, looked up by text
    pick->addWidget(m_plate, 1);
    lv->addLayout(pick);
    m_map = new PlateMap(left);
    lv->addWidget(m_map, 1);
    auto* legend = new QHBoxLayout;
    legend->addWidget(legendChip(PlateMap::WellState::Unused, tr("unused"), left));
    legend->addWidget(legendChip(PlateMap::WellState::Planned, tr("planned"), left));
    legend->addWidget(legendChip(PlateMap::WellState::Current, tr("current"), left));
    legend->addWidget(legendChip(PlateMap::WellState::Done, tr("done"), left));
    legend->addWidget(legendChip(PlateMap::WellState::Error, tr("error"), left));
    legend->addStretch();
    lv->addLayout(legend);
    m_hover = new QLabel(left);
    m_hover->setMinimumHeight(m_hover->fontMetrics().height() * 2);
    m_hover->setWordWrap(true);
    m_hover->setStyleSheet(QStringLiteral("color:#333;"));
    lv->addWidget(m_hover);
    m_selection = new QLabel(left);
    lv->addWidget(m_selection);
    auto* selBar = new QHBoxLayout;
    m_useSelection = new QPushButton(tr("Use for this step"), left);
    m_useSelection->setToolTip(tr("Set the selected step's wells (and plate) to the selection"));
    m_aspirateSel = new QPushButton(tr("Aspirate from these"), left);
    m_dispenseSel = new QPushButton(tr("Dispense into these"), left);
    auto* clear = new QPushButton(tr("Clear"), left);
    for (auto* b : {m_useSelection, m_aspirateSel, m_dispenseSel, clear})
        selBar->addWidget(b);
    selBar->addStretch();
    lv->addLayout(selBar);

    m_tabs = new QTabWidget(split);
    m_editor = new RecipeEditor(m_tabs);
    m_calibration = new CalibrationPanel(analyzer, m_tabs);
    m_run = new RunPanel(m_runner, m_tabs);
    // Each tab scrolls rather than making the window taller than a laptop's display
    // (the editor's step form alone is taller than some screens leave room for).
    auto scrolled = [this](QWidget* page) {
        auto* area = new QScrollArea(m_tabs);
        area->setWidgetResizable(true);
        area->setFrameShape(QFrame::NoFrame);
        area->setWidget(page);
        return area;
    };
    m_tabs->addTab(scrolled(m_editor), tr("Recipe"));
    m_tabs->addTab(scrolled(m_calibration), tr("Calibrate"));
    m_tabs->addTab(scrolled(m_run), tr("Run"));
    split->addWidget(left);
    split->addWidget(m_tabs);
    // Even halves: at 3:2 the recipe tab got about 400 px at 1366 and cut its own table
    // and buttons, while the plate map draws to scale in whatever room it has.
    split->setStretchFactor(0, 1);
    split->setStretchFactor(1, 1);
    auto* v = new QVBoxLayout(this);
    v->setContentsMargins(0, 0, 0, 0);
    v->addWidget(split);

    m_editor->setDeck(m_deck);
    m_calibration->setDeck(m_deck);

    connect(m_plate, qOverload<int>(&QComboBox::activated), this, [this] { refreshMap(); });
    connect(m_map, &PlateMap::hovered, this, [this](const QString& t) { m_hover->setText(t); });
    connect(m_map, &PlateMap::selectionChanged, this, [this] {
        const auto specs = motion::plates::describeWells(std::vector<motion::plates::WellId>(m_map->selection().begin(), m_map->selection().end()));
        QStringList parts;
        for (const auto& s : specs)
            parts << QString::fromStdString(s);
        m_selection->setText(m_map->selection().empty() ? tr("Click a well or drag across wells to select them (Ctrl adds).")
                                                        : tr("%1 wells selected: %2").arg(m_map->selection().size()).arg(parts.join(QStringLiteral(", "))));
        const bool any = !m_map->selection().empty();
        m_useSelection->setEnabled(any && m_editor->currentStep() >= 0);
        m_aspirateSel->setEnabled(any);
        m_dispenseSel->setEnabled(any);
    });
    connect(m_useSelection, &QPushButton::clicked, this, [this] { selectionToStep(0); });
    connect(m_aspirateSel, &QPushButton::clicked, this, [this] { selectionToStep(1); });
    connect(m_dispenseSel, &QPushButton::clicked, this, [this] { selectionToStep(2); });
    connect(clear, &QPushButton::clicked, m_map, &PlateMap::clearSelection);
    connect(m_editor, &RecipeEditor::recipeChanged, this, &PlatesScreen::revalidate);
    connect(m_editor, &RecipeEditor::currentStepChanged, this, [this] { emit m_map->selectionChanged(); });
    connect(m_editor, &RecipeEditor::newRequested, this, [this] {
        if (heldForRun())
            return;
        if (m_editor->isModified() && m_confirm && !m_confirm(tr("Discard the changes to this recipe?")))
            return;
        newRecipe();
    });
    connect(m_editor, &RecipeEditor::openRequested, this, [this] {
        if (heldForRun())
            return;
        if (m_editor->isModified() && m_confirm && !m_confirm(tr("Discard the changes to this recipe?")))
            return;
        const QString path = m_choose ? m_choose(tr("Open recipe"), tr("Recipes (*.recipe.json *.json)"), false) : QString();
        if (!path.isEmpty())
            openRecipe(path);
    });
    auto saveAs = [this] {
        const QString path = m_choose ? m_choose(tr("Save recipe"), tr("Recipes (*.recipe.json)"), true) : QString();
        if (!path.isEmpty())
            saveRecipe(path);
    };
    connect(m_editor, &RecipeEditor::saveRequested, this, [this, saveAs] {
        if (m_editor->path().isEmpty())
            saveAs();
        else
            saveRecipe(m_editor->path());
    });
    connect(m_editor, &RecipeEditor::saveAsRequested, this, saveAs);
    connect(m_editor, &RecipeEditor::importLabwareRequested, this, &PlatesScreen::importLabware);
    connect(m_calibration, &CalibrationPanel::calibrationsChanged, this, [this] {
        m_calibrations = m_calibration->calibrations();
        saveCalibrations();
        revalidate();
    });
    connect(m_calibration, &CalibrationPanel::problem, this, &PlatesScreen::problem);
    // The plan's times follow the analyzer's reported limits (dev::jobs::deckWithDeviceMotion).
    connect(m_client, &dev::Instrument::identified, this, [this] {
        if (m_runner->state() == dev::jobs::RunState::Idle || m_runner->state() == dev::jobs::RunState::Finished)
            revalidate();
    });
    connect(m_run, &RunPanel::runRequested, this, [this] { runRecipe(); });
    connect(m_run, &RunPanel::resumeFromLogRequested, this, &PlatesScreen::resumeFromLog);
    connect(m_run, &RunPanel::problem, this, &PlatesScreen::problem);
    connect(m_runner, &dev::jobs::RecipeRunner::progressChanged, this, &PlatesScreen::refreshMap);
    connect(m_runner, &dev::jobs::RecipeRunner::stateChanged, this, [this] {
        m_editor->setFilesHeld(runHoldsFiles(), tr("Held while a run is under way: the recipe that runs stays the recipe on screen"));
    });
    connect(m_runner, &dev::jobs::RecipeRunner::message, this, [this](const motion::msg::Message& m, bool isProblem) {
        if (isProblem)
            emit problem(ui::words::text(m));
        else
            emit note(ui::words::text(m));
    });
    m_logDir = QDir::tempPath();
    newRecipe();
}

void PlatesScreen::setConfirm(Confirm c)
{
    m_confirm = c;
    m_run->setConfirm(c);
    m_calibration->setConfirm(std::move(c));
}

void PlatesScreen::setInterruptedDecider(dev::jobs::InterruptedDecider d)
{
    m_decide = d;
    m_run->setInterruptedDecider(std::move(d));
}

void PlatesScreen::setCalibrationFile(const QString& path)
{
    m_calibrationFile = path;
    m_calibrations.clear();
    std::string text;
    motion::msg::Message error;
    if (QFileInfo::exists(path)) {
        if (!dev::files::readText(path, &text, &error)) {
            emit problem(ui::words::text(error));
        } else {
            const dev::files::plates::CalibrationRead r = dev::files::plates::parseCalibration(text);
            if (!r.ok())
                emit problem(tr("the slot calibration %1 cannot be read; the slots use their nominal places:\n%2")
                                 .arg(path, ui::words::fileProblems(r.problems, QFileInfo(path).fileName()).join(QLatin1Char('\n'))));
            else
                m_calibrations = r.calibrations;
        }
    }
    m_calibration->setCalibrations(m_calibrations);
    revalidate();
}

void PlatesScreen::saveCalibrations()
{
    if (m_calibrationFile.isEmpty())
        return;
    QDir().mkpath(QFileInfo(m_calibrationFile).absolutePath());
    motion::msg::Message error;
    if (!dev::files::writeAtomically(m_calibrationFile, dev::files::plates::writeCalibration(m_deck.id, m_calibrations), &error))
        emit problem(ui::words::text(error));
    else
        emit note(tr("slot calibration saved to %1").arg(m_calibrationFile));
}

void PlatesScreen::newRecipe()
{
    motion::plates::Recipe r;
    r.name = tr("new recipe").toStdString();
    r.plates = {{tr("samples", "the name of a new recipe's plate").toStdString(), m_deck.plateSlots.empty() ? "1" : m_deck.plateSlots.front().id, "sbs-96", 55, 70}};
    m_filePlaces.clear();
    m_editor->setRecipe(r, QString());
    refreshPlateChoices();
}

QString PlatesScreen::recipePath() const { return m_editor->path(); }

QString PlatesScreen::baseDir() const
{
    return m_editor->path().isEmpty() ? QDir::currentPath() : QFileInfo(m_editor->path()).absolutePath();
}

bool PlatesScreen::runHoldsFiles() const
{
    const dev::jobs::RunState s = m_runner->state();
    return s == dev::jobs::RunState::Running || s == dev::jobs::RunState::Pausing || s == dev::jobs::RunState::Paused || s == dev::jobs::RunState::Aborting;
}

bool PlatesScreen::heldForRun()
{
    // Like the Scan screen: the recipe that runs stays the recipe on screen.
    if (!runHoldsFiles())
        return false;
    emit problem(tr("A run is under way: the recipe and plate map stay as they are until it has finished or been aborted."));
    return true;
}

bool PlatesScreen::openRecipe(const QString& path)
{
    if (heldForRun())
        return false;
    const dev::files::plates::LoadedRecipe l = dev::files::plates::loadRecipe(path, m_deck, m_calibrations);
    if (!l.readable) {
        // Every problem goes to the Problems pane with its line and column; the banner
        // only says so, as a banner cuts a list of them after its first line.
        const QString name = QFileInfo(path).fileName();
        m_editor->showProblems(l.problems, name);
        emit problem(tr("%1 was not opened: its problems are listed under Problems").arg(name));
        return false;
    }
    m_filePlaces = l.problems;
    m_fileRecipe = dev::files::plates::writeRecipe(l.recipe);
    m_editor->setRecipe(l.recipe, path);
    refreshPlateChoices();
    emit note(tr("opened %1").arg(path));
    emit recipePathChanged(path);
    return true;
}

bool PlatesScreen::saveRecipe(const QString& path)
{
    motion::msg::Message error;
    if (!dev::files::writeAtomically(path, dev::files::plates::writeRecipe(m_editor->recipe()), &error)) {
        emit problem(ui::words::text(error));
        return false;
    }
    m_filePlaces.clear();  // written anew: its lines are not the ones read
    m_editor->markSaved(path);
    emit note(tr("saved %1").arg(path));
    emit recipePathChanged(path);
    return true;
}

motion::plates::PlanContext PlatesScreen::context(motion::msg::Problems* problems) const
{
    motion::msg::Problems found;
    motion::plates::PlanContext c;
    // Times follow the analyzer's own planner limits once it has reported them.
    c.deck = dev::jobs::deckWithDeviceMotion(m_deck, m_client->identity());
    c.calibration = dev::files::plates::calibrationTransforms(m_calibrations);
    dev::files::plates::resolveLabware(m_editor->recipe(), baseDir(), c, &found);
    if (problems)
        problems->insert(problems->end(), found.begin(), found.end());
    return c;
}

void PlatesScreen::revalidate()
{
    motion::msg::Problems problems;
    m_context = context(&problems);
    const motion::plates::PlanContext& c = m_context;
    m_plan = motion::plates::planRecipe(m_editor->recipe(), c);
    // The file's lines and columns hold while the recipe on screen is still the file (an
    // edit reaches here before the undo stack counts it, so the recipe itself is compared).
    const bool asRead = !m_filePlaces.empty() && dev::files::plates::writeRecipe(m_editor->recipe()) == m_fileRecipe;
    for (motion::msg::Problem p : m_plan.problems) {
        if (asRead)
            for (const motion::msg::Problem& placed : m_filePlaces)
                if (placed.path == p.path && placed.message == p.message) {
                    p.file = placed.file;
                    p.line = placed.line;
                    p.column = placed.column;
                    break;
                }
        problems.push_back(std::move(p));
    }
    m_editor->showProblems(problems);
    QStringList errors;
    for (const motion::msg::Problem& p : problems)
        if (p.isError())
            errors << ui::words::problem(p);
    m_planOk = errors.isEmpty() && m_plan.ok() && !m_plan.ops.empty();
    m_run->setPlan(m_plan, m_planOk, errors.isEmpty() ? (m_plan.ops.empty() ? tr("the recipe has no steps") : QString()) : errors.first());
    refreshPlateChoices();

    // The calibration wizard teaches on what the recipe puts in each slot.
    std::map<std::string, motion::plates::Labware> bySlot;
    std::map<std::string, double> safeZ;
    for (const auto& p : m_editor->recipe().plates) {
        const auto lw = c.labware.find(p.labware);
        if (lw != c.labware.end()) {
            bySlot[p.slot] = lw->second;
            safeZ[p.slot] = p.safeZMm;
        }
    }
    m_calibration->setSlotLabware(bySlot, safeZ);
}

void PlatesScreen::refreshPlateChoices()
{
    const QString keep = m_plate->currentText();
    m_plate->clear();
    for (const auto& p : m_editor->recipe().plates)
        m_plate->addItem(QString::fromStdString(p.name));
    const int i = m_plate->findText(keep);
    m_plate->setCurrentIndex(i >= 0 ? i : 0);
    refreshMap();
}

void PlatesScreen::showPlate(const QString& plateName)
{
    const int i = m_plate->findText(plateName);
    if (i >= 0) {
        m_plate->setCurrentIndex(i);
        refreshMap();
    }
}

void PlatesScreen::showTab(const QString& name)
{
    const QStringList tabs = {QStringLiteral("recipe"), QStringLiteral("calibrate"), QStringLiteral("run")};
    if (tabs.contains(name))
        m_tabs->setCurrentIndex(tabs.indexOf(name));
}

void PlatesScreen::changeEvent(QEvent* event)
{
    QWidget::changeEvent(event);
    if (event->type() == QEvent::LanguageChange)
        refreshMap();
}

void PlatesScreen::refreshMap()
{
    const std::string name = m_plate->currentText().toStdString();
    const motion::plates::RecipePlate* p = m_editor->recipe().plate(name);
    const motion::plates::PlanContext& c = m_context;
    const auto lw = p ? c.labware.find(p->labware) : c.labware.end();
    if (!p || lw == c.labware.end()) {
        if (!m_map->labware().wells.empty())
            m_map->setLabware({}, QString());
        return;
    }
    const QString title = tr("%1 in slot %2: %3")
                              .arg(QString::fromStdString(p->name), QString::fromStdString(p->slot), ui::words::shippedName(lw->second.displayName));
    if (m_map->labware().id != lw->second.id || m_map->labware().wells.size() != lw->second.wells.size())
        m_map->setLabware(lw->second, title);
    m_map->setTitle(title);
    m_map->setTransform(c.transform(p->slot), c.calibration.count(p->slot) > 0);
    QMap<QString, PlateMap::WellState> states;
    QMap<QString, double> volumes;
    for (const auto& w : m_plan.wells)
        if (w.plate == name)
            volumes[QString::fromStdString(w.well)] = w.dispensedUl - w.aspiratedUl;
    const auto& opStates = m_runner->opStates();
    const bool sameRun = opStates.size() == m_plan.ops.size() && m_runner->plan().fingerprint == m_plan.fingerprint;
    const dev::jobs::RunProgress pr = m_runner->progress();
    for (const auto& op : m_plan.ops) {
        if (op.plate != name || op.well.empty())
            continue;
        const QString well = QString::fromStdString(op.well);
        PlateMap::WellState st = PlateMap::WellState::Planned;
        if (sameRun) {
            const auto s = opStates[static_cast<std::size_t>(op.index)];
            if (s == dev::files::plates::OpState::Done || s == dev::files::plates::OpState::Skipped)
                st = PlateMap::WellState::Done;
            if (op.index == pr.currentOp && m_runner->state() != dev::jobs::RunState::Idle && m_runner->state() != dev::jobs::RunState::Finished)
                st = m_runner->state() == dev::jobs::RunState::Stopped ? PlateMap::WellState::Error : PlateMap::WellState::Current;
        }
        // A well visited several times shows its least finished visit.
        const auto prev = states.constFind(well);
        if (prev == states.constEnd() || *prev == PlateMap::WellState::Done || st == PlateMap::WellState::Current || st == PlateMap::WellState::Error)
            states[well] = st;
    }
    m_map->setWellStates(states);
    m_map->setVolumes(volumes);
}

void PlatesScreen::selectionToStep(int mode)
{
    std::vector<motion::plates::WellId> wells(m_map->selection().begin(), m_map->selection().end());
    if (wells.empty())
        return;
    const std::vector<std::string> specs = {[&] {
        std::string joined;
        for (const auto& s : motion::plates::describeWells(wells))
            joined += (joined.empty() ? "" : ", ") + s;
        return joined;
    }()};
    const std::string plate = m_editor->recipe().plates.size() > 1 ? m_plate->currentText().toStdString() : std::string();
    if (mode == 0) {
        const int i = m_editor->currentStep();
        if (i < 0)
            return;
        m_editor->edit(tr("use the selection in step %1").arg(i + 1), [i, specs, plate](motion::plates::Recipe& r) {
            auto& s = r.steps[static_cast<std::size_t>(i)];
            s.wells = specs;
            s.station.clear();
            if (!plate.empty())
                s.plate = plate;
        });
        return;
    }
    motion::plates::Step s;
    s.type = mode == 1 ? motion::plates::StepType::Aspirate : motion::plates::StepType::Dispense;
    s.wells = specs;
    s.plate = plate;
    s.volumeUl = 10;
    const int at = m_editor->currentStep() + 1;
    m_editor->edit(mode == 1 ? tr("aspirate from the selection") : tr("dispense into the selection"), [at, s](motion::plates::Recipe& r) {
        r.steps.insert(r.steps.begin() + std::min<std::size_t>(static_cast<std::size_t>(at), r.steps.size()), s);
    });
    m_editor->setCurrentStep(at);
}

bool PlatesScreen::runRecipe()
{
    if (!m_planOk) {
        emit problem(tr("the recipe does not validate: see its problems"));
        return false;
    }
    const auto& st = m_client->status();
    motion::plates::StartState start;
    if (st.axes.size() >= 4)
        start = {st.axes[0].commanded, st.axes[1].commanded, st.axes[2].commanded, st.axes[3].commanded};
    const motion::plates::RecipePlan plan = motion::plates::planRecipe(m_editor->recipe(), m_context, start);
    motion::msg::Message error;
    const QString name = QString::fromStdString(m_editor->recipe().name.empty() ? "recipe" : m_editor->recipe().name);
    if (!m_runner->setPlan(plan, name, &error)) {
        emit problem(ui::words::text(error));
        return false;
    }
    double deepest = 0;
    for (const auto& p : m_editor->recipe().plates)
        deepest = std::max(deepest, p.depthZMm);
    // Operations, not wells: a recipe that washes, mixes and dispenses counts more of them
    // than it visits wells (the dialog had said "47 wells" of a plan over 30).
    if (m_confirm
        && !m_confirm(tr("Run \"%1\": %2 operations over %3 wells, about %4. The tip goes down to Z %5 mm; the analyzer moves on its "
                         "own until the end (Pause, Abort, or Esc for the E-stop). Start?")
                          .arg(name)
                          .arg(plan.ops.size())
                          .arg(plan.wellsVisited())
                          .arg(ui::words::duration(plan.totalTimeS))
                          .arg(deepest)))
        return false;
    QDir().mkpath(m_logDir);
    const QString log = QDir(m_logDir).filePath(runLogName(name, QDateTime::currentDateTime()));
    if (!m_runner->start(log, &error)) {
        emit problem(ui::words::text(error));
        return false;
    }
    showTab(QStringLiteral("run"));
    return true;
}

void PlatesScreen::resumeFromLog()
{
    const QString path = m_choose ? m_choose(tr("Resume from run log"), tr("Run logs (*.run.jsonl *.jsonl)"), false) : QString();
    if (path.isEmpty())
        return;
    const motion::plates::RecipePlan plan = motion::plates::planRecipe(m_editor->recipe(), m_context, dev::jobs::RecipeRunner::resumeStart(path, *m_client));
    motion::msg::Message error;
    if (!m_runner->setPlan(plan, QString::fromStdString(m_editor->recipe().name), &error) || !m_runner->resumeFromLog(path, m_decide, &error)) {
        emit problem(ui::words::text(error));
        return;
    }
    showTab(QStringLiteral("run"));
}

void PlatesScreen::importLabware()
{
    if (heldForRun())
        return;
    const QString from = m_choose ? m_choose(tr("Import labware"), tr("Labware definitions (*.json)"), false) : QString();
    if (from.isEmpty())
        return;
    std::string text;
    motion::msg::Message error;
    if (!dev::files::readText(from, &text, &error)) {
        emit problem(ui::words::text(error));
        return;
    }
    const dev::files::plates::LabwareRead r = dev::files::plates::parseLabware(text);
    if (!r.labware) {
        emit problem(tr("%1 is not a plate definition BenchPilot can use:\n%2")
                         .arg(QFileInfo(from).fileName(), ui::words::fileProblems(r.problems, QFileInfo(from).fileName()).join(QLatin1Char('\n'))));
        return;
    }
    const QString to = QDir(baseDir()).filePath(QString::fromStdString(r.labware->id) + QStringLiteral(".labware.json"));
    if (!dev::files::writeAtomically(to, dev::files::plates::writeLabware(*r.labware), &error)) {
        emit problem(ui::words::text(error));
        return;
    }
    const std::string ref = m_editor->path().isEmpty() ? to.toStdString() : QFileInfo(to).fileName().toStdString();
    const std::string plate = m_plate->currentText().toStdString();
    m_editor->edit(tr("use imported labware %1").arg(QString::fromStdString(r.labware->id)), [plate, ref](motion::plates::Recipe& rec) {
        for (auto& p : rec.plates)
            if (p.name == plate)
                p.labware = ref;
    });
    emit note(tr("imported %1 (%2 wells) as %3").arg(QString::fromStdString(r.labware->displayName)).arg(r.labware->wells.size()).arg(to));
}

QString PlatesScreen::runLogName(const QString& recipeName, const QDateTime& when)
{
    // Letters and digits of any script stay (a Chinese name reads as itself); a name that
    // would start with '-' would read as an option to the tools people open logs with.
    QString stem = recipeName;
    stem.replace(QRegularExpression(QStringLiteral("[^\\p{L}\\p{N}_.]+")), QStringLiteral("-"));
    stem.remove(QRegularExpression(QStringLiteral("^[-.]+|-+$")));
    if (stem.isEmpty())
        stem = QStringLiteral("recipe");
    return QStringLiteral("%1-%2.run.jsonl").arg(stem, when.toString(QStringLiteral("yyyyMMdd-HHmmss-zzz")));
}

} // namespace ui
