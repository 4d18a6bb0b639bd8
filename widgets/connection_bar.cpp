#include "widgets/connection_bar.h"
#include "widgets/common/elided_label.h"

#include "widgets/status_lamp.h"

#include "widgets/wording/wording.h"

#include <QComboBox>
#include <QEvent>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QTimer>
#include <QToolButton>

namespace ui {

namespace {
/// The profile list's last entry opens a file dialog rather than naming a profile.
const QString kOpenProfile = QStringLiteral("\x01open");
/// A listed port's serial number, beside its name (Qt::UserRole).
constexpr int kSerialNumberRole = Qt::UserRole + 1;
} // namespace

QList<qint32> ConnectionBar::baudRates() { return {9600, 19200, 38400, 57600, 115200, 230400, 250000, 460800, 921600}; }

ConnectionBar::ConnectionBar(const QString& title, QWidget* parent) : QWidget(parent), m_titleText(title)
{
    auto* l = new QHBoxLayout(this);
    l->setContentsMargins(4, 2, 4, 2);
    m_lamp = new StatusLamp(QString(), this);
    m_title = new QLabel(this);
    m_title->setMinimumWidth(70);
    m_source = new QComboBox(this);
    m_source->setMinimumWidth(170);
    // A path can be typed in: benchpilot-sim's pty, or a port the system does not list.
    m_source->setEditable(true);
    m_source->setInsertPolicy(QComboBox::NoInsert);
    m_source->setFocusPolicy(Qt::StrongFocus);
    m_refresh = new QToolButton(this);
    m_refresh->setText(QStringLiteral("⟳"));
    m_baud = new QComboBox(this);
    m_baud->setFocusPolicy(Qt::StrongFocus);
    for (qint32 b : baudRates())
        m_baud->addItem(QString::number(b), b);
    m_baud->setCurrentText(QStringLiteral("115200"));
    m_profile = new QComboBox(this);
    m_profile->setFocusPolicy(Qt::StrongFocus);
    m_profile->setMinimumWidth(110);
    m_profile->setMaximumWidth(200);
    m_profile->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_profile->addItem(QString(), QString());
    m_profile->addItem(QString(), kOpenProfile);
    m_connect = new QPushButton(this);
    // Whatever room is left: a long identity ends in "…", the whole of it in the tooltip.
    m_identity = new ElidedLabel(this);
    m_identity->setStyleSheet(QStringLiteral("color:#444;"));
    m_identity->setMinimumWidth(40);  // a few letters of the state at least; the status bar has it all
    l->addWidget(m_lamp);
    l->addWidget(m_title);
    l->addWidget(m_source);
    l->addWidget(m_refresh);
    l->addWidget(m_baud);
    l->addWidget(m_profile);
    l->addWidget(m_connect);
    l->addWidget(m_identity, 1);
    m_source->addItem(QString(), QString());  // the simulator; worded in retranslateUi()
    retranslateUi();
    refreshPorts();
    connect(m_refresh, &QToolButton::clicked, this, &ConnectionBar::refreshPorts);
    connect(m_connect, &QPushButton::clicked, this, [this] {
        if (m_state == dev::LinkState::Disconnected || m_state == dev::LinkState::Lost)
            emit connectRequested(choice());
        else
            emit disconnectRequested();
    });
    // Return in the typed path connects. An editable combo hands the key to its line edit a
    // second time: the request is made once per turn of the event loop.
    connect(m_source->lineEdit(), &QLineEdit::returnPressed, this, [this] {
        if (m_returnQueued)
            return;
        m_returnQueued = true;
        QTimer::singleShot(0, this, [this] {
            m_returnQueued = false;
            if (m_state == dev::LinkState::Disconnected || m_state == dev::LinkState::Lost)
                emit connectRequested(choice());
        });
    });
    connect(m_profile, QOverload<int>::of(&QComboBox::activated), this, [this](int index) {
        if (m_profile->itemData(index).toString() == kOpenProfile) {
            m_profile->setCurrentIndex(m_lastProfile);
            emit profileFileRequested();
            return;
        }
        m_lastProfile = index;
        m_profile->setToolTip(m_profile->itemData(index).toString().isEmpty() ? QString() : m_profile->itemData(index).toString());
        updateTexts();
    });
}

void ConnectionBar::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    QWidget::changeEvent(event);
}

void ConnectionBar::setTitle(const QString& title)
{
    m_titleText = title;
    m_title->setText(QStringLiteral("<b>%1</b>").arg(m_titleText));
}

void ConnectionBar::retranslateUi()
{
    m_title->setText(QStringLiteral("<b>%1</b>").arg(m_titleText));
    m_lamp->setToolTip(tr("Link state"));
    m_source->setItemText(0, tr("Simulator"));
    m_source->lineEdit()->setPlaceholderText(tr("port or path"));
    m_refresh->setToolTip(tr("Look for serial ports again"));
    m_profile->setItemText(0, tr("Default wiring"));
    m_profile->setItemText(m_profile->count() - 1, tr("Open a profile file…"));
    updateTexts();
}

