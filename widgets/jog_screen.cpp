#include "widgets/jog_screen.h"
#include "widgets/common/button_key.h"

#include "widgets/axis_row.h"
#include "widgets/input_policy.h"
#include "widgets/live_strip.h"
#include "widgets/wording/wording.h"

#include "widgets/wording/wording.h"

#include <QAbstractItemView>
#include <QAbstractSpinBox>
#include <QApplication>
#include <QComboBox>
#include <QGridLayout>
#include <QKeyEvent>
#include <QLocale>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QTextEdit>
#include <QPushButton>
#include <QSlider>
#include <QSplitter>
#include <QVBoxLayout>

#include <cmath>

namespace ui {

JogScreen::JogScreen(dev::Instrument* client, QWidget* parent) : QWidget(parent), m_client(client)
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
    m_homeAll = new QPushButton(tr("Home all"), this);
    m_homeAll->setToolTip(tr("Home every axis (the analyzer lifts Z first, then X and Y)"));
    m_stop = new QPushButton(tr("Stop"), this);
    m_stop->setToolTip(tr("Decelerate every axis to rest (Space)"));
    setButtonKey(m_stop, QKeySequence(Qt::Key_Space));
    // Where homing is not possible (a GRBL controller with $22=0) the operator may take the present
    // position as home; after an alarm that lost the position, unlock on the operator's word.
    m_setHome = new QPushButton(tr("Set home here…"), this);
    m_setHome->setToolTip(tr("Take the present position as home for every axis (the controller cannot home): absolute moves "
                             "count from here"));
    m_setHome->setVisible(false);
    m_unlock = new QPushButton(tr("Unlock…"), this);
    m_unlock->setToolTip(tr("The controller lost track of its position: take the position it believes as true (or home it)"));
    m_unlock->setVisible(false);
    header->addWidget(m_setHome);
    header->addWidget(m_unlock);
    header->addWidget(m_homeAll);
    header->addWidget(m_stop);
    top->addLayout(header);

    auto* speedRow = new QHBoxLayout;
    speedRow->addWidget(new QLabel(tr("Jog speed"), this));
    m_speed = new QSlider(Qt::Horizontal, this);
    m_speed->setRange(1, 100);
    m_speed->setValue(20);
    m_speed->setMaximumWidth(260);
    m_speed->setToolTip(tr("Hold-to-jog speed as a share of each axis' maximum; hold Shift for full speed"));
    m_speedLabel = new QLabel(this);
    speedRow->addWidget(m_speed);
    speedRow->addWidget(m_speedLabel);
    speedRow->addSpacing(24);
    m_keys = new QLabel(this);  // the instrument's own axes: worded in showKeys()
    m_keys->setObjectName(QStringLiteral("jogKeys"));
    m_keys->setStyleSheet(QStringLiteral("color:#555;"));
    speedRow->addWidget(m_keys);
    speedRow->addSpacing(12);
    // Whether the arrow keys move the machine or the text cursor: said, not guessed.
    m_keysMode = new QLabel(this);
    speedRow->addWidget(m_keysMode);
    speedRow->addStretch();
    connect(qApp, &QApplication::focusChanged, this, [this] { showKeysMode(); });
    // Jog keys reach this screen whichever of its controls (a button, the slider, the
    // tab bar) has the focus; only a text field being edited keeps them.
    qApp->installEventFilter(this);
    top->addLayout(speedRow);
    // A device that cannot stop by itself when BenchPilot goes away (GRBL) says so, with the bound.
    m_hostLossNote = new QLabel(this);
    m_hostLossNote->setWordWrap(true);
    m_hostLossNote->setStyleSheet(QStringLiteral("color:#8a4b00;"));
    m_hostLossNote->setVisible(false);
    top->addWidget(m_hostLossNote);

    m_gridHost = new QWidget(this);
    m_grid = new QGridLayout(m_gridHost);
    m_grid->setHorizontalSpacing(6);  // 13 columns beside the navigation on a 1366-pixel screen
    top->addWidget(m_gridHost);
    m_strip = new LiveStrip(this);
    m_strip->setVisible(false);
    top->addWidget(m_strip, 3);
    top->addStretch(1);

