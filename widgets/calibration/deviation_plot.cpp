#include "widgets/calibration/deviation_plot.h"

#include <QEvent>

#include <algorithm>
#include <cmath>

namespace ui {

namespace {
const QColor kUp(0x1f, 0x5f, 0xc8);
const QColor kDown(0xc8, 0x3c, 0x1e);
} // namespace

DeviationPlot::DeviationPlot(QWidget* parent) : QCustomPlot(parent)
{
    setMinimumHeight(160);
    auto graph = [this](QColor c, Qt::PenStyle style, double width) {
        QCPGraph* g = addGraph();
        g->setPen(QPen(c, width, style));
        return g;
    };
    m_before = graph(QColor(0x99, 0x99, 0x99), Qt::SolidLine, 2);
    m_upMean = graph(kUp, Qt::SolidLine, 2);
    m_upHi = graph(kUp, Qt::DashLine, 1);
    m_upLo = graph(kUp, Qt::DashLine, 1);
    m_downMean = graph(kDown, Qt::SolidLine, 2);
    m_downHi = graph(kDown, Qt::DashLine, 1);
    m_downLo = graph(kDown, Qt::DashLine, 1);
    m_upDots = graph(kUp, Qt::SolidLine, 1);
    m_downDots = graph(kDown, Qt::SolidLine, 1);
    for (QCPGraph* g : {m_upDots, m_downDots}) {
        g->setLineStyle(QCPGraph::lsNone);
        g->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssDisc, g->pen().color(), 5));
    }
    for (QCPGraph* g : {m_upHi, m_upLo, m_downHi, m_downLo})
        g->removeFromLegend();
    m_upLo->removeFromLegend();
    for (QCPAxis* a : {xAxis, yAxis})
        a->grid()->setPen(QPen(QColor(0xdd, 0xdd, 0xdd), 0, Qt::DotLine));
    yAxis->grid()->setZeroLinePen(QPen(QColor(0x90, 0x90, 0x90), 1));
    legend->setVisible(true);
    legend->setFont(QFont(font().family(), 8));
    axisRect()->insetLayout()->setInsetAlignment(0, Qt::AlignTop | Qt::AlignLeft);
    setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
    retranslateUi();
}

void DeviationPlot::retranslateUi()
{
    xAxis->setLabel(tr("target (mm)"));
    yAxis->setLabel(tr("deviation (µm)"));
    m_before->setName(tr("before (mean)"));
    m_upMean->setName(tr("↑ mean ± 2s"));
    m_downMean->setName(tr("↓ mean ± 2s"));
    m_upDots->setName(tr("↑ readings"));
    m_downDots->setName(tr("↓ readings"));
    replot(QCustomPlot::rpQueuedReplot);
}

void DeviationPlot::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    QCustomPlot::changeEvent(event);
}

void DeviationPlot::clearAll()
{
    for (int i = 0; i < graphCount(); ++i)
        graph(i)->data()->clear();
    replot(QCustomPlot::rpQueuedReplot);
}

void DeviationPlot::showTargets(const std::vector<double>& targetsMm)
{
    for (QCPGraph* g : {m_upMean, m_upHi, m_upLo, m_downMean, m_downHi, m_downLo, m_upDots, m_downDots})
        g->data()->clear();
    m_frame.reset();
    if (targetsMm.empty())
        return;
    const auto [lo, hi] = std::minmax_element(targetsMm.begin(), targetsMm.end());
    m_frame = std::make_pair(*lo, *hi);
    xAxis->setRange(*lo - (*hi - *lo) * 0.03 - 0.5, *hi + (*hi - *lo) * 0.03 + 0.5);
    yAxis->setRange(-1, 1);
    replot(QCustomPlot::rpQueuedReplot);
}

void DeviationPlot::setBefore(const std::optional<motion::metrology::Evaluation>& before)
{
    m_before->data()->clear();
    if (before)
        for (const auto& t : before->targets)
            m_before->addData(t.targetMm, t.meanMm * 1e3);
    m_before->setVisible(before.has_value());
    if (before)
        m_before->addToLegend();
    else
        m_before->removeFromLegend();
}

void DeviationPlot::setData(const std::vector<motion::metrology::Reading>& readings, const motion::metrology::Evaluation& e)
{
    for (QCPGraph* g : {m_upMean, m_upHi, m_upLo, m_downMean, m_downHi, m_downLo, m_upDots, m_downDots})
        g->data()->clear();
    double lo = 0, hi = 0, x0 = 1e300, x1 = -1e300;
    auto span = [&](double x, double yUm) {
        lo = std::min(lo, yUm);
        hi = std::max(hi, yUm);
        x0 = std::min(x0, x);
        x1 = std::max(x1, x);
    };
    for (const auto& r : readings) {
        const double um = r.deviationMm() * 1e3;
        (r.direction == motion::metrology::Direction::Up ? m_upDots : m_downDots)->addData(r.targetMm, um);
        span(r.targetMm, um);
    }
    // Means and bands only where the evaluation has them (a run in progress has some).
    if (!e.targets.empty() && e.ok()) {
        for (const auto& t : e.targets) {
            m_upMean->addData(t.targetMm, t.meanUpMm * 1e3);
            m_upHi->addData(t.targetMm, (t.meanUpMm + 2 * t.sUpMm) * 1e3);
            m_upLo->addData(t.targetMm, (t.meanUpMm - 2 * t.sUpMm) * 1e3);
            span(t.targetMm, (t.meanUpMm + 2 * t.sUpMm) * 1e3);
            span(t.targetMm, (t.meanUpMm - 2 * t.sUpMm) * 1e3);
            if (t.meanDownMm && t.sDownMm) {
                m_downMean->addData(t.targetMm, *t.meanDownMm * 1e3);
                m_downHi->addData(t.targetMm, (*t.meanDownMm + 2 * *t.sDownMm) * 1e3);
                m_downLo->addData(t.targetMm, (*t.meanDownMm - 2 * *t.sDownMm) * 1e3);
            }
        }
    }
    for (int i = 0; i < m_before->dataCount(); ++i)
        span(m_before->data()->at(i)->key, m_before->data()->at(i)->value);
    if (m_frame) {
        x0 = std::min(x0, m_frame->first);
        x1 = std::max(x1, m_frame->second);
    }
    if (x0 > x1) {
        x0 = 0;
        x1 = 1;
    }
    const double pad = std::max(0.5, (hi - lo) * 0.1);
    xAxis->setRange(x0 - (x1 - x0) * 0.03 - 0.5, x1 + (x1 - x0) * 0.03 + 0.5);
    yAxis->setRange(lo - pad, hi + pad);
    replot(QCustomPlot::rpQueuedReplot);
}

} // namespace ui
