#include "widgets/plates/recipe_editor.h"
#include "widgets/common/button_key.h"
#include "widgets/plates/step_texts.h"

#include "widgets/plates/step_form.h"

#include "motion/plans/plates/labware.h"

#include <QComboBox>
#include "widgets/common/number_field.h"
#include "widgets/wording/wording.h"

#include <QEvent>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMenu>
#include <QPushButton>
#include <QSignalBlocker>
#include <QStyle>
#include <QTableWidget>
#include <QToolButton>
#include <QUndoCommand>
#include <QUndoStack>
#include <QVBoxLayout>

namespace ui {

namespace {

/// A change of the recipe, kept as the whole recipe before and after: recipes
/// are small, and a snapshot can never be undone wrongly.
class RecipeCommand : public QUndoCommand {
public:
    RecipeCommand(RecipeEditor* editor, motion::plates::Recipe before, motion::plates::Recipe after, const QString& text, int mergeId)
        : QUndoCommand(text), m_editor(editor), m_before(std::move(before)), m_after(std::move(after)), m_id(mergeId)
    {
    }
    void undo() override { m_editor->apply(m_before); }
    void redo() override { m_editor->apply(m_after); }
    int id() const override { return m_id; }
    bool mergeWith(const QUndoCommand* other) override
    {
        m_after = static_cast<const RecipeCommand*>(other)->m_after;
        return true;
    }

private:
    RecipeEditor* m_editor;
    motion::plates::Recipe m_before, m_after;
    int m_id;
};

/// Merge ids: a field of a step, or of a plate, typed into several times.
int mergeIdFor(int kind, int index, const QString& field) { return (kind << 24) ^ (index << 12) ^ static_cast<int>(qHash(field) & 0xFFF); }

QToolButton* toolButton(const QString& text, const QString& tip, QWidget* parent)
{
    auto* b = new QToolButton(parent);
    b->setText(text);
    b->setToolTip(tip);
    b->setToolButtonStyle(Qt::ToolButtonTextOnly);
    return b;
}

} // namespace

RecipeEditor::RecipeEditor(QWidget* parent) : QWidget(parent), m_undo(new QUndoStack(this))
{
    auto* v = new QVBoxLayout(this);
    auto* bar = new QHBoxLayout;
    auto* newB = toolButton(tr("New"), tr("A new recipe with one 96-well plate in slot 1"), this);
    auto* openB = toolButton(tr("Open…"), tr("Open a recipe file (Ctrl+O)"), this);
    auto* saveB = toolButton(tr("Save"), tr("Save the recipe (Ctrl+S)"), this);
    auto* saveAsB = toolButton(tr("Save as…"), tr("Save the recipe under another name"), this);
    auto* undoB = toolButton(tr("Undo"), tr("Undo the last change (Ctrl+Z)"), this);
    auto* redoB = toolButton(tr("Redo"), tr("Redo (Ctrl+Shift+Z)"), this);
    setButtonKey(openB, QKeySequence::Open);
    setButtonKey(saveB, QKeySequence::Save);
    setButtonKey(undoB, QKeySequence::Undo);
    setButtonKey(redoB, QKeySequence::Redo);
    // Two rows, so the panel fits the narrow tab it gets at 1366 px in every language:
    // the file and undo buttons, then the name with the whole width to show it.
    for (auto* b : {newB, openB, saveB, saveAsB})
        bar->addWidget(b);
    bar->addStretch();
    bar->addWidget(undoB);
    bar->addWidget(redoB);
    v->addLayout(bar);
    auto* nameRow = new QHBoxLayout;
    nameRow->addWidget(new QLabel(tr("Name"), this));
    m_name = new QLineEdit(this);
    nameRow->addWidget(m_name, 1);
    v->addLayout(nameRow);

    auto* platesBox = new QGroupBox(tr("Plates on the deck"), this);
    auto* pv = new QVBoxLayout(platesBox);
    m_plates = new QTableWidget(0, 5, platesBox);
    m_plates->setHorizontalHeaderLabels({tr("Name"), tr("Slot"), tr("Labware"), tr("Safe Z (mm)"), tr("Depth Z (mm)")});
    // The heights are as wide as their headers (a height's value is shorter); names, slots
    // and labware share the rest (all five stretched, "Depth Z (mm)" was cut at 1366 px).
    QHeaderView* header = m_plates->horizontalHeader();
    const int headerMargin = 2 * header->style()->pixelMetric(QStyle::PM_HeaderMargin, nullptr, header) + 4;
    for (int col = 0; col < m_plates->columnCount(); ++col) {
        const QString text = m_plates->horizontalHeaderItem(col)->text();
        m_plates->horizontalHeaderItem(col)->setToolTip(text);
        if (col < 3) {
            header->setSectionResizeMode(col, QHeaderView::Stretch);
        } else {
            header->setSectionResizeMode(col, QHeaderView::Fixed);
            header->resizeSection(col, header->fontMetrics().horizontalAdvance(text) + headerMargin);
        }
    }
    m_plates->verticalHeader()->setVisible(false);
    m_plates->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_plates->setMaximumHeight(120);
    pv->addWidget(m_plates);
    auto* pbar = new QHBoxLayout;
    auto* addPlate = new QPushButton(tr("Add plate"), platesBox);
    auto* removePlate = new QPushButton(tr("Remove plate"), platesBox);
    auto* importB = new QPushButton(tr("Import Opentrons labware…"), platesBox);
    importB->setToolTip(tr("Read an Opentrons labware definition (schema 2), save it as a BenchPilot plate file beside the recipe, "
                           "and use it for the selected plate"));
    pbar->addWidget(addPlate);
    pbar->addWidget(removePlate);
    pbar->addStretch();
    pv->addLayout(pbar);
    // A row of its own: beside Add and Remove it was cut to "Import Opentrons labw…".
    auto* ibar = new QHBoxLayout;
    ibar->addWidget(importB);
    ibar->addStretch();
    pv->addLayout(ibar);
    v->addWidget(platesBox);

    auto* stepsBox = new QGroupBox(tr("Steps"), this);
    auto* sv = new QVBoxLayout(stepsBox);
    m_steps = new QListWidget(stepsBox);
    m_steps->setMinimumHeight(120);
    sv->addWidget(m_steps, 2);
    auto* sbar = new QHBoxLayout;
    auto* add = new QToolButton(stepsBox);
    add->setText(tr("Add step"));
    add->setPopupMode(QToolButton::InstantPopup);
    auto* menu = new QMenu(add);
    for (int i = 0; i < motion::plates::kStepTypeCount; ++i) {
        const auto t = static_cast<motion::plates::StepType>(i);
        menu->addAction(stepTypeTitle(t), this, [this, t] { addStep(t); });
    }
    add->setMenu(menu);
    auto* dup = new QPushButton(tr("Duplicate"), stepsBox);
    auto* remove = new QPushButton(tr("Remove"), stepsBox);
    // Tool buttons: an arrow needs no push button's minimum width (the "▼" was cut).
    auto* up = new QToolButton(stepsBox);
    auto* down = new QToolButton(stepsBox);
    up->setText(tr("▲"));
    down->setText(tr("▼"));
    up->setToolTip(tr("Move the step up"));
    down->setToolTip(tr("Move the step down"));
    for (QWidget* w : {static_cast<QWidget*>(add), static_cast<QWidget*>(dup), static_cast<QWidget*>(remove), static_cast<QWidget*>(up),
                       static_cast<QWidget*>(down)})
        sbar->addWidget(w);
    sbar->addStretch();
    sv->addLayout(sbar);
    m_form = new StepForm(stepsBox);
    sv->addWidget(m_form);
    v->addWidget(stepsBox, 3);

    auto* probBox = new QGroupBox(tr("Problems"), this);
    auto* prv = new QVBoxLayout(probBox);
    m_problems = new QListWidget(probBox);
    m_problems->setMaximumHeight(110);
    m_problems->setWordWrap(true);
    prv->addWidget(m_problems);
    v->addWidget(probBox, 1);

    connect(newB, &QToolButton::clicked, this, &RecipeEditor::newRequested);
    connect(openB, &QToolButton::clicked, this, &RecipeEditor::openRequested);
    connect(saveB, &QToolButton::clicked, this, &RecipeEditor::saveRequested);
    connect(saveAsB, &QToolButton::clicked, this, &RecipeEditor::saveAsRequested);
    connect(importB, &QPushButton::clicked, this, &RecipeEditor::importLabwareRequested);
    for (QAbstractButton* b : std::initializer_list<QAbstractButton*>{newB, openB, importB}) {
        m_fileButtons << b;
        m_fileTips << b->toolTip();
    }
    connect(undoB, &QToolButton::clicked, m_undo, &QUndoStack::undo);
    connect(redoB, &QToolButton::clicked, m_undo, &QUndoStack::redo);
    connect(m_undo, &QUndoStack::canUndoChanged, undoB, &QToolButton::setEnabled);
    connect(m_undo, &QUndoStack::canRedoChanged, redoB, &QToolButton::setEnabled);
    undoB->setEnabled(false);
    redoB->setEnabled(false);
    connect(m_name, &QLineEdit::editingFinished, this, [this] {
        const std::string n = m_name->text().toStdString();
        if (n != m_recipe.name)
            edit(tr("rename the recipe"), [n](motion::plates::Recipe& r) { r.name = n; });
    });
    connect(addPlate, &QPushButton::clicked, this, [this] {
        edit(tr("add a plate"), [this](motion::plates::Recipe& r) {
            std::string slot = m_deck.plateSlots.empty() ? "1" : m_deck.plateSlots.back().id;
            for (const auto& s : m_deck.plateSlots) {
                bool used = false;
                for (const auto& p : r.plates)
                    used = used || p.slot == s.id;
                if (!used) {
                    slot = s.id;
                    break;
                }
            }
            r.plates.push_back({"plate" + std::to_string(r.plates.size() + 1), slot, "sbs-96", 55, 70});
        });
    });
    connect(removePlate, &QPushButton::clicked, this, [this] {
        const int row = m_plates->currentRow();
        if (row < 0 || row >= static_cast<int>(m_recipe.plates.size()))
            return;
        edit(tr("remove plate %1").arg(QString::fromStdString(m_recipe.plates[static_cast<std::size_t>(row)].name)),
             [row](motion::plates::Recipe& r) { r.plates.erase(r.plates.begin() + row); });
    });
    connect(m_steps, &QListWidget::currentRowChanged, this, [this](int row) {
        if (m_updating)
            return;
        m_form->setStep(row >= 0 && row < static_cast<int>(m_recipe.steps.size()) ? m_recipe.steps[static_cast<std::size_t>(row)] : motion::plates::Step{},
                        row);
        emit currentStepChanged(row);
    });
    connect(m_form, &StepForm::edited, this, [this](const motion::plates::Step& s, const QString& field) {
        const int i = currentStep();
        if (i < 0)
            return;
        const bool typing = field == QLatin1String("volume") || field == QLatin1String("speed") || field == QLatin1String("cycles")
            || field == QLatin1String("seconds") || field == QLatin1String("offset");
        edit(tr("change %1 of step %2").arg(field).arg(i + 1), [i, s](motion::plates::Recipe& r) { r.steps[static_cast<std::size_t>(i)] = s; },
             typing ? mergeIdFor(1, i, field) : -1);
    });
    connect(dup, &QPushButton::clicked, this, [this] {
        const int i = currentStep();
        if (i < 0)
            return;
        edit(tr("duplicate step %1").arg(i + 1), [i](motion::plates::Recipe& r) {
            r.steps.insert(r.steps.begin() + i + 1, r.steps[static_cast<std::size_t>(i)]);
        });
        setCurrentStep(i + 1);
    });
    connect(remove, &QPushButton::clicked, this, [this] {
        const int i = currentStep();
        if (i < 0)
            return;
        edit(tr("remove step %1").arg(i + 1), [i](motion::plates::Recipe& r) { r.steps.erase(r.steps.begin() + i); });
        setCurrentStep(std::min(i, static_cast<int>(m_recipe.steps.size()) - 1));
    });
    connect(up, &QToolButton::clicked, this, [this] { moveStep(-1); });
    connect(down, &QToolButton::clicked, this, [this] { moveStep(+1); });
    connect(m_problems, &QListWidget::currentRowChanged, this, [this](int row) {
        if (row >= 0 && row < m_problemSteps.size() && m_problemSteps[row] >= 0)
            setCurrentStep(m_problemSteps[row]);
    });
}

void RecipeEditor::setDeck(const motion::plates::Deck& deck)
{
    m_deck = deck;
    refreshPlates();
    refreshSteps();
}

void RecipeEditor::setRecipe(const motion::plates::Recipe& recipe, const QString& path)
{
    m_path = path;
    m_undo->clear();
    apply(recipe);
    m_undo->setClean();
    setCurrentStep(recipe.steps.empty() ? -1 : 0);
}

bool RecipeEditor::isModified() const { return !m_undo->isClean(); }

void RecipeEditor::markSaved(const QString& path)
{
    m_path = path;
    m_undo->setClean();
}

int RecipeEditor::currentStep() const { return m_steps->currentRow(); }

void RecipeEditor::setCurrentStep(int index)
{
    m_steps->setCurrentRow(index);
    m_form->setStep(index >= 0 && index < static_cast<int>(m_recipe.steps.size()) ? m_recipe.steps[static_cast<std::size_t>(index)]
                                                                                  : motion::plates::Step{},
                    index < static_cast<int>(m_recipe.steps.size()) ? index : -1);
}

void RecipeEditor::edit(const QString& text, const std::function<void(motion::plates::Recipe&)>& change, int mergeId)
{
    motion::plates::Recipe after = m_recipe;
    change(after);
    m_undo->push(new RecipeCommand(this, m_recipe, std::move(after), text, mergeId));
}

void RecipeEditor::apply(const motion::plates::Recipe& r)
{
    m_recipe = r;
    m_updating = true;
    m_name->setText(QString::fromStdString(r.name));
    refreshPlates();
    refreshSteps();
    m_updating = false;
    const int i = currentStep();
    m_form->setStep(i >= 0 && i < static_cast<int>(r.steps.size()) ? r.steps[static_cast<std::size_t>(i)] : motion::plates::Step{},
                    i < static_cast<int>(r.steps.size()) ? i : -1);
    emit recipeChanged();
}

QString RecipeEditor::stepSummary(const motion::plates::Step& s, int index)
{
    QString where;
    if (!s.station.empty())
        where = tr("station %1").arg(QString::fromStdString(s.station));
    else if (!s.wells.empty())
        where = (s.plate.empty() ? QString() : QString::fromStdString(s.plate) + QLatin1Char(' ')) + StepForm::wellsText(s.wells);
    QString text = QStringLiteral("%1. %2").arg(index + 1).arg(stepTypeTitle(s.type));
    switch (s.type) {
    case motion::plates::StepType::Wait: text += tr(" %1 s").arg(s.seconds); break;
    case motion::plates::StepType::TouchOff: text += tr(" %1 mm").arg(s.offsetMm); break;
    case motion::plates::StepType::Mix:
    case motion::plates::StepType::Wash: text += tr(" %1 µL × %2").arg(s.volumeUl).arg(s.cycles); break;
    default: text += tr(" %1 µL").arg(s.volumeUl); break;
    }
    if (!where.isEmpty())
        text += QStringLiteral(" · ") + where;
    if (!s.source.empty())
        text += tr(" ← %1").arg(s.source.station.empty() ? QString::fromStdString(s.source.plate + " " + s.source.well)
                                                          : QString::fromStdString(s.source.station));
    if (!s.note.empty())
        text += QStringLiteral("  — ") + QString::fromStdString(s.note);
    return text;
}

void RecipeEditor::refreshSteps()
{
    const bool was = m_updating;
    m_updating = true;
    const int row = m_steps->currentRow();
    m_steps->clear();
    for (std::size_t i = 0; i < m_recipe.steps.size(); ++i)
        m_steps->addItem(stepSummary(m_recipe.steps[i], static_cast<int>(i)));
    m_steps->setCurrentRow(std::min(row, m_steps->count() - 1));
    QStringList plateNames, stations;
    for (const auto& p : m_recipe.plates)
        plateNames << QString::fromStdString(p.name);
    for (const auto& s : m_deck.stations)
        stations << QString::fromStdString(s.id);
    m_form->setChoices(plateNames, stations);
    m_updating = was;
}

void RecipeEditor::showSlot(QComboBox* slot, const std::string& id)
{
    // A slot the deck does not have (a file's "7") is shown as it is, marked, never as slot 1.
    for (int i = slot->count() - 1; i >= 0; --i)
        if (!slot->itemData(i, kUnknownSlotRole).isNull())
            slot->removeItem(i);
    const int at = slot->findData(QString::fromStdString(id));
    if (at >= 0) {
        slot->setCurrentIndex(at);
        slot->setStyleSheet(QString());
        slot->setToolTip(QString());
        return;
    }
    const QString why = tr("Slot %1 is not on this deck: choose one of its slots").arg(QString::fromStdString(id));
    slot->addItem(tr("%1 (not on this deck)").arg(QString::fromStdString(id)), QString::fromStdString(id));
    slot->setItemData(slot->count() - 1, true, kUnknownSlotRole);
    slot->setCurrentIndex(slot->count() - 1);
    slot->setStyleSheet(QStringLiteral("QComboBox { background: #fdd; border: 1px solid #b00020; }"));
    slot->setToolTip(why);
}

QString RecipeEditor::slotTitle(const motion::plates::Slot& slot)
{
    return QStringLiteral("%1 (%2)").arg(QString::fromStdString(slot.id), ui::words::shippedName(slot.name));
}

void RecipeEditor::showLabware(QComboBox* labware, const std::string& id)
{
    labware->setCurrentText(QString::fromStdString(id));
    // A long file name shows from its start (an editable combo shows its end), whole in the tooltip.
    labware->lineEdit()->setCursorPosition(0);
    labware->setToolTip(QStringLiteral("%1\n%2").arg(
        QString::fromStdString(id),
        tr("A built-in plate, or a labware file beside the recipe (NAME.labware.json, or an Opentrons definition)")));
}

void RecipeEditor::changeEvent(QEvent* event)
{
    QWidget::changeEvent(event);
    if (event->type() == QEvent::LanguageChange)
        refreshPlates();
}

void RecipeEditor::refreshPlates()
{
    const bool was = m_updating;
    m_updating = true;
    const int n = static_cast<int>(m_recipe.plates.size());
    if (n > 0 && m_plates->rowCount() == n && m_plates->cellWidget(0, 0)) {
        // Same rows: update the values in place, so the field being typed into
        // keeps its focus (and is not deleted under its own signal).
        for (int row = 0; row < n; ++row) {
            const motion::plates::RecipePlate& p = m_recipe.plates[static_cast<std::size_t>(row)];
            auto* name = qobject_cast<QLineEdit*>(m_plates->cellWidget(row, 0));
            auto* slot = qobject_cast<QComboBox*>(m_plates->cellWidget(row, 1));
            auto* lw = qobject_cast<QComboBox*>(m_plates->cellWidget(row, 2));
            auto* safe = qobject_cast<NumberField*>(m_plates->cellWidget(row, 3));
            auto* depth = qobject_cast<NumberField*>(m_plates->cellWidget(row, 4));
            const QSignalBlocker b0(name), b1(slot), b2(lw);
            name->setText(QString::fromStdString(p.name));
            for (int i = 0; i < slot->count(); ++i)  // the language may have changed
                for (const auto& s : m_deck.plateSlots)
                    if (slot->itemData(i).toString() == QString::fromStdString(s.id))
                        slot->setItemText(i, slotTitle(s));
            showSlot(slot, p.slot);
            showLabware(lw, p.labware);
            // Only a value that differs: the field being typed into keeps its text.
            if (safe->value() != std::optional<double>(p.safeZMm))
                safe->setValue(p.safeZMm);
            if (depth->value() != std::optional<double>(p.depthZMm))
                depth->setValue(p.depthZMm);
        }
        m_updating = was;
        return;
    }
    m_plates->setRowCount(n);
    for (int row = 0; row < static_cast<int>(m_recipe.plates.size()); ++row) {
        const motion::plates::RecipePlate& p = m_recipe.plates[static_cast<std::size_t>(row)];
        auto* name = new QLineEdit(QString::fromStdString(p.name));
        connect(name, &QLineEdit::editingFinished, this, [this, row, name] {
            const std::string newName = name->text().trimmed().toStdString();
            if (row < static_cast<int>(m_recipe.plates.size()) && newName != m_recipe.plates[static_cast<std::size_t>(row)].name)
                edit(tr("rename a plate"), [row, n = newName](motion::plates::Recipe& r) {
                    // Steps that named the plate follow it.
                    const std::string old = r.plates[static_cast<std::size_t>(row)].name;
                    for (auto& s : r.steps) {
                        if (s.plate == old)
                            s.plate = n;
                        if (s.source.plate == old)
                            s.source.plate = n;
                    }
                    r.plates[static_cast<std::size_t>(row)].name = n;
                });
        });
        m_plates->setCellWidget(row, 0, name);
        auto* slot = new QComboBox;
        for (const auto& s : m_deck.plateSlots)
            slot->addItem(slotTitle(s), QString::fromStdString(s.id));
        showSlot(slot, p.slot);
        connect(slot, qOverload<int>(&QComboBox::activated), this, [this, row, slot] {
            const std::string id = slot->currentData().toString().toStdString();
            if (!slot->currentData(kUnknownSlotRole).isNull())
                return;  // the file's own slot, kept as it is until another is chosen
            edit(tr("move a plate to slot %1").arg(QString::fromStdString(id)),
                 [row, id](motion::plates::Recipe& r) { r.plates[static_cast<std::size_t>(row)].slot = id; });
        });
        m_plates->setCellWidget(row, 1, slot);
        auto* lw = new QComboBox;
        lw->setEditable(true);
        for (const auto& l : motion::plates::builtinLabware())
            lw->addItem(QString::fromStdString(l.id));
        showLabware(lw, p.labware);
        connect(lw, &QComboBox::textActivated, this, [this, row](const QString& text) {
            const std::string id = text.trimmed().toStdString();
            if (row < static_cast<int>(m_recipe.plates.size()) && id != m_recipe.plates[static_cast<std::size_t>(row)].labware)
                edit(tr("change a plate's labware"), [row, id](motion::plates::Recipe& r) { r.plates[static_cast<std::size_t>(row)].labware = id; });
        });
        m_plates->setCellWidget(row, 2, lw);
        for (int col : {3, 4}) {
            // The file's value as it is, even out of range: shown invalid until the
            // operator fixes it, never clamped (a spin box made safe Z −5 into 0).
            auto* z = new NumberField;
            z->setFieldName(col == 3 ? tr("Safe Z") : tr("Depth Z"));
            z->setRange(0.0, m_deck.travelZMm > 0 ? m_deck.travelZMm : 100.0);
            z->setDisplay('g', 10);  // every digit the file has: a rounded display would be written back
            z->setHelp(col == 3 ? tr("Machine Z at which the tip clears this plate (Z counts down from home)")
                                : tr("Machine Z the tip goes down to in a well"));
            z->setValue(col == 3 ? p.safeZMm : p.depthZMm);
            connect(z, &QLineEdit::editingFinished, this, [this, row, col, z] {
                const auto value = z->value();
                if (!value || row >= static_cast<int>(m_recipe.plates.size()))
                    return;  // an invalid entry changes nothing
                const auto& now = m_recipe.plates[static_cast<std::size_t>(row)];
                const double v = *value;
                if (v == (col == 3 ? now.safeZMm : now.depthZMm))
                    return;
                edit(col == 3 ? tr("change a safe height") : tr("change a depth"),
                     [row, col, v](motion::plates::Recipe& r) {
                         auto& pl = r.plates[static_cast<std::size_t>(row)];
                         (col == 3 ? pl.safeZMm : pl.depthZMm) = v;
                     },
                     mergeIdFor(2, row, QString::number(col)));
            });
            m_plates->setCellWidget(row, col, z);
        }
    }
    m_updating = was;
}

void RecipeEditor::addStep(motion::plates::StepType type)
{
    const int at = currentStep() + 1;
    motion::plates::Step s;
    s.type = type;
    switch (type) {
    case motion::plates::StepType::Aspirate:
    case motion::plates::StepType::Dispense: s.volumeUl = 10; s.wells = {"A1"}; break;
    case motion::plates::StepType::Mix: s.volumeUl = 50; s.cycles = 3; s.wells = {"A1"}; break;
    case motion::plates::StepType::Wash:
        s.volumeUl = 200;
        s.cycles = 2;
        s.station = m_deck.stations.empty() ? "" : m_deck.stations.front().id;
        break;
    case motion::plates::StepType::AirGap: s.volumeUl = 5; break;
    case motion::plates::StepType::Wait: s.seconds = 5; break;
    case motion::plates::StepType::TouchOff: s.offsetMm = 1.5; s.wells = {"A1"}; break;
    }
    edit(tr("add step: %1").arg(stepTypeTitle(type)),
         [at, s](motion::plates::Recipe& r) { r.steps.insert(r.steps.begin() + std::min<std::size_t>(static_cast<std::size_t>(at), r.steps.size()), s); });
    setCurrentStep(at);
}

void RecipeEditor::moveStep(int delta)
{
    const int i = currentStep(), j = i + delta;
    if (i < 0 || j < 0 || j >= static_cast<int>(m_recipe.steps.size()))
        return;
    edit(tr("move step %1").arg(i + 1), [i, j](motion::plates::Recipe& r) { std::swap(r.steps[static_cast<std::size_t>(i)], r.steps[static_cast<std::size_t>(j)]); });
    setCurrentStep(j);
}

void RecipeEditor::showProblems(const motion::msg::Problems& problems, const QString& refusedFile)
{
    m_problems->clear();
    m_problemSteps.clear();
    auto row = [this](const QString& text, const QColor& colour, int step) {
        auto* item = new QListWidgetItem(text, m_problems);
        if (colour.isValid())
            item->setForeground(colour);
        m_problemSteps << step;
    };
    if (!refusedFile.isEmpty())
        row(tr("%1 was not opened (the recipe on screen is unchanged):").arg(refusedFile), QColor(0xc6, 0x28, 0x28), -1);
    for (const motion::msg::Severity severity : {motion::msg::Severity::Error, motion::msg::Severity::Warning})
        for (const motion::msg::Problem& p : problems) {
            if (p.severity != severity)
                continue;
            // Only a problem of the recipe on screen points at one of its steps.
            int step = -1;
            if (refusedFile.isEmpty() && p.file.empty() && p.path.rfind("steps[", 0) == 0)
                step = QString::fromStdString(p.path.substr(6)).section(QLatin1Char(']'), 0, 0).toInt();
            row(ui::words::problem(p), p.isError() ? QColor(0xc6, 0x28, 0x28) : QColor(0xb2, 0x6a, 0x00), step);
        }
    if (problems.empty() && refusedFile.isEmpty())
        row(tr("The recipe validates."), QColor(), -1);
}

QStringList RecipeEditor::problemRows() const
{
    QStringList out;
    for (int i = 0; i < m_problems->count(); ++i)
        out << m_problems->item(i)->text();
    return out;
}

void RecipeEditor::setFilesHeld(bool held, const QString& why)
{
    for (int i = 0; i < m_fileButtons.size(); ++i) {
        m_fileButtons[i]->setEnabled(!held);
        m_fileButtons[i]->setToolTip(held ? why : m_fileTips[i]);
    }
}

} // namespace ui
