#include "widgets/xy_view.h"

#include <algorithm>
#include <cmath>

namespace ui {

XyView::XyView(const PlotDataSource* source, QWidget* parent) : QCustomPlot(parent), m_source(source)
{
    setObjectName(QStringLiteral("xyView"));
    setMinimumSize(200, 200);
    // Measured first, commanded dashed on top: where they agree both stay visible.
    m_measured = new QCPCurve(xAxis, yAxis);
    m_measured->setName(tr("measured"));
    m_measured->setPen(QPen(QColor(0x1f, 0x77, 0xb4), 2));
    m_commanded = new QCPCurve(xAxis, yAxis);
    m_commanded->setName(tr("commanded"));
    m_commanded->setPen(QPen(QColor(0x30, 0x30, 0x30), 1, Qt::DashLine));
    m_now = new QCPCurve(xAxis, yAxis);
    m_now->setName(tr("now"));
    m_now->setLineStyle(QCPCurve::lsNone);
    m_now->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssDisc, QColor(0xd3, 0x2f, 0x2f), 7));
    m_now->removeFromLegend();
    for (QCPCurve* c : {m_commanded, m_measured})
        c->setAntialiased(false);
    legend->setVisible(true);
    QFont lf = legend->font();
    lf.setPointSizeF(lf.pointSizeF() * 0.85);
    legend->setFont(lf);
    legend->setBorderPen(Qt::NoPen);
    for (QCPAxis* a : {xAxis, yAxis}) {
        a->grid()->setPen(QPen(QColor(0xdd, 0xdd, 0xdd), 0, Qt::DotLine));
        a->setNumberFormat(QStringLiteral("gb"));
    }
    plotLayout()->insertRow(0);
    QFont tf = font();
    tf.setBold(true);
    plotLayout()->addElement(0, 0, new QCPTextElement(this, tr("XY path"), tf));
    // The legend in a row of its own under the title: inside the axes it would hide
    // whichever corner the path happens to run through.
    axisRect()->insetLayout()->take(legend);
    plotLayout()->insertRow(1);
    plotLayout()->addElement(1, 0, legend);
    legend->setFillOrder(QCPLegend::foColumnsFirst);
    plotLayout()->setRowStretchFactor(1, 0.001);
    plotLayout()->setRowSpacing(0);
    setInstrument(1);
}

void XyView::setInstrument(int instrument)
{
    m_instrument = instrument;
    const QString unit = m_source ? m_source->channelUnit(channels().value(1)) : QString();
    xAxis->setLabel(unit.isEmpty() ? tr("X") : tr("X (%1)").arg(unit));
    yAxis->setLabel(unit.isEmpty() ? tr("Y") : tr("Y (%1)").arg(unit));
}

QVector<dev::tele::ChannelKey> XyView::channels() const
{
    QVector<dev::tele::ChannelKey> out;
    for (std::uint8_t axis : {std::uint8_t(0), std::uint8_t(1)})
        for (auto kind : {dev::proto::ChannelKind::Commanded, dev::proto::ChannelKind::Measured})
            out << dev::tele::ChannelKey{m_instrument, dev::proto::ChannelRef{axis, kind}};
    return out;
}

int XyView::fill(QCPCurve* curve, dev::proto::ChannelKind kind, double t0S, double t1S, int maxPoints)
{
    m_points.clear();
    const dev::tele::ChannelStore* xs = m_source->store({m_instrument, {0, kind}});
    const dev::tele::ChannelStore* ys = m_source->store({m_instrument, {1, kind}});
    if (xs && ys && !xs->empty() && !ys->empty() && maxPoints > 0) {
        const std::size_t lo = xs->lowerBound(t0S), hi = xs->lowerBound(t1S);
        const std::size_t n = hi - lo;
        const std::size_t stride = std::max<std::size_t>(1, (n + static_cast<std::size_t>(maxPoints) - 1) / static_cast<std::size_t>(maxPoints));
        int k = 0;
        auto add = [&](std::size_t i) {
            const dev::tele::Sample x = xs->at(i);
            const auto y = ys->nearest(x.tS);
            if (y)
                m_points.append(QCPCurveData(k++, x.value, y->value));
        };
        for (std::size_t i = lo; i < hi; i += stride)
            add(i);
        if (n > 0 && (n - 1) % stride != 0)
            add(hi - 1);  // always end at the newest point of the range
    }
    curve->data()->set(m_points, true);
    return static_cast<int>(m_points.size());
}

void XyView::refresh(double anchorS, double x0S, double x1S)
{
    if (!m_source || std::isnan(anchorS)) {
        for (QCPCurve* c : {m_commanded, m_measured, m_now})
            c->data()->clear();
        replot(QCustomPlot::rpQueuedRefresh);
        return;
    }
    updateLayout();
    const int maxPoints = 2 * std::max(axisRect()->width(), 100);
    const double t0 = anchorS + x0S, t1 = anchorS + x1S;
    fill(m_commanded, dev::proto::ChannelKind::Commanded, t0, t1, maxPoints);
    const int measured = fill(m_measured, dev::proto::ChannelKind::Measured, t0, t1, maxPoints);
    m_now->data()->clear();
    if (measured > 0) {
        const QCPCurveData last = *(m_measured->data()->constEnd() - 1);
        m_now->addData(0, last.key, last.value);
    }

    // Fit both paths at one scale on both axes, so a circle looks round.
    bool fx = false, fy = false;
    QCPRange bx, by;
    for (QCPCurve* c : {m_commanded, m_measured}) {
        bool okx = false, oky = false;
        const QCPRange rx = c->getKeyRange(okx), ry = c->getValueRange(oky);
        if (okx) {
            bx = fx ? QCPRange(std::min(bx.lower, rx.lower), std::max(bx.upper, rx.upper)) : rx;
            fx = true;
        }
        if (oky) {
            by = fy ? QCPRange(std::min(by.lower, ry.lower), std::max(by.upper, ry.upper)) : ry;
            fy = true;
        }
    }
    if (fx && fy) {
        const double w = std::max(1, axisRect()->width()), h = std::max(1, axisRect()->height());
        const double minSpan = 0.01;  // a resting machine still gets a readable 10 µm box
        const double perPx = std::max({bx.size() * 1.15 / w, by.size() * 1.15 / h, minSpan / std::min(w, h)});
        xAxis->setRange(bx.center() - perPx * w / 2, bx.center() + perPx * w / 2);
        yAxis->setRange(by.center() - perPx * h / 2, by.center() + perPx * h / 2);
    }
    replot(QCustomPlot::rpQueuedRefresh);
}

int XyView::commandedPoints() const { return m_commanded->data()->size(); }
int XyView::measuredPoints() const { return m_measured->data()->size(); }

} // namespace ui
