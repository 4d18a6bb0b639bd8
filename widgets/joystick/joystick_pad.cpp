#include "widgets/joystick/joystick_pad.h"

#include <QMouseEvent>
#include <QPainter>

#include <algorithm>
#include <cmath>

namespace ui {

JoystickPad::JoystickPad(QWidget* parent) : QWidget(parent)
{
    setObjectName(QStringLiteral("joystickPad"));
    // Small enough that the screen fits 1366 × 768 in Chinese too, whose lines are taller;
    // it grows with the room it gets.
    setMinimumSize(168, 168);
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
    setToolTip(tr("Drag the knob: speed grows with the distance from the centre. Let go to stop."));
    setCursor(Qt::OpenHandCursor);
}

QPointF JoystickPad::centre() const { return {width() / 2.0, height() / 2.0}; }

double JoystickPad::radius() const { return std::min(width(), height()) / 2.0 - 18; }

void JoystickPad::setDeadband(double share)
{
    m_deadband = std::clamp(share, 0.0, 0.9);
    update();
}

void JoystickPad::showDeflection(QPointF d)
{
    if (m_dragging)
        return;
    m_deflection = d;
    update();
}

void JoystickPad::setFromPosition(QPointF pos)
{
    const double r = std::max(1.0, radius());
    QPointF d((pos.x() - centre().x()) / r, (centre().y() - pos.y()) / r);
    const double len = std::hypot(d.x(), d.y());
    if (len > 1)
        d /= len;
    m_deflection = d;
    update();
    emit deflectionChanged(d);
}

void JoystickPad::release()
{
    const bool was = m_dragging || !m_deflection.isNull();
    m_dragging = false;
    setCursor(Qt::OpenHandCursor);
    m_deflection = {};
    update();
    if (was) {
        emit deflectionChanged(m_deflection);
        emit released();
    }
}

void JoystickPad::mousePressEvent(QMouseEvent* e)
{
    if (e->button() != Qt::LeftButton || !isEnabled())
        return;
    m_dragging = true;
    setCursor(Qt::ClosedHandCursor);
    setFromPosition(e->position());
}

void JoystickPad::mouseMoveEvent(QMouseEvent* e)
{
    if (m_dragging)
        setFromPosition(e->position());
}

void JoystickPad::mouseReleaseEvent(QMouseEvent* e)
{
    if (e->button() == Qt::LeftButton && m_dragging)
        release();
}

void JoystickPad::paintEvent(QPaintEvent*)
{
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    const QPointF c = centre();
    const double r = radius();
    const bool on = isEnabled();
    p.setPen(QPen(QColor(0x90, 0x90, 0x90), 2));
    p.setBrush(on ? QColor(0xf4, 0xf6, 0xf8) : QColor(0xe6, 0xe6, 0xe6));
    p.drawEllipse(c, r, r);
    p.setPen(QPen(QColor(0xc8, 0xc8, 0xc8), 1, Qt::DashLine));
    p.drawLine(QPointF(c.x() - r, c.y()), QPointF(c.x() + r, c.y()));
    p.drawLine(QPointF(c.x(), c.y() - r), QPointF(c.x(), c.y() + r));
    p.setPen(Qt::NoPen);
    p.setBrush(QColor(0xdd, 0xe3, 0xea));
    p.drawEllipse(c, r * m_deadband, r * m_deadband);
    p.setPen(QColor(0x70, 0x70, 0x70));
    p.drawText(QRectF(c.x() + r - 14, c.y() - 20, 30, 16), Qt::AlignCenter, tr("+X", "joystick direction"));
    p.drawText(QRectF(c.x() - 15, c.y() - r - 2, 30, 16), Qt::AlignCenter, tr("+Y", "joystick direction"));
    const QPointF knob(c.x() + m_deflection.x() * r, c.y() - m_deflection.y() * r);
    if (!m_deflection.isNull()) {
        p.setPen(QPen(QColor(0x1f, 0x77, 0xb4, 160), 3));
        p.drawLine(c, knob);
    }
    p.setPen(QPen(QColor(0x12, 0x45, 0x6e), 2));
    p.setBrush(on ? (m_dragging ? QColor(0x1f, 0x77, 0xb4) : QColor(0x4a, 0x90, 0xc8)) : QColor(0xaa, 0xaa, 0xaa));
    p.drawEllipse(knob, 16, 16);
}

} // namespace ui
