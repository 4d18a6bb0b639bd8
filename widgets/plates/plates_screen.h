#pragma once
// The Plates screen ("plates" in the navigation): the plate map of the recipe's
// plates, the recipe editor, the calibration wizard and the run controls, on
// the analyzer. Dialogs (files, confirmations, the decision about a well
// interrupted mid-dispense) come in as callbacks from app/.
#include "device/client/instrument.h"
#include "device/jobs/recipe_runner.h"
#include "motion/plans/plates/calibration.h"
#include "motion/plans/recipes/recipe_plan.h"

#include <QDateTime>
#include <QWidget>

#include <functional>

class QComboBox;
class QLabel;
class QPushButton;
class QTabWidget;

namespace ui {

class CalibrationPanel;
class PlateMap;
class RecipeEditor;
class RunPanel;

class PlatesScreen : public QWidget {
    Q_OBJECT
public:
    using Confirm = std::function<bool(const QString& question)>;
    /// Asks for a file: `save` true for a name to write. "" = cancelled.
    using FileChooser = std::function<QString(const QString& title, const QString& filter, bool save)>;

    explicit PlatesScreen(dev::Instrument* analyzer, QWidget* parent = nullptr);

    void setConfirm(Confirm c);
    void setFileChooser(FileChooser f) { m_choose = std::move(f); }
    void setInterruptedDecider(dev::jobs::InterruptedDecider d);
    /// Where the slots' calibration is kept between runs (read now, written on every change).
    void setCalibrationFile(const QString& path);
    /// Where run logs go.
    void setRunLogDirectory(const QString& dir) { m_logDir = dir; }
    /// The file name a run of `recipeName` started at `when` logs to.
    static QString runLogName(const QString& recipeName, const QDateTime& when);

    bool openRecipe(const QString& path);
    bool saveRecipe(const QString& path);
    void newRecipe();
    QString recipePath() const;
    /// Starts a run of the recipe as it is (asks first when a confirm is set); false with a message.
    bool runRecipe();

    const motion::plates::RecipePlan& plan() const { return m_plan; }
    PlateMap* plateMap() const { return m_map; }
    RecipeEditor* recipeEditor() const { return m_editor; }
    CalibrationPanel* calibrationPanel() const { return m_calibration; }
    RunPanel* runPanel() const { return m_run; }
    dev::jobs::RecipeRunner* runner() const { return m_runner; }
    void showPlate(const QString& plateName);
    /// The tab to show: "recipe", "calibrate", "run".
    void showTab(const QString& name);

    /// A run under way (or paused) holds the recipe and its files: nothing replaces them.
    bool runHoldsFiles() const;

signals:
    void problem(const QString& message);
    void note(const QString& message);
    /// A recipe was opened or saved here (for remembering it between runs).
    void recipePathChanged(const QString& path);

protected:
    /// The plate's title under the map names built-in labware in the language shown.
    void changeEvent(QEvent* event) override;

private:
    /// True (with a problem said) when a run holds the files.
    bool heldForRun();
    void revalidate();
    void refreshPlateChoices();
    void refreshMap();
    void selectionToStep(int mode);
    void importLabware();
    void resumeFromLog();
    void saveCalibrations();
    motion::plates::PlanContext context(motion::msg::Problems* problems) const;
    QString baseDir() const;

    dev::Instrument* m_client;
    dev::jobs::RecipeRunner* m_runner;
    Confirm m_confirm;
    FileChooser m_choose;
    dev::jobs::InterruptedDecider m_decide;
    motion::plates::Deck m_deck;
    std::vector<motion::plates::SlotCalibration> m_calibrations;
    QString m_calibrationFile, m_logDir;
    motion::plates::RecipePlan m_plan;
    motion::plates::PlanContext m_context;  ///< of the last validation: labware files are read once per change, not per well
    bool m_planOk = false;
    /// The opened file's problems with their lines and columns, lent to the plan's own
    /// while the recipe on screen is still exactly that file.
    motion::msg::Problems m_filePlaces;
    std::string m_fileRecipe;  ///< that file's recipe as writeRecipe writes it
    PlateMap* m_map;
    QComboBox* m_plate;
    QLabel* m_hover;
    QLabel* m_selection;
    QPushButton* m_useSelection;
    QPushButton* m_aspirateSel;
    QPushButton* m_dispenseSel;
    QTabWidget* m_tabs;
    RecipeEditor* m_editor;
    CalibrationPanel* m_calibration;
    RunPanel* m_run;
};

} // namespace ui