    auto updateSpeedLabel = [this] { m_speedLabel->setText(tr("%1 %").arg(m_speed->value())); };
    updateSpeedLabel();
    connect(m_speed, &QSlider::valueChanged, this, updateSpeedLabel);
    connect(m_speed, &QSlider::valueChanged, this, [this] {
        for (auto it = m_holds.cbegin(); it != m_holds.cend(); ++it)
            m_client->startJog(it.key(), holdVelocity(it.key(), it.value()));
    });
    connect(m_homeAll, &QPushButton::clicked, this, [this] { homeAxes(0); });
    connect(m_setHome, &QPushButton::clicked, this, [this] {
        if (confirm(tr("Take the present position as home for every axis of the %1? Absolute moves then count from here: do so "
                       "only when you know where the machine stands.")
                        .arg(m_client->identity().kindName())))
            m_client->setZero(0);
    });
    connect(m_unlock, &QPushButton::clicked, this, [this] {
        if (confirm(tr("Unlock the %1? Its controller lost track of its position; unlocking takes the position it believes as "
                       "true. Home it as soon as you can.")
                        .arg(m_client->identity().kindName())))
            m_client->unlock();
    });
    connect(m_stop, &QPushButton::clicked, this, [this] {
        endAllHolds();
        m_client->stop();
    });
    connect(m_client, &dev::Instrument::identified, this, &JogScreen::rebuild);
    connect(m_client, &dev::Instrument::statusChanged, this, &JogScreen::refresh);
    connect(m_client, &dev::Instrument::limitsChanged, this, &JogScreen::refresh);
    connect(m_client, &dev::Instrument::stateChanged, this, [this](dev::LinkState s) {
        if (s != dev::LinkState::Ready)
            m_holds.clear();  // the client dropped its jogs with the link
        refresh();
    });
    rebuild();
}

void JogScreen::setTelemetry(dev::tele::TelemetryHub* hub, int instrument)
{
    m_strip->setTelemetry(hub, instrument);
    m_strip->setVisible(hub != nullptr);
}

double JogScreen::speedFraction() const { return m_speed->value() / 100.0; }

void JogScreen::setSpeedFraction(double f) { m_speed->setValue(static_cast<int>(std::lround(std::clamp(f, 0.01, 1.0) * 100))); }

void JogScreen::rebuild()
{
    endAllHolds();
    qDeleteAll(m_rows);
    m_rows.clear();
    while (QLayoutItem* item = m_grid->takeAt(0)) {
        delete item->widget();
        delete item;
    }
    const auto& id = m_client->identity();
    m_title->setText(id.axes.isEmpty() ? tr("No instrument") : ui::words::modelName(id));
    showKeys();
    if (id.axes.isEmpty()) {
        refresh();
        return;
    }
    const QStringList heads = {tr("Axis"), tr("Commanded"), id.kind == dev::proto::DeviceKind::Stage ? tr("Grating") : tr("Encoder"),
                               tr("Homed"), tr("Home sw"), tr("Limit sw"), tr("Moving"), tr("Step"), tr("Hold"),
                               QString(), QString(), tr("Go to"), tr("Soft limits")};
    for (int c = 0; c < heads.size(); ++c) {
        auto* h = new QLabel(QStringLiteral("<span style='color:#555'>%1</span>").arg(heads[c]), m_gridHost);
        h->setAlignment(c == 1 || c == 2 ? Qt::AlignRight : Qt::AlignCenter);
        m_grid->addWidget(h, 0, c);
    }
    for (int i = 0; i < id.axes.size(); ++i) {
        auto* row = new AxisRow(i, id.axes[i], id.kind, m_grid, i + 1, m_gridHost);
        connect(row, &AxisRow::stepRequested, this, [this](int axis, double delta) {
            m_strip->setAxis(axis);
            const double v = m_client->identity().axes[axis].maxSpeed * speedFraction();
            m_client->jogStep(axis, delta, std::max(v, 1e-3));
        });
        connect(row, &AxisRow::holdStarted, this, &JogScreen::startHold);
        connect(row, &AxisRow::holdEnded, this, &JogScreen::endHold);
        connect(row, &AxisRow::homeRequested, this, [this](int axis) { homeAxes(static_cast<quint8>(1u << axis)); });
        connect(row, &AxisRow::zeroRequested, this, [this](int axis) { m_client->setZero(static_cast<quint8>(1u << axis)); });
        connect(row, &AxisRow::goToRequested, this, &JogScreen::goTo);
        connect(row, &AxisRow::problem, this, &JogScreen::problem);
        connect(row, &AxisRow::doneTyping, this, [this] { setFocus(Qt::OtherFocusReason); });
        m_rows << row;
    }
    m_grid->setColumnStretch(heads.size(), 1);
    QStringList letters;
    for (const auto& a : id.axes)
        letters << QString(a.letter);
    m_strip->setAxes(letters);
    refresh();
}

