#include "widgets/axis_row.h"

#include "widgets/common/number_field.h"

#include "widgets/common/reading_text.h"

#include "widgets/input_policy.h"
#include "widgets/status_lamp.h"

#include <QComboBox>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QToolButton>

#include <cmath>

namespace ui {
namespace {
QWidget* lampBox(QWidget* parent, StatusLamp* lamp)
{
    auto* w = new QWidget(parent);
    auto* l = new QHBoxLayout(w);
    l->setContentsMargins(0, 0, 0, 0);
    l->addStretch();
    l->addWidget(lamp);
    l->addStretch();
    return w;
}
} // namespace

QList<double> AxisRow::stepPresets(const dev::AxisDescriptor& d, dev::proto::DeviceKind kind)
{
    if (d.unit == dev::proto::AxisUnit::Microlitre)
        return {0.5, 1, 5, 10, 50, 100};
    if (kind == dev::proto::DeviceKind::Stage)
        return {0.001, 0.01, 0.1, 1, 10};
    return {0.01, 0.1, 1, 10, 50};
}

AxisRow::AxisRow(int axis, const dev::AxisDescriptor& d, dev::proto::DeviceKind kind, QGridLayout* grid, int row,
                 QWidget* parent)
    : QObject(parent), m_axis(axis), m_desc(d), m_kind(kind)
{
    m_decimals = d.resolution > 0 ? std::max(0, static_cast<int>(std::ceil(-std::log10(d.resolution) - 1e-9))) : 3;
    m_name = new QLabel(QStringLiteral("<b>%1</b>").arg(d.letter), parent);
    QFont mono(QStringLiteral("DejaVu Sans Mono"));
    mono.setStyleHint(QFont::Monospace);
    mono.setPointSizeF(mono.pointSizeF() * 1.15);
    m_commanded = new QLabel(parent);
    m_measured = new QLabel(parent);
    for (QLabel* l : {m_commanded, m_measured}) {
        l->setFont(mono);
        l->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
        l->setMinimumWidth(l->fontMetrics().horizontalAdvance(QStringLiteral("-0000.0000")) + 6);
    }
    m_homed = new StatusLamp(QString(), parent);
    m_homeSwitch = new StatusLamp(QString(), parent);
    m_limitSwitch = new StatusLamp(QString(), parent);
    m_moving = new StatusLamp(QString(), parent);

    m_step = new QComboBox(parent);
    m_step->setEditable(true);
    for (double s : stepPresets(d, kind))
        m_step->addItem(QString::number(s), s);
    m_step->setCurrentIndex(std::min(2, m_step->count() - 1));
    // A typed step is kept as typed: "-5" shows as invalid with its reason (a validator
    // used to drop the minus and step by 5).
    auto* stepEntry = new NumberField(m_step);
    stepEntry->setObjectName(QStringLiteral("jogStep%1").arg(d.letter));
    stepEntry->setFieldName(tr("Step %1").arg(d.letter));
    stepEntry->setRange(0, d.travelMax - d.travelMin);
    m_step->setLineEdit(stepEntry);
    m_step->setCurrentIndex(std::min(2, m_step->count() - 1));
    m_step->setMinimumWidth(80);
    auto makeTool = [&](const QString& text) {
        auto* b = new QToolButton(parent);
        b->setText(text);
        b->setMinimumWidth(34);
        return b;
    };
    m_stepMinus = makeTool(QStringLiteral("−"));
    m_stepPlus = makeTool(QStringLiteral("+"));
    m_holdMinus = makeTool(QStringLiteral("◀◀"));
    m_holdPlus = makeTool(QStringLiteral("▶▶"));
    m_home = new QPushButton(parent);
    m_zero = new QPushButton(parent);
    // The target is kept as typed: "1e9" or "abc" shows as invalid with its reason, and Go says why.
    auto* target = new NumberField(parent);
    target->setObjectName(QStringLiteral("jogTarget%1").arg(d.letter));
    target->setFieldName(tr("Target %1").arg(d.letter));
    target->setRange(-1e6, 1e6);
    target->setEmptyAllowed(true);
    m_target = target;
    m_go = new QPushButton(parent);
    m_limits = new QLabel(parent);
    retranslateUi();
    // Wide enough for its own placeholder ("target mm" was cut to "tar…") and a position.
    m_target->setMinimumWidth(std::max(m_target->fontMetrics().horizontalAdvance(m_target->placeholderText()),
                                       m_target->fontMetrics().horizontalAdvance(QStringLiteral("-0000.000")))
                              + 16);
    m_target->setMaximumWidth(m_target->minimumWidth() + 30);

    int c = 0;
    grid->addWidget(m_name, row, c++);
    grid->addWidget(m_commanded, row, c++);
    grid->addWidget(m_measured, row, c++);
    grid->addWidget(lampBox(parent, m_homed), row, c++);
    grid->addWidget(lampBox(parent, m_homeSwitch), row, c++);
    grid->addWidget(lampBox(parent, m_limitSwitch), row, c++);
    grid->addWidget(lampBox(parent, m_moving), row, c++);
    auto* stepBox = new QWidget(parent);
    auto* sl = new QHBoxLayout(stepBox);
    sl->setContentsMargins(0, 0, 0, 0);
    sl->addWidget(m_stepMinus);
    sl->addWidget(m_step);
    sl->addWidget(m_stepPlus);
    grid->addWidget(stepBox, row, c++);
    auto* holdBox = new QWidget(parent);
    auto* hl = new QHBoxLayout(holdBox);
    hl->setContentsMargins(0, 0, 0, 0);
    hl->addWidget(m_holdMinus);
    hl->addWidget(m_holdPlus);
    grid->addWidget(holdBox, row, c++);
    grid->addWidget(m_home, row, c++);
    grid->addWidget(m_zero, row, c++);
    auto* goBox = new QWidget(parent);
    auto* gl = new QHBoxLayout(goBox);
    gl->setContentsMargins(0, 0, 0, 0);
    gl->addWidget(m_target);
    gl->addWidget(m_go);
    grid->addWidget(goBox, row, c++);
    grid->addWidget(m_limits, row, c++);
    m_controls = {m_step, m_stepMinus, m_stepPlus, m_holdMinus, m_holdPlus, m_home, m_zero, m_target, m_go};

    connect(m_stepMinus, &QToolButton::clicked, this, [this] {
        if (auto s = step())
            emit stepRequested(m_axis, -*s);
    });
    connect(m_stepPlus, &QToolButton::clicked, this, [this] {
        if (auto s = step())
            emit stepRequested(m_axis, *s);
    });
    connect(m_holdMinus, &QToolButton::pressed, this, [this] { emit holdStarted(m_axis, -1); });
    connect(m_holdPlus, &QToolButton::pressed, this, [this] { emit holdStarted(m_axis, +1); });
    connect(m_holdMinus, &QToolButton::released, this, [this] { emit holdEnded(m_axis); });
    connect(m_holdPlus, &QToolButton::released, this, [this] { emit holdEnded(m_axis); });
    connect(m_home, &QPushButton::clicked, this, [this] { emit homeRequested(m_axis); });
    connect(m_zero, &QPushButton::clicked, this, [this] { emit zeroRequested(m_axis); });
    auto go = [this] {
        if (auto* f = qobject_cast<NumberField*>(m_target); f && !f->isValid()) {
            emit problem(tr("Axis %1: %2").arg(m_desc.letter).arg(f->problem()));
            return;
        }
        bool ok = false;
        const double v = QLocale().toDouble(m_target->text(), &ok);
        const double v2 = ok ? v : m_target->text().toDouble(&ok);
        if (!ok) {
            emit problem(tr("Axis %1: '%2' is not a position").arg(m_desc.letter).arg(m_target->text()));
            return;
        }
        emit goToRequested(m_axis, v2);
    };
    connect(m_go, &QPushButton::clicked, this, go);
    connect(m_target, &QLineEdit::returnPressed, this, go);
    connect(m_target, &QLineEdit::returnPressed, this, &AxisRow::doneTyping);
    connect(m_step->lineEdit(), &QLineEdit::returnPressed, this, &AxisRow::doneTyping);
    connect(m_step, qOverload<int>(&QComboBox::activated), this, &AxisRow::doneTyping);
}

AxisRow::~AxisRow() = default;

void AxisRow::retranslateUi()
{
    // The row's widgets sit in its screen's grid, not under this object: the screen's
    // run-time rewording cannot tell this class's words from another's ("Home" the
    // button, "home" the event), so the row words itself again on a language switch.
    const QChar letter = m_desc.letter;
    m_name->setToolTip(m_desc.unit == dev::proto::AxisUnit::Microlitre ? tr("Plunger pump, µL") : tr("Axis %1, mm").arg(letter));
    m_step->setToolTip(tr("Step size in %1: pick a preset or type your own").arg(m_desc.unitName()));
    setUsualToolTip(m_stepMinus, tr("Step %1 down by the step size").arg(letter));
    setUsualToolTip(m_stepPlus, tr("Step %1 up by the step size").arg(letter));
    setUsualToolTip(m_holdMinus, tr("Hold to move %1 down; release to stop").arg(letter));
    setUsualToolTip(m_holdPlus, tr("Hold to move %1 up; release to stop").arg(letter));
    m_home->setText(tr("Home"));
    setUsualToolTip(m_home, tr("Seek the home switch and make it zero"));
    m_zero->setText(tr("Zero"));
    setUsualToolTip(m_zero, tr("Make the present position zero"));
    m_target->setPlaceholderText(tr("target %1").arg(m_desc.unitName()));
    if (auto* f = qobject_cast<NumberField*>(m_target))
        f->setFieldName(tr("Target %1").arg(letter));
    if (auto* f = qobject_cast<NumberField*>(m_step->lineEdit()))
        f->setFieldName(tr("Step %1").arg(letter));
    m_go->setText(tr("Go"));
    setUsualToolTip(m_go, tr("Move %1 to the target (absolute)").arg(letter));
    m_limits->setToolTip(tr("Soft limits: moves beyond them are refused"));
    showLampTips();
}

void AxisRow::showLampTips()
{
    if (m_stale) {
        const QString unknown = tr("Unknown: the instrument is not connected");
        for (StatusLamp* lamp : {m_homed, m_homeSwitch, m_limitSwitch, m_moving})
            lamp->setToolTip(unknown);
        for (QLabel* l : {m_commanded, m_measured})
            l->setToolTip(tr("The last reading before the link went down, not where the axis is now"));
        return;
    }
    m_commanded->setToolTip(tr("Commanded position (%1)").arg(m_desc.unitName()));
    m_measured->setToolTip(m_kind == dev::proto::DeviceKind::Stage ? tr("Grating scale reading (%1)").arg(m_desc.unitName())
                                                              : tr("Encoder reading (%1)").arg(m_desc.unitName()));
    m_homed->setToolTip(m_isHomed ? tr("Homed") : m_homing ? tr("Homing…") : tr("Not homed: absolute moves are refused"));
    m_homeSwitch->setToolTip(tr("Home switch"));
    m_limitSwitch->setToolTip(tr("Limit switch"));
    m_moving->setToolTip(tr("Moving"));
}

QString AxisRow::format(double v) const { return readingText(v, m_decimals); }

std::optional<double> AxisRow::step() const
{
    bool ok = false;
    const QString t = m_step->currentText().trimmed();
    double s = QLocale().toDouble(t, &ok);
    if (!ok)
        s = t.toDouble(&ok);
    if (!ok || !(s > 0)) {
        m_step->setStyleSheet(QStringLiteral("QComboBox { background:#fde2e1; }"));
        emit const_cast<AxisRow*>(this)->problem(tr("Axis %1: step '%2' is not a positive number").arg(m_desc.letter).arg(t));
        return std::nullopt;
    }
    m_step->setStyleSheet(QString());
    return s;
}

void AxisRow::showReadout(const dev::AxisReadout& r)
{
    m_commanded->setText(format(r.commanded));
    m_measured->setText(format(r.measured));
    const bool wasStale = m_stale;
    m_stale = false;
    if (wasStale)
        for (QLabel* l : {m_commanded, m_measured})
            l->setStyleSheet(QString());
    m_homed->setTone(r.homed ? StatusLamp::Tone::Ok : r.homing ? StatusLamp::Tone::Active : StatusLamp::Tone::Warning);
    m_homeSwitch->setTone(r.homeSwitch ? StatusLamp::Tone::Active : StatusLamp::Tone::Off);
    m_limitSwitch->setTone(r.limitSwitch ? StatusLamp::Tone::Alarm : StatusLamp::Tone::Off);
    m_moving->setTone(r.fault ? StatusLamp::Tone::Alarm : r.moving ? StatusLamp::Tone::Active : StatusLamp::Tone::Off);
    const bool tipsChange = wasStale || m_isHomed != r.homed || m_homing != r.homing || m_homed->toolTip().isEmpty();
    m_isHomed = r.homed;
    m_homing = r.homing;
    if (tipsChange)
        showLampTips();
    setEnabledOr(m_go, !m_whyNot.isEmpty() ? m_whyNot
                       : r.homed           ? QString()
                                           : tr("Home %1 first: absolute moves need a homed axis").arg(m_desc.letter));
}

void AxisRow::showStale()
{
    if (m_stale)
        return;
    m_stale = true;
    for (StatusLamp* lamp : {m_homed, m_homeSwitch, m_limitSwitch, m_moving})
        lamp->setTone(StatusLamp::Tone::Unknown);
    m_isHomed = false;
    m_homing = false;
    for (QLabel* l : {m_commanded, m_measured})
        l->setStyleSheet(QStringLiteral("color:#9e9e9e;"));
    showLampTips();
}

void AxisRow::showLimits(const dev::SoftLimits& l)
{
    // Two lines: the Jog screen's grid has to fit a 1366-pixel screen beside the navigation.
    m_limits->setText(QStringLiteral("%1 …\n%2 %3").arg(format(l.min), format(l.max), m_desc.unitName()));
}

void AxisRow::setEnabled(const QString& whyNot)
{
    m_whyNot = whyNot;
    for (QWidget* w : m_controls)
        setEnabledOr(w, whyNot);
    setEnabledOr(m_go, !whyNot.isEmpty() ? whyNot
                       : m_isHomed       ? QString()
                                         : tr("Home %1 first: absolute moves need a homed axis").arg(m_desc.letter));
}

} // namespace ui
