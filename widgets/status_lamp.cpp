#include "widgets/status_lamp.h"

#include <QPainter>

namespace ui {

StatusLamp::StatusLamp(const QString& toolTip, QWidget* parent) : QWidget(parent)
{
    setToolTip(toolTip);
    setFixedSize(16, 16);
}

void StatusLamp::setTone(Tone tone)
{
    if (tone == m_tone)
        return;
    m_tone = tone;
    update();
}

void StatusLamp::paintEvent(QPaintEvent*)
{
    QColor c;
    switch (m_tone) {
    case Tone::Off: c = QColor(0xC8, 0xC8, 0xC8); break;
    case Tone::Ok: c = QColor(0x2E, 0xA0, 0x43); break;
    case Tone::Active: c = QColor(0x1F, 0x6F, 0xEB); break;
    case Tone::Warning: c = QColor(0xE3, 0x9B, 0x0B); break;
    case Tone::Alarm: c = QColor(0xD7, 0x26, 0x2B); break;
    case Tone::Unknown: c = QColor(0x9E, 0x9E, 0x9E); break;
    }
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    if (m_tone == Tone::Unknown) {
        p.setPen(QPen(c, 1.5, Qt::DotLine));
        p.setBrush(Qt::NoBrush);
        p.drawEllipse(QRectF(2.5, 2.5, width() - 5, height() - 5));
        return;
    }
    p.setPen(QPen(c.darker(140), 1));
    p.setBrush(c);
    p.drawEllipse(QRectF(2, 2, width() - 4, height() - 4));
}

} // namespace ui
