#pragma once
// The recipe editor: the plates the recipe uses (slot, labware, heights), its
// steps as a list with a form for the one selected, and the problems the plan
// finds, each leading to its step. Every change is one undoable command on a
// QUndoStack (Ctrl+Z / Ctrl+Shift+Z); typing into one field merges into one.
#include "motion/plans/plates/deck.h"
#include "motion/plans/recipes/recipe.h"
#include "motion/problem.h"

#include <QWidget>

#include <functional>

class QAbstractButton;
class QComboBox;
class QLineEdit;
class QListWidget;
class QTableWidget;
class QToolButton;
class QUndoStack;

namespace ui {

class StepForm;

class RecipeEditor : public QWidget {
    Q_OBJECT
public:
    explicit RecipeEditor(QWidget* parent = nullptr);

    void setDeck(const motion::plates::Deck& deck);
    /// Replaces the recipe (after New or Open): the undo history starts afresh.
    void setRecipe(const motion::plates::Recipe& recipe, const QString& path);
    const motion::plates::Recipe& recipe() const { return m_recipe; }
    QString path() const { return m_path; }
    bool isModified() const;
    void markSaved(const QString& path);
    QUndoStack* undoStack() const { return m_undo; }

    int currentStep() const;
    void setCurrentStep(int index);
    /// Lists every problem, errors first, each as ui::words::problem words it (with its file,
    /// line and column where known); selecting one about a step of the recipe on screen
    /// goes to that step. `refusedFile`: these are the problems of a file that was not
    /// opened (the recipe on screen is unchanged), said first.
    void showProblems(const motion::msg::Problems& problems, const QString& refusedFile = {});
    /// What the Problems pane lists, one row each (for tests and the accessibility tree).
    QStringList problemRows() const;

    /// Changes the recipe as one undoable command named `text`. Consecutive
    /// commands with the same non-negative `mergeId` merge into one.
    void edit(const QString& text, const std::function<void(motion::plates::Recipe&)>& change, int mergeId = -1);
    /// Called by the undo commands: shows `r` without making a command.
    void apply(const motion::plates::Recipe& r);

    /// A one-line summary of a step for the list: "2. dispense 50 µL · assay row A ← reagents A1".
    static QString stepSummary(const motion::plates::Step& s, int index);

    /// While held, New, Open… and Import are disabled with `why` as their tooltip.
    void setFilesHeld(bool held, const QString& why);

signals:
    void recipeChanged();
    void currentStepChanged(int index);
    void newRequested();
    void openRequested();
    void saveRequested();
    void saveAsRequested();
    void importLabwareRequested();

protected:
    /// The shipped deck's slot names are worded per language (ui::words::shippedName): the
    /// plate rows are built again.
    void changeEvent(QEvent* event) override;

private:
    static QString slotTitle(const motion::plates::Slot& slot);  ///< "1 (back)", the name in the language shown
    void showLabware(QComboBox* labware, const std::string& id);
    static constexpr int kUnknownSlotRole = Qt::UserRole + 1;  ///< set on a slot item the deck does not have
    void showSlot(QComboBox* slot, const std::string& id);
    void refreshPlates();
    void refreshSteps();
    void addStep(motion::plates::StepType type);
    void moveStep(int delta);

    motion::plates::Recipe m_recipe;
    motion::plates::Deck m_deck;
    QString m_path;
    QUndoStack* m_undo;
    bool m_updating = false;
    QLineEdit* m_name;
    QList<QAbstractButton*> m_fileButtons;  ///< New, Open…, Import: what replaces the recipe
    QStringList m_fileTips;
    QTableWidget* m_plates;
    QListWidget* m_steps;
    StepForm* m_form;
    QListWidget* m_problems;
    QList<int> m_problemSteps;
};

} // namespace ui
