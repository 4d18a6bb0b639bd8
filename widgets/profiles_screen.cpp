#include "widgets/profiles_screen.h"

#include "motion/any_profile.h"
#include "motion/step_timing.h"

#include "widgets/common/number_field.h"
#include "widgets/wording/wording.h"

#include <qcustomplot.h>

#include <QAbstractTableModel>
#include <QComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QSplitter>
#include <QTableView>
#include <QTimer>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace ui {

namespace {

constexpr std::int64_t kMaxTableSteps = 200000;  ///< larger tables take seconds to build: ask for a coarser step
constexpr int kPlotSamples = 800;

/// What each kind reads from the form (the rest is hidden so nobody tunes a field that does nothing).
struct KindFields {
    bool aMax, jMax, accelTime, startSpeed, plateau;
};

KindFields fieldsOf(motion::ProfileKind kind)
{
    switch (kind) {
    case motion::ProfileKind::SeedSCurve: return {false, false, true, false, false};
    case motion::ProfileKind::Trapezoid: return {true, false, false, true, true};
    case motion::ProfileKind::Exponential: return {false, false, true, false, false};
    case motion::ProfileKind::JerkLimited: return {true, true, false, false, false};
    }
    return {};
}

}  // namespace

/// The step-period table as a lazy model: a long move has tens of thousands of rows.
class StepTableModel : public QAbstractTableModel {
public:
    explicit StepTableModel(QObject* parent) : QAbstractTableModel(parent) {}

    void setTable(motion::StepTable table)
    {
        beginResetModel();
        m_table = std::move(table);
        endResetModel();
    }
    const motion::StepTable& table() const { return m_table; }

    int rowCount(const QModelIndex& parent = {}) const override
    {
        return parent.isValid() ? 0 : static_cast<int>(m_table.entries.size());
    }
    int columnCount(const QModelIndex& parent = {}) const override { return parent.isValid() ? 0 : 5; }

    QVariant data(const QModelIndex& index, int role) const override
    {
        if (!index.isValid() || index.row() >= rowCount())
            return {};
        const auto& e = m_table.entries[static_cast<std::size_t>(index.row())];
        if (role == Qt::TextAlignmentRole)
            return int(Qt::AlignRight | Qt::AlignVCenter);
        if (role == Qt::ToolTipRole) {
            if (e.zeroCorrected)
                return ProfilesScreen::tr("Match 0 cannot fire: edge moved one tick late, the next step one tick early");
            if (e.clamped)
                return ProfilesScreen::tr("Rate outside 80 Hz … 20 kHz: clamped");
            return {};
        }
        if (role == Qt::ForegroundRole && (e.clamped || e.zeroCorrected))
            return QColor(e.clamped ? QColor(180, 60, 0) : QColor(0, 90, 170));
        if (role != Qt::DisplayRole)
            return {};
        switch (index.column()) {
        case 0: return QString::number(e.idealPeriodS * 1e6, 'f', 2);
        case 1: return QString::number(e.periodTicks);
        case 2: return QString::number(e.wholePeriods);
        case 3: return QString::number(e.matchTicks);
        case 4:
            return e.clamped ? ProfilesScreen::tr("clamped")
                             : (e.zeroCorrected ? ProfilesScreen::tr("+1 tick") : QString());
        }
        return {};
    }

    QVariant headerData(int section, Qt::Orientation orientation, int role) const override
    {
        if (role != Qt::DisplayRole)
            return {};
        if (orientation == Qt::Vertical)
            return section + 1;
        switch (section) {
        case 0: return ProfilesScreen::tr("Ideal period (µs)");
        case 1: return ProfilesScreen::tr("Period (ticks)");
        case 2: return ProfilesScreen::tr("Whole periods");
        case 3: return ProfilesScreen::tr("Match (ticks)");
        case 4: return ProfilesScreen::tr("Note");
        }
        return {};
    }

private:
    motion::StepTable m_table;
};

