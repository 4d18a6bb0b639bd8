#include "widgets/patterns/contour_plot.h"

#include <cmath>

namespace ui {

ContourPlot::ContourPlot(QWidget* parent) : QCustomPlot(parent)
{
    setObjectName(QStringLiteral("contourPlot"));
    setMinimumHeight(140);
    m_graph = addGraph();
    m_graph->setName(tr("contour error"));
    m_graph->setPen(QPen(QColor(0x1f, 0x77, 0xb4), 1));
    m_graph->setAdaptiveSampling(true);
    // Each judged sample marked: a sparse run (a controller polled at 10 Hz) shows how few
    // points its line joins.
    m_graph->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssDisc, 3));
    m_worst = addGraph();
    m_worst->setName(tr("largest"));
    m_worst->setLineStyle(QCPGraph::lsNone);
    m_worst->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssCircle, QPen(QColor(0xd3, 0x2f, 0x2f), 2), QBrush(Qt::NoBrush), 9));
    xAxis->setLabel(tr("distance along the path (mm)"));
    yAxis->setLabel(tr("contour error (µm)"));
    for (QCPAxis* a : {xAxis, yAxis})
        a->grid()->setPen(QPen(QColor(0xdd, 0xdd, 0xdd), 0, Qt::DotLine));
    yAxis->grid()->setZeroLinePen(QPen(QColor(0x90, 0x90, 0x90), 1));
    yAxis->setRange(-1, 1);
    setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
    axisRect()->setRangeZoom(Qt::Horizontal);
    axisRect()->setRangeDrag(Qt::Horizontal);
}

void ContourPlot::addSample(double pathMm, double errorMm)
{
    const double um = errorMm * 1e3;
    m_graph->addData(pathMm, um);
    if (std::fabs(um) > m_worstAbsUm) {
        m_worstAbsUm = std::fabs(um);
        m_worst->data()->clear();
        m_worst->addData(pathMm, um);
    }
}

void ContourPlot::clear()
{
    m_graph->data()->clear();
    m_worst->data()->clear();
    m_worstAbsUm = -1;
    yAxis->setRange(-1, 1);
    replot(QCustomPlot::rpQueuedReplot);
}

void ContourPlot::setPathLength(double mm)
{
    xAxis->setRange(0, std::max(mm, 1e-3));
}

void ContourPlot::refresh()
{
    const double span = std::max(1.0, m_worstAbsUm * 1.2);
    yAxis->setRange(-span, span);
    replot(QCustomPlot::rpQueuedReplot);
}

} // namespace ui