void ConnectionBar::updateTexts()
{
    const bool idle = m_state == dev::LinkState::Disconnected || m_state == dev::LinkState::Lost;
    m_connect->setText(idle ? tr("Connect") : tr("Disconnect"));
    const QString locked = tr("Disconnect to change the connection.");
    m_source->setToolTip(idle ? tr("The simulated instrument, a serial port, or a path typed in (e.g. the pty benchpilot-sim "
                                   "serves); the protocol is detected when it connects: BenchPilot or GRBL")
                              : locked);
    m_baud->setToolTip(idle ? tr("Baud rate (8N1); GRBL boards usually run at 115200") : locked);
    const QString profile = m_profile->currentData().toString();
    m_profile->setToolTip(!idle ? locked
                          : profile.isEmpty()
                              ? tr("Machine profile: how a GRBL controller is wired to this instrument (axes, pump, trigger "
                                   "output, status rate). Default wiring: each axis on the GRBL axis of its letter, the "
                                   "analyzer's pump on A at 1 µL per mm, no trigger")
                              : tr("Machine profile %1").arg(profile));
    m_identity->setFullText(m_activity.isEmpty() ? QStringLiteral("%1 — %2").arg(ui::words::term(dev::linkStateTerm(m_state)), m_identityText)
                                                 : m_activity);
}

QString ConnectionBar::portLabel(const dev::SerialTransport::PortInfo& port)
{
    // What the adapter says of itself, as it says it (not translated); a manufacturer the
    // description already names is not said twice.
    QString what = port.description;
    if (!port.manufacturer.isEmpty() && !what.contains(port.manufacturer, Qt::CaseInsensitive))
        what = what.isEmpty() ? port.manufacturer : QStringLiteral("%1 %2").arg(port.manufacturer, what);
    if (what.isEmpty() && port.serialNumber.isEmpty())
        return port.name;
    if (port.serialNumber.isEmpty())
        return QStringLiteral("%1 — %2").arg(port.name, what);
    if (what.isEmpty())
        return tr("%1 — serial number %2").arg(port.name, port.serialNumber);
    return tr("%1 — %2, serial number %3").arg(port.name, what, port.serialNumber);
}

void ConnectionBar::setPortLister(PortLister lister)
{
    m_listPorts = std::move(lister);
    refreshPorts();
}

void ConnectionBar::refreshPorts()
{
    const ConnectionChoice keep = choice();
    while (m_source->count() > 1)
        m_source->removeItem(1);
    for (const auto& p : m_listPorts ? m_listPorts() : QList<dev::SerialTransport::PortInfo>{}) {
        m_source->addItem(portLabel(p), p.name);
        m_source->setItemData(m_source->count() - 1, p.serialNumber, kSerialNumberRole);
    }
    setChoice(keep);
}

ConnectionChoice ConnectionBar::choice() const
{
    ConnectionChoice c;
    const QString text = m_source->currentText().trimmed();
    const int idx = m_source->currentIndex();
    QString port;
    if (idx >= 0 && m_source->itemText(idx) == m_source->currentText()) {
        port = m_source->itemData(idx).toString();  // a listed entry
        c.serialNumber = m_source->itemData(idx, kSerialNumberRole).toString();
    } else if (!text.isEmpty() && text != m_source->itemText(0)) {
        port = text;                                 // a path typed in
    }
    c.simulator = port.isEmpty();
    c.port = port;
    c.baud = m_baud->currentData().toInt();
    c.profile = m_profile->currentData().toString();
    if (c.profile == kOpenProfile)
        c.profile.clear();
    return c;
}

void ConnectionBar::setChoice(const ConnectionChoice& c)
{
    int idx = 0;
    if (!c.simulator) {
        // The adapter by its serial number first: replugged, it may be ttyUSB1 now, and
        // ttyUSB0 another adapter.
        idx = c.serialNumber.isEmpty() ? -1 : m_source->findData(c.serialNumber, kSerialNumberRole);
        if (idx < 0)
            idx = m_source->findData(c.port);
        if (idx < 0) {
            // A typed path that exists (a pty, a /dev/serial/by-id link) is shown as it is; a
            // remembered port that is not there now is kept, so it can be retried when it is back.
            m_source->addItem(QFileInfo::exists(c.port) ? c.port : tr("%1 (not found)").arg(c.port), c.port);
            idx = m_source->count() - 1;
            m_source->setItemData(idx, c.serialNumber, kSerialNumberRole);
        }
    }
    m_source->setCurrentIndex(idx);
    const int b = m_baud->findData(c.baud);
    if (b >= 0)
        m_baud->setCurrentIndex(b);
    if (c.profile.isEmpty()) {
        m_profile->setCurrentIndex(0);
        m_lastProfile = 0;
    } else {
        addProfile(c.profile, true);
    }
    updateTexts();
}

int ConnectionBar::openProfileIndex() const { return m_profile->count() - 1; }

void ConnectionBar::addProfile(const QString& path, bool choose)
{
    if (path.isEmpty())
        return;
    int idx = m_profile->findData(path);
    if (idx < 0) {
        m_profile->insertItem(openProfileIndex(), QFileInfo(path).fileName(), path);
        idx = m_profile->findData(path);
    }
    if (choose) {
        m_profile->setCurrentIndex(idx);
        m_lastProfile = idx;
    }
    updateTexts();
}

QStringList ConnectionBar::profiles() const
{
    QStringList out;
    for (int i = 1; i < openProfileIndex(); ++i)
        out << m_profile->itemData(i).toString();
    return out;
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
    m_lamp->setToolTip(ui::words::term(dev::linkStateTerm(state)));
    const bool idle = state == dev::LinkState::Disconnected || state == dev::LinkState::Lost;
    m_source->setEnabled(idle);
    m_baud->setEnabled(idle);
    m_profile->setEnabled(idle);
    m_refresh->setEnabled(idle);
    m_identityText = identity;
    updateTexts();
}

void ConnectionBar::showActivity(const QString& text)
{
    m_activity = text;
    if (!text.isEmpty())
        m_lamp->setTone(StatusLamp::Tone::Active);
    updateTexts();
}

} // namespace ui