ProfilesScreen::ProfilesScreen(QWidget* parent) : QWidget(parent)
{
    auto* top = new QHBoxLayout(this);

    // Left: kind, limits, results.
    auto* left = new QVBoxLayout;
    auto* title = new QLabel(tr("Motion profiles"), this);
    QFont tf = title->font();
    tf.setPointSizeF(tf.pointSizeF() * 1.3);
    tf.setBold(true);
    title->setFont(tf);
    left->addWidget(title);
    auto* form = new QFormLayout;
    m_kind = new QComboBox(this);
    m_kind->setObjectName(QStringLiteral("kind"));
    m_kind->addItem(tr("Seed S-curve (seed 000)"), int(motion::ProfileKind::SeedSCurve));
    m_kind->addItem(tr("Trapezoid with plateau steps (seed 001)"), int(motion::ProfileKind::Trapezoid));
    m_kind->addItem(tr("Exponential (seed 003)"), int(motion::ProfileKind::Exponential));
    m_kind->addItem(tr("Jerk-limited, time-optimal"), int(motion::ProfileKind::JerkLimited));
    m_kind->setCurrentIndex(3);
    m_kind->setToolTip(tr("Shape of the speed change"));
    form->addRow(tr("Kind"), m_kind);
    m_distance = addField(form, QStringLiteral("distance"), tr("Distance"), tr(" mm"), -1000, 1000, 50, 3,
                          tr("Signed length of the move"));
    m_vMax = addField(form, QStringLiteral("vmax"), tr("Max velocity"), tr(" mm/s"), 0, 10000, 50, 2,
                      tr("Cruise speed the move may not exceed"));
    m_aMax = addField(form, QStringLiteral("amax"), tr("Max acceleration"), tr(" mm/s²"), 0, 1e6, 500, 1,
                      tr("Acceleration limit (the trapezoid uses it for both ramps)"));
    m_jMax = addField(form, QStringLiteral("jmax"), tr("Max jerk"), tr(" mm/s³"), 0, 1e8, 10000, 0,
                      tr("How fast the acceleration may change"));
    m_accelTime = addField(form, QStringLiteral("accelTime"), tr("Acceleration time"), tr(" s"), 0, 10, 0.1, 3,
                           tr("Seed S-curve: ramp duration t2. Exponential: reaches 95 % of the max velocity (3τ)"));
    m_startSpeed = addField(form, QStringLiteral("startSpeed"), tr("Start speed"), tr(" mm/s"), 0, 10000, 1.5, 2,
                            tr("Speed the motor can jump to from rest (seed 001 start speed)"));
    m_plateau = addField(form, QStringLiteral("plateau"), tr("Plateau"), tr(" mm"), 0, 1000, 0.05, 3,
                         tr("Distance run at the start speed before accelerating and after braking (seed 001 plateau steps)"));
    m_step = addField(form, QStringLiteral("step"), tr("Step size"), tr(" mm"), 0.0001, 10, 0.01, 4,
                      tr("Travel per (micro)step, for the step-period table"));
    left->addLayout(form);

    m_error = new QLabel(this);
    m_error->setObjectName(QStringLiteral("error"));
    m_error->setWordWrap(true);
    m_error->setStyleSheet(QStringLiteral("color: #b3261e;"));
    m_error->hide();
    left->addWidget(m_error);
    m_moveTime = new QLabel(this);
    m_moveTime->setObjectName(QStringLiteral("moveTime"));
    QFont mf = m_moveTime->font();
    mf.setPointSizeF(mf.pointSizeF() * 1.2);
    mf.setBold(true);
    m_moveTime->setFont(mf);
    left->addWidget(m_moveTime);
    m_summary = new QLabel(this);
    m_summary->setObjectName(QStringLiteral("summary"));
    m_summary->setWordWrap(true);
    left->addWidget(m_summary);
    left->addStretch(1);

    // Right: four stacked plots sharing the time axis, the step table under them.
    auto* splitter = new QSplitter(Qt::Vertical, this);
    auto* plotsHost = new QWidget(splitter);
    auto* plots = new QVBoxLayout(plotsHost);
    plots->setContentsMargins(0, 0, 0, 0);
    plots->setSpacing(2);
    const QString yLabels[4] = {tr("s (mm)"), tr("v (mm/s)"), tr("a (mm/s²)"), tr("j (mm/s³)")};
    const QColor colors[4] = {QColor(31, 119, 180), QColor(44, 160, 44), QColor(214, 39, 40), QColor(148, 103, 189)};
    const char* names[4] = {"plotPosition", "plotVelocity", "plotAcceleration", "plotJerk"};
    for (int i = 0; i < 4; ++i) {
        m_plots[i] = new QCustomPlot(plotsHost);
        m_plots[i]->setObjectName(QString::fromLatin1(names[i]));
        m_plots[i]->setMinimumHeight(90);
        m_plots[i]->addGraph();
        m_plots[i]->graph(0)->setPen(QPen(colors[i], 1.6));
        m_plots[i]->yAxis->setLabel(yLabels[i]);
        m_plots[i]->xAxis->setTickLabels(i == 3);
        // Separate plots size their left margin to their own tick labels; fix it so the four
        // time axes line up and a moment reads straight down through s, v, a and j.
        m_plots[i]->axisRect()->setAutoMargins(QCP::msTop | QCP::msRight | QCP::msBottom);
        m_plots[i]->axisRect()->setMargins(QMargins(86, 0, 0, 0));
        if (i == 3)
            m_plots[i]->xAxis->setLabel(tr("t (s)"));
        plots->addWidget(m_plots[i], 1);
    }
    auto* tableHost = new QWidget(splitter);
    auto* tableLayout = new QVBoxLayout(tableHost);
    tableLayout->setContentsMargins(0, 0, 0, 0);
    m_tableSummary = new QLabel(tableHost);
    m_tableSummary->setObjectName(QStringLiteral("tableSummary"));
    m_tableSummary->setWordWrap(true);
    tableLayout->addWidget(m_tableSummary);
    m_table = new QTableView(tableHost);
    m_table->setObjectName(QStringLiteral("stepTable"));
    m_model = new StepTableModel(this);
    m_table->setModel(m_model);
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    m_table->verticalHeader()->setDefaultSectionSize(m_table->fontMetrics().height() + 4);
    m_table->setAlternatingRowColors(true);
    tableLayout->addWidget(m_table, 1);
    splitter->addWidget(plotsHost);
    splitter->addWidget(tableHost);
    splitter->setStretchFactor(0, 3);
    splitter->setStretchFactor(1, 2);

    top->addLayout(left, 0);
    top->addWidget(splitter, 1);

    // Coalesce: typing "120" in a spin box must not plan three moves and rebuild three tables.
    m_replanTimer = new QTimer(this);
    m_replanTimer->setSingleShot(true);
    m_replanTimer->setInterval(60);
    connect(m_replanTimer, &QTimer::timeout, this, &ProfilesScreen::replan);
    connect(m_kind, qOverload<int>(&QComboBox::currentIndexChanged), this, [this] {
        updateFieldVisibility();
        scheduleReplan();
    });
    updateFieldVisibility();
    replan();
}

