#include "widgets/joystick/joystick_screen.h"

#include "device/client/joystick_driver.h"
#include "widgets/joystick/joystick_pad.h"
#include "widgets/joystick/travel_view.h"
#include "widgets/common/number_field.h"
#include "widgets/common/reading_text.h"

#include "widgets/wording/wording.h"

#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QLocale>
#include <QLabel>
#include <QPushButton>
#include <QSlider>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace ui {

JoystickScreen::JoystickScreen(dev::Instrument* client, QWidget* parent)
    : QWidget(parent), m_client(client), m_driver(new dev::JoystickDriver(client, this))
{
    setFocusPolicy(Qt::StrongFocus);
    auto* top = new QVBoxLayout(this);
    auto* header = new QHBoxLayout;
    m_title = new QLabel(this);
    QFont tf = m_title->font();
    tf.setPointSizeF(tf.pointSizeF() * 1.3);
    tf.setBold(true);
    m_title->setFont(tf);
    m_state = new QLabel(this);
    header->addWidget(m_title);
    header->addSpacing(12);
    header->addWidget(m_state, 1);
    top->addLayout(header);

    auto* body = new QHBoxLayout;
    auto* left = new QVBoxLayout;
    auto* sticks = new QHBoxLayout;
    m_pad = new JoystickPad(this);
    m_pad->setFocusPolicy(Qt::NoFocus);
    sticks->addWidget(m_pad, 1);
    auto* zBox = new QVBoxLayout;
    m_z = new QSlider(Qt::Vertical, this);
    m_z->setObjectName(QStringLiteral("joystickZ"));
    m_z->setRange(-100, 100);
    m_z->setValue(0);
    m_z->setFocusPolicy(Qt::NoFocus);
    m_z->setToolTip(tr("Z: push up or down; it springs back to the centre (stop) when let go"));
    m_zLabel = new QLabel(tr("Z"), this);
    m_zLabel->setAlignment(Qt::AlignCenter);
    zBox->addWidget(m_zLabel);
    zBox->addWidget(m_z, 1, Qt::AlignHCenter);
    sticks->addLayout(zBox);
    left->addLayout(sticks, 1);

    auto* settings = new QGroupBox(tr("Response"), this);
    auto* form = new QFormLayout(settings);
    // Kept as typed: "-5" or "1e9" is shown as invalid with its reason, never turned into
    // another speed; the stick goes on with the settings last valid.
    m_maxSpeed = new NumberField(settings);
    m_maxSpeed->setObjectName(QStringLiteral("joystickMaxSpeed"));
    m_maxSpeed->setRange(0.01, 1000);
    m_maxSpeed->setDisplay('g', 10);
    m_maxSpeed->setUnit(tr(" mm/s"));
    m_maxSpeed->setHelp(tr("Speed at full deflection (each axis is also held to its own maximum)"));
    m_deadband = new NumberField(settings);
    m_deadband->setObjectName(QStringLiteral("joystickDeadband"));
    m_deadband->setRange(0, 50);
    m_deadband->setInteger(true);
    m_deadband->setUnit(tr(" %"));
    m_deadband->setHelp(tr("Deflection around the centre that does nothing"));
    m_expo = new NumberField(settings);
    m_expo->setObjectName(QStringLiteral("joystickExpo"));
    m_expo->setRange(0, 1);
    m_expo->setDisplay('g', 10);
    m_expo->setHelp(tr("0: speed grows linearly with deflection; 1: cubically (finer near the centre)"));
    form->addRow(tr("Max speed"), m_maxSpeed);
    form->addRow(tr("Dead-band"), m_deadband);
    form->addRow(tr("Expo"), m_expo);
    left->addWidget(settings);
    m_readout = new QLabel(this);
    m_readout->setTextFormat(Qt::RichText);
    m_readout->setObjectName(QStringLiteral("joystickReadout"));
    m_speed = new QLabel(this);
    m_speed->setObjectName(QStringLiteral("joystickSpeed"));
    left->addWidget(m_readout);
    left->addWidget(m_speed);
    m_hint = new QLabel(this);  // names PgUp/PgDn only where there is a Z: rebuild()
    m_hint->setWordWrap(true);
    m_hint->setStyleSheet(QStringLiteral("color:#555;"));
    left->addWidget(m_hint);
    body->addLayout(left, 2);

    auto* right = new QVBoxLayout;
    m_travel = new TravelView(this);
    right->addWidget(m_travel, 1);
    auto* clear = new QPushButton(tr("Clear trail"), this);
    clear->setFocusPolicy(Qt::NoFocus);
    right->addWidget(clear, 0, Qt::AlignRight);
    body->addLayout(right, 3);
    top->addLayout(body, 1);

    setSettings(JoystickSettings{});
    connect(m_pad, &JoystickPad::deflectionChanged, this, &JoystickScreen::apply);
    connect(m_z, &QSlider::valueChanged, this, &JoystickScreen::apply);
    connect(m_z, &QSlider::sliderReleased, this, [this] { m_z->setValue(0); });
    connect(clear, &QPushButton::clicked, m_travel, &TravelView::clearTrail);
    for (NumberField* box : {m_maxSpeed, m_deadband, m_expo})
        connect(box, &QLineEdit::editingFinished, this, [this] {
            if (m_maxSpeed->isValid() && m_deadband->isValid() && m_expo->isValid())
                m_inForce = this->settings();
            m_pad->setDeadband(m_inForce.shaping.deadband);
            apply();
        });
    connect(m_client, &dev::Instrument::identified, this, &JoystickScreen::rebuild);
    connect(m_client, &dev::Instrument::statusChanged, this, &JoystickScreen::refresh);
    connect(m_client, &dev::Instrument::limitsChanged, this, &JoystickScreen::refresh);
    connect(m_client, &dev::Instrument::eventReceived, this, [this](const dev::DeviceEvent& e) {
        // Homing sets the coordinates' origin: a trail drawn in the old ones means nothing now.
        if (e.kind == dev::proto::EventKind::HomeDone)
            m_travel->clearTrail();
    });
    connect(m_client, &dev::Instrument::stateChanged, this, [this](dev::LinkState s) {
        if (s != dev::LinkState::Ready)
            stopAll();
        refresh();
    });
    rebuild();
}