void JogScreen::refresh()
{
    const bool ready = m_client->isReady();
    const auto& st = m_client->status();
    QString state = ui::words::term(dev::linkStateTerm(m_client->state()));
    if (ready && st.estop)
        state = tr("E-STOP active — press Reset E-stop to clear");
    m_state->setText(state);
    m_state->setStyleSheet(ready && !st.estop ? QStringLiteral("color:#2e7d32;") : QStringLiteral("color:#b71c1c; font-weight:bold;"));
    const bool canMove = ready && !st.estop;
    const bool canHome = m_client->can(dev::Capability::Homing);
    // A greyed control says why: the same reason for the whole screen.
    const QString whyNot = !ready ? tr("Connect the instrument first")
        : st.estop               ? tr("E-STOP is latched: press Reset E-stop first")
                                 : QString();
    setUsualToolTip(m_homeAll, tr("Home every axis (the analyzer lifts Z first, then X and Y)"));
    setEnabledOr(m_homeAll, !whyNot.isEmpty() ? whyNot : canHome ? QString() : ui::words::text(m_client->whyNot(dev::Capability::Homing)));
    m_setHome->setVisible(ready && !m_client->capabilities().testFlag(dev::Capability::Homing)
                          && m_client->capabilities().testFlag(dev::Capability::SetZero));
    m_setHome->setEnabled(canMove && !st.anyMoving() && !st.positionLost);
    m_unlock->setVisible(ready && st.positionLost);
    const bool noWatchdog = ready && m_client->capabilities().testFlag(dev::Capability::VelocityJog)
                            && !m_client->capabilities().testFlag(dev::Capability::StopsOnHostLoss);
    m_hostLossNote->setVisible(noWatchdog);
    if (noWatchdog)
        m_hostLossNote->setText(ui::words::text(m_client->whyNot(dev::Capability::StopsOnHostLoss)));
    setEnabledOr(m_stop, ready ? QString() : tr("Connect the instrument first"));
    for (AxisRow* r : m_rows) {
        r->setEnabled(whyNot);
        if (!ready)
            r->showStale();
        else if (r->axis() < st.axes.size())
            r->showReadout(st.axes[r->axis()]);
        if (r->axis() < m_client->softLimits().size())
            r->showLimits(m_client->softLimits()[r->axis()]);
    }
}

void JogScreen::showKeys()
{
    // Only the keys of axes the instrument has: the stage has no Z for PgUp/PgDn to move.
    const auto& id = m_client->identity();
    QStringList axes;
    if (id.axisIndex(QLatin1Char('X')) >= 0)
        axes << QStringLiteral("←/→ X");
    if (id.axisIndex(QLatin1Char('Y')) >= 0)
        axes << QStringLiteral("↑/↓ Y");
    if (id.axisIndex(QLatin1Char('Z')) >= 0)
        axes << QStringLiteral("PgUp/PgDn Z");
    m_keys->setText(axes.isEmpty() ? tr("Keys: Space stop, Esc E-stop")
                                   : tr("Keys: %1, Shift fast, Space stop, Esc E-stop").arg(axes.join(tr(", ", "between the items of a list"))));
}

void JogScreen::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange && m_keys) {
        // Worded here rather than by the window's rewording of texts already shown: the rows'
        // buttons sit in this screen's grid, where "Home" could be read as another class's word.
        const auto& id = m_client->identity();
        m_title->setText(id.axes.isEmpty() ? tr("No instrument") : ui::words::modelName(id));
        showKeys();
        for (AxisRow* r : m_rows)
            r->retranslateUi();
        refresh();
        showKeysMode();
    }
    QWidget::changeEvent(event);
}

bool JogScreen::confirm(const QString& question) { return !m_confirm || m_confirm(question); }

double JogScreen::holdVelocity(int axis, int direction) const
{
    const double vmax = m_client->identity().axes[axis].maxSpeed;
    return direction * vmax * (m_fast ? 1.0 : speedFraction());
}

