#include "widgets/connection_bar.h"

#include "device/link/serial_transport.h"
#include "widgets/status_lamp.h"

#include "widgets/wording/wording.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QToolButton>

namespace ui {

QList<qint32> ConnectionBar::baudRates() { return {9600, 19200, 38400, 57600, 115200, 230400, 460800, 921600}; }

ConnectionBar::ConnectionBar(const QString& title, QWidget* parent) : QWidget(parent)
{
    auto* l = new QHBoxLayout(this);
    l->setContentsMargins(4, 2, 4, 2);
    m_lamp = new StatusLamp(tr("Link state"), this);
    m_title = new QLabel(QStringLiteral("<b>%1</b>").arg(title), this);
    m_title->setMinimumWidth(70);
    m_source = new QComboBox(this);
    m_source->setMinimumWidth(190);
    m_source->setToolTip(tr("The simulated instrument, or a serial port"));
    auto* refresh = new QToolButton(this);
    refresh->setText(QStringLiteral("⟳"));
    refresh->setToolTip(tr("Look for serial ports again"));
    m_baud = new QComboBox(this);
    for (qint32 b : baudRates())
        m_baud->addItem(QString::number(b), b);
    m_baud->setCurrentText(QStringLiteral("115200"));
    m_baud->setToolTip(tr("Baud rate (8N1)"));
    m_connect = new QPushButton(tr("Connect"), this);
    m_identity = new QLabel(this);
    m_identity->setStyleSheet(QStringLiteral("color:#444;"));
    l->addWidget(m_lamp);
    l->addWidget(m_title);
    l->addWidget(m_source);
    l->addWidget(refresh);
    l->addWidget(m_baud);
    l->addWidget(m_connect);
    l->addWidget(m_identity, 1);
    refreshPorts();
    connect(refresh, &QToolButton::clicked, this, &ConnectionBar::refreshPorts);
    connect(m_connect, &QPushButton::clicked, this, [this] {
        if (m_state == dev::LinkState::Disconnected || m_state == dev::LinkState::Lost)
            emit connectRequested(choice());
        else
            emit disconnectRequested();
    });
}

void ConnectionBar::refreshPorts()
{
    const ConnectionChoice keep = choice();
    m_source->clear();
    m_source->addItem(tr("Simulator"), QString());
    for (const auto& p : dev::SerialTransport::availablePorts())
        m_source->addItem(p.description.isEmpty() ? p.name : QStringLiteral("%1 — %2").arg(p.name, p.description), p.name);
    setChoice(keep);
}

ConnectionChoice ConnectionBar::choice() const
{
    ConnectionChoice c;
    const QString port = m_source->currentData().toString();
    c.simulator = port.isEmpty();
    c.port = port;
    c.baud = m_baud->currentData().toInt();
    return c;
}

void ConnectionBar::setChoice(const ConnectionChoice& c)
{
    int idx = 0;
    if (!c.simulator) {
        idx = m_source->findData(c.port);
        if (idx < 0) {
            // Keep a remembered port even while it is unplugged, so it can be retried.
            m_source->addItem(tr("%1 (not found)").arg(c.port), c.port);
            idx = m_source->count() - 1;
        }
    }
    m_source->setCurrentIndex(idx);
    const int b = m_baud->findData(c.baud);
    if (b >= 0)
        m_baud->setCurrentIndex(b);
}

void ConnectionBar::showState(dev::LinkState state, const QString& identity)
{
    m_state = state;
    using T = StatusLamp::Tone;
    switch (state) {
    case dev::LinkState::Disconnected: m_lamp->setTone(T::Off); break;
    case dev::LinkState::Connecting:
    case dev::LinkState::Identified: m_lamp->setTone(T::Active); break;
    case dev::LinkState::Ready: m_lamp->setTone(T::Ok); break;
    case dev::LinkState::Lost: m_lamp->setTone(T::Alarm); break;
    }
    m_lamp->setToolTip(words::term(dev::linkStateTerm(state)));
    const bool idle = state == dev::LinkState::Disconnected || state == dev::LinkState::Lost;
    m_connect->setText(idle ? tr("Connect") : tr("Disconnect"));
    m_source->setEnabled(idle);
    m_baud->setEnabled(idle);
    m_identity->setText(QStringLiteral("%1 — %2").arg(words::term(dev::linkStateTerm(state)), identity));
}

} // namespace ui