// Kept as typed: "-5" in Max velocity is shown as invalid with its reason (and no plan),
// never turned into 5 by a spin box that cannot take the minus.
NumberField* ProfilesScreen::addField(QFormLayout* form, const QString& objectName, const QString& label,
                                      const QString& suffix, double min, double max, double value, int decimals,
                                      const QString& tip)
{
    auto* box = new NumberField(this);
    box->setObjectName(objectName);
    box->setRange(min, max);
    box->setDisplay('g', std::max(10, decimals + 6));  // every digit a value has: a rounded display would be taken back as typed
    box->setValue(value);
    box->setUnit(suffix);
    box->setHelp(tip);
    form->addRow(label, box);
    connect(box, &NumberField::entryChanged, this, &ProfilesScreen::scheduleReplan);
    return box;
}

int ProfilesScreen::stepTableRows() const { return m_model->rowCount(); }

void ProfilesScreen::scheduleReplan() { m_replanTimer->start(); }

void ProfilesScreen::updateFieldVisibility()
{
    const auto f = fieldsOf(static_cast<motion::ProfileKind>(m_kind->currentData().toInt()));
    const std::pair<NumberField*, bool> rows[] = {
        {m_aMax, f.aMax}, {m_jMax, f.jMax}, {m_accelTime, f.accelTime}, {m_startSpeed, f.startSpeed}, {m_plateau, f.plateau}};
    for (const auto& [box, visible] : rows) {
        box->setVisible(visible);
        // Hide the row's label too, through the form layout that owns the box.
        for (QFormLayout* fl : findChildren<QFormLayout*>())
            if (QWidget* label = fl->labelForField(box))
                label->setVisible(visible);
    }
}

void ProfilesScreen::showError(const QString& message)
{
    m_error->setText(message);
    m_error->setVisible(!message.isEmpty());
}