JoystickScreen::~JoystickScreen() { stopAll(); }

JoystickSettings JoystickScreen::settings() const
{
    JoystickSettings s = m_inForce;
    if (m_maxSpeed->isValid() && m_deadband->isValid() && m_expo->isValid()) {
        s.maxSpeedMmS = m_maxSpeed->valueOr(s.maxSpeedMmS);
        s.shaping.deadband = m_deadband->valueOr(0) / 100.0;
        s.shaping.expo = m_expo->valueOr(s.shaping.expo);
    }
    return s;
}

void JoystickScreen::setSettings(const JoystickSettings& s)
{
    m_inForce = s;
    m_maxSpeed->setValue(s.maxSpeedMmS);
    m_deadband->setValue(static_cast<int>(std::lround(s.shaping.deadband * 100)));
    m_expo->setValue(s.shaping.expo);
    m_pad->setDeadband(s.shaping.deadband);
}

void JoystickScreen::rebuild()
{
    stopAll();
    const auto& id = m_client->identity();
    m_title->setText(id.axes.isEmpty() ? tr("No instrument") : tr("%1 — joystick").arg(ui::words::modelName(id)));
    m_zAxis = id.axisIndex(QLatin1Char('Z'));
    m_z->setVisible(m_zAxis >= 0);
    m_zLabel->setVisible(m_zAxis >= 0);
    m_hint->setText(m_zAxis >= 0 ? tr("Drag the knob; let go to stop. Arrow keys push the stick to the rim, PgUp/PgDn move Z. "
                                      "Esc: E-stop.")
                                 : tr("Drag the knob; let go to stop. Arrow keys push the stick to the rim. Esc: E-stop."));
    if (id.axes.size() >= 2 && std::min(id.axes[0].maxSpeed, id.axes[1].maxSpeed) > 0.01) {
        const double vmax = std::min(id.axes[0].maxSpeed, id.axes[1].maxSpeed);
        m_maxSpeed->setRange(0.01, vmax);
        if (m_maxSpeed->valueOr(0) > vmax) {
            // The instrument is slower than the setting: shown at its maximum, as in force.
            m_maxSpeed->setValue(vmax);
            m_inForce.maxSpeedMmS = vmax;
        }
    }
    refresh();
}

