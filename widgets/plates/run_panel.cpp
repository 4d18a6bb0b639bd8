#include "widgets/plates/run_panel.h"
#include "widgets/common/button_key.h"
#include "widgets/plates/step_texts.h"

#include "device/client/request_error.h"
#include "widgets/wording/wording.h"

#include <QEvent>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QListWidget>
#include <QProgressBar>
#include <QPushButton>
#include <QTableWidget>
#include <QTime>
#include <QTimer>
#include <QVBoxLayout>

#include <cmath>

namespace ui {

using dev::jobs::RunState;

using ui::words::duration;

RunPanel::RunPanel(dev::jobs::RecipeRunner* runner, QWidget* parent) : QWidget(parent), m_runner(runner)
{
    auto* v = new QVBoxLayout(this);
    auto* controls = new QHBoxLayout;
    m_run = new QPushButton(tr("Run"), this);
    m_run->setToolTip(tr("Run the recipe from its first well, logging every well (F5)"));
    setButtonKey(m_run, QKeySequence(Qt::Key_F5));
    m_pause = new QPushButton(tr("Pause"), this);
    m_pause->setToolTip(tr("Stop after the well under way, with the tip up"));
    m_resume = new QPushButton(tr("Resume"), this);
    m_resume->setToolTip(tr("Continue a paused or stopped run"));
    m_abort = new QPushButton(tr("Abort"), this);
    m_abort->setToolTip(tr("Stop at once, then raise the tip; the log can resume it later"));
    m_abort->setStyleSheet(QStringLiteral("QPushButton:enabled { color:#b71c1c; font-weight:bold; }"));
    m_fromLog = new QPushButton(tr("Resume from log…"), this);
    m_fromLog->setToolTip(tr("Continue a run that ended early (a crash, a pulled cable) from its run log: wells already done are not done again"));
    for (auto* b : {m_run, m_pause, m_resume, m_abort})
        controls->addWidget(b);
    controls->addStretch();
    v->addLayout(controls);

    m_progress = new QProgressBar(this);
    m_progress->setRange(0, 1000);
    m_progress->setTextVisible(true);
    v->addWidget(m_progress);
    m_state = new QLabel(this);
    m_current = new QLabel(this);
    m_times = new QLabel(this);
    // Beside the state, not after the four run buttons: there it was cut to "Resum…" on a
    // 1366-pixel screen.
    auto* stateRow = new QHBoxLayout;
    stateRow->addWidget(m_state, 1);
    stateRow->addWidget(m_fromLog);
    v->addLayout(stateRow);
    v->addWidget(m_current);
    v->addWidget(m_times);

    auto* planBox = new QGroupBox(tr("Plan: what the run does, op by op"), this);
    auto* pv = new QVBoxLayout(planBox);
    m_summary = new QLabel(planBox);
    m_summary->setWordWrap(true);
    pv->addWidget(m_summary);
    m_speed = new QLabel(planBox);
    m_speed->setObjectName(QStringLiteral("planSpeed"));
    m_speed->setWordWrap(true);
    m_speed->setToolTip(tr("The bound is the least time any controller could take for these wells in this order under the axes' limits "
                           "and the travel rules (docs/recipes.md)"));
    pv->addWidget(m_speed);
    m_table = new QTableWidget(0, 8, planBox);
    m_table->setHorizontalHeaderLabels({tr("#"), tr("Step"), tr("What"), tr("Where"), tr("X (mm)"), tr("Y (mm)"), tr("Plunger (µL)"), tr("Starts at")});
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->verticalHeader()->setVisible(false);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    // Made after the plan table (which stays the panel's first table), shown above it.
    m_orders = new QTableWidget(0, 4, planBox);
    m_orders->setObjectName(QStringLiteral("orderComparison"));
    m_orders->setHorizontalHeaderLabels({tr("Well order"), tr("Planned"), tr("Bound"), tr("Planned / bound")});
    m_orders->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_orders->horizontalHeader()->setStretchLastSection(true);
    m_orders->verticalHeader()->setVisible(false);
    m_orders->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_orders->setMaximumHeight(m_orders->horizontalHeader()->sizeHint().height() * 7);
    m_orders->setToolTip(tr("Every step with wells planned in each order; the recipe's own order is the one shown above"));
    pv->addWidget(m_orders);
    pv->addWidget(m_table);
    v->addWidget(planBox, 3);

    m_messages = new QListWidget(this);
    m_messages->setObjectName(QStringLiteral("runMessages"));
    m_messages->setMaximumHeight(100);
    m_messages->setWordWrap(true);
    v->addWidget(m_messages, 1);

    connect(m_run, &QPushButton::clicked, this, &RunPanel::runRequested);
    connect(m_fromLog, &QPushButton::clicked, this, &RunPanel::resumeFromLogRequested);
    connect(m_pause, &QPushButton::clicked, m_runner, &dev::jobs::RecipeRunner::pause);
    connect(m_abort, &QPushButton::clicked, this, [this] {
        if (m_confirm && !m_confirm(tr("Abort the run? The analyzer stops at once and raises the tip; the wells not done yet "
                                       "stay undone (the run log can resume them later).")))
            return;
        m_runner->abort();
    });
    connect(m_resume, &QPushButton::clicked, this, [this] {
        motion::msg::Message error;
        if (!m_runner->resume(m_decide, &error))
            emit problem(ui::words::text(error));
    });
    connect(m_runner, &dev::jobs::RecipeRunner::stateChanged, this, &RunPanel::refresh);
    connect(m_runner, &dev::jobs::RecipeRunner::progressChanged, this, &RunPanel::refresh);
    connect(m_runner, &dev::jobs::RecipeRunner::message, this, [this](const motion::msg::Message& m, bool problemText) {
        auto* item = new QListWidgetItem(m_messages);
        item->setData(Qt::UserRole, QTime::currentTime().toString(QStringLiteral("HH:mm:ss")));
        item->setData(Qt::UserRole + 1, QVariant::fromValue(m));
        wordLine(item);
        if (problemText)
            item->setForeground(QColor(0xc6, 0x28, 0x28));
        m_messages->scrollToBottom();
        while (m_messages->count() > 200)
            delete m_messages->takeItem(0);
    });
    // Elapsed time and ETA tick between wells too.
    auto* tick = new QTimer(this);
    tick->setInterval(500);
    connect(tick, &QTimer::timeout, this, [this] {
        if (isVisible() && m_runner->state() == RunState::Running)
            refresh();
    });
    tick->start();
    refresh();
}

void RunPanel::setPlan(const motion::plates::RecipePlan& plan, bool runnable, const QString& why)
{
    m_runnable = runnable;
    m_planOps = runnable ? static_cast<int>(plan.ops.size()) : 0;
    m_summary->setText(runnable ? tr("%1 operations over %2 wells · %3 µL dispensed, %4 µL aspirated · plunger %5 → %6 µL · about %7")
                                      .arg(plan.ops.size())
                                      .arg(plan.wellsVisited())
                                      .arg(plan.totalDispensedUl, 0, 'g', 6)
                                      .arg(plan.totalAspiratedUl, 0, 'g', 6)
                                      .arg(plan.pumpStartUl, 0, 'g', 6)
                                      .arg(plan.pumpEndUl, 0, 'g', 6)
                                      .arg(duration(plan.totalTimeS))
                                : tr("Not runnable: %1").arg(why));
    m_plannedS = runnable ? plan.totalTimeS : 0;
    m_boundS = runnable ? plan.boundS : 0;
    const int rows = std::min(static_cast<int>(plan.ops.size()), kMaxPlanRows);
    m_table->setUpdatesEnabled(false);
    m_table->setRowCount(rows);
    for (int r = 0; r < rows; ++r) {
        const motion::plates::PlanOp& op = plan.ops[static_cast<std::size_t>(r)];
        const QStringList cells = {QString::number(op.index + 1),
                                   QString::number(op.step + 1),
                                   opTitle(op),
                                   ui::words::text(op.where()),
                                   QString::number(op.at.x, 'f', 2),
                                   QString::number(op.at.y, 'f', 2),
                                   op.pumpNetUl == 0 ? QStringLiteral("0") : QString::number(op.pumpNetUl, 'f', 2),
                                   duration(op.startS)};
        for (int c = 0; c < cells.size(); ++c) {
            auto* item = m_table->item(r, c);
            if (!item)
                m_table->setItem(r, c, item = new QTableWidgetItem);
            item->setText(cells[c]);
        }
    }
    m_table->setUpdatesEnabled(true);
    refresh();
}

void RunPanel::setOrderComparison(const std::vector<motion::plates::OrderComparison>& orders)
{
    m_orders->setRowCount(static_cast<int>(orders.size()));
    for (int r = 0; r < static_cast<int>(orders.size()); ++r) {
        const motion::plates::OrderComparison& o = orders[static_cast<std::size_t>(r)];
        const QStringList cells = {wellOrderTitle(o.order),
                                   o.ok ? duration(o.totalTimeS) : tr("cannot be used"),
                                   o.ok ? duration(o.boundS) : QString(),
                                   o.ok && o.boundS > 0 ? QString::number(o.totalTimeS / o.boundS, 'f', 2) : QString()};
        for (int c = 0; c < cells.size(); ++c) {
            auto* item = m_orders->item(r, c);
            if (!item)
                m_orders->setItem(r, c, item = new QTableWidgetItem);
            item->setText(cells[c]);
        }
        m_orders->item(r, 0)->setToolTip(QString::fromLatin1(motion::plates::wellOrderName(o.order)));  // what the recipe file says
    }
    m_orders->setVisible(!orders.empty());
}

void RunPanel::refresh()
{
    const RunState s = m_runner->state();
    const dev::jobs::RunProgress p = m_runner->progress();
    const bool busy = s == RunState::Running || s == RunState::Pausing || s == RunState::Aborting;
    m_run->setEnabled(m_runnable && !busy && s != RunState::Paused);
    m_fromLog->setEnabled(m_runnable && !busy && s != RunState::Paused);
    m_pause->setEnabled(s == RunState::Running);
    m_resume->setEnabled(s == RunState::Paused || (s == RunState::Stopped && !m_runner->logPath().isEmpty()));
    m_abort->setEnabled(s == RunState::Running || s == RunState::Pausing || s == RunState::Paused);
    m_progress->setValue(static_cast<int>(std::lround(p.fraction * 1000)));
    m_progress->setFormat(tr("%1 of %2 operations").arg(p.opsDone).arg(s == RunState::Idle ? m_planOps : p.opsTotal));
    m_state->setText(tr("State: %1").arg(ui::words::term(dev::jobs::runStateTerm(s))));
    // Paused between two ops nothing is under way: the op Resume begins with is "next".
    m_current->setText(p.currentOp >= 0 && s != RunState::Idle ? tr("Current: %1").arg(ui::words::text(p.currentLabel))
                       : p.nextOp >= 0                          ? tr("Next: %1").arg(ui::words::text(p.nextLabel))
                                                                : tr("Current: —"));
    m_times->setText(s == RunState::Idle ? QString()
                                         : tr("Elapsed %1 · ETA %2").arg(duration(p.elapsedS), s == RunState::Finished ? tr("done") : duration(p.etaS)));
    if (m_boundS <= 0)
        m_speed->clear();
    else if (s == RunState::Finished && p.deviceS > 0)
        m_speed->setText(tr("Took %1 on the analyzer's clock: %2 times the time-optimal bound (%3); planned %4")
                             .arg(duration(p.deviceS), QString::number(p.deviceS / m_boundS, 'f', 2), duration(m_boundS), duration(m_plannedS)));
    else
        m_speed->setText(tr("Time-optimal bound %1: the plan takes %2 times it").arg(duration(m_boundS), QString::number(m_plannedS / m_boundS, 'f', 2)));
    if (p.currentOp >= 0 && p.currentOp < m_table->rowCount() && busy)
        m_table->selectRow(p.currentOp);
}

void RunPanel::wordLine(QListWidgetItem* item)
{
    const auto m = item->data(Qt::UserRole + 1).value<motion::msg::Message>();
    item->setText(QStringLiteral("%1  %2").arg(item->data(Qt::UserRole).toString(), ui::words::sentence(ui::words::text(m))));
    item->setToolTip(item->text());  // a line cut with "…" (a long log name) is whole here
}

void RunPanel::changeEvent(QEvent* event)
{
    // The run's messages so far are reworded too: a switch mid-run leaves no line in the old language.
    if (event->type() == QEvent::LanguageChange)
        for (int i = 0; i < m_messages->count(); ++i)
            wordLine(m_messages->item(i));
    QWidget::changeEvent(event);
}

} // namespace ui