void JogScreen::startHold(int axis, int direction)
{
    if (!m_client->isReady() || axis < 0 || axis >= m_client->identity().axes.size())
        return;
    m_holds[axis] = direction;
    m_strip->setAxis(axis);
    m_client->startJog(axis, holdVelocity(axis, direction));
}

void JogScreen::endHold(int axis)
{
    if (m_holds.remove(axis))
        m_client->stopJog(axis);
}

void JogScreen::endAllHolds()
{
    const auto axes = m_holds.keys();
    for (int a : axes)
        endHold(a);
}

void JogScreen::homeAxes(quint8 mask)
{
    const auto& id = m_client->identity();
    QString which;
    for (int i = 0; i < id.axes.size(); ++i)
        if (mask == 0 || (mask & (1u << i)))
            which += id.axes[i].letter;
    const QString order = m_client->capabilities().testFlag(dev::Capability::CoupledXyThenZ) && which.contains(QLatin1Char('Z')) && which.size() > 1
        ? tr(" Z rises to its switch first, then the other axes go to theirs.")
        : QString();
    // Homing the plunger drives it to its empty end: whatever it holds goes out of the tip.
    QString liquid;
    const auto& st = m_client->status();
    for (int i = 0; i < id.axes.size() && i < st.axes.size(); ++i)
        if ((mask == 0 || (mask & (1u << i))) && id.axes[i].letter == QLatin1Char('P') && st.axes[i].commanded > 0.05)
            liquid = tr(" The plunger holds %1 µL: homing it pushes that out of the tip, wherever the tip is now.")
                         .arg(QLocale().toString(st.axes[i].commanded, 'f', 1));
    if (!confirm(tr("Home %1 of the %2?%3%4 Keep hands and labware clear.").arg(which, ui::words::term(dev::instrumentTerm(id.kind)), order, liquid)))
        return;
    m_client->home(mask);
}

void JogScreen::goTo(int axis, double target)
{
    const auto& id = m_client->identity();
    const auto& d = id.axes[axis];
    const double from = axis < m_client->status().axes.size() ? m_client->status().axes[axis].commanded : 0;
    const double travel = d.travelMax - d.travelMin;
    const Confirm& ask = m_confirmLongMove ? m_confirmLongMove : m_confirm;
    if (std::abs(target - from) > kFarMoveShare * travel && ask
        && !ask(tr("Move %1 from %2 to %3 %4? That is %5 %4.")
                        .arg(d.letter)
                        .arg(from, 0, 'f', 3)
                        .arg(target, 0, 'f', 3)
                        .arg(d.unitName())
                        .arg(std::abs(target - from), 0, 'f', 3)))
        return;
    m_client->move({{axis, target}}, false);
}

int JogScreen::axisForKey(int key, int* direction) const
{
    const auto& id = m_client->identity();
    QChar letter;
    switch (key) {
    case Qt::Key_Left: letter = QLatin1Char('X'); *direction = -1; break;
    case Qt::Key_Right: letter = QLatin1Char('X'); *direction = +1; break;
    case Qt::Key_Up: letter = QLatin1Char('Y'); *direction = +1; break;
    case Qt::Key_Down: letter = QLatin1Char('Y'); *direction = -1; break;
    case Qt::Key_PageUp: letter = QLatin1Char('Z'); *direction = +1; break;
    case Qt::Key_PageDown: letter = QLatin1Char('Z'); *direction = -1; break;
    default: return -1;
    }
    return id.axisIndex(letter);
}

/// A text field that needs the arrow keys has the focus: a line edit, an editable combo,
/// a spin box, an editable text. A list, a button or a combo picked from keeps no jog keys.
// A table or list with the focus keeps the arrow keys: an operator who clicked a recipe
// step and presses Down means the next step, not a move of the machine.
static bool listFocus() { return qobject_cast<QAbstractItemView*>(QApplication::focusWidget()) != nullptr; }

static bool typingFocus()
{
    QWidget* f = QApplication::focusWidget();
    if (!f)
        return false;
    if (auto* c = qobject_cast<QComboBox*>(f))
        return c->isEditable();
    if (auto* t = qobject_cast<QPlainTextEdit*>(f))
        return !t->isReadOnly();
    if (auto* t = qobject_cast<QTextEdit*>(f))
        return !t->isReadOnly();
    return qobject_cast<QLineEdit*>(f) || qobject_cast<QAbstractSpinBox*>(f) || listFocus();
}