void JoystickScreen::refresh()
{
    const bool ready = m_client->isReady();
    const auto& st = m_client->status();
    const auto& id = m_client->identity();
    QString state = ui::words::term(dev::linkStateTerm(m_client->state()));
    if (ready && st.estop)
        state = tr("E-STOP active — press Reset E-stop to clear");
    m_state->setText(state);
    m_state->setStyleSheet(ready && !st.estop ? QStringLiteral("color:#2e7d32;") : QStringLiteral("color:#b71c1c; font-weight:bold;"));
    const bool canMove = ready && !st.estop;
    if (!canMove && (m_pad->dragging() || m_z->value() != 0)) {
        m_pad->release();
        m_z->setValue(0);
    }
    m_pad->setEnabled(canMove);
    m_z->setEnabled(canMove);
    if (!m_wish.empty())
        showSpeed();
    if (id.axes.size() < 2 || st.axes.size() < 2)
        return;
    QString rows;
    for (int i = 0; i < id.axes.size() && i < st.axes.size(); ++i) {
        if (id.axes[i].unit != dev::proto::AxisUnit::Millimetre)
            continue;
        rows += tr("<tr><td><b>%1</b></td><td align=right>%2</td><td align=right>%3</td><td>%4</td></tr>")
                    .arg(id.axes[i].letter)
                    .arg(readingText(st.axes[i].commanded, 3), readingText(st.axes[i].measured, 3))
                    .arg(!ready ? QString() : st.axes[i].homed ? QString() : tr("not homed"));
    }
    m_readout->setText(tr("<table cellspacing=6><tr><td></td><td>commanded</td><td>%1</td><td></td></tr>%2</table>")
                           .arg(id.kind == dev::proto::DeviceKind::Stage ? tr("grating") : tr("encoder"), rows));
    // Without a live link the positions are the last ones read: greyed and said so.
    m_readout->setStyleSheet(ready ? QString() : QStringLiteral("color:#9e9e9e;"));
    m_readout->setToolTip(ready ? QString() : tr("The last positions read before the link went down, not where the axes are now"));
    if (!ready)
        return;
    const auto& lim = m_client->softLimits();
    QRectF soft(id.axes[0].travelMin, id.axes[1].travelMin, id.axes[0].travelMax - id.axes[0].travelMin,
                id.axes[1].travelMax - id.axes[1].travelMin);
    if (lim.size() >= 2)
        soft = QRectF(QPointF(lim[0].min, lim[1].min), QPointF(lim[0].max, lim[1].max));
    m_travel->setTravel(QRectF(id.axes[0].travelMin, id.axes[1].travelMin, id.axes[0].travelMax - id.axes[0].travelMin,
                               id.axes[1].travelMax - id.axes[1].travelMin),
                        soft);
    m_travel->addPosition({st.axes[0].measured, st.axes[1].measured}, {st.axes[0].commanded, st.axes[1].commanded});
}

motion::path::Vec2 JoystickScreen::keyDeflection() const
{
    motion::path::Vec2 d{0, 0};
    if (m_keys.contains(Qt::Key_Right))
        d.x += 1;
    if (m_keys.contains(Qt::Key_Left))
        d.x -= 1;
    if (m_keys.contains(Qt::Key_Up))
        d.y += 1;
    if (m_keys.contains(Qt::Key_Down))
        d.y -= 1;
    return d;
}

double JoystickScreen::keyZ() const
{
    return (m_keys.contains(Qt::Key_PageUp) ? 1.0 : 0.0) - (m_keys.contains(Qt::Key_PageDown) ? 1.0 : 0.0);
}

