#pragma once
// Running a recipe: the plan (the dry run: every well with its place, plunger
// move and time, the totals), Run / Pause / Resume / Abort, progress with the
// current well, elapsed time and ETA, and what the run said along the way.
#include "device/jobs/recipe_runner.h"

#include <QWidget>

#include <functional>

class QLabel;
class QListWidget;
class QListWidgetItem;
class QProgressBar;
class QPushButton;
class QTableWidget;

namespace ui {

class RunPanel : public QWidget {
    Q_OBJECT
public:
    explicit RunPanel(dev::jobs::RecipeRunner* runner, QWidget* parent = nullptr);
    void setInterruptedDecider(dev::jobs::InterruptedDecider decide) { m_decide = std::move(decide); }
    /// Asked before Abort (a destructive action, widgets/common/confirmation.h); none: Abort at once.
    void setConfirm(std::function<bool(const QString&)> confirm) { m_confirm = std::move(confirm); }
    /// The plan to show; `runnable` false (with `why`) disables Run.
    void setPlan(const motion::plates::RecipePlan& plan, bool runnable, const QString& why);

    /// "2 min 53 s", "48 s", "1 h 05 min".
    /// Rows of the plan table at most (the totals cover every well).
    static constexpr int kMaxPlanRows = 5000;

signals:
    void runRequested();
    void resumeFromLogRequested();
    void problem(const QString& message);

protected:
    void changeEvent(QEvent* event) override;

private:
    void refresh();
    /// Words a message line from what it keeps (its time and message), in the language shown.
    static void wordLine(QListWidgetItem* item);

    dev::jobs::RecipeRunner* m_runner;
    dev::jobs::InterruptedDecider m_decide;
    std::function<bool(const QString&)> m_confirm;
    bool m_runnable = false;
    QLabel* m_summary;
    QTableWidget* m_table;
    int m_planOps = 0;  ///< the plan on screen, before a run has one
    QPushButton* m_run;
    QPushButton* m_pause;
    QPushButton* m_resume;
    QPushButton* m_abort;
    QPushButton* m_fromLog;
    QProgressBar* m_progress;
    QLabel* m_current;
    QLabel* m_times;
    QLabel* m_state;
    QListWidget* m_messages;
};

} // namespace ui
