#include "widgets/tuning/gains_panel.h"

#include "widgets/common/number_field.h"

#include <QGridLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

#include <cmath>

namespace ui {

using motion::control::ContinuousGains;
using motion::control::DiscreteGains;

namespace {
QString gainText(double v) { return QString::number(v, 'g', 5); }

QString seconds(double s)
{
    if (!std::isfinite(s))
        return QStringLiteral("∞");
    if (s == 0)
        return QStringLiteral("0");
    if (std::abs(s) < 1e-3)
        return QStringLiteral("%1 µs").arg(gainText(s * 1e6));
    if (std::abs(s) < 1)
        return QStringLiteral("%1 ms").arg(gainText(s * 1e3));
    return QStringLiteral("%1 s").arg(gainText(s));
}
} // namespace

QString describeGains(const DiscreteGains& g, double periodS)
{
    const ContinuousGains c = motion::control::toContinuous(g, periodS);
    return GainsPanel::tr("Kp %1 · Ki %2 /s · Kd %3").arg(gainText(c.kp), gainText(c.kiPerS), seconds(c.kdS));
}

GainsPanel::GainsPanel(QWidget* parent) : QWidget(parent)
{
    auto* v = new QVBoxLayout(this);
    m_title = new QLabel(this);
    m_title->setStyleSheet(QStringLiteral("font-weight: bold;"));
    v->addWidget(m_title);
    m_form = new QLabel(this);
    m_form->setWordWrap(true);
    m_form->setStyleSheet(QStringLiteral("color: #555;"));
    v->addWidget(m_form);

    auto* grid = new QGridLayout;
    grid->addWidget(new QLabel(tr("continuous"), this), 0, 1);
    grid->addWidget(new QLabel(tr("per control period"), this), 0, 2);
    const QString names[3] = {tr("Kp"), tr("Ki [1/s]"), tr("Kd [s]")};
    const char* objectNames[3] = {"kpEdit", "kiEdit", "kdEdit"};
    for (int i = 0; i < 3; ++i) {
        grid->addWidget(new QLabel(names[i], this), i + 1, 0);
        // No validator: a typed "-5" stays "-5", shown invalid with the reason, and is never sent.
        m_edit[i] = new NumberField(this);
        m_edit[i]->setObjectName(QLatin1String(objectNames[i]));
        m_edit[i]->setFieldName(names[i]);
        m_edit[i]->setRange(0.0, std::nullopt);
        m_edit[i]->setDisplay('g', 6);  // the device holds float32: more digits are noise
        // entryChanged, not textEdited: QLineEdit announces an edit before the field has read it.
        connect(m_edit[i], &NumberField::entryChanged, this, [this] { showEdited(); });
        grid->addWidget(m_edit[i], i + 1, 1);
        m_discrete[i] = new QLabel(this);
        m_discrete[i]->setObjectName(QString::fromLatin1(objectNames[i]).replace(QStringLiteral("Edit"), QStringLiteral("Discrete")));
        m_discrete[i]->setTextInteractionFlags(Qt::TextSelectableByMouse);
        grid->addWidget(m_discrete[i], i + 1, 2);
    }
    v->addLayout(grid);
    m_times = new QLabel(this);
    m_times->setObjectName(QStringLiteral("gainsNote"));
    m_times->setStyleSheet(QStringLiteral("color: #555;"));
    v->addWidget(m_times);

    auto* buttons = new QHBoxLayout;
    m_apply = new QPushButton(tr("Apply"), this);
    m_apply->setObjectName(QStringLiteral("gainsApply"));
    m_revert = new QPushButton(tr("Revert"), this);
    m_revert->setObjectName(QStringLiteral("gainsRevert"));
    m_save = new QPushButton(tr("Save to device"), this);
    m_save->setToolTip(tr("Apply these gains and keep them as the device's power-up gains"));
    m_read = new QPushButton(tr("Read back"), this);
    m_read->setToolTip(tr("Read the gains in force from the device"));
    for (auto* b : {m_apply, m_revert, m_save, m_read})
        buttons->addWidget(b);
    v->addLayout(buttons);
    connect(m_apply, &QPushButton::clicked, this, [this] {
        if (const auto g = edited())
            emit applyRequested(*g, tr("edited"));
    });
    connect(m_save, &QPushButton::clicked, this, [this] {
        if (const auto g = edited())
            emit saveRequested(*g);
    });
    connect(m_revert, &QPushButton::clicked, this, [this] {
        // Edits not applied are what Revert takes back first; nothing is sent for them.
        if (hasUnappliedEdits()) {
            setEdited(m_inForce);
            return;
        }
        if (const auto p = previous())
            emit revertRequested(p->gains, tr("reverted to %1").arg(p->time.toString(QStringLiteral("HH:mm:ss"))));
    });
    connect(m_read, &QPushButton::clicked, this, &GainsPanel::readBackRequested);

    v->addWidget(new QLabel(tr("Applied gain sets"), this));
    m_table = new QTableWidget(0, 5, this);
    m_table->setObjectName(QStringLiteral("gainsHistory"));
    m_table->setHorizontalHeaderLabels({tr("Time"), tr("Source"), tr("Kp"), tr("Ki [1/s]"), tr("Kd [s]")});
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setSectionResizeMode(1, QHeaderView::Stretch);
    m_table->verticalHeader()->setVisible(false);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setWordWrap(false);
    v->addWidget(m_table, 1);
    setMinimumWidth(380);
    clearTarget(tr("no target chosen"));
}

void GainsPanel::clearTarget(const QString& why)
{
    m_hasTarget = false;
    m_history.clear();
    m_table->setRowCount(0);
    m_title->setText(tr("PID gains"));
    m_form->setText(why);
    for (int i = 0; i < 3; ++i) {
        m_edit[i]->clear();
        m_discrete[i]->clear();
    }
    m_times->clear();
    refreshButtons();
}

void GainsPanel::setTarget(const QString& name, double periodS, bool device, const DiscreteGains& g, const QString& source)
{
    m_hasTarget = true;
    m_periodS = periodS;
    m_device = device;
    m_history.clear();
    m_table->setRowCount(0);
    m_title->setText(tr("PID gains of %1").arg(name));
    m_form->setText(tr("Shown in continuous form: Kp, Ki in 1/s, Kd in s. Beside them the discrete gains per control "
                       "period T = %1 that %2 runs: ki = Ki·T, kd = Kd/T.")
                        .arg(seconds(periodS), device ? tr("the device") : tr("the model's loop")));
    // The citation is for whoever wants to check the form, not for every reader.
    m_form->setToolTip(tr("Incremental PID: Δu = kp·(e_k − e_k−1) + ki·e_k + kd·(e_k − 2e_k−1 + e_k−2); "
                          "see docs/tuning.md (the stage paper's eq. 2)."));
    setInForce(g, source);
}

void GainsPanel::setInForce(const DiscreteGains& g, const QString& source)
{
    m_inForce = g;
    addHistory(source, g);
    setEdited(g);
}

void GainsPanel::setEdited(const DiscreteGains& g)
{
    const ContinuousGains c = motion::control::toContinuous(g, m_periodS);
    const double values[3] = {c.kp, c.kiPerS, c.kdS};
    for (int i = 0; i < 3; ++i)
        m_edit[i]->setValue(values[i]);
    showEdited();
}

std::optional<DiscreteGains> GainsPanel::edited() const
{
    double v[3];
    for (int i = 0; i < 3; ++i) {
        const auto x = m_edit[i]->value();
        if (!x)
            return std::nullopt;
        v[i] = *x;
    }
    return motion::control::toDiscrete(ContinuousGains{v[0], v[1], v[2]}, m_periodS);
}

void GainsPanel::showEdited()
{
    if (!m_hasTarget) {
        for (auto* l : m_discrete)
            l->clear();
        m_times->clear();
        refreshButtons();
        return;
    }
    const auto g = edited();
    if (g) {
        m_discrete[0]->setText(tr("kp = %1").arg(gainText(g->kp)));
        m_discrete[1]->setText(tr("ki = %1").arg(gainText(g->ki)));
        m_discrete[2]->setText(tr("kd = %1").arg(gainText(g->kd)));
        const ContinuousGains c = motion::control::toContinuous(*g, m_periodS);
        const bool changed = hasUnappliedEdits();
        m_times->setText(tr("Ti = Kp/Ki = %1 · Td = Kd/Kp = %2%3")
                             .arg(seconds(c.tiS()), seconds(c.tdS()), changed ? tr(" · edited, not applied") : QString()));
    } else {
        for (auto* l : m_discrete)
            l->setText(QStringLiteral("—"));
        m_times->setText(problem());
    }
    refreshButtons();
}

QString GainsPanel::problem() const
{
    // A wrong entry is said before one still being typed: it needs the operator's eye.
    for (auto* e : m_edit)
        if (!e->isValid() && !e->isIncomplete())
            return tr("%1 Nothing is sent until it is fixed.").arg(e->problem());
    for (auto* e : m_edit)
        if (e->isIncomplete())
            return tr("%1 is still being typed: nothing is sent until it is a number.").arg(e->fieldName());
    return {};
}

bool GainsPanel::hasUnappliedEdits() const
{
    if (!m_hasTarget)
        return false;
    const auto g = edited();
    if (!g)
        return true;
    auto near = [](double a, double b) { return std::abs(a - b) <= 1e-5 * std::max(std::abs(a), std::abs(b)) + 1e-300; };
    return !(near(g->kp, m_inForce.kp) && near(g->ki, m_inForce.ki) && near(g->kd, m_inForce.kd));
}

std::optional<GainsPanel::HistoryEntry> GainsPanel::previous() const
{
    for (int i = m_history.size() - 1; i >= 0; --i)
        if (m_history[i].gains != m_inForce)
            return m_history[i];
    return std::nullopt;
}

void GainsPanel::addHistory(const QString& source, const DiscreteGains& g)
{
    m_history.push_back({QDateTime::currentDateTime(), source, g});
    const ContinuousGains c = motion::control::toContinuous(g, m_periodS);
    const int row = m_table->rowCount();
    m_table->insertRow(row);
    const QString cells[5] = {m_history.back().time.toString(QStringLiteral("HH:mm:ss")), source, gainText(c.kp), gainText(c.kiPerS), gainText(c.kdS)};
    for (int col = 0; col < 5; ++col)
        m_table->setItem(row, col, new QTableWidgetItem(cells[col]));
    m_table->scrollToBottom();
    refreshButtons();
}

void GainsPanel::setBusy(bool busy)
{
    m_busy = busy;
    refreshButtons();
}

void GainsPanel::refreshButtons()
{
    const bool usable = m_hasTarget && !m_busy;
    for (auto* e : m_edit)
        e->setEnabled(m_hasTarget);
    const bool valid = edited().has_value();
    m_apply->setEnabled(usable && valid);
    m_apply->setToolTip(valid || !m_hasTarget ? tr("Send these gains to the target; they take over between two control periods (bumpless)") : problem());
    m_save->setEnabled(usable && m_device && valid);
    m_save->setVisible(m_device || !m_hasTarget);
    m_read->setVisible(m_device || !m_hasTarget);
    m_read->setEnabled(usable && m_device);
    const bool edits = hasUnappliedEdits();
    m_revert->setEnabled(usable && (edits || previous().has_value()));
    m_revert->setToolTip(edits ? tr("Put the gains in force back in the fields (nothing is sent)")
                               : tr("Apply again the set that was in force before the last change"));
}

} // namespace ui
