#pragma once
// The Profiles screen: pick a profile kind (seed 000 S-curve, seed 001 trapezoid, seed 003
// exponential, jerk-limited) and its limits, see position, velocity, acceleration and jerk
// against time, the move time, and the seed-001 step-period table the move turns into
// (72 MHz clock, 50 µs interrupt: whole periods + match ticks). Pure motion-library view: it
// needs no instrument, so engineers can try limits before sending them to a machine.
#include <QWidget>

class QComboBox;
class QCustomPlot;
class QFormLayout;
class QLabel;
class QTableView;
class QTimer;

namespace ui {

class NumberField;

class StepTableModel;

class ProfilesScreen : public QWidget {
    Q_OBJECT
public:
    explicit ProfilesScreen(QWidget* parent = nullptr);

    /// Move time of the current plan in s, or a negative value while the inputs are invalid.
    double moveTimeS() const { return m_moveTimeS; }
    /// Rows of the step-period table currently shown.
    int stepTableRows() const;

private:
    void replan();
    void scheduleReplan();
    void updateFieldVisibility();
    NumberField* addField(QFormLayout* form, const QString& objectName, const QString& label,
                          const QString& suffix, double min, double max, double value, int decimals,
                          const QString& tip);
    void showError(const QString& message);
    /// No plan shown: `why` in the error line, the plots and table empty.
    void showNoPlan(const QString& why);

    QComboBox* m_kind;
    NumberField* m_distance;
    NumberField* m_vMax;
    NumberField* m_aMax;
    NumberField* m_jMax;
    NumberField* m_accelTime;
    NumberField* m_startSpeed;
    NumberField* m_plateau;
    NumberField* m_step;
    QLabel* m_moveTime;
    QLabel* m_summary;
    QLabel* m_tableSummary;
    QLabel* m_error;
    QCustomPlot* m_plots[4];  ///< s, v, a, j
    QTableView* m_table;
    StepTableModel* m_model;
    QTimer* m_replanTimer;
    double m_moveTimeS = -1;
};

}  // namespace ui