void JogScreen::addPanel(QWidget* panel)
{
    // Beside the live strip, not under it: on a 768-pixel display the rows under the axes
    // are all the height there is, and a picture a few rows high is no picture.
    auto* top = static_cast<QVBoxLayout*>(layout());
    const int at = top->indexOf(m_strip);
    auto* split = new QSplitter(Qt::Horizontal, this);
    split->setChildrenCollapsible(false);
    top->removeWidget(m_strip);
    split->addWidget(m_strip);
    split->addWidget(panel);
    split->setStretchFactor(0, 1);
    split->setStretchFactor(1, 1);
    top->insertWidget(at, split, 6);
}

bool JogScreen::typing() const { return isVisible() && typingFocus(); }

bool JogScreen::keysAreMine() const { return isVisible() || (m_keysElsewhere && m_keysElsewhere()); }

QString JogScreen::keysModeText() const
{
    if (!typing())
        return tr("Keys jog the axes");
    return listFocus() ? tr("A list has the keys — click an empty spot to jog with them")
                       : tr("Typing in a field — press Enter or click an empty spot to jog with the keys");
}

void JogScreen::showKeysMode()
{
    m_keysMode->setText(keysModeText());
    m_keysMode->setStyleSheet(typing() ? QStringLiteral("color:#8a4b00; font-weight:bold;") : QStringLiteral("color:#2e7d32;"));
}

void JogScreen::showEvent(QShowEvent* event)
{
    QWidget::showEvent(event);
    // Coming to this screen, the keys jog: the focus is not left in a Step or Go-to field.
    if (typingFocus() || !QApplication::focusWidget() || !isAncestorOf(QApplication::focusWidget()))
        setFocus(Qt::OtherFocusReason);
    showKeysMode();
}

bool JogScreen::eventFilter(QObject* watched, QEvent* event)
{
    const QEvent::Type t = event->type();
    if ((t == QEvent::KeyPress || t == QEvent::KeyRelease || t == QEvent::ShortcutOverride) && watched != this && keysAreMine()
        && watched->isWidgetType() && static_cast<QWidget*>(watched)->window() == window() && !typingFocus()) {
        auto* k = static_cast<QKeyEvent*>(event);
        int direction = 0;
        if (axisForKey(k->key(), &direction) >= 0) {
            if (t == QEvent::ShortcutOverride)
                return false;  // no shortcut takes them; the key event follows
            return handleJogKey(k, t == QEvent::KeyPress);
        }
    }
    return QWidget::eventFilter(watched, event);
}

bool JogScreen::handleJogKey(QKeyEvent* event, bool press)
{
    if (press)
        keyPressEvent(event);
    else
        keyReleaseEvent(event);
    return event->isAccepted();
}

void JogScreen::keyPressEvent(QKeyEvent* event)
{
    if (event->key() == Qt::Key_Shift) {
        m_fast = true;
        for (auto it = m_holds.cbegin(); it != m_holds.cend(); ++it)
            m_client->startJog(it.key(), holdVelocity(it.key(), it.value()));
    }
    int direction = 0;
    const int axis = axisForKey(event->key(), &direction);
    if (axis < 0 || typingFocus()) {
        QWidget::keyPressEvent(event);
        return;
    }
    event->accept();
    if (event->isAutoRepeat())
        return;  // the hold is already running; repeats would only re-send it
    m_fast = event->modifiers() & Qt::ShiftModifier;
    startHold(axis, direction);
}

void JogScreen::keyReleaseEvent(QKeyEvent* event)
{
    if (event->key() == Qt::Key_Shift) {
        m_fast = false;
        for (auto it = m_holds.cbegin(); it != m_holds.cend(); ++it)
            m_client->startJog(it.key(), holdVelocity(it.key(), it.value()));
    }
    int direction = 0;
    const int axis = axisForKey(event->key(), &direction);
    if (axis < 0 || event->isAutoRepeat()) {
        QWidget::keyReleaseEvent(event);
        return;
    }
    event->accept();
    endHold(axis);
}

void JogScreen::focusOutEvent(QFocusEvent* event)
{
    // A key release that lands in another window never reaches us: stop now.
    endAllHolds();
    QWidget::focusOutEvent(event);
}

void JogScreen::hideEvent(QHideEvent* event)
{
    endAllHolds();
    QWidget::hideEvent(event);
}

} // namespace ui
