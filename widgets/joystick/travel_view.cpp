#include "widgets/joystick/travel_view.h"

#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>

namespace ui {

TravelView::TravelView(QWidget* parent) : QWidget(parent)
{
    setObjectName(QStringLiteral("travelView"));
    setMinimumSize(220, 220);
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
}

void TravelView::setTravel(const QRectF& travelMm, const QRectF& softLimitsMm)
{
    m_travel = travelMm.normalized();
    m_soft = softLimitsMm.normalized();
    update();
}

void TravelView::addPosition(QPointF measuredMm, QPointF commandedMm)
{
    if (m_trail.empty() || QLineF(m_trail.back(), measuredMm).length() > 1e-4) {
        m_trail.push_back(measuredMm);
        if (m_trail.size() > kMaxTrail)
            m_trail.pop_front();
    }
    m_measured = measuredMm;
    m_commanded = commandedMm;
    m_havePosition = true;
    update();
}

void TravelView::setLive(bool live)
{
    if (m_live == live)
        return;
    m_live = live;
    update();
}

void TravelView::clearTrail()
{
    m_trail.clear();
    update();
}

QPointF TravelView::toPixel(QPointF mm) const
{
    const double margin = 34;
    const double scale = std::min((width() - 2 * margin) / std::max(1e-9, m_travel.width()),
                                  (height() - 2 * margin) / std::max(1e-9, m_travel.height()));
    const double w = m_travel.width() * scale, h = m_travel.height() * scale;
    const double left = (width() - w) / 2, bottom = (height() + h) / 2;
    return {left + (mm.x() - m_travel.left()) * scale, bottom - (mm.y() - m_travel.top()) * scale};
}

void TravelView::paintEvent(QPaintEvent*)
{
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    p.fillRect(rect(), QColor(0xfb, 0xfb, 0xfb));
    auto box = [&](const QRectF& r) {
        const QPointF a = toPixel(r.topLeft()), b = toPixel(r.bottomRight());
        return QRectF(a, b).normalized();
    };
    // Travel, a 10 mm grid, the soft limits.
    const QRectF travel = box(m_travel);
    p.setPen(QPen(QColor(0x60, 0x60, 0x60), 1.5));
    p.setBrush(Qt::white);
    p.drawRect(travel);
    p.setPen(QPen(QColor(0xe6, 0xe6, 0xe6), 1));
    const double step = m_travel.width() > 150 ? 20 : 10;
    for (double x = std::ceil(m_travel.left() / step) * step; x < m_travel.right(); x += step)
        p.drawLine(toPixel({x, m_travel.top()}), toPixel({x, m_travel.bottom()}));
    for (double y = std::ceil(m_travel.top() / step) * step; y < m_travel.bottom(); y += step)
        p.drawLine(toPixel({m_travel.left(), y}), toPixel({m_travel.right(), y}));
    p.setPen(QPen(QColor(0xe0, 0x8a, 0x00), 1.5, Qt::DashLine));
    p.setBrush(Qt::NoBrush);
    p.drawRect(box(m_soft));
    p.setPen(QColor(0x55, 0x55, 0x55));
    p.drawText(QRectF(travel.left() - 30, travel.bottom() + 2, 60, 16), Qt::AlignCenter, QString::number(m_travel.left()));
    p.drawText(QRectF(travel.right() - 30, travel.bottom() + 2, 60, 16), Qt::AlignCenter,
               tr("%1 mm").arg(m_travel.right()));
    p.drawText(QRectF(travel.left() - 34, travel.top() - 8, 32, 16), Qt::AlignRight | Qt::AlignVCenter,
               QString::number(m_travel.bottom()));
    p.drawText(QRectF(travel.left(), travel.top() - 22, travel.width(), 16), Qt::AlignLeft,
               tr("XY travel to scale · dashed: soft limits"));
    // Trail, then where the axes are.
    if (m_trail.size() >= 2) {
        QPainterPath path(toPixel(m_trail.front()));
        for (std::size_t i = 1; i < m_trail.size(); ++i)
            path.lineTo(toPixel(m_trail[i]));
        p.setPen(QPen(QColor(0x1f, 0x77, 0xb4), 1.5));
        p.drawPath(path);
    }
    if (m_havePosition && !m_live) {
        const QPointF at = toPixel(m_measured);
        p.setPen(QPen(QColor(0x90, 0x90, 0x90), 1.5, Qt::DashLine));
        p.setBrush(Qt::NoBrush);
        p.drawEllipse(at, 5, 5);
        p.setPen(QColor(0x70, 0x70, 0x70));
        p.drawText(QRectF(travel.left(), travel.bottom() + 18, travel.width(), 16), Qt::AlignCenter,
                   tr("not connected: the grey ring is the last known position"));
    } else if (m_havePosition) {
        p.setPen(QPen(QColor(0x30, 0x30, 0x30), 1.5));
        p.setBrush(Qt::NoBrush);
        p.drawEllipse(toPixel(m_commanded), 7, 7);
        p.setPen(Qt::NoPen);
        p.setBrush(QColor(0xd3, 0x2f, 0x2f));
        p.drawEllipse(toPixel(m_measured), 4.5, 4.5);
    }
}

} // namespace ui