void JoystickScreen::apply()
{
    const auto& id = m_client->identity();
    if (id.axes.size() < 2)
        return;
    const JoystickSettings s = settings();
    motion::path::Vec2 d{m_pad->deflection().x(), m_pad->deflection().y()};
    const motion::path::Vec2 keys = keyDeflection();
    if (!m_pad->dragging() && (keys.x != 0 || keys.y != 0)) {
        d = keys;
        m_pad->showDeflection(QPointF(d.x, d.y) / std::max(1.0, std::hypot(d.x, d.y)));
    } else if (!m_pad->dragging()) {
        m_pad->showDeflection({});
    }
    const motion::path::Vec2 v = motion::jog::shapeStick(d, s.shaping);
    std::map<int, double> wish = {{0, v.x * s.maxSpeedMmS}, {1, v.y * s.maxSpeedMmS}};
    if (m_zAxis >= 0) {
        const double zIn = keyZ() != 0 ? keyZ() : m_z->value() / 100.0;
        wish[m_zAxis] = motion::jog::shapeAxis(zIn, s.shaping) * std::min(s.maxSpeedMmS, id.axes[m_zAxis].maxSpeed);
    }
    m_driver->setVelocities(wish);
    m_wish = wish;
    showSpeed();
}

QString JoystickScreen::speedText() const { return m_speed->text(); }

void JoystickScreen::showSpeed()
{
    // The device holds an axis at its soft limit whatever the stick asks: the line says what
    // the machine does, not the wish ("20.00 mm/s" against a limit was a lie).
    const auto& st = m_client->status();
    const auto& lim = m_client->softLimits();
    const auto& id = m_client->identity();
    double v[2] = {0, 0};
    QStringList held;
    for (int a = 0; a < 2; ++a) {
        const auto it = m_wish.find(a);
        v[a] = it == m_wish.end() ? 0.0 : it->second;
        if (v[a] == 0 || a >= st.axes.size() || a >= lim.size() || a >= id.axes.size())
            continue;
        const double at = st.axes[a].commanded;
        const double slack = std::max(1e-3, 2 * id.axes[a].resolution);
        if ((v[a] < 0 && at <= lim[a].min + slack) || (v[a] > 0 && at >= lim[a].max - slack)) {
            v[a] = 0;
            held << QString(id.axes[a].letter);
        }
    }
    QString text = tr("Commanded speed: %1 mm/s").arg(QLocale().toString(std::hypot(v[0], v[1]), 'f', 2));
    if (!held.isEmpty())
        text += tr(" · %1 held at its soft limit").arg(held.join(QStringLiteral(", ")));
    m_speed->setText(text);
}

void JoystickScreen::stopAll()
{
    m_keys.clear();
    if (m_pad->dragging() || !m_pad->deflection().isNull())
        m_pad->release();
    if (m_z->value() != 0) {
        const QSignalBlocker block(m_z);
        m_z->setValue(0);
    }
    m_driver->stop();
    m_wish.clear();
    // No client read here: stopAll() also runs from the destructor, when the client may be gone.
    m_speed->setText(tr("Commanded speed: %1 mm/s").arg(QLocale().toString(0.0, 'f', 2)));
}

static bool stickKey(int key)
{
    return key == Qt::Key_Left || key == Qt::Key_Right || key == Qt::Key_Up || key == Qt::Key_Down
        || key == Qt::Key_PageUp || key == Qt::Key_PageDown;
}

void JoystickScreen::keyPressEvent(QKeyEvent* event)
{
    if (!stickKey(event->key())) {
        QWidget::keyPressEvent(event);  // Esc goes on to the window's E-stop
        return;
    }
    event->accept();
    if (event->isAutoRepeat() || !m_pad->isEnabled())
        return;
    m_keys.insert(event->key());
    apply();
}

void JoystickScreen::keyReleaseEvent(QKeyEvent* event)
{
    if (!stickKey(event->key()) || event->isAutoRepeat()) {
        QWidget::keyReleaseEvent(event);
        return;
    }
    event->accept();
    m_keys.remove(event->key());
    apply();
}

void JoystickScreen::focusOutEvent(QFocusEvent* event)
{
    // A key release that lands in another window never reaches us; a drag keeps the mouse.
    if (!m_pad->dragging())
        stopAll();
    QWidget::focusOutEvent(event);
}

void JoystickScreen::hideEvent(QHideEvent* event)
{
    stopAll();
    QWidget::hideEvent(event);
}

void JoystickScreen::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::ActivationChange && !isActiveWindow())
        stopAll();
    QWidget::changeEvent(event);
}

} // namespace ui
