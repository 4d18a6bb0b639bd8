#include "widgets/calibration/polar_plot.h"

#include <QEvent>

#include <cmath>

namespace ui {

namespace {
constexpr double kPi = 3.141592653589793;
}

PolarPlot::PolarPlot(QWidget* parent) : QCustomPlot(parent)
{
    setMinimumSize(220, 220);
    auto curve = [this](QColor c, Qt::PenStyle s, double w) {
        auto* k = new QCPCurve(xAxis, yAxis);
        k->setPen(QPen(c, w, s));
        return k;
    };
    m_nominal = curve(QColor(0x90, 0x90, 0x90), Qt::DashLine, 1);
    m_ccw = curve(QColor(0x1f, 0x5f, 0xc8), Qt::SolidLine, 1.5);
    m_cw = curve(QColor(0xc8, 0x3c, 0x1e), Qt::SolidLine, 1.5);
    m_live = curve(QColor(0x20, 0x80, 0x40), Qt::SolidLine, 1);
    m_nominal->removeFromLegend();
    m_live->removeFromLegend();
    m_caption = new QCPItemText(this);
    m_caption->setPositionAlignment(Qt::AlignLeft | Qt::AlignTop);
    m_caption->position->setType(QCPItemPosition::ptAxisRectRatio);
    m_caption->position->setCoords(0.01, 0.01);
    legend->setVisible(true);
    legend->setFont(QFont(font().family(), 8));
    axisRect()->insetLayout()->setInsetAlignment(0, Qt::AlignBottom | Qt::AlignRight);
    retranslateUi();
}

void PolarPlot::retranslateUi()
{
    xAxis->setLabel(tr("X about the centre (mm)"));
    yAxis->setLabel(tr("Y about the centre (mm)"));
    m_ccw->setName(tr("counter-clockwise"));
    m_cw->setName(tr("clockwise"));
    m_caption->setText(m_magnification > 0 ? tr("deviation magnified %1×").arg(m_magnification, 0, 'g', 6) : QString());
    replot(QCustomPlot::rpQueuedReplot);
}

void PolarPlot::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    QCustomPlot::changeEvent(event);
}

void PolarPlot::resizeEvent(QResizeEvent* event)
{
    QCustomPlot::resizeEvent(event);
    keepRound();
}

void PolarPlot::keepRound()
{
    // Equal scales on both axes: a circle must look like one.
    const QRect r = axisRect()->rect();
    if (r.width() <= 0 || r.height() <= 0)
        return;
    const double e = m_extent * 1.1;
    if (r.width() >= r.height()) {
        yAxis->setRange(-e, e);
        const double half = e * r.width() / r.height();
        xAxis->setRange(-half, half);
    } else {
        xAxis->setRange(-e, e);
        const double half = e * r.height() / r.width();
        yAxis->setRange(-half, half);
    }
    replot(QCustomPlot::rpQueuedReplot);
}

void PolarPlot::clearAll()
{
    for (QCPCurve* c : {m_nominal, m_cw, m_ccw, m_live})
        c->data()->clear();
    m_magnification = 0;
    retranslateUi();
}

void PolarPlot::setEvaluation(const motion::metrology::CircularEvaluation& e, double R, double magnification)
{
    clearAll();
    m_magnification = magnification > 0 ? magnification : motion::metrology::autoMagnification(e, R);
    for (int k = 0; k <= 360; ++k) {
        const double a = k * kPi / 180;
        m_nominal->addData(R * std::cos(a), R * std::sin(a));
    }
    m_extent = R;
    for (const auto& run : e.runs) {
        QCPCurve* c = run.rotation == motion::metrology::Rotation::Cw ? m_cw : m_ccw;
        const auto pts = motion::metrology::polarPlot(run, R, m_magnification);
        for (std::size_t k = 0; k <= pts.size() && !pts.empty(); ++k) {
            const auto& p = pts[k % pts.size()];
            c->addData(p.plotRadiusMm * std::cos(p.angleRad), p.plotRadiusMm * std::sin(p.angleRad));
            m_extent = std::max(m_extent, std::fabs(p.plotRadiusMm));
        }
    }
    retranslateUi();
    keepRound();
}

void PolarPlot::showLive(const std::vector<motion::metrology::XyPoint>& samples, const motion::metrology::XyPoint& c, double R)
{
    m_live->data()->clear();
    for (const auto& s : samples)
        m_live->addData(s.xMm - c.xMm, s.yMm - c.yMm);
    m_extent = std::max(m_extent, R);
    if (m_nominal->dataCount() == 0)
        for (int k = 0; k <= 360; ++k)
            m_nominal->addData(R * std::cos(k * kPi / 180), R * std::sin(k * kPi / 180));
    keepRound();
}

} // namespace ui
