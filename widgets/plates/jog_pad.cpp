#include "widgets/plates/jog_pad.h"

#include <QComboBox>
#include <QGridLayout>
#include <QLabel>
#include <QPushButton>
#include <QSlider>

#include <cmath>

namespace ui {

JogPad::JogPad(dev::Instrument* client, QWidget* parent) : QWidget(parent), m_client(client)
{
    auto* g = new QGridLayout(this);
    g->setContentsMargins(0, 0, 0, 0);
    g->addWidget(arrow(tr("▲ back"), 'Y', -1, tr("Y toward the back")), 0, 1);
    g->addWidget(arrow(tr("◀ X−"), 'X', -1, tr("X to the left")), 1, 0);
    g->addWidget(arrow(tr("X+ ▶"), 'X', +1, tr("X to the right")), 1, 2);
    g->addWidget(arrow(tr("▼ front"), 'Y', +1, tr("Y toward the front")), 2, 1);
    g->addWidget(arrow(tr("Z up"), 'Z', -1, tr("Raise the tip")), 0, 4);
    g->addWidget(arrow(tr("Z down"), 'Z', +1, tr("Lower the tip")), 2, 4);
    m_step = new QComboBox(this);
    m_step->addItem(tr("hold to move"), 0.0);
    for (double mm : {0.02, 0.05, 0.1, 0.5, 1.0, 5.0})
        m_step->addItem(tr("step %1 mm").arg(mm), mm);
    m_step->setToolTip(tr("Hold a button to move while it is pressed, or choose a step for each click"));
    g->addWidget(m_step, 1, 4);
    m_speed = new QSlider(Qt::Horizontal, this);
    m_speed->setRange(1, 50);
    m_speed->setValue(5);
    m_speed->setToolTip(tr("Speed as a share of each axis' maximum (slow for teaching)"));
    g->addWidget(new QLabel(tr("speed"), this), 3, 0);
    g->addWidget(m_speed, 3, 1, 1, 4);
    g->setColumnMinimumWidth(3, 16);
}

double JogPad::stepMm() const { return m_step->currentData().toDouble(); }

void JogPad::setStepMm(double mm)
{
    const int i = m_step->findData(mm);
    if (i >= 0)
        m_step->setCurrentIndex(i);
}

QPushButton* JogPad::arrow(const QString& text, char axis, int direction, const QString& tip)
{
    auto* b = new QPushButton(text, this);
    b->setToolTip(tip);
    b->setAutoRepeat(false);
    b->setFocusPolicy(Qt::NoFocus);
    b->setMinimumWidth(80);
    connect(b, &QPushButton::pressed, this, [this, axis, direction] { press(axis, direction); });
    connect(b, &QPushButton::released, this, [this, axis] { release(axis); });
    return b;
}

double JogPad::speed(char axis) const
{
    const int i = m_client->identity().axisIndex(QChar::fromLatin1(axis));
    if (i < 0)
        return 0;
    return m_client->identity().axes[i].maxSpeed * m_speed->value() / 100.0;
}

void JogPad::press(char axis, int direction)
{
    const int i = m_client->identity().axisIndex(QChar::fromLatin1(axis));
    if (i < 0 || !m_client->isReady())
        return;
    const double step = stepMm();
    if (step > 0)
        m_client->jogStep(i, direction * step, speed(axis));
    else
        m_client->startJog(i, direction * speed(axis));
}

void JogPad::release(char axis)
{
    const int i = m_client->identity().axisIndex(QChar::fromLatin1(axis));
    if (i >= 0 && m_client->isJogging(i))
        m_client->stopJog(i);
}

void JogPad::hideEvent(QHideEvent* event)
{
    m_client->stopAllJogs();
    QWidget::hideEvent(event);
}

} // namespace ui
