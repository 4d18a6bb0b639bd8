#pragma once
// Step tests: size and direction, the responses overlaid (one colour a run,
// the legend gives its gains) and the metrics of every run beside the plot.
#include "motion/control/experiment.h"
#include "motion/control/tuning/step_verdict.h"

#include <QWidget>

class QComboBox;
class QLabel;
class QPushButton;
class QTableWidget;

namespace ui {

class NumberField;

class ResponsePlot;

class StepTestPanel : public QWidget {
    Q_OBJECT
public:
    explicit StepTestPanel(QWidget* parent = nullptr);

    /// "mm": sizes in µm; "": a model's own unit.
    void setUnit(const QString& unit);
    /// Signed step in the target's unit (mm for a stage).
    double step() const;
    void setStep(double magnitude, bool positive);
    /// A run as judgeStep judged it (the Z–N verification is judged the same way).
    void addResult(const motion::control::Record& record, const motion::control::StepVerdict& verdict, const QString& legend);
    void setBusy(bool busy);
    void setReady(bool ready);
    int runs() const;
    ResponsePlot* plot() const { return m_plot; }
    QTableWidget* metricsTable() const { return m_table; }

signals:
    void runRequested(double step);

private:
    void refresh();

    NumberField* m_size;
    QComboBox* m_direction;
    QPushButton* m_run;
    QPushButton* m_clear;
    ResponsePlot* m_plot;
    QTableWidget* m_table;
    QString m_unit = QStringLiteral("mm");
    bool m_busy = false, m_ready = false;
};

} // namespace ui
