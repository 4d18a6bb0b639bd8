#pragma once
// The Ziegler–Nichols assistant: method (ultimate gain or relay), the abort
// envelope and the method's settings, Start/Abort, the oscillation of the last
// run (live from telemetry on an instrument), Ku/Tu found, and the rules table
// with a "Use these" button per row.
#include "device/jobs/tuning/tuning_runner.h"
#include "motion/control/tuning/tuning_result.h"

#include <QWidget>

class QCheckBox;
class QComboBox;
class QLabel;
class QPushButton;
class QStackedWidget;
class QTableWidget;

namespace ui {

class NumberField;
class ResponsePlot;

class ZnPanel : public QWidget {
    Q_OBJECT
public:
    explicit ZnPanel(QWidget* parent = nullptr);

    /// "mm": sizes in µm; "": a model's own unit.
    void setUnit(const QString& unit);
    /// The settings as the runner takes them (target units).
    dev::TuningRunner::ZnOptions options() const;
    void setOptions(const dev::TuningRunner::ZnOptions& o);
    /// Ku, Tu and the rules for the loop period; clears with an empty result.
    void showResult(const motion::control::TuningResult& r);
    void clearResult(const QString& note = {});
    void showRun(const motion::control::Record& record, const QString& label);
    void showLive(const QVector<double>& tS, const QVector<double>& measured, const QVector<double>& output, const QString& title);
    void setBusy(bool busy);
    void setReady(bool ready);
    QTableWidget* rulesTable() const { return m_rules; }
    ResponsePlot* plot() const { return m_plot; }
    QString resultText() const;

signals:
    void startRequested();
    void abortRequested();
    /// "Use these" on a row: the rule's gains in the target's discrete form.
    void useRule(const QString& ruleId, const motion::control::DiscreteGains& gains, const QString& source);

private:
    /// The verification's line of the result: its verdict first, then its figures.
    static QString verificationText(const motion::control::TuningResult& r);
    NumberField* spin(const QString& objectName, double min, double max, int decimals, double value);
    double toTarget(double shown) const;
    double toShown(double target) const;
    void refresh();

    QComboBox* m_method;
    NumberField* m_excursion;
    NumberField* m_following;
    NumberField* m_duration;
    QStackedWidget* m_methodPages;
    NumberField* m_trialStep;
    NumberField* m_startKp;
    NumberField* m_kpMax;
    NumberField* m_amplitude;
    NumberField* m_hysteresis;
    QCheckBox* m_refine;
    QComboBox* m_verify;
    QPushButton* m_start;
    QPushButton* m_abort;
    ResponsePlot* m_plot;
    QLabel* m_result;
    QTableWidget* m_rules;
    QString m_unit = QStringLiteral("mm");
    bool m_busy = false, m_ready = false;
    motion::control::TuningResult m_shown;
};

} // namespace ui
