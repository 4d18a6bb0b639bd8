#pragma once
// A plot of tuning runs on a time axis from each run's start: overlaid step
// responses (one colour each, legend with the gains), or one oscillation with
// the controller output on a second axis. Positions relative to each run's
// start, in µm for a mm target (in the plant's unit for a model).
#include "motion/control/experiment.h"

#include <QColor>
#include <QString>
#include <QWidget>

class QCPGraph;
class QCustomPlot;

namespace ui {

class ResponsePlot : public QWidget {
    Q_OBJECT
public:
    enum class Mode { Overlay, Oscillation };
    explicit ResponsePlot(Mode mode, QWidget* parent = nullptr);

    /// "mm" shows µm; "" shows the plant's own unit.
    void setUnit(const QString& unit);
    /// Overlay: adds a run (setpoint dashed, measured solid, same colour). Oscillation: replaces the shown run.
    /// `showS` > 0: the time range to show (the union over runs); else the whole run.
    void addRun(const motion::control::Record& record, const QString& legend, double showS = 0);
    /// Oscillation mode, live: the newest samples (times in s from the run's start).
    void setLive(const QVector<double>& tS, const QVector<double>& measured, const QVector<double>& output, const QString& title);
    void clear();
    /// The colour of the i-th run, for tables that name runs beside the plot.
    static QColor colour(int run);
    int runCount() const { return m_runs; }
    QCustomPlot* plot() const { return m_plot; }
    /// A run's legend as drawn: its gains, "(…)", on a line of their own.
    static QString legendLines(const QString& legend);

private:
    double scale() const { return m_unit == QLatin1String("mm") ? 1000.0 : 1.0; }
    QString axisUnit() const;
    void relabel();

    Mode m_mode;
    QCustomPlot* m_plot;
    QString m_unit = QStringLiteral("mm");
    int m_runs = 0;
    double m_showS = 0;
};

} // namespace ui
