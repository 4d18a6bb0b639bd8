#include "widgets/tuning/response_plot.h"

#include <qcustomplot.h>

#include <QVBoxLayout>

namespace ui {
namespace {
const QColor kColours[] = {QColor(31, 119, 180), QColor(214, 39, 40), QColor(44, 160, 44), QColor(148, 103, 189),
                           QColor(255, 127, 14), QColor(23, 190, 207), QColor(140, 86, 75), QColor(227, 119, 194)};
}

QColor ResponsePlot::colour(int run) { return kColours[run % 8]; }

ResponsePlot::ResponsePlot(Mode mode, QWidget* parent) : QWidget(parent), m_mode(mode)
{
    auto* v = new QVBoxLayout(this);
    v->setContentsMargins(0, 0, 0, 0);
    m_plot = new QCustomPlot(this);
    m_plot->setMinimumHeight(220);
    m_plot->legend->setVisible(true);
    m_plot->legend->setFont(QFont(font().family(), 8));
    if (mode == Mode::Overlay) {
        // Under the plot, as wide as the widget: the runs' legends (their gains) were wider than
        // the axis rect beside the gains and the results, and cut at the left.
        m_plot->axisRect()->insetLayout()->take(m_plot->legend);
        m_plot->plotLayout()->addElement(1, 0, m_plot->legend);
        m_plot->plotLayout()->setRowStretchFactor(1, 0.001);
        m_plot->legend->setMargins(QMargins(4, 2, 4, 2));
    } else {
        m_plot->axisRect()->insetLayout()->setInsetAlignment(0, Qt::AlignRight | Qt::AlignTop);
    }
    m_plot->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
    if (m_mode == Mode::Oscillation) {
        m_plot->yAxis2->setVisible(true);
        m_plot->yAxis2->setTickLabels(true);
    }
    v->addWidget(m_plot);
    relabel();
}

QString ResponsePlot::axisUnit() const
{
    return m_unit == QLatin1String("mm") ? QStringLiteral("µm") : m_unit;
}

void ResponsePlot::relabel()
{
    m_plot->xAxis->setLabel(tr("time from the start [s]"));
    const QString u = axisUnit();
    m_plot->yAxis->setLabel(u.isEmpty() ? tr("output − start") : tr("position − start [%1]").arg(u));
    if (m_mode == Mode::Oscillation)
        m_plot->yAxis2->setLabel(u.isEmpty() ? tr("controller output u") : tr("controller output u [%1]").arg(u));
}

void ResponsePlot::setUnit(const QString& unit)
{
    m_unit = unit;
    relabel();
    m_plot->replot();
}

void ResponsePlot::clear()
{
    m_plot->clearGraphs();
    m_runs = 0;
    m_showS = 0;
    m_plot->replot();
}

QString ResponsePlot::legendLines(const QString& legend)
{
    // "Ziegler–Nichols PID verification (Kp 2.5 · Ki 962 /s · Kd 1.6 ms)" on one line was wider
    // than the plot and cut at its left: what the run was on one line, its gains on the next.
    const int open = static_cast<int>(legend.indexOf(QStringLiteral(" (")));
    return open > 0 && legend.endsWith(QLatin1Char(')')) ? legend.left(open) + QLatin1Char('\n') + legend.mid(open + 1) : legend;
}

void ResponsePlot::addRun(const motion::control::Record& r, const QString& legend, double showS)
{
    if (m_mode == Mode::Oscillation)
        clear();
    const double k = scale();
    QVector<double> t, y, sp, u;
    // A model run can hold millions of periods: a few thousand points draw the same curve.
    const std::size_t stride = std::max<std::size_t>(1, r.size() / 4000);
    t.reserve(static_cast<int>(r.size() / stride + 1));
    for (std::size_t i = 0; i < r.size(); i += stride) {
        t << static_cast<double>(i) * r.periodS;
        y << (r.measured[i] - r.startPosition) * k;
        sp << (r.setpoint[i] - r.startPosition) * k;
        u << (r.output[i] - r.startOutput) * k;
    }
    const QColor c = colour(m_runs);
    QCPGraph* setpoint = m_plot->addGraph();
    setpoint->setData(t, sp, true);
    setpoint->setPen(QPen(c, 1, Qt::DashLine));
    setpoint->removeFromLegend();
    QCPGraph* measured = m_plot->addGraph();
    measured->setData(t, y, true);
    measured->setPen(QPen(c, 1.6));
    measured->setName(legendLines(legend));
    if (m_mode == Mode::Oscillation) {
        QCPGraph* out = m_plot->addGraph(m_plot->xAxis, m_plot->yAxis2);
        out->setData(t, u, true);
        out->setPen(QPen(QColor(120, 120, 120), 1));
        out->setLineStyle(QCPGraph::lsStepLeft);
        out->setName(tr("controller output u"));
        m_plot->yAxis2->rescale();
    }
    ++m_runs;
    m_plot->rescaleAxes();
    if (m_mode == Mode::Oscillation)
        m_plot->yAxis2->rescale();
    if (showS > 0) {
        m_showS = std::max(m_showS, showS);
        m_plot->xAxis->setRange(0, m_showS);
    }
    // A little room above and below, so extremes are not drawn on the frame.
    m_plot->yAxis->scaleRange(1.1, m_plot->yAxis->range().center());
    if (m_mode == Mode::Oscillation)
        m_plot->yAxis2->scaleRange(1.1, m_plot->yAxis2->range().center());
    m_plot->replot();
}

void ResponsePlot::setLive(const QVector<double>& tS, const QVector<double>& measured, const QVector<double>& output, const QString& title)
{
    m_plot->clearGraphs();
    const double k = scale();
    QVector<double> y = measured, u = output;
    for (auto& v : y)
        v *= k;
    for (auto& v : u)
        v *= k;
    QCPGraph* g = m_plot->addGraph();
    g->setData(tS, y, true);
    g->setPen(QPen(kColours[0], 1.4));
    g->setName(title);
    if (m_mode == Mode::Oscillation) {
        QCPGraph* out = m_plot->addGraph(m_plot->xAxis, m_plot->yAxis2);
        out->setData(tS, u, true);
        out->setPen(QPen(QColor(120, 120, 120), 1));
        out->setLineStyle(QCPGraph::lsStepLeft);
        out->setName(tr("controller output u"));
    }
    m_plot->rescaleAxes();
    m_plot->replot(QCustomPlot::rpQueuedReplot);
}

} // namespace ui