void ProfilesScreen::showNoPlan(const QString& why)
{
    m_moveTimeS = -1;
    showError(why);
    m_moveTime->setText(tr("Move time: —"));
    m_summary->clear();
    for (auto* plot : m_plots) {
        plot->graph(0)->data()->clear();
        plot->replot();
    }
    m_model->setTable({});
    m_tableSummary->clear();
}

void ProfilesScreen::replan()
{
    motion::ProfileRequest r;
    r.kind = static_cast<motion::ProfileKind>(m_kind->currentData().toInt());
    if (const QString typed = NumberField::firstProblemUnder(this); !typed.isEmpty()) {
        showNoPlan(typed);
        return;
    }
    // Every shown field is valid here; a hidden one is not used by this kind of profile.
    r.vMaxMmS = m_vMax->valueOr(0);
    r.aMaxMmS2 = m_aMax->valueOr(0);
    r.jMaxMmS3 = m_jMax->valueOr(0);
    r.accelTimeS = m_accelTime->valueOr(0);
    r.startSpeedMmS = m_startSpeed->valueOr(0);
    r.plateauMm = m_plateau->valueOr(0);
    const auto planned = motion::planProfile(m_distance->valueOr(0), r);
    if (!planned) {
        showNoPlan(tr("Cannot plan this move: %1").arg(ui::words::text(planned.error())));
        return;
    }
    showError({});
    const motion::AnyProfile& p = *planned;
    m_moveTimeS = p.duration();
    m_moveTime->setText(tr("Move time: %1 s").arg(m_moveTimeS, 0, 'f', 4));

    // Curves: sample densely, plus the end, so ramps and joins are visible.
    QVector<double> t, series[4];
    double peak[4] = {0, 0, 0, 0};
    const double T = p.duration();
    for (int k = 0; k <= kPlotSamples; ++k) {
        const auto s = p.at(T * k / kPlotSamples);
        const double values[4] = {s.s, s.v, s.a, s.j};
        t << s.t;
        for (int i = 0; i < 4; ++i) {
            series[i] << values[i];
            peak[i] = std::max(peak[i], std::fabs(values[i]));
        }
    }
    for (int i = 0; i < 4; ++i) {
        m_plots[i]->graph(0)->setData(t, series[i], true);
        m_plots[i]->xAxis->setRange(0, T > 0 ? T : 1);
        m_plots[i]->graph(0)->rescaleValueAxis(false, true);
        const QCPRange range = m_plots[i]->yAxis->range();
        const double pad = std::max(range.size() * 0.08, 1e-9);
        m_plots[i]->yAxis->setRange(range.lower - pad, range.upper + pad);
        m_plots[i]->replot();
    }
    m_summary->setText(tr("Peak velocity %1 mm/s · peak acceleration %2 mm/s² · peak jerk %3 mm/s³")
                           .arg(peak[1], 0, 'g', 5)
                           .arg(peak[2], 0, 'g', 5)
                           .arg(peak[3], 0, 'g', 5));

    // Seed 001 step-period table of this move.
    const double stepMm = m_step->valueOr(0);
    const double steps = std::floor(std::fabs(p.distance()) / stepMm + 1e-9);
    if (steps > kMaxTableSteps) {
        m_model->setTable({});
        m_tableSummary->setText(tr("%1 steps: too many for the table (at most %2); use a larger step size.")
                                    .arg(steps, 0, 'f', 0)
                                    .arg(kMaxTableSteps));
        return;
    }
    const motion::StepTimerConfig timer;  // the seed's 72 MHz clock and 50 µs interrupt
    motion::StepTable table = motion::stepTableForProfile(p, stepMm, timer);
    m_tableSummary->setText(
        tr("Step periods at %1 MHz, %2 µs interrupt (%3 ticks): %4 steps, table time %5 s vs ideal %6 s "
           "(error %7 µs), %8 clamped to 80 Hz … 20 kHz, %9 zero-match corrections.")
            .arg(timer.clockHz / 1e6, 0, 'g', 4)
            .arg(timer.interruptPeriodS * 1e6, 0, 'g', 4)
            .arg(table.interruptTicks)
            .arg(table.entries.size())
            .arg(table.tableDurationS, 0, 'f', 5)
            .arg(table.idealDurationS, 0, 'f', 5)
            .arg(table.timeErrorS * 1e6, 0, 'f', 1)
            .arg(table.clampedCount)
            .arg(table.zeroCorrections));
    m_model->setTable(std::move(table));
}

}  // namespace ui
